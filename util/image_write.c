/*
 * image_write.c - PNG (libpng), PAM and PGM encoders for ef_image
 * (formats and the un-premultiply rule in image_write.h).
 */
#include "image_write.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* WITH_PNG=0 (Makefile) builds without libpng, e.g. for 32-bit bit-exact
 * checks where the i386 -dev package is unavailable: PNG output is then
 * refused up front (ef_util_format_available) rather than failing late. */
#ifndef EF_NO_PNG
#include <png.h>
#include <setjmp.h>
#endif

static int ext_is(const char *ext, const char *want)
{
    for (; *ext && *want; ext++, want++) {
        char c = *ext;
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != *want)
            return 0;
    }
    return *ext == '\0' && *want == '\0';
}

ef_util_format ef_util_format_from_path(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');

    if (!dot || dot == base) /* no extension, or a dot file like ".png" */
        return EF_UTIL_FMT_UNKNOWN;
    if (ext_is(dot + 1, "png"))
        return EF_UTIL_FMT_PNG;
    if (ext_is(dot + 1, "pam"))
        return EF_UTIL_FMT_PAM;
    if (ext_is(dot + 1, "pgm"))
        return EF_UTIL_FMT_PGM;
    return EF_UTIL_FMT_UNKNOWN;
}

static void set_err(char *err, size_t size, const char *msg)
{
    if (size) {
        strncpy(err, msg, size - 1);
        err[size - 1] = '\0';
    }
}

static int io_error(char *err, size_t size)
{
    int saved = errno ? errno : EIO;
    set_err(err, size, strerror(saved));
    errno = saved;
    return -1;
}

/* ------------------------------------------------------------- netpbm */

static int write_pam(FILE *fp, const ef_image *img, char *err, size_t errsize)
{
    size_t rowbytes = (size_t)img->width * 4u;

    errno = 0;
    if (fprintf(fp, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n", (int)img->width,
                (int)img->height) < 0)
        return io_error(err, errsize);
    for (int32_t y = 0; y < img->height; y++)
        if (fwrite(img->px + (size_t)y * img->stride, 1, rowbytes, fp) != rowbytes)
            return io_error(err, errsize);
    return 0;
}

static int write_pgm(FILE *fp, const ef_image *img, char *err, size_t errsize)
{
    uint8_t *row = malloc((size_t)img->width);
    int rc = 0;

    if (!row) {
        set_err(err, errsize, "out of memory");
        errno = ENOMEM;
        return -1;
    }
    errno = 0;
    if (fprintf(fp, "P5\n%d %d\n255\n", (int)img->width, (int)img->height) < 0)
        rc = io_error(err, errsize);
    for (int32_t y = 0; rc == 0 && y < img->height; y++) {
        const uint8_t *src = img->px + (size_t)y * img->stride;
        for (int32_t x = 0; x < img->width; x++)
            row[x] = src[4 * (size_t)x + 3];
        if (fwrite(row, 1, (size_t)img->width, fp) != (size_t)img->width)
            rc = io_error(err, errsize);
    }
    free(row);
    return rc;
}

int ef_util_format_available(ef_util_format fmt)
{
#ifdef EF_NO_PNG
    if (fmt == EF_UTIL_FMT_PNG)
        return 0;
#endif
    return fmt != EF_UTIL_FMT_UNKNOWN;
}

/* ---------------------------------------------------------------- PNG */
#ifndef EF_NO_PNG

/* libpng reports errors by calling this and never returning: keep the
 * message for our caller instead of letting libpng print it. */
typedef struct png_err_ctx {
    char msg[200];
} png_err_ctx;

static void png_on_error(png_structp png, png_const_charp msg)
{
    png_err_ctx *ctx = png_get_error_ptr(png);
    strncpy(ctx->msg, msg, sizeof ctx->msg - 1);
    ctx->msg[sizeof ctx->msg - 1] = '\0';
    png_longjmp(png, 1);
}

static void png_on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* warnings do not change the file we write */
}

static int write_png(FILE *fp, const ef_image *img, char *err, size_t errsize)
{
    png_err_ctx ectx;
    png_structp png;
    png_infop info = NULL;
    uint8_t *row = malloc((size_t)img->width * 4u);

    if (!row) {
        set_err(err, errsize, "out of memory");
        errno = ENOMEM;
        return -1;
    }
    memset(&ectx, 0, sizeof ectx);
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ectx, png_on_error, png_on_warning);
    if (png)
        info = png_create_info_struct(png);
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        free(row);
        set_err(err, errsize, "cannot initialise libpng");
        errno = ENOMEM;
        return -1;
    }
    errno = 0;
    /* Nothing assigned below this point is read after a longjmp except
     * png, info and row, which do not change: no volatile needed. */
    if (setjmp(png_jmpbuf(png))) {
        int saved = errno ? errno : EIO;
        png_destroy_write_struct(&png, &info);
        free(row);
        /* A failed fwrite (disk full, file size limit) reaches us as libpng's
         * "Write Error": report the system's reason, as PAM and PGM do. */
        if (ferror(fp))
            set_err(err, errsize, strerror(saved));
        else
            set_err(err, errsize, ectx.msg[0] ? ectx.msg : "libpng error");
        errno = saved;
        return -1;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int32_t y = 0; y < img->height; y++) {
        const uint8_t *src = img->px + (size_t)y * img->stride;
        for (int32_t x = 0; x < img->width; x++) {
            const uint8_t *p = src + 4 * (size_t)x;
            uint8_t *q = row + 4 * (size_t)x;
            q[0] = ef_util_unpremultiply(p[0], p[3]);
            q[1] = ef_util_unpremultiply(p[1], p[3]);
            q[2] = ef_util_unpremultiply(p[2], p[3]);
            q[3] = p[3];
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    if (ferror(fp))
        return io_error(err, errsize);
    return 0;
}
#else
static int write_png(FILE *fp, const ef_image *img, char *err, size_t errsize)
{
    (void)fp;
    (void)img;
    set_err(err, errsize, "this edgeflag was built without PNG support (WITH_PNG=0)");
    errno = ENOSYS;
    return -1;
}
#endif

int ef_util_write_image(FILE *fp, ef_util_format fmt, const ef_image *img, char *err, size_t errsize)
{
    set_err(err, errsize, "");
    switch (fmt) {
    case EF_UTIL_FMT_PNG: return write_png(fp, img, err, errsize);
    case EF_UTIL_FMT_PAM: return write_pam(fp, img, err, errsize);
    case EF_UTIL_FMT_PGM: return write_pgm(fp, img, err, errsize);
    case EF_UTIL_FMT_UNKNOWN: break;
    }
    set_err(err, errsize, "unknown output format");
    errno = EINVAL;
    return -1;
}
