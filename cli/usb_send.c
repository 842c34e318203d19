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

/* One send: the device, what goes to it and how far it got. */
typedef struct session {
    libusb_context *ctx;
    libusb_device_handle *h;
    const usb_target *t;
    const usb_opts *opts;
    int proto;
    const char *who, *ids;
    unsigned char *data;
    size_t len, sent;
    unsigned fails; /* tries in a row that delivered nothing */
} session;

/* How a chunk went: a libusb_transfer_status, -1 if it could not be
 * submitted or -2 if the event loop broke (err the libusb error), and the
 * bytes the device took. */
typedef struct chunk {
    int st, err, actual;
} chunk;

/* One bulk OUT transfer of n bytes from s->data + s->sent; waits for it,
 * cancelling on a signal. */
static chunk bulk_out(session *s, struct libusb_transfer *tr, int n)
{
    chunk c = {0, 0, 0};
    int done = 0, cancelled = 0, r, failures = 0;

    libusb_fill_bulk_transfer(tr, s->h, s->t->ep_out, s->data + s->sent, n, on_transfer_done,
                              &done, s->opts->timeout_ms);
    r = libusb_submit_transfer(tr);
    if (r != 0) {
        c.st = -1;
        c.err = r;
        return c;
    }
    while (!done) {
        struct timeval tv;

        if ((usb_stop || failures > 0) && !cancelled) {
            libusb_cancel_transfer(tr);
            cancelled = 1;
        }
        tv.tv_sec = 0;
        tv.tv_usec = 100000;
        r = libusb_handle_events_timeout_completed(s->ctx, &tv, &done);
        if (r != 0 && r != LIBUSB_ERROR_INTERRUPTED && ++failures > 50) {
            /* the event loop is broken: leave the transfer (never free it in flight) */
            c.st = -2;
            c.err = r;
            return c;
        }
    }
    c.st = (int)tr->status;
    c.actual = tr->actual_length;
    return c;
}

static const char *proto_name(int proto)
{
    return proto == USB_PROTO_PRINTER ? "printer" : "raw";
}

/* A stall: cleared, and a printer asked why. CLI_OK to try again, else
 * CLI_RUNTIME (said). */
static int on_stall(session *s)
{
    char faults[64];

    libusb_clear_halt(s->h, s->t->ep_out);
    if (s->proto == USB_PROTO_PRINTER &&
        usb_port_faults(usb_printer_port_status(s->h, s->t, s->opts->timeout_ms), faults,
                        sizeof faults)[0] != '\0') {
        cli_error("%s stalled: printer reports %s; %lu of %lu bytes delivered", s->who, faults,
                  (unsigned long)s->sent, (unsigned long)s->len);
        return CLI_RUNTIME;
    }
    if (++s->fails > s->opts->retries) {
        cli_error("endpoint 0x%02x of %s stalled on %u tries; %lu of %lu bytes delivered",
                  (unsigned)s->t->ep_out, s->who, s->fails, (unsigned long)s->sent,
                  (unsigned long)s->len);
        return CLI_RUNTIME;
    }
    return CLI_OK;
}

/* A chunk that did not all go through: CLI_OK to try again, else
 * CLI_RUNTIME (said). */
static int on_short_chunk(session *s, chunk c)
{
    unsigned long sent = (unsigned long)s->sent, len = (unsigned long)s->len;

    if (c.st == LIBUSB_TRANSFER_NO_DEVICE || (c.st == -1 && c.err == LIBUSB_ERROR_NO_DEVICE)) {
        cli_error("USB device %s was unplugged; %lu of %lu bytes delivered", s->who, sent, len);
        return CLI_RUNTIME;
    }
    if (c.st == LIBUSB_TRANSFER_CANCELLED) {
        cli_error("interrupted; %lu of %lu bytes delivered to %s", sent, len, s->who);
        return CLI_RUNTIME;
    }
    if (c.st == -1) {
        cli_error("cannot send to %s: %s; %lu of %lu bytes delivered", s->who,
                  libusb_strerror((enum libusb_error)c.err), sent, len);
        return CLI_RUNTIME;
    }
    if (c.actual > 0)
        s->fails = 0; /* partial progress: the device is alive */
    if (c.st == LIBUSB_TRANSFER_STALL)
        return on_stall(s);
    if (c.st == LIBUSB_TRANSFER_TIMED_OUT) {
        if (++s->fails <= s->opts->retries)
            return CLI_OK;
        cli_error("sending to %s timed out after %u tries of %u ms; %lu of %lu bytes "
                  "delivered",
                  s->who, s->fails, s->opts->timeout_ms, sent, len);
        return CLI_RUNTIME;
    }
    if (c.st == LIBUSB_TRANSFER_COMPLETED) {
        if (++s->fails <= s->opts->retries)
            return CLI_OK;
        cli_error("%s took no data on %u tries; %lu of %lu bytes delivered", s->who, s->fails,
                  sent, len);
        return CLI_RUNTIME;
    }
    cli_error("USB transfer to %s failed (%s); %lu of %lu bytes delivered", s->who,
              c.st == LIBUSB_TRANSFER_OVERFLOW ? "overflow" : "I/O error", sent, len);
    return CLI_RUNTIME;
}

/* The send loop proper, with the device claimed. */
static int send_chunks(session *s)
{
    struct libusb_transfer *tr = libusb_alloc_transfer(0);
    progress pg;
    int rc = CLI_OK;

    if (tr == NULL) {
        cli_error("out of memory");
        return CLI_RUNTIME;
    }
    pg.on = !s->opts->quiet && isatty(STDERR_FILENO);
    pg.total = s->len;
    pg.t0 = pg.last = cli_now_ms();
    progress_draw(&pg, 0, 0);
    while (rc == CLI_OK && s->sent < s->len) {
        size_t left = s->len - s->sent;
        int n = (int)(left < s->opts->chunk ? left : s->opts->chunk);
        chunk c = {LIBUSB_TRANSFER_CANCELLED, 0, 0};

        if (!usb_stop)
            c = bulk_out(s, tr, n);
        s->sent += (size_t)(c.actual > 0 ? c.actual : 0);
        progress_draw(&pg, s->sent, 0);
        if (c.st == LIBUSB_TRANSFER_COMPLETED && c.actual > 0) {
            s->fails = 0;
            continue;
        }
        if (pg.on)
            progress_draw(&pg, s->sent, 1);
        if (c.st == -2) {
            cli_error("USB event handling failed (%s); %lu of %lu bytes delivered to %s",
                      libusb_strerror((enum libusb_error)c.err), (unsigned long)s->sent,
                      (unsigned long)s->len, s->who);
            return CLI_RUNTIME; /* tr may still be in flight: not freed */
        }
        rc = on_short_chunk(s, c);
    }
    if (rc == CLI_OK)
        progress_draw(&pg, s->sent, 1);
    libusb_free_transfer(tr);
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

/* The line that says what went where, with the printer's model if its
 * device ID (id) names one. */
static void say_sent(const session *s, const char *id)
{
    char model[80] = "";
    const char *m = strstr(id, "MDL:");

    if (m == NULL)
        m = strstr(id, "MODEL:");
    if (m != NULL) {
        m = strchr(m, ':') + 1;
        snprintf(model, sizeof model, ", %.*s", (int)strcspn(m, ";"), m);
    }
    printf("sent %lu bytes to %s (interface %d, %s%s)\n", (unsigned long)s->sent, s->who,
           s->t->iface, proto_name(s->proto), model);
    fflush(stdout);
}

/* Open, detach, claim, printer checks, send, release, re-attach, close. */
static int send_session(session *s, libusb_device *dev)
{
    const usb_target *t = s->t;
    const usb_opts *opts = s->opts;
    const char *who = s->who, *ids = s->ids;
    int proto = s->proto;
    libusb_device_handle *h;
    char id[USB_PRINTER_ID_MAX + 1] = "", faults[64];
    int r, rc, detached = 0;

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

    s->h = h;
    rc = send_chunks(s);
    if (rc == CLI_OK && !opts->quiet)
        say_sent(s, id);
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
    session s;
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
    memset(&s, 0, sizeof s);
    s.ctx = ctx;
    s.t = t;
    s.opts = opts;
    s.proto = proto;
    s.who = who;
    s.ids = ids;
    s.data = data;
    s.len = len;
    rc = send_session(&s, dev);
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    return rc;
}
