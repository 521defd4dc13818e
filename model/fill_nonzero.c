/*
 * fill_nonzero.c - the non-zero winding filler (docs/spec.md section 7.2).
 *
 * Accumulates the packed 7-bit winding counters left to right, eight lanes to
 * a 64-bit word, masking the pad bits after every add; a lane's pad bit after
 * adding 0x7F is set exactly when the counter is non-zero, and those pad bits,
 * gathered in sample order, are the coverage mask.  The heavy part runs only
 * at marked, non-zero cells (mask tracking, through the occupancy map as in
 * fill_evenodd.c); cells are cleared as they are read.  Spans go to the
 * caller's callback or straight to the compositor (ef_fill), as there.
 */
#include "internal.h"

static inline uint32_t lanes_nonzero(uint64_t acc) { return ef_gather_pads(((acc & EF_LANES7) + EF_LANES7) & EF_PADS); }

/* For N = 16 and 32 with compositing, the lanes are added as 16-byte
 * vectors (GCC's and Clang's generic vector extension: SSE2 on x86-64, NEON
 * on AArch64, plain words elsewhere).  The arithmetic is the same byte-wise
 * add and mask as the words' (lanes do not carry into each other), so the
 * results are the same bits; EF_NO_VECTOR builds (tests/portability.sh)
 * take the word path instead. */
#if defined(__GNUC__) && !defined(EF_NO_VECTOR)
#define EF_FILL_VECTOR 1
typedef uint8_t ef_u8x16 __attribute__((vector_size(16)));

/* Sum of the 16 bytes of v, each at most 2 (so no byte carries). */
static inline uint32_t byte_sum16(ef_u8x16 v)
{
    uint64_t w[2];
    memcpy(w, &v, 16);
    return (uint32_t)(((w[0] + w[1]) * UINT64_C(0x0101010101010101)) >> 56);
}
#else
#define EF_FILL_VECTOR 0
#endif

static EF_ALWAYS_INLINE void fill_nonzero(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span,
                                          void *user, const ef_blend *blend, const int direct, const int words,
                                          const int check_overflow)
{
    /* Compositing needs only how many samples are covered, not which: for
     * N = 16, 32 the state is then that count, taken as a byte sum of the
     * lanes' non-zero flags (with vectors), or of the words' pad bits moved to
     * bit 0 of each byte (byte L: how many of the words have lane L non-zero,
     * at most 4; the multiply's top byte gets no carry); the mask by sample,
     * which costs a gather per word, is built only for the span callback and
     * N = 8 (its alpha table is by mask). */
    const int by_count = direct && words > 1;
    const int by_vector = EF_FILL_VECTOR && by_count;
    uint64_t *occ = ctx->occ;
    const int32_t W = ctx->width;
    uint64_t acc[4] = { 0, 0, 0, 0 };
    uint64_t mask = 0; /* coverage mask, the interleaved pads (by_count) or the count (by_vector) */
    uint64_t overflows = 0;
    int32_t start = xmin;
#if EF_FILL_VECTOR
    ef_u8x16 vacc[2] = { { 0 }, { 0 } };
#endif
#define NZ_SPAN(x0, n) \
    do { \
        if (by_vector) \
            ef_blend_span_n(blend, y, x0, n, (uint32_t)mask); \
        else if (by_count) \
            ef_blend_span_n(blend, y, x0, n, (uint32_t)((mask * UINT64_C(0x0101010101010101)) >> 56)); \
        else if (direct) \
            ef_blend_span(blend, y, x0, n, (uint32_t)mask); \
        else \
            span(user, y, x0, n, (uint32_t)mask); \
    } while (0)
    for (int32_t wi = xmin >> 6; wi <= xmax >> 6; wi++) {
        uint64_t bits = occ[wi];
        if (!bits)
            continue;
        occ[wi] = 0;
        do {
            int32_t p = wi * 64 + (int32_t)ef_ctz64(bits);
            bits &= bits - 1;
            /* The plotter adds to the cell's bytes modulo 256 (plotter.c):
             * the spec's lanes are the low 7 bits, the pad bits are masked
             * off here.  Read through memcpy (the bytes were written as
             * bytes), cleared as read, including a cell whose counters are
             * all 0 modulo 128 (its pad bits may be set). */
            uint64_t *cell = &ctx->nz_cells[(size_t)p * (size_t)words];
#if EF_FILL_VECTOR
            if (by_vector) {
                /* A cell whose counters cancelled closes a span here and
                 * opens one with the same count: the same pixels, and no
                 * test for it on every cell. */
                ef_u8x16 v[2];
                memcpy(v, cell, (size_t)words * 8);
                memset(cell, 0, (size_t)words * 8); /* clear-on-read */
                if (mask && p > start) {
                    int32_t len = (p < W ? p : W) - start;
                    NZ_SPAN(start, len);
                }
                ef_u8x16 nonzero = { 0 }, over = { 0 };
                for (int k = 0; k < words / 2; k++) {
                    const ef_u8x16 a = vacc[k], b = v[k] & 0x7F;
                    const ef_u8x16 sum = (a + b) & 0x7F;
                    if (check_overflow) /* as below: operands agree in sign, result not */
                        over -= (ef_u8x16)((~(a ^ b) & (a ^ sum) & 0x40) != 0);
                    vacc[k] = sum;
                    nonzero -= (ef_u8x16)(sum != 0);
                }
                if (check_overflow)
                    overflows += byte_sum16(over);
                mask = byte_sum16(nonzero);
                start = p;
                continue;
            }
#endif
            uint64_t v[4], any = 0;
            for (int w = 0; w < words; w++) {
                memcpy(&v[w], &cell[w], 8);
                v[w] &= EF_LANES7;
                any |= v[w];
            }
            memset(cell, 0, (size_t)words * 8); /* clear-on-read */
            if (any == 0)
                continue; /* contributions that cancelled: mask unchanged */
            if (mask && p > start) {
                int32_t len = (p < W ? p : W) - start;
                NZ_SPAN(start, len);
            }
            mask = 0;
            for (int w = 0; w < words; w++) {
                uint64_t a = acc[w], b = v[w];
                uint64_t sum = (a + b) & EF_LANES7;
                if (check_overflow) {
                    /* Signed 7-bit overflow per lane: operands agree in sign, result not. */
                    uint64_t ov = ~(a ^ b) & (a ^ sum) & EF_SIGN7;
                    if (ov)
                        overflows += ef_popcount32(ef_gather_pads(ov << 1)); /* bit 8L+6 -> 8L+7 */
                }
                acc[w] = sum;
                if (by_count)
                    mask += ((sum + EF_LANES7) & EF_PADS) >> 7;
                else
                    mask |= (uint64_t)lanes_nonzero(sum) << (8 * w);
            }
            start = p;
        } while (bits);
    }
    ctx->diag.winding_overflows += overflows;
    if (mask && start < W) {
        int32_t end = xmax + 1 < W ? xmax + 1 : W;
        NZ_SPAN(start, end - start);
    }
#undef NZ_SPAN
}

#define FILL_NZ(words, check) \
    do { \
        if (blend) \
            fill_nonzero(ctx, y, xmin, xmax, NULL, NULL, blend, 1, words, check); \
        else \
            fill_nonzero(ctx, y, xmin, xmax, span, user, NULL, 0, words, check); \
    } while (0)

void ef_fill_nonzero(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span, void *user,
                     const ef_blend *blend)
{
    /* A running counter is a sample's winding number, at most the number of
     * active edges in size: with at most 63 it cannot leave [-64, 63], so
     * the check is skipped there. */
    const int check = ctx->naet_row >= 64;
    switch (ctx->samples * 2 + check) {
    case 16: FILL_NZ(1, 0); break;
    case 17: FILL_NZ(1, 1); break;
    case 32: FILL_NZ(2, 0); break;
    case 33: FILL_NZ(2, 1); break;
    case 64: FILL_NZ(4, 0); break;
    default: FILL_NZ(4, 1); break;
    }
}
