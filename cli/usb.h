/* quiltc CLI: USB upload (libusb-1.0). The entry points below exist in every
 * build; with `make USB=0` cli/usb_none.c defines them as "built without USB
 * support" errors. Everything below CLI_USB_INTERNAL is shared only by the
 * cli/usb_*.c files that link libusb. */
#ifndef QUILTC_CLI_USB_H
#define QUILTC_CLI_USB_H

/* quiltc devices: lists every USB device with a bulk OUT endpoint. */
int cmd_devices(int argc, char **argv);
/* quiltc upload FILE --device VID:PID|BUS-PORT [options]. */
int cmd_upload(int argc, char **argv);
/* quiltc udev-rule VID:PID: prints a udev rule granting access without root. */
int cmd_udev_rule(int argc, char **argv);
/* Sends a whole file with default options (generate --upload); quiet drops
 * the progress bar and the summary line. Returns a CLI_* status. */
int cli_usb_send_file(const char *path, const char *device, int quiet);

#ifdef CLI_USB_INTERNAL
#include <stddef.h>

#include <libusb.h>

enum { USB_PROTO_AUTO, USB_PROTO_PRINTER, USB_PROTO_RAW };

/* Defaults and limits of the upload options. */
#define USB_CHUNK_DEFAULT 4096u
#define USB_CHUNK_MAX (1024u * 1024u)
#define USB_TIMEOUT_DEFAULT 5000u
#define USB_TIMEOUT_MAX 600000u
#define USB_RETRIES_DEFAULT 3u
#define USB_RETRIES_MAX 100u
#define USB_FILE_MAX ((size_t)256 * 1024 * 1024)

/* USB printer class (USB Device Class Definition for Printing Devices 1.1). */
#define USB_CLASS_PRINTER_IF 7
#define USB_PRINTER_GET_DEVICE_ID 0
#define USB_PRINTER_GET_PORT_STATUS 1
#define USB_PRINTER_ID_MAX 1023
#define USB_PORT_NOT_ERROR 0x08
#define USB_PORT_SELECT 0x10
#define USB_PORT_PAPER_EMPTY 0x20

typedef struct usb_opts {
    const char *device; /* VID:PID or BUS-PORT[.PORT...] */
    int iface;          /* interface number, -1 = choose */
    int protocol;       /* USB_PROTO_* */
    unsigned chunk;     /* bytes per bulk transfer */
    unsigned timeout_ms;
    unsigned retries; /* extra attempts after a timeout or stall */
    int quiet;
} usb_opts;

/* A parsed --device: either ids or a port path. */
typedef struct usb_spec {
    int by_port;
    unsigned vid, pid;
    unsigned bus;
    unsigned char ports[8];
    int nports;
} usb_spec;

/* An interface able to take a pattern: a bulk OUT endpoint. */
typedef struct usb_target {
    int iface, alt;
    int if_class, if_subclass, if_protocol;
    unsigned char ep_out, ep_in; /* ep_in 0 = none */
    unsigned max_packet;
} usb_target;

void usb_opts_default(usb_opts *o);
/* Parses VID:PID (hex) or BUS-PORT[.PORT...] (decimal). 0 on success. */
int usb_parse_spec(const char *s, usb_spec *spec);
/* "1-2.3" into buf; root hubs give "1-0". */
void usb_port_path(libusb_device *dev, char *buf, size_t size);
/* "0bad:1001 at 1-2" into buf. */
void usb_describe(libusb_device *dev, char *buf, size_t size);
/* The interface to send to: want >= 0 picks that interface; else a printer
 * interface, else a vendor one, else any with a bulk OUT endpoint.
 * 0 found, -1 none. */
int usb_find_target(libusb_device *dev, int want, usb_target *t);
/* Opens a libusb context (one-line error on failure). */
int usb_init(libusb_context **ctx);
/* Finds exactly one device matching opts->device that has a target; on
 * failure prints the one-line error and returns a CLI_* status. The caller
 * unrefs *out. */
int usb_select(libusb_context *ctx, const usb_opts *opts, libusb_device **out, usb_target *t);
/* Reads a printer's IEEE-1284 device ID (sanitised, NUL-terminated); the
 * length, or a negative libusb error. */
int usb_printer_device_id(libusb_device_handle *h, const usb_target *t, char *buf, size_t size);
/* Reads a printer's port status byte: 0..255, or a negative libusb error. */
int usb_printer_port_status(libusb_device_handle *h, const usb_target *t, unsigned timeout_ms);
/* "paper empty, offline" for a port status byte with a fault, "" if none. */
const char *usb_port_faults(int status, char *buf, size_t size);
/* Sends len bytes to the selected device; prints the outcome. CLI_* status. */
int usb_send(libusb_context *ctx, libusb_device *dev, const usb_target *t, const usb_opts *opts,
             unsigned char *data, size_t len);
#endif

#endif
