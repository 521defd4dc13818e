/*
 * internal.h - the model's blocks and the state they share (not installed).
 *
 * Blocks, in pipeline order, one file each:
 *   edge_setup.c   polygon edges -> DDA records (docs/spec.md section 5)
 *   edge_table.c   one slot per pixel row, unsorted lists; the active edge table
 *   plotter.c      exact DDA + n-rooks offset into the scanline buffer (6.1-6.4);
 *                  its speed devices, behind EF_PLOT_FAST (plotter.h), in
 *                  plotter_fast.h, plotter_sse2.h, plotter_crowd.h
 *   fill_evenodd.c XOR accumulation with mask tracking (7.2)
 *   fill_nonzero.c packed 7-bit winding accumulation with mask tracking (7.2)
 *   rasterize.c    the scanline loop that runs the blocks in order
 *   coverage.c     popcount -> alpha (7.3)
 *   composite.c    premultiplied source-over onto RGBA8 (8); its per-span
 *                  arithmetic is inline below so that the fillers can
 *                  composite their spans directly (ef_fill's fast path)
 */
#ifndef EF_INTERNAL_H
#define EF_INTERNAL_H

#include <string.h>

#include "edgeflag.h"
#include "ef_fixed.h"

/* The hot paths' helpers: inlined where the compiler would not on its own
 * (their constant arguments select the code). */
#if defined(__GNUC__)
#define EF_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define EF_ALWAYS_INLINE inline
#endif

/* Packed winding constants (spec 6.3). */
#define EF_LANES7 UINT64_C(0x7F7F7F7F7F7F7F7F)
#define EF_PADS UINT64_C(0x8080808080808080)
#define EF_SIGN7 UINT64_C(0x4040404040404040)

/* One edge (spec 5).  Edge setup fills the first group and links the record
 * into the edge table; the DDA group (step 5) is computed when the plotter
 * reaches the edge's first pixel row (ef_dda_start), which needs the same
 * inputs and gives the same values, but only for edges that are drawn and
 * without storing and reloading them for the majority of edges, which lie
 * within one pixel row.  Bit budgets: |x| <= 2^23 + 2^29 after the final step,
 * |qs| < 2^29, 0 <= e, rs < dy < 2^24: all fit int32. */
typedef struct ef_edge {
    /* DDA state (spec 5 step 5), hot in the plotter */
    int32_t x;    /* Q16.8: ceil(exact crossing of the next row) - 1 */
    int32_t e;    /* error term, 0 <= e < dy */
    int32_t qs;   /* floor(h*dX / dY); MASK edges: floor(256*dX / dY), the step over a pixel row */
    int32_t rs;   /* (h*dX) mod dY; MASK edges: (256*dX) mod dY */
    int32_t dy;   /* Y1 - Y0 > 0 */
    int32_t r1;   /* last sample row (inclusive, clipped) */
    int32_t dir;  /* +1 downward, -1 upward */
    int32_t mode; /* plotter path, EF_PLOT_* */
    /* from edge setup (steps 2-4, 6) */
    int32_t x0, y0; /* upper end point */
    int32_t dx;     /* X1 - X0 */
    int32_t r0;     /* first sample row (clipped) */
    int32_t next;   /* edge-table slot list link, -1 ends */
} ef_edge;

/* Plotter paths (plotter.c).  CLAMP: the general one.  The others need
 * 1 <= X0, X1 <= 256*W: the DDA's x = ceil(x_r) - 1 then stays in
 * [0, 256W - 1], so q = (x + off) >> 8 lies in [0, W] and the spec 6.1 clamp
 * cannot act.  STEEP additionally moves less than 6 px over any pixel row.
 * MASK (only when the plotter asks for it): moves less than 1 px over a row,
 * so a row's samples mark at most three cells, and dY < 2^21 (the row's
 * comparisons fit 32 bits); its DDA state is kept at the first sample row of
 * each pixel row (extrapolated above the edge's start in its first row). */
enum { EF_PLOT_CLAMP = 0, EF_PLOT_INSIDE = 1, EF_PLOT_STEEP = 2, EF_PLOT_MASK = 3 };
#define EF_MASK_MAX_DY (INT32_C(1) << 21)
_Static_assert((int64_t)32 * ((int64_t)1 << 24) < ((int64_t)1 << 30), "h*dX fits 30 bits: qs fits int32");

/* An active edge's place and DDA state before a crowded row (plotter.c). */
typedef struct ef_aet_saved {
    int32_t idx, x, e;
} ef_aet_saved;

/* An edge-table slot: the first edge of its list (-1: empty) and how many
 * edges the list holds (spec 6 needs the row's AET size before plotting). */
typedef struct ef_slot {
    int32_t head;
    uint32_t n;
} ef_slot;

struct ef_ctx {
    int32_t width, height;
    int samples;                         /* N */
    int32_t h, c;                        /* 256/N and h/2, Q16.8 */
    int32_t off[EF_SAMPLES_MAX];         /* plot offset per sub-scanline: 256 - h*k_s - c */
    _Alignas(16) int16_t mask_pairs[64]; /* (s, off[s]), s = 0..N-1: MASK rows' multiplier pairs (plotter.c) */

    /* edge store and edge table */
    ef_edge *edges;
    uint32_t nedges, edges_cap;
    ef_slot *slot; /* height entries: the pixel row's list of new edges */
    int32_t *aet;  /* active edge indices, unsorted */
    uint32_t naet;
    uint32_t naet_row;          /* active edges while the current row was plotted */
    ef_aet_saved *aet_saved;    /* edges_cap entries: the AET as a crowded row found it (plotter.c) */
    int32_t *crowd;             /* W + 2 entries, zero between rows: edges that may plot per cell, as differences */
    int32_t crowd_lo, crowd_hi; /* the entries of crowd that a crowded row touched */

    /* the one-scanline buffer: W+1 cells (cell W is the right-clamp sink) */
    uint32_t *eo_cells; /* even-odd: N bits per cell */
    uint64_t *nz_cells; /* non-zero: N/8 words per cell; the plotter adds to
                             * their bytes (ef_nz_lane_byte), the filler masks
                             * the pad bits off as it reads them */
    uint64_t *occ;      /* one bit per cell: marked since the last fill (mask tracking) */

    ef_diag diag;

    struct ef_trace *trace; /* transaction trace (trace.c), NULL when off */
    struct ef_filt *filt;   /* section 3.5 options (filter.c), NULL when off (the default) */
};

/* edge_setup.c: appends the edges of poly to ctx->edges (steps 1-4) and
 * links them into the edge table (step 6).  Returns EF_ERR_ARG for
 * out-of-range vertices (leaving no state behind), EF_ERR_LIMIT past the edge
 * budget.  On return row_min, row_max bound the pixel rows that hold edges
 * (row_min > row_max when none). */
ef_status ef_edges_setup(ef_ctx *ctx, const ef_polygon *poly, int32_t *row_min, int32_t *row_max);

/* floor(a / d) and its remainder in 32 bits: ef_divmod_floor_i32 (fixed/ef_fixed.h). */

/* Spec 5 step 5, exact: the DDA of an edge set up by ef_edges_setup, at its
 * first sample row r0, and its plotter path.  h = 256/N, c = h/2, last_s =
 * N - 1.  x = floor(A / dY) = X0 + floor(B / dY) with B = (Y_r - Y0)*dX - 1,
 * and Y_r - Y0 < h unless the top clip moved r0, so B fits 32 bits
 * (|B| < 2^30) and the division is a 32-bit one except for edges clipped at
 * the top.  mask_ok: the plotter can take MASK edges; their x is that of the
 * first sample row of r0's pixel row instead (the same formula at Y_r up to
 * 255 - h above Y0: |B| <= 256 * |dX| < 2^30 for them). */
static EF_ALWAYS_INLINE void ef_dda_start(ef_edge *E, int32_t h, int32_t c, int32_t w256, int last_s, int mask_ok)
{
    const int32_t dy = E->dy, dx = E->dx;
    const int32_t step = h * dx; /* |h*dx| < 2^29 */
    /* End points' x range (branch-free: edge orientation is data). */
    const int32_t neg3 = -(int32_t)(dx < 0);
    const int32_t xlo = E->x0 + (dx & neg3), xhi = E->x0 + (dx & ~neg3);
    const int32_t inside = (xlo >= 1) & (xhi <= w256);
    /* MASK: |x step| <= |qs| + 1 <= K = floor(255 / last_s), qs = floor(step /
     * dY), i.e. -K*dY <= step < K*dY (no division).  dy_low is dY when it
     * is below the bound and keeps K*dy_low < 2^27 when it is not (the test
     * fails then anyway). */
    const int32_t K = 255 / last_s, dy_low = dy & (EF_MASK_MAX_DY - 1);
    const int32_t mask = inside & (mask_ok != 0) & (dy < EF_MASK_MAX_DY) & (w256 >= 2 * EF_DEV_ONE) &
                         (step >= -K * dy_low) & (step < K * dy_low);
    /* One 32-bit division gives the DDA's step: per sample row, (qs, rs) =
     * floor divmod(h*dX, dY), or for a MASK edge per pixel row, (qn, rn) =
     * floor divmod(256*dX, dY) (|256*dX| < 256 * 1.15 * dY < 2^30 by the
     * bound above).  (An edge crossing one sample row never steps; computing
     * its step anyway costs less than the branch.) */
    const int32_t num = dx * (h + ((EF_DEV_ONE - h) & -mask));
    int32_t qs, rs;
    ef_divmod_floor_i32(num, dy, &qs, &rs);
    E->qs = qs; /* MASK edges: (qn, rn); ef_mask_demote makes them per sample row */
    E->rs = rs;
    /* The path: 0 CLAMP, 1 INSIDE, 2 STEEP (|x step| <= |qs| + 1, over at
     * most last_s steps within one row, less than 6 px), 3 MASK (under 1 px).
     * |qs| + 1 for qs >= 0, -qs = ~qs + 1 for qs < 0: (qs ^ sign) + 1 (a
     * select here compiled to a branch that mispredicted on about one edge in
     * four) */
    const int32_t sgn = -(int32_t)((uint32_t)qs >> 31);
    const uint64_t moves = (uint64_t)((uint32_t)(qs ^ sgn) + 1u) * (uint32_t)last_s;
    const int32_t steep = (moves < 6u * EF_DEV_ONE) | mask;
    E->mode = inside * (EF_PLOT_INSIDE + steep) + mask;
    /* A MASK edge starts at the first sample row of its pixel row: r0 with
     * its sample index (r0 mod N) cleared. */
    const int32_t r = E->r0 & ~(last_s & -mask);
    const int32_t t = h * r + c - E->y0; /* Y_r - Y0: >= 0 unless MASK */
    if (t <= 63) {
        int32_t q, rem;
        ef_divmod_floor_i32(t * dx - 1, dy, &q, &rem);
        E->x = E->x0 + q;
        E->e = rem;
    } else {
        /* |A| < 2^23 * 2^24 + 2^24 * 2^24 < 2^49: exact in int64. */
        int64_t A = (int64_t)E->x0 * dy + (int64_t)t * dx - 1, q, rem;
        ef_divmod_floor_i64(A, dy, &q, &rem);
        E->x = (int32_t)q;
        E->e = (int32_t)rem;
    }
}

/* A MASK edge to STEEP, for rows plotted sample by sample: (qs, rs) become
 * its per-sample step, as ef_dda_start computes it for the other paths.  Its DDA
 * state, at the first sample row of a pixel row, is what STEEP edges carry
 * between rows. */
/* log2 of a valid sample count N (8, 16, 32): 3, 4, 5.  The model's one
 * copy (edge setup's h = 2^(8 - log2 N), the traced slot = r0 >> log2 N). */
static inline unsigned ef_samples_log2(int n) { return n == 8 ? 3u : n == 16 ? 4u : 5u; }

static inline void ef_mask_demote(ef_edge *E, int32_t h)
{
    ef_divmod_floor_i32(h * E->dx, E->dy, &E->qs, &E->rs);
    E->mode = EF_PLOT_STEEP;
}
_Static_assert((int64_t)63 * ((int64_t)1 << 24) < ((int64_t)1 << 30), "t*dX fits 31 bits when t <= 63");

/* edge_table.c */
void ef_et_reset(ef_ctx *ctx);
/* Prepends to the slot's list: edge setup inserts a polygon's edges in
 * reverse input order, so every list reads in input order. */
static inline void ef_et_insert(ef_edge *edges, ef_slot *slots, uint32_t edge_index, int32_t slot)
{
    ef_slot *S = &slots[slot];
    edges[edge_index].next = S->head;
    S->head = (int32_t)edge_index;
    S->n++;
}
/* Takes slot `row`'s list (first edge, -1 if none; *n edges) out of the edge
 * table: the plotter activates them, in input order, after the edges already
 * active (the AET order of spec 6). */
int32_t ef_et_take(ef_ctx *ctx, int32_t row, uint32_t *n);

/* plotter.c: plots pixel row `row`: first the edges active from earlier rows
 * (AET order), then the row's new edges (the list `head` taken from the edge
 * table, in input order, each started with ef_dda_start), every sample row
 * of each inside this pixel row.  Edges that continue below stay in (or join)
 * the AET in that order; the others leave it (spec 6's activation and
 * retirement, done in the same pass).  Widens xmin, xmax to the cells it
 * marked (edge tracking).  ctx->naet_row must hold the number of edges plotted
 * in this row (old + new). */
void ef_plot_evenodd(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax);
void ef_plot_nonzero(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax);

/* filter.c: the section 3.5 options (docs/spec.md section 10); ef_fill
 * hands a shape to ef_filter_fill when ctx->filt is set. */
struct ef_filt;
void ef_filt_free(struct ef_filt *f);
ef_status ef_filter_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color);

/* composite.c: a shape's colour, premultiplied and prepared for the span
 * compositor below (docs/spec.md section 8). */
typedef struct ef_blend {
    uint8_t *px; /* the image */
    size_t stride;
    uint64_t p4;        /* premultiplied colour P, 4 lanes (ef_spread4) */
    uint32_t solid;     /* P packed in memory order */
    uint32_t solid8[8]; /* eight copies: solid fills store 32 bytes at a time */
    uint32_t a;         /* colour alpha */
    int samples;
    const uint8_t *count8; /* N = 8: covered samples of every mask */
    /* by number n of covered samples, 0..N, with cov = alpha(n) (spec 7.3):
     * mul(P, cov) in 4 lanes and mul(a, cov), so a partial span costs two
     * loads instead of five multiplies (filled once per shape, ef_fill) */
    uint64_t s4_n[33];
    uint32_t sa_n[33];
} ef_blend;

/* coverage.c: spec 7.3 as tables: the number of covered samples of each
 * 8-bit mask (N = 8), and alpha by number of covered samples (0..N) for
 * N = 8, 16, 32. */
const uint8_t *ef_count_of_mask8(void);
const uint8_t *ef_alpha_of_count(int samples);

/* rasterize.c: ef_rasterize with either a span callback or, when blend is not
 * NULL, spans composited directly by the fillers (same spans, same pixels). */
ef_status ef_rasterize_to(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_span_fn span, void *user,
                          const ef_blend *blend);

/* fill_*.c: scans cells xmin..xmax, clears them, reports spans of row y to
 * span(user, ...) or, when blend is not NULL, composites them. */
void ef_fill_evenodd(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span, void *user,
                     const ef_blend *blend);
void ef_fill_nonzero(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span, void *user,
                     const ef_blend *blend);

/* Non-zero buffer, byte view (plotter.c): the byte of a cell that holds
 * sample s's counter.  The filler reads a cell as N/8 words, sample s in word
 * s/8, lane L = s mod 8 (bits 8L..8L+7); lane L is byte L of the word on a
 * little-endian host and byte 7 - L on a big-endian one. */
static inline size_t ef_nz_lane_byte(unsigned s)
{
#if defined(__BYTE_ORDER__) && defined(__ORDER_BIG_ENDIAN__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    return (s & ~7u) | (7u - (s & 7u));
#elif defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    return s;
#else
    const uint16_t one = 1;
    unsigned char low;
    memcpy(&low, &one, 1);
    return low ? s : (s & ~7u) | (7u - (s & 7u));
#endif
}

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

/* Pad bits (bit 8L+7, nothing else set) of a word -> bits 0..7 in lane
 * order: the multiply moves bit 8L to bit 56+L with no carries into the top
 * byte (checked for all 256 patterns in tests/unit/test_model.c). */
static inline uint32_t ef_gather_pads(uint64_t pads)
{
    return (uint32_t)(((pads >> 7) * UINT64_C(0x0102040810204080)) >> 56);
}

/* Population count, the coverage block's core: ef_popcount32 (fixed/ef_fixed.h). */

/* ---------------------------------------------------------------------------
 * Compositing four channels at once (docs/spec.md section 8, bit for bit).
 * A pixel's four bytes are spread into four 16-bit lanes of a uint64 (byte
 * order is irrelevant: every channel gets the same arithmetic, and the colour
 * is spread the same way).  In each lane:
 *   mul(v, k) = t = v*k + 128; ((t >> 8) + t) >> 8, with v, k <= 255, so
 *   t <= 65153 and (t >> 8) + t <= 65407: no lane carries into the next;
 *   d' = (d + s - mul(d, sa)) mod 256, where mul(d, sa) <= d (sa <= 255):
 *   no lane borrows, d + s <= 510 fits, and the final mask is the uint8 wrap.
 * ------------------------------------------------------------------------ */
#define EF_LANE8X4 UINT64_C(0x00FF00FF00FF00FF)

/* bytes b0 b1 b2 b3 (memory order) -> lanes (b0, b2, b1, b3) */
static inline uint64_t ef_spread4(uint32_t v)
{
    return (uint64_t)(v & 0x00FF00FFu) | (uint64_t)((v >> 8) & 0x00FF00FFu) << 32;
}
static inline uint32_t ef_pack4(uint64_t v) { return (uint32_t)v | (uint32_t)(v >> 32) << 8; }
/* mul(v, k) of docs/spec.md 8 in each lane; lanes of v and k <= 255. */
static inline uint64_t ef_mul255x4(uint64_t v, uint32_t k)
{
    uint64_t t = v * k + UINT64_C(0x0080008000800080);
    return ((t + ((t >> 8) & EF_LANE8X4)) >> 8) & EF_LANE8X4;
}

static inline uint32_t ef_load32(const uint8_t *p)
{
    uint32_t v;
    memcpy(&v, p, 4);
    return v;
}

/* Composites the span [x, x+len) of row y (spec 7.3 + 8) where n samples,
 * 1 <= n <= N, are covered.  Inlined into the fillers through ef_blend_span
 * (by mask) and ef_blend_span_n (by count). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void
ef_blend_span_n(const ef_blend *b, int32_t y, int32_t x, int32_t len, uint32_t n)
{
    uint8_t *d = b->px + (size_t)y * b->stride + (size_t)x * 4;
    if ((int)n == b->samples) {
        if (b->a == 255) {
            /* d' = d + P - mul(d, 255) = P: a plain fill.  Every pixel gets
             * the same 4 bytes, so stores may overlap: a span is covered by
             * whole blocks from its start plus one block ending at its end,
             * with few branches (loop exits on data-dependent lengths
             * mispredict). */
            uint8_t *const e = d + (size_t)len * 4;
            if (len >= 8) {
                uint32_t pat[8]; /* a local copy: cannot alias d */
                memcpy(pat, b->solid8, sizeof pat);
                for (; d < e - 32; d += 32)
                    memcpy(d, pat, 32); /* compilers emit wide stores */
                memcpy(e - 32, pat, 32);
            } else if (len >= 2) {
                const uint64_t two = (uint64_t)b->solid * UINT64_C(0x0000000100000001);
                if (len >= 4) {
                    memcpy(d, &two, 8);
                    memcpy(d + 8, &two, 8);
                    memcpy(e - 16, &two, 8);
                    memcpy(e - 8, &two, 8);
                } else {
                    memcpy(d, &two, 8);
                    memcpy(e - 8, &two, 8);
                }
            } else {
                memcpy(d, &b->solid, 4);
            }
            return;
        }
    }
    /* mul(P, cov) and mul(a, cov) from the shape's table (for n = N, cov =
     * 255: P and a).  mul(a, cov) is its own entry: which lane holds the
     * alpha byte depends on the host's byte order (found on s390x by make
     * portability). */
    const uint64_t s4 = b->s4_n[n];
    const uint32_t sa = b->sa_n[n];
    for (int32_t i = 0; i < len; i++, d += 4) {
        uint64_t dd = ef_spread4(ef_load32(d));
        uint32_t v = ef_pack4((dd + s4 - ef_mul255x4(dd, sa)) & EF_LANE8X4);
        memcpy(d, &v, 4);
    }
}

/* ef_blend_span_n for coverage mask `mask` (not 0). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void
ef_blend_span(const ef_blend *b, int32_t y, int32_t x, int32_t len, ef_mask mask)
{
    const uint32_t n = b->samples == 8 ? b->count8[mask] : ef_popcount32(mask);
    ef_blend_span_n(b, y, x, len, n);
}

#endif /* EF_INTERNAL_H */
