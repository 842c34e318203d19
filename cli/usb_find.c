/* USB devices: --device specs, enumeration and matching, interface choice,
 * printer class requests, and `quiltc devices`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CLI_USB_INTERNAL
#include "cli.h"
#include "usb.h"

void usb_opts_default(usb_opts *o)
{
    memset(o, 0, sizeof *o);
    o->iface = -1;
    o->protocol = USB_PROTO_AUTO;
    o->chunk = USB_CHUNK_DEFAULT;
    o->timeout_ms = USB_TIMEOUT_DEFAULT;
    o->retries = USB_RETRIES_DEFAULT;
}

/* Up to max digits of base (10 or 16) from *s, at least one; -1 if none. */
static long parse_digits(const char **s, int base, int max, long limit)
{
    const char *p = *s;
    long v = 0;
    int n = 0;

    for (;; p++, n++) {
        int d;

        if (*p >= '0' && *p <= '9')
            d = *p - '0';
        else if (base == 16 && *p >= 'a' && *p <= 'f')
            d = *p - 'a' + 10;
        else if (base == 16 && *p >= 'A' && *p <= 'F')
            d = *p - 'A' + 10;
        else
            break;
        if (n == max)
            return -1;
        v = v * base + d;
    }
    if (n == 0 || v > limit)
        return -1;
    *s = p;
    return v;
}

int usb_parse_spec(const char *s, usb_spec *spec)
{
    const char *p = s;
    long a, b;

    memset(spec, 0, sizeof *spec);
    if (s == NULL)
        return -1;
    if (strchr(s, ':') != NULL) {
        if ((a = parse_digits(&p, 16, 4, 0xffff)) < 0 || *p++ != ':' ||
            (b = parse_digits(&p, 16, 4, 0xffff)) < 0 || *p != '\0')
            return -1;
        spec->vid = (unsigned)a;
        spec->pid = (unsigned)b;
        return 0;
    }
    if ((a = parse_digits(&p, 10, 3, 255)) < 1 || *p++ != '-')
        return -1;
    spec->by_port = 1;
    spec->bus = (unsigned)a;
    for (;;) {
        if (spec->nports == (int)sizeof spec->ports || (b = parse_digits(&p, 10, 3, 255)) < 1)
            return -1;
        spec->ports[spec->nports++] = (unsigned char)b;
        if (*p == '\0')
            return 0;
        if (*p++ != '.')
            return -1;
    }
}

void usb_port_path(libusb_device *dev, char *buf, size_t size)
{
    uint8_t ports[8];
    int n = libusb_get_port_numbers(dev, ports, (int)sizeof ports), i;
    size_t len;

    snprintf(buf, size, "%u-", (unsigned)libusb_get_bus_number(dev));
    if (n <= 0) {
        len = strlen(buf);
        snprintf(buf + len, size - len, "0");
        return;
    }
    for (i = 0; i < n; i++) {
        len = strlen(buf);
        snprintf(buf + len, size - len, i ? ".%u" : "%u", (unsigned)ports[i]);
    }
}

void usb_describe(libusb_device *dev, char *buf, size_t size)
{
    struct libusb_device_descriptor d;
    char path[48];

    usb_port_path(dev, path, sizeof path);
    if (libusb_get_device_descriptor(dev, &d) != 0)
        memset(&d, 0, sizeof d);
    snprintf(buf, size, "%04x:%04x at %s", (unsigned)d.idVendor, (unsigned)d.idProduct, path);
}

static int matches(libusb_device *dev, const usb_spec *spec)
{
    struct libusb_device_descriptor d;
    uint8_t ports[8];
    int n;

    if (!spec->by_port)
        return libusb_get_device_descriptor(dev, &d) == 0 && d.idVendor == spec->vid &&
               d.idProduct == spec->pid;
    if (libusb_get_bus_number(dev) != spec->bus)
        return 0;
    n = libusb_get_port_numbers(dev, ports, (int)sizeof ports);
    return n == spec->nports && memcmp(ports, spec->ports, (size_t)n) == 0;
}

/* Orders devices by bus, then port path, so listings and messages are stable. */
static int by_port(const void *pa, const void *pb)
{
    libusb_device *a = *(libusb_device *const *)pa, *b = *(libusb_device *const *)pb;
    uint8_t x[8], y[8];
    int nx, ny, i;

    if (libusb_get_bus_number(a) != libusb_get_bus_number(b))
        return libusb_get_bus_number(a) < libusb_get_bus_number(b) ? -1 : 1;
    nx = libusb_get_port_numbers(a, x, (int)sizeof x);
    ny = libusb_get_port_numbers(b, y, (int)sizeof y);
    for (i = 0; i < nx && i < ny; i++)
        if (x[i] != y[i])
            return x[i] < y[i] ? -1 : 1;
    return nx < ny ? -1 : nx > ny;
}

/* libusb_get_device_list, sorted by port. */
static ssize_t device_list(libusb_context *ctx, libusb_device ***list)
{
    ssize_t n = libusb_get_device_list(ctx, list);

    if (n > 1)
        qsort(*list, (size_t)n, sizeof **list, by_port);
    return n;
}

static struct libusb_config_descriptor *get_config(libusb_device *dev)
{
    struct libusb_config_descriptor *cfg = NULL;

    if (libusb_get_active_config_descriptor(dev, &cfg) != 0 &&
        libusb_get_config_descriptor(dev, 0, &cfg) != 0)
        return NULL;
    return cfg;
}

/* 3 printer, 2 vendor, 1 other: how much an interface looks like a target. */
static int rank(const struct libusb_interface_descriptor *a)
{
    if (a->bInterfaceClass == USB_CLASS_PRINTER_IF)
        return 3;
    if (a->bInterfaceClass == LIBUSB_CLASS_VENDOR_SPEC)
        return 2;
    return 1;
}

/* Fills t from an alternate setting with a bulk OUT endpoint; 0 if it has one. */
static int target_from_alt(const struct libusb_interface_descriptor *a, usb_target *t)
{
    int e;

    memset(t, 0, sizeof *t);
    for (e = 0; e < a->bNumEndpoints; e++) {
        const struct libusb_endpoint_descriptor *ep = &a->endpoint[e];

        if ((ep->bmAttributes & LIBUSB_TRANSFER_TYPE_MASK) != LIBUSB_TRANSFER_TYPE_BULK)
            continue;
        if ((ep->bEndpointAddress & LIBUSB_ENDPOINT_DIR_MASK) == LIBUSB_ENDPOINT_OUT) {
            if (t->ep_out == 0) {
                t->ep_out = ep->bEndpointAddress;
                t->max_packet = ep->wMaxPacketSize;
            }
        } else if (t->ep_in == 0) {
            t->ep_in = ep->bEndpointAddress;
        }
    }
    if (t->ep_out == 0)
        return -1;
    t->iface = a->bInterfaceNumber;
    t->alt = a->bAlternateSetting;
    t->if_class = a->bInterfaceClass;
    t->if_subclass = a->bInterfaceSubClass;
    t->if_protocol = a->bInterfaceProtocol;
    return 0;
}

int usb_find_target(libusb_device *dev, int want, usb_target *t)
{
    struct libusb_config_descriptor *cfg = get_config(dev);
    int i, j, best = 0;

    if (cfg == NULL)
        return -1;
    for (i = 0; i < cfg->bNumInterfaces; i++) {
        for (j = 0; j < cfg->interface[i].num_altsetting; j++) {
            const struct libusb_interface_descriptor *a = &cfg->interface[i].altsetting[j];
            usb_target cand;

            if (want >= 0 && a->bInterfaceNumber != want)
                continue;
            if (target_from_alt(a, &cand) != 0 || rank(a) <= best)
                continue;
            best = rank(a);
            *t = cand;
        }
    }
    libusb_free_config_descriptor(cfg);
    return best > 0 ? 0 : -1;
}

int usb_init(libusb_context **ctx)
{
    int r = libusb_init(ctx);

    if (r != 0) {
        cli_error("cannot start libusb: %s", libusb_strerror((enum libusb_error)r));
        return CLI_RUNTIME;
    }
    return CLI_OK;
}

int usb_select(libusb_context *ctx, const usb_opts *opts, libusb_device **out, usb_target *t)
{
    libusb_device **list;
    usb_spec spec;
    ssize_t n, i;
    int found = 0, no_target = 0;
    char names[256] = "", one[64];

    *out = NULL;
    if (usb_parse_spec(opts->device, &spec) != 0) {
        cli_error("bad --device '%s' (want VID:PID in hex, e.g. 0bad:1001, or BUS-PORT, "
                  "e.g. 1-2.3)",
                  opts->device ? opts->device : "");
        return CLI_USAGE;
    }
    n = device_list(ctx, &list);
    if (n < 0) {
        cli_error("cannot list USB devices: %s", libusb_strerror((enum libusb_error)n));
        return CLI_RUNTIME;
    }
    for (i = 0; i < n; i++) {
        usb_target cand;

        if (!matches(list[i], &spec))
            continue;
        if (usb_find_target(list[i], opts->iface, &cand) != 0) {
            no_target++;
            usb_describe(list[i], one, sizeof one);
            continue;
        }
        usb_describe(list[i], one, sizeof one);
        if (strlen(names) + strlen(one) + 3 < sizeof names)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s",
                     found ? ", " : "", one);
        if (found++ == 0) {
            *out = libusb_ref_device(list[i]);
            *t = cand;
        }
    }
    libusb_free_device_list(list, 1);
    if (found == 1)
        return CLI_OK;
    if (found > 1) {
        libusb_unref_device(*out);
        *out = NULL;
        cli_error("%d USB devices match '%s': %s; choose one with --device BUS-PORT", found,
                  opts->device, names);
        return CLI_RUNTIME;
    }
    if (no_target > 0 && opts->iface >= 0)
        cli_error("interface %d of USB device %s has no bulk OUT endpoint (see quiltc devices)",
                  opts->iface, one);
    else if (no_target > 0)
        cli_error("USB device %s has no bulk OUT endpoint to send a pattern to", one);
    else
        cli_error("no USB device matches '%s' (see quiltc devices)", opts->device);
    return CLI_RUNTIME;
}

/* Replaces bytes outside printable ASCII with '?'. */
static void sanitise(char *s)
{
    for (; *s != '\0'; s++)
        if ((unsigned char)*s < 32 || (unsigned char)*s > 126)
            *s = '?';
}

int usb_printer_device_id(libusb_device_handle *h, const usb_target *t, char *buf, size_t size)
{
    unsigned char raw[USB_PRINTER_ID_MAX + 1];
    int r, len;

    r = libusb_control_transfer(h,
                                LIBUSB_ENDPOINT_IN | LIBUSB_REQUEST_TYPE_CLASS |
                                    LIBUSB_RECIPIENT_INTERFACE,
                                USB_PRINTER_GET_DEVICE_ID, 0, (uint16_t)(t->iface << 8 | t->alt),
                                raw, USB_PRINTER_ID_MAX, 1000);
    if (r < 0)
        return r;
    if (r < 2)
        return LIBUSB_ERROR_IO;
    /* two bytes of big-endian length (counting themselves), then the text */
    len = (raw[0] << 8 | raw[1]) - 2;
    if (len < 0 || len > r - 2)
        len = r - 2;
    if ((size_t)len >= size)
        len = (int)size - 1;
    memcpy(buf, raw + 2, (size_t)len);
    buf[len] = '\0';
    sanitise(buf);
    return len;
}

int usb_printer_port_status(libusb_device_handle *h, const usb_target *t, unsigned timeout_ms)
{
    unsigned char st = 0;
    int r;

    r = libusb_control_transfer(h,
                                LIBUSB_ENDPOINT_IN | LIBUSB_REQUEST_TYPE_CLASS |
                                    LIBUSB_RECIPIENT_INTERFACE,
                                USB_PRINTER_GET_PORT_STATUS, 0, (uint16_t)t->iface, &st, 1,
                                timeout_ms);
    if (r < 0)
        return r;
    return r == 1 ? st : LIBUSB_ERROR_IO;
}

const char *usb_port_faults(int status, char *buf, size_t size)
{
    buf[0] = '\0';
    if (status < 0)
        return buf;
    if (status & USB_PORT_PAPER_EMPTY)
        snprintf(buf + strlen(buf), size - strlen(buf), "paper empty");
    if (!(status & USB_PORT_SELECT))
        snprintf(buf + strlen(buf), size - strlen(buf), "%soffline", buf[0] ? ", " : "");
    if (!(status & USB_PORT_NOT_ERROR))
        snprintf(buf + strlen(buf), size - strlen(buf), "%serror", buf[0] ? ", " : "");
    return buf;
}

static const char *class_name(int c)
{
    switch (c) {
    case LIBUSB_CLASS_PRINTER:
        return "printer";
    case LIBUSB_CLASS_VENDOR_SPEC:
        return "vendor";
    case LIBUSB_CLASS_COMM:
        return "communications";
    case LIBUSB_CLASS_DATA:
        return "CDC data";
    case LIBUSB_CLASS_MASS_STORAGE:
        return "mass storage";
    case LIBUSB_CLASS_HID:
        return "HID";
    case LIBUSB_CLASS_HUB:
        return "hub";
    default:
        return "other";
    }
}

static const char *printer_protocol(int p)
{
    switch (p) {
    case 1:
        return ", unidirectional";
    case 2:
        return ", bidirectional";
    case 3:
        return ", IEEE 1284.4";
    case 4:
        return ", IPP over USB";
    default:
        return "";
    }
}

/* A sysfs attribute of the device at path ("1-2" or "1-2:1.0"), trimmed. */
static int sysfs_attr(const char *path, const char *attr, char *buf, size_t size)
{
    char name[160];
    FILE *f;
    size_t n;

    snprintf(name, sizeof name, "/sys/bus/usb/devices/%s/%s", path, attr);
    f = fopen(name, "rb");
    if (f == NULL)
        return -1;
    n = fread(buf, 1, size - 1, f);
    fclose(f);
    while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == ' '))
        n--;
    buf[n] = '\0';
    sanitise(buf);
    return n > 0 ? 0 : -1;
}

/* Manufacturer and product: sysfs (needs no access), else string descriptors. */
static void device_strings(libusb_device *dev, libusb_device_handle *h, const char *path,
                           char *buf, size_t size)
{
    struct libusb_device_descriptor d;
    char m[128] = "", p[128] = "";

    if (sysfs_attr(path, "manufacturer", m, sizeof m) != 0 && h != NULL &&
        libusb_get_device_descriptor(dev, &d) == 0 && d.iManufacturer &&
        libusb_get_string_descriptor_ascii(h, d.iManufacturer, (unsigned char *)m, sizeof m) <= 0)
        m[0] = '\0';
    if (sysfs_attr(path, "product", p, sizeof p) != 0 && h != NULL &&
        libusb_get_device_descriptor(dev, &d) == 0 && d.iProduct &&
        libusb_get_string_descriptor_ascii(h, d.iProduct, (unsigned char *)p, sizeof p) <= 0)
        p[0] = '\0';
    sanitise(m);
    sanitise(p);
    snprintf(buf, size, "%s%s%s", m, m[0] && p[0] ? " " : "", p);
    if (buf[0] == '\0')
        snprintf(buf, size, "(no name)");
}

static void list_device(libusb_device *dev, int all)
{
    struct libusb_device_descriptor d;
    struct libusb_config_descriptor *cfg;
    libusb_device_handle *h = NULL;
    int open_err = 0, i, j, shown = 0;
    char path[48], sysname[48], name[272];

    if (libusb_get_device_descriptor(dev, &d) != 0)
        return;
    cfg = get_config(dev);
    if (cfg == NULL)
        return;
    usb_port_path(dev, path, sizeof path);
    if (libusb_get_port_number(dev) == 0)
        snprintf(sysname, sizeof sysname, "usb%u", (unsigned)libusb_get_bus_number(dev));
    else
        snprintf(sysname, sizeof sysname, "%s", path);
    for (i = 0; i < cfg->bNumInterfaces; i++)
        for (j = 0; j < cfg->interface[i].num_altsetting; j++) {
            usb_target t;

            if (target_from_alt(&cfg->interface[i].altsetting[j], &t) == 0)
                shown = 1;
        }
    if (!shown && !all) {
        libusb_free_config_descriptor(cfg);
        return;
    }
    open_err = libusb_open(dev, &h);
    if (open_err != 0)
        h = NULL;
    device_strings(dev, h, sysname, name, sizeof name);
    printf("%04x:%04x  %-8s %s", (unsigned)d.idVendor, (unsigned)d.idProduct, path, name);
    if (d.bDeviceClass != LIBUSB_CLASS_PER_INTERFACE)
        printf(" (%s class)", class_name(d.bDeviceClass));
    printf("\n");
    for (i = 0; i < cfg->bNumInterfaces; i++) {
        for (j = 0; j < cfg->interface[i].num_altsetting; j++) {
            const struct libusb_interface_descriptor *a = &cfg->interface[i].altsetting[j];
            usb_target t;
            char id[USB_PRINTER_ID_MAX + 1], ifpath[64];

            if (target_from_alt(a, &t) != 0) {
                if (all)
                    printf("    interface %d.%d: %s class, no bulk OUT endpoint\n",
                           a->bInterfaceNumber, a->bAlternateSetting,
                           class_name(a->bInterfaceClass));
                continue;
            }
            printf("    interface %d.%d: %s class%s, bulk OUT 0x%02x", t.iface, t.alt,
                   class_name(t.if_class),
                   t.if_class == USB_CLASS_PRINTER_IF ? printer_protocol(t.if_protocol) : "",
                   (unsigned)t.ep_out);
            if (t.ep_in)
                printf(", bulk IN 0x%02x", (unsigned)t.ep_in);
            printf(", %u-byte packets\n", t.max_packet);
            if (t.if_class != USB_CLASS_PRINTER_IF)
                continue;
            /* usblp publishes the ID in sysfs; else ask the device itself */
            snprintf(ifpath, sizeof ifpath, "%s:%d.%d", path, cfg->bConfigurationValue, t.iface);
            if (sysfs_attr(ifpath, "ieee1284_id", id, sizeof id) == 0)
                printf("        IEEE-1284 ID: %s\n", id);
            else if (h != NULL && usb_printer_device_id(h, &t, id, sizeof id) >= 0)
                printf("        IEEE-1284 ID: %s\n", id);
            else if (open_err == LIBUSB_ERROR_ACCESS)
                printf("        IEEE-1284 ID: no permission to open the device "
                       "(see quiltc udev-rule %04x:%04x)\n",
                       (unsigned)d.idVendor, (unsigned)d.idProduct);
            else
                printf("        IEEE-1284 ID: not available\n");
        }
    }
    if (h != NULL)
        libusb_close(h);
    libusb_free_config_descriptor(cfg);
}

static const char devices_usage[] =
    "usage: quiltc devices [--all]\n"
    "Lists the USB devices that could take a pattern (a bulk OUT endpoint):\n"
    "VID:PID, bus and port path (both work as upload --device), names, class,\n"
    "and per interface its endpoints and, for printers, the IEEE-1284 device ID.\n"
    "  --all   also list devices without a bulk OUT endpoint\n";

int cmd_devices(int argc, char **argv)
{
    libusb_context *ctx;
    libusb_device **list;
    ssize_t n, i;
    int all = 0, a, count = 0, rc;

    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--all") == 0) {
            all = 1;
        } else if (strcmp(argv[a], "--help") == 0 || strcmp(argv[a], "-h") == 0) {
            fputs(devices_usage, stdout);
            return CLI_OK;
        } else {
            cli_error("devices: unknown argument '%s' (try quiltc devices --help)", argv[a]);
            return CLI_USAGE;
        }
    }
    if ((rc = usb_init(&ctx)) != CLI_OK)
        return rc;
    n = device_list(ctx, &list);
    if (n < 0) {
        cli_error("cannot list USB devices: %s", libusb_strerror((enum libusb_error)n));
        libusb_exit(ctx);
        return CLI_RUNTIME;
    }
    for (i = 0; i < n; i++) {
        usb_target t;

        if (all || usb_find_target(list[i], -1, &t) == 0) {
            list_device(list[i], all);
            count++;
        }
    }
    if (count == 0)
        printf("no USB device with a bulk OUT endpoint found\n");
    libusb_free_device_list(list, 1);
    libusb_exit(ctx);
    if (fflush(stdout) != 0) {
        cli_error("cannot write to stdout");
        return CLI_RUNTIME;
    }
    return CLI_OK;
}
