/*
 * composite.c - compositing block (docs/spec.md section 8): premultiplied
 * source-over of a solid colour onto RGBA8, driven by the filler's spans.
 * A solid span of an opaque colour is a plain store (the blend reduces to
 * d' = P exactly, since mul(d, 255) = d); everything else blends per pixel.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

ef_status ef_image_alloc(ef_image *img, int32_t width, int32_t height)
{
    memset(img, 0, sizeof *img);
    if (width < 1 || height < 1 || width > EF_MAX_CANVAS || height > EF_MAX_CANVAS)
        return EF_ERR_ARG;
    img->stride = (size_t)width * 4;
    img->px = calloc((size_t)height, img->stride);
    if (!img->px)
        return EF_ERR_NOMEM;
    img->width = width;
    img->height = height;
    return EF_OK;
}

void ef_image_free(ef_image *img)
{
    free(img->px);
    memset(img, 0, sizeof *img);
}

typedef struct blend_job {
    ef_image *img;
    int samples;
    uint8_t p[4];            /* premultiplied colour, alpha last */
    uint32_t solid;          /* P packed in memory order, for opaque solid spans */
    uint32_t full;           /* the full mask 2^N - 1 */
} blend_job;

static void blend_span(void *user, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    blend_job *j = user;
    uint8_t *d = j->img->px + (size_t)y * j->img->stride + (size_t)x * 4;
    if (mask == j->full && j->p[3] == 255) {
        for (int32_t i = 0; i < len; i++, d += 4)
            memcpy(d, &j->solid, 4);
        return;
    }
    uint32_t cov = ef_coverage_alpha(mask, j->samples);
    uint8_t s[4];
    for (int ch = 0; ch < 4; ch++)
        s[ch] = ef_mul255(j->p[ch], cov);
    uint32_t sa = s[3];
    for (int32_t i = 0; i < len; i++, d += 4) {
        for (int ch = 0; ch < 4; ch++)
            d[ch] = (uint8_t)(d[ch] + s[ch] - ef_mul255(d[ch], sa));
    }
}

ef_status ef_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color)
{
    if (!ctx || !img || img->width != ctx->width || img->height != ctx->height)
        return EF_ERR_ARG;
    blend_job j;
    j.img = img;
    j.samples = ctx->samples;
    j.p[0] = ef_mul255(color.r, color.a);
    j.p[1] = ef_mul255(color.g, color.a);
    j.p[2] = ef_mul255(color.b, color.a);
    j.p[3] = color.a;
    memcpy(&j.solid, j.p, 4);
    j.full = ctx->samples == 32 ? UINT32_MAX : (UINT32_C(1) << ctx->samples) - 1;
    /* A transparent colour changes no pixel, but it is still rasterized so that
     * the diagnostics (and later the vectors) see every shape. */
    return ef_rasterize(ctx, poly, rule, blend_span, &j);
}
