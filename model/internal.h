/*
 * internal.h - the model's blocks and the state they share (not installed).
 *
 * Blocks, in pipeline order, one file each:
 *   edge_setup.c   polygon edges -> DDA records (docs/spec.md section 5)
 *   edge_table.c   one slot per pixel row, unsorted lists; the active edge table
 *   plotter.c      exact DDA + n-rooks offset into the scanline buffer (6.1-6.4)
 *   fill_evenodd.c XOR accumulation with mask tracking (7.2)
 *   fill_nonzero.c packed 7-bit winding accumulation with mask tracking (7.2)
 *   rasterize.c    the scanline loop that runs the blocks in order
 *   coverage.c     popcount -> alpha (7.3)
 *   composite.c    premultiplied source-over onto RGBA8 (8)
 */
#ifndef EF_INTERNAL_H
#define EF_INTERNAL_H

#include "edgeflag.h"
#include "ef_fixed.h"

/* Packed winding constants (spec 6.3). */
#define EF_LANES7 UINT64_C(0x7F7F7F7F7F7F7F7F)
#define EF_PADS UINT64_C(0x8080808080808080)
#define EF_SIGN7 UINT64_C(0x4040404040404040)

/* One edge's DDA record (spec 5, step 5-6).  Bit budgets: |x| <= 2^23 + 2^29
 * after the final step, |qs| < 2^29, 0 <= e, rs < dy < 2^24: all fit int32. */
typedef struct ef_edge {
    int32_t x;      /* Q16.8: ceil(exact crossing of row r) - 1 */
    int32_t e;      /* error term, 0 <= e < dy */
    int32_t qs;     /* floor(h*dX / dY) */
    int32_t rs;     /* (h*dX) mod dY */
    int32_t dy;     /* Y1 - Y0 > 0 */
    int32_t r;      /* next sample row to plot */
    int32_t r1;     /* last sample row (inclusive, clipped) */
    int32_t dir;    /* +1 downward, -1 upward */
    int32_t next;   /* edge-table slot list link, -1 ends */
} ef_edge;
_Static_assert((int64_t)32 * ((int64_t)1 << 24) < ((int64_t)1 << 30), "h*dX fits 30 bits: qs fits int32");

struct ef_ctx {
    int32_t width, height;
    int samples;            /* N */
    int32_t h, c;           /* 256/N and h/2, Q16.8 */
    int32_t off[32];        /* plot offset per sub-scanline: 256 - h*k_s - c */

    /* edge store and edge table */
    ef_edge *edges;
    uint32_t nedges, edges_cap;
    int32_t *slot;          /* height entries: first edge of the pixel row, -1 = none */
    int32_t *aet;           /* active edge indices, unsorted */
    uint32_t naet;
    uint32_t naet_row;      /* active edges while the current row was plotted */

    /* the one-scanline buffer: W+1 cells (cell W is the right-clamp sink) */
    uint32_t *eo_cells;     /* even-odd: N bits per cell */
    uint64_t *nz_cells;     /* non-zero: N/8 words per cell */
    uint64_t *occ;          /* one bit per cell: marked since the last fill (mask tracking) */

    ef_diag diag;
};

/* edge_setup.c: appends the edges of poly to ctx->edges and links them into
 * the edge table.  Returns EF_ERR_ARG for out-of-range vertices, EF_ERR_LIMIT
 * past the edge budget. On return row_min, row_max bound the pixel rows
 * that hold edges (row_min > row_max when none). */
ef_status ef_edges_setup(ef_ctx *ctx, const ef_polygon *poly, int32_t *row_min, int32_t *row_max);

/* edge_table.c */
void ef_et_reset(ef_ctx *ctx);
void ef_et_insert(ef_ctx *ctx, uint32_t edge_index, int32_t slot);
/* Moves slot `row`'s edges to the active edge table. */
void ef_et_activate(ef_ctx *ctx, int32_t row);
/* Drops active edges that have plotted their last row. */
void ef_aet_retire(ef_ctx *ctx);

/* plotter.c: plots every active edge's sample rows of pixel row `row`.
 * Widens xmin, xmax to the cells it marked (edge tracking). */
void ef_plot_evenodd(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax);
void ef_plot_nonzero(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax);

/* fill_*.c: scans cells xmin..xmax, clears them, reports spans of row y. */
void ef_fill_evenodd(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span, void *user);
void ef_fill_nonzero(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span, void *user);

/* Index of the lowest set bit of v != 0. */
static inline unsigned ef_ctz64(uint64_t v)
{
#if defined(__GNUC__)
    return (unsigned)__builtin_ctzll(v);
#else
    unsigned n = 0;
    while (!(v & 1u)) {
        v >>= 1;
        n++;
    }
    return n;
#endif
}

/* Population count, the coverage block's core (portable; compilers fold it). */
static inline unsigned ef_popcount32(uint32_t v)
{
    v = v - ((v >> 1) & 0x55555555u);
    v = (v & 0x33333333u) + ((v >> 2) & 0x33333333u);
    v = (v + (v >> 4)) & 0x0F0F0F0Fu;
    return (v * 0x01010101u) >> 24;
}

#endif /* EF_INTERNAL_H */
