/*
 * ef_gen.h - seeded regression scenes for hardware implementations of the
 * edge-flag rasterizer (`edgeflag gen`, docs/gen.md).
 *
 * Modelled on Berkeley TestFloat's testfloat_gen: a commented table of
 * directed corner cases first (gen_cases.c), then seeded random cases
 * (gen_random.c), numbered globally so a regression farm can split the run
 * into exact shards.  Every case is a scene: a canvas and shapes of closed
 * contours with Q16.8 vertices, written in the peerbench `.scene` text that
 * `edgeflag render` reads, with every coordinate as the exact decimal of its
 * Q16.8 value, so reading a file back gives the generator's vertices bit for
 * bit.
 *
 * Determinism: integer arithmetic only, no clock, locale or path in any
 * output.  The bytes of case k depend only on EF_GEN_VERSION, the model
 * version string and the configuration below (seed, level, grid option,
 * random count) -- never on the shard, the machine or the build.  The
 * drawing (every non-comment line) of random case j depends only on
 * (seed, j).
 */
#ifndef EF_GEN_H
#define EF_GEN_H

#include <stddef.h>
#include <stdint.h>

#include "ef_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Bumped whenever the content of any case changes: a regression that pins
 * (seed, level, count) reproduces the same files for one generator version. */
#define EF_GEN_VERSION 1
#define EF_GEN_DEFAULT_SEED UINT64_C(20070101)
#define EF_GEN_LEVEL1_RANDOM 200u
#define EF_GEN_LEVEL2_RANDOM 20000u
/* Case numbers have six digits in file names (case_NNNNNN.scene). */
#define EF_GEN_MAX_CASES 1000000u

/* The corner-case categories of the directed table (docs/gen.md section 5). */
typedef enum ef_gen_category {
    EF_GEN_CAT_SAMPLE_GRID = 0, /* vertices exactly on sample rows and columns */
    EF_GEN_CAT_HORIZONTAL,      /* horizontal edges */
    EF_GEN_CAT_VERTICAL,        /* vertical edges */
    EF_GEN_CAT_ZERO_LENGTH,     /* zero-length edges (repeated vertices) */
    EF_GEN_CAT_SLOPE,           /* +-1 sample per row, near-horizontal, near-vertical, long */
    EF_GEN_CAT_DEGENERATE,      /* degenerate and zero-area polygons, empty shapes */
    EF_GEN_CAT_COINCIDENT,      /* coincident and overlapping edges */
    EF_GEN_CAT_CANCEL,          /* windings that cancel */
    EF_GEN_CAT_OVERFLOW,        /* winding counter past 127 (spec 6.4) */
    EF_GEN_CAT_LIMITS,          /* coordinates at +-(2^23 - 1) Q16.8 */
    EF_GEN_CAT_OUTSIDE,         /* far outside the clip rectangle */
    EF_GEN_CAT_CLIP_BORDER,     /* edges on the clip borders */
    EF_GEN_CAT_EDGES_PER_ROW,   /* many edges crossing one scanline */
    EF_GEN_CAT_CANVAS,          /* 1 x 1 and maximum canvas sizes */
    EF_GEN_CAT_COMPOSITING,     /* alpha and colour extremes, many shapes */
    EF_GEN_CAT_RANDOM,          /* the seeded random cases */
    EF_GEN_NCATEGORIES
} ef_gen_category;
/* Short lower-case name ("sample-grid", ..., "random"); NULL if out of range. */
EF_API const char *ef_gen_category_name(ef_gen_category c);

/* What a directed case is known to produce, at every sample count; written
 * in its header ("# expect: ...") and checked by tests/unit/test_gen.c. */
typedef enum ef_gen_expect_kind {
    EF_GEN_EXPECT_ANY = 0, /* nothing simple to state */
    EF_GEN_EXPECT_EMPTY,   /* every pixel stays (0, 0, 0, 0) */
    EF_GEN_EXPECT_FULL,    /* every pixel has alpha 255 */
    EF_GEN_EXPECT_PROBE    /* pixel (x, y) has the alpha given */
} ef_gen_expect_kind;
typedef struct ef_gen_expect {
    ef_gen_expect_kind kind;
    int32_t x, y;    /* EF_GEN_EXPECT_PROBE */
    uint8_t alpha;   /* EF_GEN_EXPECT_PROBE */
    int8_t overflow; /* 1: winding overflows are counted; 0: none; -1: not stated */
} ef_gen_expect;

/* ---------------------------------------------------------- configuration */
typedef struct ef_gen_config {
    uint64_t seed;     /* random cases; printed in every header */
    int level;         /* 1 or 2 */
    int grid;          /* grid-dependent directed cases: 8, 16 or 32, or 0 for the
                             * level's default (16 at level 1, all three at level 2) */
    int rules_swapped; /* level 2: each directed case again with evenodd <-> nonzero
                             * (set by ef_gen_config_defaults; level 1 never) */
    uint32_t nrandom;  /* random cases: at least the level's count */
} ef_gen_config;

/* Defaults for a level: seed EF_GEN_DEFAULT_SEED, grid 0, the level's
 * random count.  EF_ERR_ARG for a level other than 1 or 2. */
EF_API ef_status ef_gen_config_defaults(ef_gen_config *c, int level);
/* The level's random count (EF_GEN_LEVEL1_RANDOM, EF_GEN_LEVEL2_RANDOM), 0 if invalid. */
EF_API uint32_t ef_gen_level_random(int level);
/* EF_OK, or EF_ERR_ARG (bad level or grid, nrandom below the level's count:
 * "can raise, never lower"), or EF_ERR_LIMIT (more than EF_GEN_MAX_CASES). */
EF_API ef_status ef_gen_config_check(const ef_gen_config *c);
/* Directed cases of this configuration (case numbers 0 .. D-1). */
EF_API uint32_t ef_gen_directed_count(const ef_gen_config *c);
/* D + nrandom. */
EF_API uint32_t ef_gen_total(const ef_gen_config *c);

/* ------------------------------------------------------------- sharding */
/* Shard `index` of `count` (1-based: 1 <= index <= count) holds the cases k
 * with k mod count == index - 1.  Returns 1 if case k is in it. */
EF_API int ef_gen_in_shard(uint32_t k, uint32_t index, uint32_t count);

/* ------------------------------------------------------------ the PRNG */
/* splitmix64 (Steele, Lea, Flood 2014), written out: state += 0x9E3779B97F4A7C15,
 * then the output mix of the new state.  Seeded with 0 the first outputs are
 * 0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4, 0x06C45D188009454F. */
EF_API uint64_t ef_gen_splitmix64(uint64_t *state);
/* Seed of random case j (0-based among the random cases): output number j
 * of the splitmix64 stream seeded with `seed`, i.e. mix(seed + (j+1) * gamma). */
EF_API uint64_t ef_gen_case_seed(uint64_t seed, uint32_t j);

/* -------------------------------------------------------------- a case */
typedef struct ef_gen_case {
    uint32_t number; /* global case number k */
    uint32_t total;  /* cases in the run */
    int directed;    /* 1: from the table, 0: random */
    uint32_t index;  /* directed: k; random: j = k - directed count */
    ef_gen_category category;
    const char *name;   /* directed: the table's name; random: "random" */
    int grid;           /* directed: the sample grid it was built for, 0 if none */
    int rules_swapped;  /* a level-2 rule-swapped variant */
    uint64_t case_seed; /* random cases */
    ef_gen_expect expect;
    char desc[768];     /* one line, no tabs */
    ef_scene scene;     /* the drawing */
    char fit_note[400]; /* ef_gen_fit: what was done to fit the DUT, or why it was refused; "" */
} ef_gen_case;

/* Builds case k (0 <= k < ef_gen_total(c)) into *out (initialised here; free
 * it with ef_gen_case_destroy even on failure).  EF_ERR_ARG for a bad k or
 * configuration, EF_ERR_NOMEM. */
EF_API ef_status ef_gen_build(const ef_gen_config *c, uint32_t k, ef_gen_case *out);
EF_API void ef_gen_case_destroy(ef_gen_case *gc);

/* ------------------------------------------------------ the DUT's limits */
/* A DUT's limits as a board's identify states them (docs/board.md 3.1);
 * 0 in a field: no limit. */
typedef struct ef_gen_limits {
    int32_t width, height; /* the largest canvas, W_MAX x H_MAX */
    uint32_t edges;        /* the most EDGE commands of one shape, E_MAX */
    uint32_t samples_mask; /* bit 3: 8, bit 4: 16, bit 5: 32 samples per pixel */
} ef_gen_limits;
typedef enum ef_gen_fit_result {
    EF_GEN_FIT_AS_IS = 0, /* the case fits: unchanged */
    EF_GEN_FIT_FITTED,    /* changed to fit (gc->fit_note says how) */
    EF_GEN_FIT_REFUSED    /* cannot be fitted (gc->fit_note says why) */
} ef_gen_fit_result;
/* 1 if the DUT takes this sample count. */
EF_API int ef_gen_limits_takes(const ef_gen_limits *lim, int samples);
/* Fits case gc (from ef_gen_build) to the DUT (docs/gen.md section 11): a
 * grid case for a sample count it does not take is refused; a canvas over
 * its largest is scaled by 1/2^k (expectations dropped); a shape over its
 * edges is split into shapes of whole contours only when the model renders
 * the same bytes at every sample count it takes and every rule setting,
 * else refused.  *res says which; gc->fit_note says how or why.  EF_OK, or
 * EF_ERR_NOMEM and the like from the model (then gc is unchanged or fitted). */
EF_API ef_status ef_gen_fit(const ef_gen_limits *lim, ef_gen_case *gc, ef_gen_fit_result *res);

/* ------------------------------------------------------------- text out */
typedef struct ef_gen_text {
    char *data; /* NUL-terminated */
    size_t len, cap;
} ef_gen_text;
EF_API void ef_gen_text_destroy(ef_gen_text *t);
/* Appends s to t (NUL-terminated after it).  EF_ERR_NOMEM. */
EF_API ef_status ef_gen_text_append(ef_gen_text *t, const char *s);

/* The case's file: header comments, then `scene W H`, shapes and contours
 * with exact Q16.8 decimals.  Replaces t's content.  EF_ERR_ARG if a contour
 * has fewer than 3 points (the format needs 3), EF_ERR_NOMEM. */
EF_API ef_status ef_gen_format(const ef_gen_config *c, const ef_gen_case *gc, ef_gen_text *t);
/* "case_NNNNNN.scene" (buf of at least 32 bytes). */
EF_API void ef_gen_file_name(uint32_t k, char *buf, size_t size);
/* index.tsv: its two header lines (a comment naming the run and shard, then
 * the column names), and one row per case, appended to t. */
EF_API ef_status ef_gen_index_header(const ef_gen_config *c, uint32_t shard_index, uint32_t shard_count,
                                     ef_gen_text *t);
EF_API ef_status ef_gen_index_row(const ef_gen_case *gc, ef_gen_text *t);
/* Exact decimal of v / 256 (at most 8 fraction digits, no trailing zeros),
 * appended to t. */
EF_API ef_status ef_gen_append_q8(ef_gen_text *t, int32_t v);

#ifdef __cplusplus
}
#endif

#endif /* EF_GEN_H */
