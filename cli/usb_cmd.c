/* quiltc upload and quiltc udev-rule: arguments, then cli/usb_send.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CLI_USB_INTERNAL
#include "cli.h"
#include "usb.h"

static const char upload_usage[] =
    "usage: quiltc upload FILE --device VID:PID|BUS-PORT [options]\n"
    "Sends FILE as it is to a USB machine (see quiltc devices).\n"
    "  --device D        VID:PID in hex (0bad:1001) or bus and port path (1-2.3)\n"
    "  --interface N     interface number (default: a printer interface, else a\n"
    "                    vendor one, else any with a bulk OUT endpoint)\n"
    "  --protocol P      printer (device ID and port status checks) or raw\n"
    "                    (default: printer on a printer-class interface)\n"
    "  --chunk BYTES     bytes per bulk transfer (default 4096, at most 1048576)\n"
    "  --timeout MS      per transfer (default 5000)\n"
    "  --retries N       extra tries after a timeout or a stall (default 3)\n"
    "  --quiet, -q       no progress bar, no summary line\n";

/* "--name value" or "--name=value": the value, advancing *a; NULL if not this option. */
static const char *opt_value(int argc, char **argv, int *a, const char *name, int *missing)
{
    size_t n = strlen(name);

    if (strncmp(argv[*a], name, n) != 0)
        return NULL;
    if (argv[*a][n] == '=')
        return argv[*a] + n + 1;
    if (argv[*a][n] != '\0')
        return NULL;
    if (*a + 1 >= argc) {
        *missing = 1;
        return NULL;
    }
    return argv[++*a];
}

static int parse_uint(const char *opt, const char *s, unsigned lo, unsigned hi, unsigned *out)
{
    unsigned long long v;

    if (cli_parse_u64(s, &v) != 0 || v < lo || v > hi) {
        cli_error("upload: %s must be a whole number from %u to %u, not '%s'", opt, lo, hi, s);
        return -1;
    }
    *out = (unsigned)v;
    return 0;
}

/* Parses upload options after argv[0]; *file gets the one positional. */
static int parse_upload(int argc, char **argv, usb_opts *o, const char **file)
{
    int a, missing = 0;

    usb_opts_default(o);
    *file = NULL;
    for (a = 1; a < argc; a++) {
        const char *v;
        unsigned u;

        if ((v = opt_value(argc, argv, &a, "--device", &missing)) != NULL) {
            o->device = v;
        } else if ((v = opt_value(argc, argv, &a, "--interface", &missing)) != NULL) {
            if (parse_uint("--interface", v, 0, 255, &u) != 0)
                return CLI_USAGE;
            o->iface = (int)u;
        } else if ((v = opt_value(argc, argv, &a, "--protocol", &missing)) != NULL) {
            if (strcmp(v, "printer") == 0) {
                o->protocol = USB_PROTO_PRINTER;
            } else if (strcmp(v, "raw") == 0) {
                o->protocol = USB_PROTO_RAW;
            } else {
                cli_error("upload: --protocol must be printer or raw, not '%s'", v);
                return CLI_USAGE;
            }
        } else if ((v = opt_value(argc, argv, &a, "--chunk", &missing)) != NULL) {
            if (parse_uint("--chunk", v, 1, USB_CHUNK_MAX, &o->chunk) != 0)
                return CLI_USAGE;
        } else if ((v = opt_value(argc, argv, &a, "--timeout", &missing)) != NULL) {
            if (parse_uint("--timeout", v, 1, USB_TIMEOUT_MAX, &o->timeout_ms) != 0)
                return CLI_USAGE;
        } else if ((v = opt_value(argc, argv, &a, "--retries", &missing)) != NULL) {
            if (parse_uint("--retries", v, 0, USB_RETRIES_MAX, &o->retries) != 0)
                return CLI_USAGE;
        } else if (missing) {
            cli_error("upload: %s needs a value", argv[a]);
            return CLI_USAGE;
        } else if (strcmp(argv[a], "--quiet") == 0 || strcmp(argv[a], "-q") == 0) {
            o->quiet = 1;
        } else if (argv[a][0] == '-' && argv[a][1] != '\0') {
            cli_error("upload: unknown option '%s' (try quiltc upload --help)", argv[a]);
            return CLI_USAGE;
        } else if (*file != NULL) {
            cli_error("upload: one file at a time ('%s' and '%s')", *file, argv[a]);
            return CLI_USAGE;
        } else {
            *file = argv[a];
        }
    }
    if (*file == NULL) {
        cli_error("upload: no file given (usage: quiltc upload FILE --device VID:PID|BUS-PORT)");
        return CLI_USAGE;
    }
    if (o->device == NULL) {
        cli_error("upload: no --device given (see quiltc devices)");
        return CLI_USAGE;
    }
    return CLI_OK;
}

static int upload(const char *path, const usb_opts *o)
{
    libusb_context *ctx;
    libusb_device *dev;
    usb_target t;
    usb_spec spec;
    char *buf;
    size_t len;
    int rc;

    if (usb_parse_spec(o->device, &spec) != 0) {
        cli_error("bad --device '%s' (want VID:PID in hex, e.g. 0bad:1001, or BUS-PORT, "
                  "e.g. 1-2.3)",
                  o->device);
        return CLI_USAGE;
    }
    if (cli_read_file(path, USB_FILE_MAX, &buf, &len) != 0)
        return CLI_RUNTIME;
    if (len == 0) {
        cli_error("'%s' is empty: nothing to send", path);
        free(buf);
        return CLI_RUNTIME;
    }
    if ((rc = usb_init(&ctx)) != CLI_OK) {
        free(buf);
        return rc;
    }
    rc = usb_select(ctx, o, &dev, &t);
    if (rc == CLI_OK) {
        rc = usb_send(ctx, dev, &t, o, (unsigned char *)buf, len);
        libusb_unref_device(dev);
    }
    libusb_exit(ctx);
    free(buf);
    return rc;
}

int cmd_upload(int argc, char **argv)
{
    usb_opts o;
    const char *file;
    int a, rc;

    for (a = 1; a < argc; a++)
        if (strcmp(argv[a], "--help") == 0 || strcmp(argv[a], "-h") == 0) {
            fputs(upload_usage, stdout);
            return CLI_OK;
        }
    if ((rc = parse_upload(argc, argv, &o, &file)) != CLI_OK)
        return rc;
    return upload(file, &o);
}

int cli_usb_send_file(const char *path, const char *device, int quiet)
{
    usb_opts o;

    usb_opts_default(&o);
    o.device = device;
    o.quiet = quiet;
    return upload(path, &o);
}

static const char udev_usage[] =
    "usage: quiltc udev-rule VID:PID [--group NAME]\n"
    "Prints a udev rule that lets the logged-in user (and group NAME, default\n"
    "plugdev) use the device without root. Save it as\n"
    "/etc/udev/rules.d/70-quiltc.rules, then run\n"
    "  sudo udevadm control --reload-rules && sudo udevadm trigger\n"
    "and plug the machine in again.\n";

int cmd_udev_rule(int argc, char **argv)
{
    const char *ids = NULL, *group = "plugdev";
    usb_spec spec;
    int a, missing = 0;

    for (a = 1; a < argc; a++) {
        const char *v;

        if (strcmp(argv[a], "--help") == 0 || strcmp(argv[a], "-h") == 0) {
            fputs(udev_usage, stdout);
            return CLI_OK;
        }
        if ((v = opt_value(argc, argv, &a, "--group", &missing)) != NULL) {
            group = v;
        } else if (missing) {
            cli_error("udev-rule: --group needs a value");
            return CLI_USAGE;
        } else if (argv[a][0] == '-') {
            cli_error("udev-rule: unknown option '%s' (try quiltc udev-rule --help)", argv[a]);
            return CLI_USAGE;
        } else if (ids != NULL) {
            cli_error("udev-rule: one VID:PID at a time");
            return CLI_USAGE;
        } else {
            ids = argv[a];
        }
    }
    if (ids == NULL || usb_parse_spec(ids, &spec) != 0 || spec.by_port) {
        cli_error("udev-rule: want the device's VID:PID in hex, e.g. quiltc udev-rule 0bad:1001 "
                  "(see quiltc devices)");
        return CLI_USAGE;
    }
    if (group[0] == '\0' || strspn(group, "abcdefghijklmnopqrstuvwxyz"
                                          "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") !=
                                strlen(group)) {
        cli_error("udev-rule: bad --group '%s' (letters, digits, '_' and '-')", group);
        return CLI_USAGE;
    }
    printf("# quiltc: USB access to %04x:%04x without root, for the user at the seat (uaccess)\n"
           "# and for members of group %s. Save as /etc/udev/rules.d/70-quiltc.rules, then:\n"
           "#   sudo udevadm control --reload-rules && sudo udevadm trigger\n"
           "SUBSYSTEM==\"usb\", ENV{DEVTYPE}==\"usb_device\", ATTR{idVendor}==\"%04x\", "
           "ATTR{idProduct}==\"%04x\", MODE=\"0660\", GROUP=\"%s\", TAG+=\"uaccess\"\n",
           spec.vid, spec.pid, group, spec.vid, spec.pid, group);
    if (fflush(stdout) != 0) {
        cli_error("cannot write to stdout");
        return CLI_RUNTIME;
    }
    return CLI_OK;
}
