/*
 * composite.c - compositing block (docs/spec.md section 8): premultiplied
 * source-over of a solid colour onto RGBA8, driven by the filler's spans.
 * A solid span of an opaque colour is a plain store (the blend reduces to
 * d' = P exactly, since mul(d, 255) = d); everything else blends per pixel,
 * four channels at once in 16-bit lanes (ef_blend_span, internal.h, which
 * the fillers inline so that no span goes through a function pointer).
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "trace.h"

ef_status ef_image_create(ef_image *img, int32_t width, int32_t height)
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

void ef_image_destroy(ef_image *img)
{
    free(img->px);
    memset(img, 0, sizeof *img);
}

ef_status ef_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color)
{
    if (!ctx || !img || img->width != ctx->width || img->height != ctx->height)
        return EF_ERR_ARG;
    if (ctx->trace)
        return ef_trace_fill(ctx, img, poly, rule, color); /* the cycle-stamped pipeline */
    if (ctx->filt)
        return ef_filter_fill(ctx, img, poly, rule, color); /* section 3.5 options (filter.c) */
    ef_blend b;
    uint8_t p[4] = { ef_mul255(color.r, color.a), ef_mul255(color.g, color.a), ef_mul255(color.b, color.a), color.a };
    memcpy(&b.solid, p, 4);
    for (int i = 0; i < 8; i++)
        b.solid8[i] = b.solid;
    b.px = img->px;
    b.stride = img->stride;
    b.p4 = ef_spread4(b.solid);
    b.a = color.a;
    b.samples = ctx->samples;
    b.count8 = ef_count_of_mask8();
    const uint8_t *alpha_n = ef_alpha_of_count(ctx->samples);
    for (int n = 0; n <= ctx->samples; n++) {
        b.s4_n[n] = ef_mul255x4(b.p4, alpha_n[n]);
        b.sa_n[n] = ef_mul255(color.a, alpha_n[n]);
    }
    /* A transparent colour changes no pixel, but it is still rasterized so that
     * the diagnostics (and later the vectors) see every shape.  The fillers
     * composite each span as they close it (ef_blend_span in internal.h). */
    return ef_rasterize_to(ctx, poly, rule, NULL, NULL, &b);
}
