/*
 * transport_usb_none.c - the USB transport when edgeflag-host is built
 * without libusb-1.0 (host/usb.mk): it says so in --version and refuses every
 * operation with EF_HOST_EUNSUPPORTED, so `list` and `--transport usb` tell
 * the user what is missing instead of finding nothing.
 */
#include "transport.h"

#include <stdio.h>

static int none_probe(const ef_host_opts *o, ef_found *found, int max)
{
    (void)o, (void)found, (void)max;
    return EF_HOST_EUNSUPPORTED;
}

static int none_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)
{
    (void)o;
    *out = NULL;
    snprintf(err, errlen, "edgeflag-host was built without libusb-1.0 (install libusb-1.0-0-dev and rebuild)");
    return EF_HOST_EUNSUPPORTED;
}

static int none_bytes(ef_link *l, uint8_t *out)
{
    (void)l, (void)out;
    return EF_HOST_EUNSUPPORTED;
}

static int none_reset(ef_link *l)
{
    (void)l;
    return EF_HOST_EUNSUPPORTED;
}

static int none_write(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms)
{
    (void)l, (void)buf, (void)len, (void)timeout_ms;
    return EF_HOST_EUNSUPPORTED;
}

static int none_flush(ef_link *l, int timeout_ms)
{
    (void)l, (void)timeout_ms;
    return EF_HOST_EUNSUPPORTED;
}

static int none_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    (void)l, (void)buf, (void)cap, (void)timeout_ms;
    *got = 0;
    return EF_HOST_EUNSUPPORTED;
}

static void none_close(ef_link *l) { (void)l; }

static const char *none_version(void)
{
    return "absent: built without libusb-1.0 (install libusb-1.0-0-dev and rebuild)";
}

const ef_transport_ops ef_transport_usb = {
    .name = "usb",
    .probe = none_probe,
    .open = none_open,
    .identify = none_bytes,
    .status = none_bytes,
    .reset = none_reset,
    .write = none_write,
    .flush = none_flush,
    .read = none_read,
    .close = none_close,
    .version = none_version,
};
