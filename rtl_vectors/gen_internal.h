/*
 * gen_internal.h - what the parts of the scene generator share: a scene
 * builder with a sticky error (so the directed table's builders read as
 * straight lists of contours), the sample-grid helpers of docs/spec.md
 * section 4, and the two case sources (the directed table, random cases).
 */
#ifndef EF_GEN_INTERNAL_H
#define EF_GEN_INTERNAL_H

#include "ef_gen.h"

/* The largest magnitude a Q16.8 vertex may have: 2^23 - 1 (32767.99609375 px). */
#define EF_GEN_LIM (EF_COORD_LIMIT - 1)
/* One pixel in Q16.8 units. */
#define EF_GEN_PX 256

typedef struct ef_genb {
    ef_scene *s;
    ef_status st;  /* the first failure; later calls do nothing */
    ef_point *pts; /* the contour being built */
    uint32_t n, cap;
    int grid;         /* N of the grid-dependent cases, 0 if none */
    int h, c;         /* 256/N and h/2 (spec 4) */
    const uint8_t *k; /* ef_pattern(N): k_s of sub-scanline s */
    int swap;         /* evenodd <-> nonzero in every shape */
} ef_genb;

void ef_genb_init(ef_genb *b, ef_scene *s, int grid, int swap);
void ef_genb_free(ef_genb *b);
void ef_genb_canvas(ef_genb *b, int32_t w, int32_t h);
void ef_genb_shape(ef_genb *b, ef_rule rule, uint8_t r, uint8_t g, uint8_t bl, uint8_t a);
/* Appends a vertex to the open contour; one outside |v| <= EF_GEN_LIM is a
 * bug in a builder and fails the case with EF_ERR_RANGE. */
void ef_genb_pt(ef_genb *b, int32_t x, int32_t y);
/* Closes the open contour (adds it to the current shape). */
void ef_genb_end(ef_genb *b);
/* Contour (x0,y0) (x1,y0) (x1,y1) (x0,y1): with x0 < x1 and y0 < y1 it runs
 * clockwise on the screen (y down): the left edge goes up, dir = -1. */
void ef_genb_rect(ef_genb *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1);
/* A contour of n points given as x0, y0, x1, y1, ... */
void ef_genb_poly(ef_genb *b, const int32_t *xy, uint32_t n);

/* Sample grid (spec 4): Y of sample row r, X of sample column k in pixel
 * column i, and X of sample s (sub-scanline s) of pixel column i. */
static inline int32_t ef_genb_row(const ef_genb *b, int32_t r) { return b->h * r + b->c; }
static inline int32_t ef_genb_col(const ef_genb *b, int32_t i, int32_t k) { return EF_GEN_PX * i + b->h * k + b->c; }
static inline int32_t ef_genb_sx(const ef_genb *b, int32_t i, int s) { return ef_genb_col(b, i, b->k[s]); }

/* ------------------------------------------------------- directed table */
enum {
    EF_GEN_F_GRID = 1,   /* built for a sample grid: once per grid */
    EF_GEN_F_LEVEL2 = 2, /* level 2 only */
    EF_GEN_F_NOSWAP = 4  /* no rule-swapped variant (nothing to swap, or it repeats a row) */
};
typedef struct ef_gen_dcase {
    const char *name;
    ef_gen_category cat;
    unsigned flags;
    ef_gen_expect expect;
    void (*build)(ef_genb *b, int arg);
    int arg;
    const char *desc;
} ef_gen_dcase;
extern const ef_gen_dcase ef_gen_dcases[];
extern const uint32_t ef_gen_ndcases;

/* ------------------------------------------------------- random cases */
/* Builds random case j's drawing from its seed into s (already
 * initialised); writes a one-line summary into desc. */
ef_status ef_gen_random_build(uint64_t case_seed, ef_scene *s, char *desc, size_t desc_size, int *grid);

#endif /* EF_GEN_INTERNAL_H */
