/* Placeholder until cli/usb_*.c exists: built with USB=0. */
