/*
 * transport_absent.c - the table of a transport that this build leaves out
 * (its library was absent when edgeflag-host was built: host/module.mk).
 * Every operation says so; `--version` and `list` name what is missing.
 */
#include "transport.h"

#define ABSENT(name, why)                                                                                          \
    static int name##_probe(const ef_host_opts *o, ef_found *f, int max)                                          \
    {                                                                                                              \
        (void)o, (void)f, (void)max;                                                                               \
        return EF_HOST_EUNSUPPORTED;                                                                               \
    }                                                                                                              \
    static int name##_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)                       \
    {                                                                                                              \
        (void)out, (void)o, (void)err, (void)errlen;                                                               \
        return EF_HOST_EUNSUPPORTED;                                                                               \
    }                                                                                                              \
    static const char *name##_version(void) { return why; }                                                        \
    const ef_transport_ops ef_transport_##name = { #name, name##_probe, name##_open, 0, 0, 0, 0, 0, 0, 0,          \
                                                   name##_version };

#ifdef EF_ABSENT_USB
ABSENT(usb, "absent: built without libusb-1.0 (install libusb-1.0-0-dev and rebuild)")
#endif
#ifdef EF_ABSENT_GPIO
ABSENT(gpio, "absent: built without libgpiod (install libgpiod-dev and rebuild)")
#endif
