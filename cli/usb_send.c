/* Sending a file over USB: detach the kernel driver, claim, printer status,
 * chunked bulk OUT with stall/timeout retries, unplug and Ctrl-C handling,
 * a progress bar on a terminal, release and re-attach. */
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

#define CLI_USB_INTERNAL
#include "cli.h"
#include "usb.h"

/* Set by SIGINT/SIGTERM while a send runs; the loop cancels the transfer. */
static volatile sig_atomic_t usb_stop;

static void on_signal(int sig)
{
    (void)sig;
    usb_stop = 1;
}

typedef struct progress {
    int on;
    size_t total;
    double t0, last;
} progress;

static void progress_draw(progress *p, size_t done, int final)
{
    char bar[31];
    double now, secs, rate;
    int i, fill;

    if (!p->on)
        return;
    now = cli_now_ms();
    if (!final && now - p->last < 100.0)
        return;
    p->last = now;
    fill = p->total ? (int)((double)done * 30.0 / (double)p->total) : 30;
    for (i = 0; i < 30; i++)
        bar[i] = i < fill ? '#' : '-';
    bar[30] = '\0';
    secs = (now - p->t0) / 1000.0;
    rate = secs > 0.0 ? (double)done / 1024.0 / secs : 0.0;
    fprintf(stderr, "\r[%s] %3d%%  %lu/%lu bytes  %.1f KiB/s ", bar,
            p->total ? (int)((double)done * 100.0 / (double)p->total) : 100, (unsigned long)done,
            (unsigned long)p->total, rate);
    if (final)
        fputc('\n', stderr);
    fflush(stderr);
}

static void LIBUSB_CALL on_transfer_done(struct libusb_transfer *tr)
{
    *(int *)tr->user_data = 1;
}

/* One bulk OUT transfer of n bytes; waits for it, cancelling on a signal.
 * Returns a libusb_transfer_status (or -1 if it could not be submitted, with
 * *err the libusb error) and the bytes the device took in *actual. */
static int bulk_out(libusb_context *ctx, libusb_device_handle *h, struct libusb_transfer *tr,
                    const usb_target *t, unsigned char *buf, int n, unsigned timeout_ms,
                    int *actual, int *err)
{
    int done = 0, cancelled = 0, r, failures = 0;

    *actual = 0;
    libusb_fill_bulk_transfer(tr, h, t->ep_out, buf, n, on_transfer_done, &done, timeout_ms);
    r = libusb_submit_transfer(tr);
    if (r != 0) {
        *err = r;
        return -1;
    }
    while (!done) {
        struct timeval tv;

        if ((usb_stop || failures > 0) && !cancelled) {
            libusb_cancel_transfer(tr);
            cancelled = 1;
        }
        tv.tv_sec = 0;
        tv.tv_usec = 100000;
        r = libusb_handle_events_timeout_completed(ctx, &tv, &done);
        if (r != 0 && r != LIBUSB_ERROR_INTERRUPTED && ++failures > 50) {
            /* the event loop is broken: leave the transfer (never free it in flight) */
            *err = r;
            return -2;
        }
    }
    *actual = tr->actual_length;
    return (int)tr->status;
}

static const char *proto_name(int proto)
{
    return proto == USB_PROTO_PRINTER ? "printer" : "raw";
}

/* The send loop proper, with the device claimed. */
static int send_chunks(libusb_context *ctx, libusb_device_handle *h, const usb_target *t,
                       const usb_opts *opts, int proto, const char *who, unsigned char *data,
                       size_t len, size_t *sent_out)
{
    struct libusb_transfer *tr = libusb_alloc_transfer(0);
    progress pg;
    size_t sent = 0;
    unsigned fails = 0;
    int rc = CLI_OK;

    if (tr == NULL) {
        cli_error("out of memory");
        return CLI_RUNTIME;
    }
    pg.on = !opts->quiet && isatty(STDERR_FILENO);
    pg.total = len;
    pg.t0 = pg.last = cli_now_ms();
    progress_draw(&pg, 0, 0);
    while (sent < len) {
        size_t left = len - sent;
        int n = (int)(left < opts->chunk ? left : opts->chunk), actual, err = 0, st;
        char faults[64];

        if (usb_stop) {
            st = LIBUSB_TRANSFER_CANCELLED;
            actual = 0;
        } else {
            st = bulk_out(ctx, h, tr, t, data + sent, n, opts->timeout_ms, &actual, &err);
        }
        sent += (size_t)(actual > 0 ? actual : 0);
        progress_draw(&pg, sent, 0);
        if (st == LIBUSB_TRANSFER_COMPLETED && actual > 0) {
            fails = 0;
            continue;
        }
        if (pg.on)
            progress_draw(&pg, sent, 1);
        if (st == -2) {
            cli_error("USB event handling failed (%s); %lu of %lu bytes delivered to %s",
                      libusb_strerror((enum libusb_error)err), (unsigned long)sent,
                      (unsigned long)len, who);
            *sent_out = sent;
            return CLI_RUNTIME; /* tr may still be in flight: not freed */
        }
        if (st == LIBUSB_TRANSFER_NO_DEVICE || (st == -1 && err == LIBUSB_ERROR_NO_DEVICE)) {
            cli_error("USB device %s was unplugged; %lu of %lu bytes delivered", who,
                      (unsigned long)sent, (unsigned long)len);
            rc = CLI_RUNTIME;
            break;
        }
        if (st == LIBUSB_TRANSFER_CANCELLED) {
            cli_error("interrupted; %lu of %lu bytes delivered to %s", (unsigned long)sent,
                      (unsigned long)len, who);
            rc = CLI_RUNTIME;
            break;
        }
        if (st == -1) {
            cli_error("cannot send to %s: %s; %lu of %lu bytes delivered", who,
                      libusb_strerror((enum libusb_error)err), (unsigned long)sent,
                      (unsigned long)len);
            rc = CLI_RUNTIME;
            break;
        }
        if (actual > 0)
            fails = 0; /* partial progress: the device is alive */
        if (st == LIBUSB_TRANSFER_STALL) {
            int ps;

            libusb_clear_halt(h, t->ep_out);
            if (proto == USB_PROTO_PRINTER) {
                ps = usb_printer_port_status(h, t, opts->timeout_ms);
                if (usb_port_faults(ps, faults, sizeof faults)[0] != '\0') {
                    cli_error("%s stalled: printer reports %s; %lu of %lu bytes delivered", who,
                              faults, (unsigned long)sent, (unsigned long)len);
                    rc = CLI_RUNTIME;
                    break;
                }
            }
            if (++fails > opts->retries) {
                cli_error("endpoint 0x%02x of %s stalled on %u tries; %lu of %lu bytes delivered",
                          (unsigned)t->ep_out, who, fails, (unsigned long)sent,
                          (unsigned long)len);
                rc = CLI_RUNTIME;
                break;
            }
        } else if (st == LIBUSB_TRANSFER_TIMED_OUT) {
            if (++fails > opts->retries) {
                cli_error("sending to %s timed out after %u tries of %u ms; %lu of %lu bytes "
                          "delivered",
                          who, fails, opts->timeout_ms, (unsigned long)sent, (unsigned long)len);
                rc = CLI_RUNTIME;
                break;
            }
        } else if (st == LIBUSB_TRANSFER_COMPLETED) {
            if (++fails > opts->retries) {
                cli_error("%s took no data on %u tries; %lu of %lu bytes delivered", who, fails,
                          (unsigned long)sent, (unsigned long)len);
                rc = CLI_RUNTIME;
                break;
            }
        } else {
            cli_error("USB transfer to %s failed (%s); %lu of %lu bytes delivered", who,
                      st == LIBUSB_TRANSFER_OVERFLOW ? "overflow" : "I/O error",
                      (unsigned long)sent, (unsigned long)len);
            rc = CLI_RUNTIME;
            break;
        }
    }
    if (rc == CLI_OK)
        progress_draw(&pg, sent, 1);
    libusb_free_transfer(tr);
    *sent_out = sent;
    return rc;
}

static int claim_error(int r, int iface, const char *who, const char *ids)
{
    if (r == LIBUSB_ERROR_BUSY)
        cli_error("interface %d of %s is busy: another program or driver holds it", iface, who);
    else if (r == LIBUSB_ERROR_ACCESS)
        cli_error("permission denied claiming interface %d of %s (run 'quiltc udev-rule %s')",
                  iface, who, ids);
    else if (r == LIBUSB_ERROR_NO_DEVICE)
        cli_error("USB device %s was unplugged; 0 bytes delivered", who);
    else
        cli_error("cannot claim interface %d of %s: %s", iface, who,
                  libusb_strerror((enum libusb_error)r));
    return CLI_RUNTIME;
}

/* Open, detach, claim, printer checks, send, release, re-attach, close. */
static int send_session(libusb_context *ctx, libusb_device *dev, const usb_target *t,
                        const usb_opts *opts, int proto, const char *who, const char *ids,
                        unsigned char *data, size_t len)
{
    libusb_device_handle *h;
    char id[USB_PRINTER_ID_MAX + 1] = "", faults[64];
    int r, rc, detached = 0;
    size_t sent = 0;

    r = libusb_open(dev, &h);
    if (r == LIBUSB_ERROR_ACCESS) {
        cli_error("permission denied opening USB device %s (run 'quiltc udev-rule %s' for a "
                  "rule that allows it)",
                  who, ids);
        return CLI_RUNTIME;
    }
    if (r != 0) {
        cli_error("cannot open USB device %s: %s", who, libusb_strerror((enum libusb_error)r));
        return CLI_RUNTIME;
    }
    /* 1: a kernel driver (usblp) holds it; errors: no way to know, claim tells */
    if (libusb_kernel_driver_active(h, t->iface) == 1) {
        r = libusb_detach_kernel_driver(h, t->iface);
        if (r != 0 && r != LIBUSB_ERROR_NOT_FOUND) {
            rc = claim_error(r == LIBUSB_ERROR_ACCESS ? r : LIBUSB_ERROR_BUSY, t->iface, who, ids);
            libusb_close(h);
            return rc;
        }
        detached = r == 0;
    }
    r = libusb_claim_interface(h, t->iface);
    if (r != 0) {
        rc = claim_error(r, t->iface, who, ids);
        goto out_attach;
    }
    if (t->alt != 0 && (r = libusb_set_interface_alt_setting(h, t->iface, t->alt)) != 0) {
        cli_error("cannot select setting %d of interface %d of %s: %s", t->alt, t->iface, who,
                  libusb_strerror((enum libusb_error)r));
        rc = CLI_RUNTIME;
        goto out_release;
    }
    if (proto == USB_PROTO_PRINTER) {
        /* both requests are optional in practice: a failure is not fatal */
        usb_printer_device_id(h, t, id, sizeof id);
        r = usb_printer_port_status(h, t, opts->timeout_ms);
        if (usb_port_faults(r, faults, sizeof faults)[0] != '\0') {
            cli_error("printer %s reports %s; nothing sent", who, faults);
            rc = CLI_RUNTIME;
            goto out_release;
        }
    }

    rc = send_chunks(ctx, h, t, opts, proto, who, data, len, &sent);
    if (rc == CLI_OK && !opts->quiet) {
        char model[80] = "";
        const char *m = strstr(id, "MDL:");

        if (m == NULL)
            m = strstr(id, "MODEL:");
        if (m != NULL) {
            m = strchr(m, ':') + 1;
            snprintf(model, sizeof model, ", %.*s", (int)strcspn(m, ";"), m);
        }
        printf("sent %lu bytes to %s (interface %d, %s%s)\n", (unsigned long)sent, who, t->iface,
               proto_name(proto), model);
        fflush(stdout);
    }
out_release:
    libusb_release_interface(h, t->iface);
out_attach:
    if (detached)
        libusb_attach_kernel_driver(h, t->iface);
    libusb_close(h);
    return rc;
}

int usb_send(libusb_context *ctx, libusb_device *dev, const usb_target *t, const usb_opts *opts,
             unsigned char *data, size_t len)
{
    struct libusb_device_descriptor d;
    struct sigaction sa, old_int, old_term;
    char who[64], ids[16];
    int rc, proto = opts->protocol;

    usb_describe(dev, who, sizeof who);
    if (libusb_get_device_descriptor(dev, &d) != 0)
        memset(&d, 0, sizeof d);
    snprintf(ids, sizeof ids, "%04x:%04x", (unsigned)d.idVendor, (unsigned)d.idProduct);
    if (proto == USB_PROTO_AUTO)
        proto = t->if_class == USB_CLASS_PRINTER_IF ? USB_PROTO_PRINTER : USB_PROTO_RAW;

    /* Ctrl-C from here on is noted, not fatal: the kernel driver goes back */
    usb_stop = 0;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    rc = send_session(ctx, dev, t, opts, proto, who, ids, data, len);
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    return rc;
}
