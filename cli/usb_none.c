/* Built with `make USB=0`: the USB commands exist and say why they fail. */
#include "cli.h"
#include "usb.h"

static int no_usb(void)
{
    cli_error("built without USB support (rebuild without USB=0)");
    return CLI_RUNTIME;
}

int cmd_devices(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return no_usb();
}

int cmd_upload(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return no_usb();
}

int cmd_udev_rule(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return no_usb();
}

int cli_usb_send_file(const char *path, const char *device, int quiet)
{
    (void)path;
    (void)device;
    (void)quiet;
    return no_usb();
}
