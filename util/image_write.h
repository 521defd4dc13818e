/*
 * image_write.h - encoders from the model's premultiplied RGBA8 image
 * (ef_image) to the files `edgeflag render` writes.
 *
 *   PNG  straight (non-premultiplied) RGBA, 8 bits; un-premultiplied with
 *        the integer rule c = min(255, (C*255 + A/2) / A) for A > 0, and
 *        (0,0,0,0) for A = 0 (docs/cli.md).
 *   PAM  P7, TUPLTYPE RGB_ALPHA, DEPTH 4, MAXVAL 255: the model's
 *        premultiplied bytes exactly as computed (for bit comparisons).
 *   PGM  P5, MAXVAL 255: the alpha channel only (the coverage of a single
 *        opaque shape).
 */
#ifndef EF_UTIL_IMAGE_WRITE_H
#define EF_UTIL_IMAGE_WRITE_H

#include "edgeflag.h"

#include <stdio.h>

typedef enum ef_util_format {
    EF_UTIL_FMT_UNKNOWN = 0,
    EF_UTIL_FMT_PNG,
    EF_UTIL_FMT_PAM,
    EF_UTIL_FMT_PGM
} ef_util_format;

/* By the extension of path (case-insensitive): .png, .pam, .pgm. */
ef_util_format ef_util_format_from_path(const char *path);

/* 1 if this build can write fmt (PNG needs libpng: WITH_PNG=0 drops it). */
int ef_util_format_available(ef_util_format fmt);

/* Straight-alpha value of a premultiplied channel (the rule above). */
static inline uint8_t ef_util_unpremultiply(uint8_t c, uint8_t a)
{
    uint32_t v;
    if (a == 0)
        return 0;
    v = ((uint32_t)c * 255u + a / 2u) / a;
    return (uint8_t)(v > 255u ? 255u : v);
}

/* Encodes img to fp.  0 on success; -1 on a write or encoder error, with a
 * message in err (NUL-terminated) and errno set when it is an I/O error. */
int ef_util_write_image(FILE *fp, ef_util_format fmt, const ef_image *img, char *err, size_t errsize);

#endif /* EF_UTIL_IMAGE_WRITE_H */
