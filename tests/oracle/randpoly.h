/*
 * randpoly.h - seeded, deterministic generator of nasty random polygons for
 * testing edgeflag against the oracle.  Same seed, same options, same canvas:
 * same polygon, on every platform (only fixed-width integer arithmetic, own
 * PRNG).  Distributions are documented in docs/oracle.md.
 */
#ifndef EO_RANDPOLY_H
#define EO_RANDPOLY_H

#include <stdint.h>

#include "oracle.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ PRNG */
/* splitmix64 (Steele, Lea, Flood 2014; the constants of Vigna's reference
 * code): state += 0x9E3779B97F4A7C15; z = state;
 * z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9; z = (z ^ (z >> 27)) * 0x94D049BB133111EB;
 * return z ^ (z >> 31). */
typedef struct eo_rng {
    uint64_t state;
} eo_rng;
void eo_rng_seed(eo_rng *g, uint64_t seed); /* state = seed */
uint64_t eo_rng_next(eo_rng *g);
uint64_t eo_rng_below(eo_rng *g, uint64_t n);            /* uniform in [0, n), n >= 1, rejection (no bias) */
int64_t eo_rng_range(eo_rng *g, int64_t lo, int64_t hi); /* uniform in [lo, hi], hi - lo < 2^62 */
int eo_rng_percent(eo_rng *g, unsigned pct);             /* 1 with probability pct/100 */

/* --------------------------------------------------------- contour kinds */
#define EO_RP_RANDOM (1u << 0)  /* 3..12 random points: self-intersecting */
#define EO_RP_GRID (1u << 1)    /* every vertex on a sample row; x on a sample column, often exactly on a sample */
#define EO_RP_RECT (1u << 2)    /* axis-aligned rectangle, either orientation */
#define EO_RP_ORTHO (1u << 3)   /* rectilinear staircase (horizontal + vertical edges only) */
#define EO_RP_DEGEN (1u << 4)   /* 1-/2-point, repeated points, collinear, back-and-forth, zero-length edges */
#define EO_RP_SLOPE (1u << 5)   /* from a sample, edges of slope +-1 sample/row, +-1 pixel/row, vertical, horizontal */
#define EO_RP_FAR (1u << 6)     /* vertices far outside the canvas, up to +-(2^23-1) */
#define EO_RP_WOUND (1u << 7)   /* a small contour repeated m times (m up to ~300: winding overflow) */
#define EO_RP_TINY (1u << 8)    /* sub-pixel polygon around a sample (vertices within +-h+1) */
#define EO_RP_BORDER (1u << 9)  /* edges exactly on x = 0, x = 256W, y = 0, y = 256H */
#define EO_RP_SHARED (1u << 10) /* m triangles sharing one edge (coincident edges, high winding) */
#define EO_RP_ALL ((1u << 11) - 1)
#define EO_RP_NKINDS 11
const char *eo_rp_kind_name(unsigned kind_bit);

typedef struct eo_randpoly_opts {
    int samples;           /* 8, 16, 32: grid coordinates use that N's sample grid; 0: mix of all three */
    uint32_t max_points;   /* total points of the polygon; 0: 1024.  Never exceeded. */
    uint32_t max_contours; /* contours drawn (a WOUND/SHARED one may add copies); 0: 6 */
    unsigned kinds;        /* EO_RP_* kinds allowed; 0: EO_RP_ALL */
} eo_randpoly_opts;

/* An owned polygon; layout of the view equals ef_polygon's. */
typedef struct eo_randpoly {
    eo_point *pts;
    uint32_t *start; /* ncontours + 1 entries, start[0] = 0 */
    uint32_t npoints, ncontours;
    uint32_t pts_cap, start_cap;
    unsigned kinds_used; /* EO_RP_* bits of the contours generated */
} eo_randpoly;

void eo_randpoly_init(eo_randpoly *rp);
void eo_randpoly_free(eo_randpoly *rp);
/* Generates a polygon for a W x H canvas (1 <= W, H <= EO_MAX_CANVAS) from
 * seed; rp's buffers are reused.  opts may be NULL.  Every coordinate obeys
 * |v| <= 2^23 - 1.  Returns EO_OK, EO_ERR_ARG or EO_ERR_NOMEM. */
int eo_randpoly_gen(eo_randpoly *rp, uint64_t seed, int W, int H, const eo_randpoly_opts *opts);
eo_polygon eo_randpoly_view(const eo_randpoly *rp);

/* Random test configuration (docs/oracle.md): W, H mostly small, N uniform
 * over {8, 16, 32}, rule uniform. */
void eo_rand_config(eo_rng *g, int *W, int *H, int *samples, int *rule_evenodd);

#ifdef __cplusplus
}
#endif

#endif /* EO_RANDPOLY_H */
