/*
 * ef_filter.h - the paper's section 3.5 options of an ef_ctx: a 2x2-pixel
 * filter base (the tent) instead of the one-pixel box, and per-colour-channel
 * sample offsets for striped LCD panels (RGB or BGR), docs/spec.md section 10.
 *
 * Both are off by default: a context that never calls ef_ctx_set_filter
 * renders exactly what it always did.  With either on, ef_fill (and so
 * ef_scene_render) composites filtered, per-channel coverage; ef_rasterize
 * still reports the unfiltered masks of the spec's own samples.
 */
#ifndef EF_FILTER_H
#define EF_FILTER_H

#include "edgeflag.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ef_filter {
    EF_FILTER_BOX = 0, /* one-pixel box: popcount (spec 7.3), the default */
    EF_FILTER_TENT = 1 /* 2x2-pixel tent, weights (2k+1)(2s+1)-style over 4N^3 (spec 10.2) */
} ef_filter;

typedef enum ef_subpixel {
    EF_SUBPIXEL_NONE = 0, /* one coverage for all channels, the default */
    EF_SUBPIXEL_RGB = 1,  /* R samples 85/256 px left, B 85/256 px right (spec 10.1) */
    EF_SUBPIXEL_BGR = 2   /* B left, R right */
} ef_subpixel;

/* Selects the options (EF_ERR_ARG for values outside the enums, EF_ERR_NOMEM).
 * The tent needs a (W+1) x (H+1) mask canvas per channel; the contexts for
 * it are made here, once. */
EF_API ef_status ef_ctx_set_filter(ef_ctx *ctx, ef_filter filter, ef_subpixel subpixel);
EF_API void ef_ctx_get_filter(const ef_ctx *ctx, ef_filter *filter, ef_subpixel *subpixel);

/* The denominator D of the filter's coverage: N for the box, 4 N^3 for the
 * tent.  A channel's coverage is sum / D (0 <= sum <= D), its alpha
 * floor((255 sum + D/2) / D). */
EF_API uint32_t ef_filter_denominator(const ef_ctx *ctx);

/* Per-pixel coverage of poly under rule with the context's options: called
 * for every pixel (x, y) of the canvas with a non-zero sum in some channel,
 * row by row, left to right; sum[0..2] are R, G, B (all three equal without
 * subpixel offsets).  The same numbers ef_fill composites. */
typedef void (*ef_cov_fn)(void *user, int32_t y, int32_t x, const uint32_t sum[3]);
EF_API ef_status ef_filter_coverage(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_cov_fn fn, void *user);

#ifdef __cplusplus
}
#endif

#endif /* EF_FILTER_H */
