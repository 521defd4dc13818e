/*
 * gpio_lib.h - what the GPIO transport needs from libgpiod, behind one small
 * interface so transport_gpio.c (the bus cycles, docs/board-gpio.md) is the
 * same for every library: gpio_v1.c (libgpiod 1.x, Debian 12), gpio_v2.c
 * (libgpiod 2.1 and newer) and gpio_none.c (built without libgpiod).  The
 * Makefile fragment host/gpio.mk picks one by the installed version.
 *
 * Every function returns 0 (or a count) or a negative EF_HOST_E* from
 * transport.h, translated from errno here at the library boundary, and leaves
 * a sentence in err when it fails.
 */
#ifndef EF_GPIO_LIB_H
#define EF_GPIO_LIB_H

#include <errno.h>
#include <stddef.h>
#include <stdint.h>

#include "transport.h"

typedef struct ef_gpiol ef_gpiol; /* an open chip and, once requested, its lines */

/* Opens the chip at path (/dev/gpiochipN). */
int ef_gpiol_open(ef_gpiol **out, const char *path, char *err, size_t errlen);
void ef_gpiol_close(ef_gpiol *c);
/* The chip's label and number of lines. */
int ef_gpiol_info(ef_gpiol *c, char *label, size_t labellen, unsigned *nlines);
/* A line's name ("" when it has none) and consumer ("" when it is free). */
int ef_gpiol_line(ef_gpiol *c, unsigned offset, char *name, size_t namelen, char *consumer, size_t conslen);
/* Requests n_out lines as outputs (driven low) and n_in as inputs, once.
 * Bit i of the values below is the i-th offset of each list. */
int ef_gpiol_request(ef_gpiol *c, const unsigned *out_offsets, unsigned n_out, const unsigned *in_offsets,
                     unsigned n_in, const char *consumer, char *err, size_t errlen);
int ef_gpiol_set(ef_gpiol *c, uint32_t values);
int ef_gpiol_get(ef_gpiol *c, uint32_t *values);
/* "libgpiod 1.6.3 (v1 API)", or why there is no GPIO support. */
const char *ef_gpiol_version(void);
/* 1 when built with a libgpiod, 0 for gpio_none.c. */
int ef_gpiol_available(void);

static inline int ef_gpiol_errno(int e)
{
    switch (e) {
    case EBUSY: return EF_HOST_EBUSY;
    case EACCES:
    case EPERM: return EF_HOST_EACCESS;
    case ENOENT:
    case ENXIO: return EF_HOST_ENOTFOUND;
    case ENODEV: return EF_HOST_ENODEV;
    case ENOMEM: return EF_HOST_ENOMEM;
    case EINVAL: return EF_HOST_EINVAL;
    case ETIMEDOUT: return EF_HOST_ETIMEDOUT;
    default: return EF_HOST_EIO;
    }
}

#endif /* EF_GPIO_LIB_H */
