/*
 * An LD_PRELOAD shim for tests/check_usb.sh: the kernel-driver and busy
 * cases umockdev 0.17 cannot replay (its ioctl scripts crash on
 * USBDEVFS_CLAIMINTERFACE errors and USBDEVFS_GETDRIVER lines). quiltc
 * links libusb dynamically, so these definitions come first; the rest of
 * libusb talks to umockdev as usual. QC_SHIM selects the case:
 *   busy        claiming an interface fails with LIBUSB_ERROR_BUSY
 *   driver      a kernel driver holds every interface; detaching works
 *   stuck       a kernel driver holds every interface; detaching fails (busy)
 * Each detach and attach appends a line to the file QC_SHIM_LOG names.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libusb.h>

static int mode_is(const char *m)
{
    const char *v = getenv("QC_SHIM");
    return v != NULL && strcmp(v, m) == 0;
}

static void note(const char *what, int iface)
{
    const char *path = getenv("QC_SHIM_LOG");
    FILE *f = path != NULL ? fopen(path, "a") : NULL;

    if (f != NULL) {
        fprintf(f, "%s %d\n", what, iface);
        fclose(f);
    }
}

int libusb_kernel_driver_active(libusb_device_handle *h, int iface)
{
    (void)h;
    (void)iface;
    return mode_is("driver") || mode_is("stuck");
}

int libusb_detach_kernel_driver(libusb_device_handle *h, int iface)
{
    (void)h;
    note("detach", iface);
    return mode_is("stuck") ? LIBUSB_ERROR_BUSY : 0;
}

int libusb_attach_kernel_driver(libusb_device_handle *h, int iface)
{
    (void)h;
    note("attach", iface);
    return 0;
}

int libusb_claim_interface(libusb_device_handle *h, int iface)
{
    int (*real)(libusb_device_handle *, int);

    if (mode_is("busy"))
        return LIBUSB_ERROR_BUSY;
    *(void **)&real = dlsym(RTLD_NEXT, "libusb_claim_interface");
    return real != NULL ? real(h, iface) : LIBUSB_ERROR_OTHER;
}
