/*
 * pattern_search.c - scoring and searching n-rooks sample patterns
 * (the paper's section 3.3 criterion; docs/patterns.md).
 *
 * Not part of the rasterizer's datapath: it produces the tables that
 * model/pattern_tables.c freezes, and lets a test prove they are still what
 * the criterion selects.  Integer-only and deterministic, so the tables are
 * reproducible bit for bit on any machine.
 *
 * Criterion (lexicographic):
 *   1. grid star discrepancy, lower is better;
 *   2. spread = sum of squared nearest-neighbour distances, higher is better.
 * Orientation of the winner (the 8 symmetries of the square score the same):
 *   3. exact star discrepancy anchored at the pixel's top-left, lower first;
 *   4. lexicographically least table.
 * For N = 8 this selects exactly 2,7,4,1,6,3,0,5 out of all 40320
 * permutations; the literal reading (minimising the spread) and the
 * continuous star discrepancy do not (docs/patterns.md, section 1).
 */
#include "ef_patterns.h"

#include <string.h>

#define NMAX EF_PATTERN_MAX

/* spread <= N * 2(N-1)^2 = 61504 for N = 32, so it fits below the 20-bit
 * field of a search key; the discrepancy (<= N^2) goes above it. */
#define SPREAD_BITS 20
_Static_assert(NMAX * 2 * (NMAX - 1) * (NMAX - 1) < (1 << SPREAD_BITS), "spread fits its key field");

/* ------------------------------------------------------------ scoring */

int ef_pattern_is_nrooks(int n, const uint8_t *k)
{
    uint64_t seen = 0;
    if (!ef_samples_valid(n) || !k)
        return 0;
    for (int s = 0; s < n; s++) {
        uint64_t bit;
        if (k[s] >= n)
            return 0;
        bit = (uint64_t)1 << k[s];
        if (seen & bit)
            return 0;
        seen |= bit;
    }
    return 1;
}

/* Grid star discrepancy numerator (over n^2).  Rows are added one at a time
 * so cnt[a] = #{s < b : p[s] < a} costs O(n) per row.  Boxes with a or b in
 * {0, n} have error 0 for an n-rooks pattern, so only the inner ones are
 * visited.  *ties (may be NULL) receives how many boxes reach the maximum:
 * the search uses it to tell apart patterns on the same discrepancy plateau.
 * Returns early, with some value > limit, once limit is exceeded: the search
 * only needs to know that a candidate lost. */
static uint32_t grid_discrepancy(int n, const int *p, uint32_t limit, uint32_t *ties)
{
    int cnt[NMAX + 1];
    uint32_t best = 0, nbest = 0;

    memset(cnt, 0, sizeof cnt);
    for (int b = 1; b < n; b++) {
        for (int a = p[b - 1] + 1; a < n; a++)
            cnt[a]++;
        for (int a = 1; a < n; a++) {
            int v = n * cnt[a] - a * b;
            uint32_t d = (uint32_t)(v < 0 ? -v : v);
            if (d > best) {
                best = d;
                nbest = 1;
                if (best > limit)
                    return best;
            } else if (d == best) {
                nbest++;
            }
        }
    }
    if (ties)
        *ties = nbest;
    return best;
}

/* Sum over samples of the squared distance (units (1/n)^2) to the nearest
 * other sample.  Neighbours are visited by increasing row distance, so the
 * scan stops as soon as the row distance alone exceeds the best found. */
static uint32_t spread(int n, const int *p)
{
    uint32_t total = 0;
    for (int s = 0; s < n; s++) {
        int m = 2 * n * n;
        for (int dy = 1; dy < n && dy * dy < m; dy++) {
            int t;
            for (t = s - dy; t <= s + dy; t += 2 * dy) {
                if (t >= 0 && t < n) {
                    int dx = p[s] - p[t];
                    int d = dx * dx + dy * dy;
                    if (d < m)
                        m = d;
                }
            }
        }
        total += (uint32_t)m;
    }
    return total;
}

/* Exact star discrepancy over boxes [0,x) x [0,y), numerator over 4n^2.
 * Coordinates are in units of 1/(2n): sample s is at (2p[s]+1, 2s+1).  The
 * supremum of count/n - area is approached by boxes just beyond a sample
 * coordinate (closed counts), that of area - count/n by boxes reaching up
 * to one (open counts), so only the sample coordinates and 2n matter. */
static uint32_t star_discrepancy(int n, const int *p)
{
    int64_t best = 0;
    for (int ix = 0; ix <= n; ix++) {
        int64_t x = ix < n ? 2 * p[ix] + 1 : 2 * n;
        for (int iy = 0; iy <= n; iy++) {
            int64_t y = iy < n ? 2 * iy + 1 : 2 * n;
            int64_t closed = 0, open = 0, area = x * y;
            for (int s = 0; s < n; s++) {
                int64_t px = 2 * p[s] + 1, py = 2 * s + 1;
                closed += px <= x && py <= y;
                open += px < x && py < y;
            }
            if (4 * n * closed - area > best)
                best = 4 * n * closed - area;
            if (area - 4 * n * open > best)
                best = area - 4 * n * open;
        }
    }
    return (uint32_t)best;
}

static void score_ints(int n, const int *p, ef_pattern_score *out)
{
    out->discrepancy = grid_discrepancy(n, p, UINT32_MAX, NULL);
    out->spread = spread(n, p);
    out->star = star_discrepancy(n, p);
}

static void to_ints(int n, const uint8_t *k, int *p)
{
    for (int s = 0; s < n; s++)
        p[s] = k[s];
}

ef_status ef_pattern_score_of(int n, const uint8_t *k, ef_pattern_score *out)
{
    int p[NMAX] = { 0 };
    if (!out || !ef_pattern_is_nrooks(n, k))
        return EF_ERR_ARG;
    to_ints(n, k, p);
    score_ints(n, p, out);
    return EF_OK;
}

int ef_pattern_compare(const ef_pattern_score *a, const ef_pattern_score *b)
{
    if (a->discrepancy != b->discrepancy)
        return a->discrepancy < b->discrepancy ? -1 : 1;
    if (a->spread != b->spread)
        return a->spread > b->spread ? -1 : 1;
    return 0;
}

/* ------------------------------------------------------- orientation */

static int lex_compare(int n, const int *a, const int *b)
{
    for (int s = 0; s < n; s++)
        if (a[s] != b[s])
            return a[s] < b[s] ? -1 : 1;
    return 0;
}

/* Image g (0..7) of p under the symmetries of the square: bit 2 transposes
 * (inverse permutation: swaps the roles of rows and columns), bit 0 mirrors
 * left-right, bit 1 mirrors top-bottom.  Together they give all 8. */
static void symmetry_image(int n, const int *p, int g, int *out)
{
    int q[NMAX];
    for (int s = 0; s < n; s++) {
        if (g & 4)
            q[p[s]] = s;
        else
            q[s] = p[s];
    }
    for (int s = 0; s < n; s++) {
        int v = q[(g & 2) ? n - 1 - s : s];
        out[s] = (g & 1) ? n - 1 - v : v;
    }
}

static void canonical_ints(int n, const int *p, int *out)
{
    int best[NMAX] = { 0 };
    uint32_t best_star = UINT32_MAX;
    for (int g = 0; g < 8; g++) {
        int img[NMAX];
        uint32_t st;
        symmetry_image(n, p, g, img);
        st = star_discrepancy(n, img);
        if (st < best_star || (st == best_star && lex_compare(n, img, best) < 0)) {
            best_star = st;
            memcpy(best, img, sizeof(int) * (size_t)n);
        }
    }
    memcpy(out, best, sizeof(int) * (size_t)n);
}

ef_status ef_pattern_canonical(int n, const uint8_t *k, uint8_t *out)
{
    int p[NMAX] = { 0 };
    if (!out || !ef_pattern_is_nrooks(n, k))
        return EF_ERR_ARG;
    to_ints(n, k, p);
    canonical_ints(n, p, p);
    for (int s = 0; s < n; s++)
        out[s] = (uint8_t)p[s];
    return EF_OK;
}

/* ----------------------------------------------------------- search */

/* The search compares candidates through one integer key, lower is better.
 * Two objectives share the same bounded evaluation:
 *   OBJ_CRITERION  discrepancy, then spread (the criterion itself, exactly
 *                  as ef_pattern_compare orders it);
 *   OBJ_PLATEAU    discrepancy, then the number of boxes at the maximum: a
 *                  guide for the first phase, which must get off plateaus
 *                  where every swap keeps the same discrepancy.
 * The discrepancy sits in the high bits in both, so both only ever accept
 * what is no worse in discrepancy than their limit allows. */
enum objective { OBJ_CRITERION, OBJ_PLATEAU };

#define TIES_BITS 10
_Static_assert((NMAX - 1) * (NMAX - 1) < (1 << TIES_BITS), "tie count fits its key field");

static int obj_shift(enum objective obj) { return obj == OBJ_CRITERION ? SPREAD_BITS : TIES_BITS; }

/* Key of p if it is <= limit, else UINT64_MAX.  Skips the rest of the work
 * when the discrepancy alone already loses (most rejected moves). */
static uint64_t key_bounded(int n, const int *p, uint64_t limit, enum objective obj)
{
    int shift = obj_shift(obj);
    uint64_t dlim64 = limit >> shift;
    uint32_t dlim = dlim64 > UINT32_MAX ? UINT32_MAX : (uint32_t)dlim64;
    uint32_t ties = 0;
    uint32_t d = grid_discrepancy(n, p, dlim, obj == OBJ_PLATEAU ? &ties : NULL);
    uint64_t key;

    if (d > dlim)
        return UINT64_MAX;
    if (obj == OBJ_CRITERION)
        key = ((uint64_t)d << SPREAD_BITS) | (((uint64_t)1 << SPREAD_BITS) - 1 - spread(n, p));
    else
        key = ((uint64_t)d << TIES_BITS) | ties;
    return key <= limit ? key : UINT64_MAX;
}

static void copy_pattern(int n, int *dst, const int *src) { memcpy(dst, src, sizeof(int) * (size_t)n); }

/* N = 8: every permutation, in lexicographic order.  Ties under the
 * criterion are broken by the orientation rule directly (least star, then
 * the first in lexicographic order), which is the same as taking the
 * canonical image of the best: each winner's 8 images are winners too. */
static void search_exhaustive(int n, int *best)
{
    int p[NMAX];
    uint64_t best_key = UINT64_MAX;
    uint32_t best_star = UINT32_MAX;

    for (int s = 0; s < n; s++)
        p[s] = s;
    for (;;) {
        uint64_t key = key_bounded(n, p, best_key, OBJ_CRITERION);
        if (key != UINT64_MAX) {
            uint32_t st = star_discrepancy(n, p);
            if (key < best_key || st < best_star) {
                best_key = key;
                best_star = st;
                copy_pattern(n, best, p);
            }
        }
        /* next permutation in lexicographic order */
        int i = n - 2, j = n - 1;
        while (i >= 0 && p[i] > p[i + 1])
            i--;
        if (i < 0)
            break;
        while (p[j] < p[i])
            j--;
        int t = p[i];
        p[i] = p[j];
        p[j] = t;
        for (int a = i + 1, b = n - 1; a < b; a++, b--) {
            t = p[a];
            p[a] = p[b];
            p[b] = t;
        }
    }
}

/* xorshift64 (Marsaglia 2003): a fixed, documented generator, so the search
 * is reproducible without depending on the C library's rand(). */
typedef struct rng {
    uint64_t s;
} rng;
static uint32_t rng_below(rng *r, uint32_t bound)
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 7;
    r->s ^= r->s << 17;
    return (uint32_t)((r->s >> 32) % bound);
}

static int log2_exact(int n)
{
    int m = 0;
    while ((1 << m) < n)
        m++;
    return m;
}

/* Best structured candidate, under the criterion, of two classic
 * low-discrepancy families (all n-rooks):
 *  - rank-1 lattices k = (a*s + b) mod n, a odd (the paper's 8-sample
 *    winner is one: 5s + 2);
 *  - linear scrambles of the bit-reversal (Hammersley) pattern,
 *    k = L * rev(s) xor c over GF(2), L lower unitriangular. */
static void search_structured(int n, int *best)
{
    int p[NMAX];
    uint64_t best_key = UINT64_MAX;
    int m = log2_exact(n);
    int nfree = m * (m - 1) / 2;

    for (int a = 1; a < n; a += 2) {
        for (int b = 0; b < n; b++) {
            for (int s = 0; s < n; s++)
                p[s] = (a * s + b) % n;
            uint64_t key = key_bounded(n, p, best_key, OBJ_CRITERION);
            if (key < best_key) {
                best_key = key;
                copy_pattern(n, best, p);
            }
        }
    }
    for (uint32_t lm = 0; lm < (1u << nfree); lm++) {
        int col[8];
        int bit = 0;
        for (int i = 0; i < m; i++) {
            col[i] = 1 << i;
            for (int j = 0; j < i; j++, bit++)
                if (lm >> bit & 1u)
                    col[i] |= 1 << j;
        }
        for (int c = 0; c < n; c++) {
            for (int s = 0; s < n; s++) {
                int v = c;
                for (int i = 0; i < m; i++)
                    if (s >> (m - 1 - i) & 1) /* bit i of rev(s) */
                        v ^= col[i];
                p[s] = v;
            }
            uint64_t key = key_bounded(n, p, best_key, OBJ_CRITERION);
            if (key < best_key) {
                best_key = key;
                copy_pattern(n, best, p);
            }
        }
    }
}

/* Late-acceptance hill climbing (Burke & Bykov 2017): a move (swap the
 * columns of two rows, which keeps the pattern n-rooks) is taken when it is
 * no worse than the current pattern or than the one `hist` moves ago.
 * Integer keys only, no temperatures.  Starting from p, leaves the best
 * pattern seen in best and returns its key.  Since the history starts at
 * the start's key, no accepted pattern is ever worse than the start. */
#define LAHC_HIST_MAX 1024
static uint64_t lahc(int n, int *p, long iters, int hist_len, enum objective obj, rng *r, int *best)
{
    uint64_t hist[LAHC_HIST_MAX];
    uint64_t cur = key_bounded(n, p, UINT64_MAX - 1, obj), best_key = cur;

    copy_pattern(n, best, p);
    for (int h = 0; h < hist_len; h++)
        hist[h] = cur;
    for (long it = 0; it < iters; it++) {
        int h = (int)(it % hist_len);
        int i = (int)rng_below(r, (uint32_t)n);
        int j = (int)rng_below(r, (uint32_t)n - 1);
        int t;
        uint64_t limit = cur > hist[h] ? cur : hist[h];
        uint64_t key;

        j += j >= i;
        t = p[i];
        p[i] = p[j];
        p[j] = t;
        key = key_bounded(n, p, limit, obj);
        if (key != UINT64_MAX) {
            cur = key;
            if (cur < best_key) {
                best_key = cur;
                copy_pattern(n, best, p);
            }
        } else {
            p[j] = p[i];
            p[i] = t;
        }
        if (cur < hist[h])
            hist[h] = cur;
    }
    return best_key;
}

/* Search budget: fixed counts, never a clock, so the result does not
 * depend on the machine.  Tuned so N = 32 takes about a second on the
 * 2-core reference machine.  Start 0 is the structured winner; the others
 * are Fisher-Yates shuffles from one xorshift64 stream seeded below. */
#define SEARCH_SEED 0x9E3779B97F4A7C15ull
#define SEARCH_STARTS 4
#define SEARCH_HIST 1000

static long plateau_iters(int n) { return n <= 16 ? 40000L : 150000L; }
static long spread_iters(int n) { return n <= 16 ? 40000L : 400000L; }

/* Two phases per start: first get the discrepancy down (OBJ_PLATEAU), then,
 * never giving back discrepancy, drive the spread up (OBJ_CRITERION).  The
 * best pattern under the criterion over all starts wins; ties keep the
 * earlier start. */
static void search_heuristic(int n, int *best)
{
    int p[NMAX], phase1[NMAX], cand[NMAX];
    rng r = { SEARCH_SEED };
    uint64_t best_key;

    search_structured(n, best);
    best_key = key_bounded(n, best, UINT64_MAX - 1, OBJ_CRITERION);
    for (int start = 0; start < SEARCH_STARTS; start++) {
        uint64_t key;
        if (start == 0) {
            copy_pattern(n, p, best);
        } else {
            for (int s = 0; s < n; s++)
                p[s] = s;
            for (int s = n - 1; s > 0; s--) {
                int j = (int)rng_below(&r, (uint32_t)s + 1);
                int t = p[s];
                p[s] = p[j];
                p[j] = t;
            }
        }
        lahc(n, p, plateau_iters(n), SEARCH_HIST, OBJ_PLATEAU, &r, phase1);
        key = lahc(n, phase1, spread_iters(n), SEARCH_HIST, OBJ_CRITERION, &r, cand);
        if (key < best_key) {
            best_key = key;
            copy_pattern(n, best, cand);
        }
    }
}

ef_status ef_pattern_search(int n, uint8_t *k_out, ef_pattern_score *score)
{
    int best[NMAX] = { 0 };
    if (!ef_samples_valid(n) || !k_out)
        return EF_ERR_ARG;
    if (n == 8)
        search_exhaustive(n, best);
    else
        search_heuristic(n, best);
    canonical_ints(n, best, best);
    for (int s = 0; s < n; s++)
        k_out[s] = (uint8_t)best[s];
    if (score)
        score_ints(n, best, score);
    return EF_OK;
}
