/*
 * gpio_none.c - gpio_lib.h when edgeflag-host is built without libgpiod
 * (host/gpio.mk found none): every operation says so, like libusb's null
 * backend, so the rest of the host tool builds and runs everywhere.
 */
#include "gpio_lib.h"

#include <stdio.h>

int ef_gpiol_open(ef_gpiol **out, const char *path, char *err, size_t errlen)
{
    *out = NULL;
    snprintf(err, errlen,
             "%s: the gpio transport is absent: edgeflag-host was built without libgpiod "
             "(install libgpiod-dev and rebuild)",
             path);
    return EF_HOST_EUNSUPPORTED;
}

void ef_gpiol_close(ef_gpiol *c) { (void)c; }

int ef_gpiol_info(ef_gpiol *c, char *label, size_t labellen, unsigned *nlines)
{
    (void)c, (void)label, (void)labellen, (void)nlines;
    return EF_HOST_EUNSUPPORTED;
}

int ef_gpiol_line(ef_gpiol *c, unsigned offset, char *name, size_t namelen, char *consumer, size_t conslen)
{
    (void)c, (void)offset, (void)name, (void)namelen, (void)consumer, (void)conslen;
    return EF_HOST_EUNSUPPORTED;
}

int ef_gpiol_request(ef_gpiol *c, const unsigned *out_offsets, unsigned n_out, const unsigned *in_offsets,
                     unsigned n_in, const char *consumer, char *err, size_t errlen)
{
    (void)c, (void)out_offsets, (void)n_out, (void)in_offsets, (void)n_in, (void)consumer, (void)err, (void)errlen;
    return EF_HOST_EUNSUPPORTED;
}

int ef_gpiol_set(ef_gpiol *c, uint32_t values)
{
    (void)c, (void)values;
    return EF_HOST_EUNSUPPORTED;
}

int ef_gpiol_get(ef_gpiol *c, uint32_t *values)
{
    (void)c, (void)values;
    return EF_HOST_EUNSUPPORTED;
}

const char *ef_gpiol_version(void) { return "absent: built without libgpiod (install libgpiod-dev and rebuild)"; }

int ef_gpiol_available(void) { return 0; }
