/*
 * edgeflag.h - public interface of libedgeflag, the bit-exact reference model
 * of the scanline edge-flag antialiasing rasterizer (Kallio 2007, version F).
 *
 * Data flows one way:
 *   scene (shapes of closed contours, device Q16.8 vertices)
 *     -> edge setup -> edge table -> active edges -> plotter (exact DDA + n-rooks)
 *     -> scanline buffer (XOR bits | packed 7-bit winding words)
 *     -> filler (mask tracking) -> span sink (coverage masks)
 *     -> coverage -> compositing onto premultiplied RGBA8.
 *
 * docs/spec.md is the contract; every format named here is defined there.
 * All state lives in an ef_ctx, so one process (a DPI-C testbench, say) can
 * hold several independent models.  The library never prints or exits.
 *
 * Lifetimes: what the library allocates is made by a `_create` and released
 * by the matching `_destroy` (ef_ctx_create / ef_ctx_destroy, ef_image_create
 * / ef_image_destroy, ef_scene_create / ef_scene_destroy, ...); a `_defaults`
 * only fills an options struct and holds nothing.
 *
 *     #include <edgeflag/edgeflag.h>   // cc ... $(pkg-config --cflags --libs edgeflag)
 */
#ifndef EDGEFLAG_H
#define EDGEFLAG_H

#include <stddef.h>
#include <stdint.h>

#include "ef_api.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The version these headers are of; ef_version() is the one of the library a
 * program runs with (the two differ when the program was built against other
 * headers than the libedgeflag.so it finds). */
#define EF_VERSION_STRING "0.1.0"
EF_API const char *ef_version(void);

/* ---------------------------------------------------------------- status */
typedef enum ef_status {
    EF_OK = 0,
    EF_ERR_NOMEM = -1,      /* allocation failed */
    EF_ERR_ARG = -2,        /* a parameter outside its documented domain */
    EF_ERR_LIMIT = -3,      /* a documented limit exceeded (docs/limits.md) */
    EF_ERR_SYNTAX = -4,     /* malformed input text */
    EF_ERR_RANGE = -5,      /* a number outside the accepted range */
    EF_ERR_IO = -6,         /* reading or writing a file failed */
    EF_ERR_UNSUPPORTED = -7 /* valid input using a feature we do not model */
} ef_status;
EF_API const char *ef_strerror(ef_status s);

/* ---------------------------------------------------------------- limits */
#define EF_MAX_CANVAS 16384                /* width and height, pixels */
#define EF_COORD_LIMIT (1 << 23)           /* |device coordinate| < 2^23 (Q16.8) */
#define EF_MAX_POINTS_PER_SCENE (1u << 24) /* vertices over all contours */
#define EF_MAX_EDGES_PER_SHAPE (1u << 22)  /* edge store of one ef_rasterize call */

/* -------------------------------------------------------- configuration */
typedef enum ef_rule { EF_RULE_NONZERO = 0, EF_RULE_EVENODD = 1 } ef_rule;

/* Samples per pixel: 8, 16 or 32 (EF_SAMPLES_TEXT in messages).  Adding a
 * count is the walk of docs/source.md, "To add a sample count". */
#define EF_SAMPLES_MAX 32
#define EF_SAMPLES_TEXT "8, 16 or 32"
static inline int ef_samples_valid(int n) { return n == 8 || n == 16 || n == 32; }

/* A pixel's coverage mask: bit s = sample s (docs/spec.md section 4), so it
 * holds EF_SAMPLES_MAX bits. */
typedef uint32_t ef_mask;
#if defined(__cplusplus)
static_assert(sizeof(ef_mask) * 8 >= EF_SAMPLES_MAX, "a mask holds a bit per sample");
#else
_Static_assert(sizeof(ef_mask) * 8 >= EF_SAMPLES_MAX, "a mask holds a bit per sample");
#endif

/* ------------------------------------------------------------ geometry */
/* A vertex in device space, Q16.8: value = x / 256 px, y grows downward,
 * pixel (i, j) is the square [i, i+1) x [j, j+1).  |x|, |y| < EF_COORD_LIMIT. */
typedef struct ef_point {
    int32_t x, y;
} ef_point;

/* A polygon: ncontours closed contours (the last point joins the first).
 * Contour c is pts[start[c] .. start[c+1]-1]; start has ncontours+1 entries. */
typedef struct ef_polygon {
    const ef_point *pts;
    const uint32_t *start;
    uint32_t ncontours;
} ef_polygon;

/* Straight (not premultiplied) 8-bit colour; a is the opacity. */
typedef struct ef_rgba8 {
    uint8_t r, g, b, a;
} ef_rgba8;

/* ------------------------------------------------------------- the model */
typedef struct ef_ctx ef_ctx;

/* Creates a model for a width x height clip rectangle (the canvas) at
 * `samples` samples per pixel.  1 <= width, height <= EF_MAX_CANVAS. */
EF_API ef_status ef_ctx_create(ef_ctx **out, int32_t width, int32_t height, int samples);
EF_API void ef_ctx_destroy(ef_ctx *ctx);
EF_API int32_t ef_ctx_width(const ef_ctx *ctx);
EF_API int32_t ef_ctx_height(const ef_ctx *ctx);
EF_API int ef_ctx_samples(const ef_ctx *ctx);

/* Coverage spans.  The filler reports, scanline by scanline left to right,
 * runs of pixels [x, x+len) on row y that share one non-empty coverage mask
 * (bit s = sample s of the pixel, docs/spec.md section 4).  A full mask
 * (all `samples` bits set) is a solid span; any other mask covers one pixel
 * per call unless neighbours share it. */
typedef void (*ef_span_fn)(void *user, int32_t y, int32_t x, int32_t len, ef_mask mask);

/* Rasterizes one polygon under `rule` and reports its coverage spans.
 * Returns EF_ERR_LIMIT if the polygon has more edges than the edge store
 * holds (docs/limits.md), EF_ERR_ARG on coordinates outside the range. */
EF_API ef_status ef_rasterize(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_span_fn span, void *user);

/* Diagnostics accumulated since the context was created (never change a result). */
typedef struct ef_diag {
    uint64_t edges_in;          /* polygon edges seen by edge setup */
    uint64_t edges_dropped;     /* crossing no sample row inside the clip rectangle */
    uint64_t winding_overflows; /* 7-bit signed winding counter left [-64, 63] (spec 6.4) */
} ef_diag;
EF_API void ef_ctx_diag(const ef_ctx *ctx, ef_diag *out);

/* ------------------------------------------------------------ patterns */
/* Horizontal sample index k_s (0..N-1) of sub-scanline s: sample s of pixel
 * (i, j) sits at (i + (2k_s+1)/(2N), j + (2s+1)/(2N)).  NULL if N invalid. */
EF_API const uint8_t *ef_pattern(int samples);

/* ---------------------------------------------------- coverage, compositing */
/* alpha = floor((255 * popcount(mask) + N/2) / N), docs/spec.md section 7. */
EF_API uint8_t ef_coverage_alpha(ef_mask mask, int samples);
/* mul(a, b) = round(a * b / 255), computed as t = a*b + 128; ((t >> 8) + t) >> 8. */
static inline uint8_t ef_mul255(uint32_t a, uint32_t b)
{
    uint32_t t = a * b + 128u;
    return (uint8_t)(((t >> 8) + t) >> 8);
}

/* A premultiplied RGBA8 image, bytes R,G,B,A, rows of `stride` bytes.
 * ef_image_create allocates the pixels (cleared to 0); ef_image_destroy frees
 * them and leaves an empty image. */
typedef struct ef_image {
    uint8_t *px;
    int32_t width, height;
    size_t stride;
} ef_image;
EF_API ef_status ef_image_create(ef_image *img, int32_t width, int32_t height);
EF_API void ef_image_destroy(ef_image *img);

/* Composites `color` source-over onto img with the coverage of polygon under
 * rule (docs/spec.md section 8). */
EF_API ef_status ef_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color);

#ifdef __cplusplus
}
#endif

#endif /* EDGEFLAG_H */
