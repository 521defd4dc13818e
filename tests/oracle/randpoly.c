/*
 * randpoly.c - seeded generator of nasty random polygons (see randpoly.h and
 * docs/oracle.md).  Only integer arithmetic; deterministic across platforms.
 */
#include "randpoly.h"

#include <stdlib.h>
#include <string.h>

#define COORD_MAX (((int64_t)1 << 23) - 1)

/* ------------------------------------------------------------------ PRNG */
void eo_rng_seed(eo_rng *g, uint64_t seed) { g->state = seed; }

uint64_t eo_rng_next(eo_rng *g)
{
    uint64_t z = (g->state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

uint64_t eo_rng_below(eo_rng *g, uint64_t n)
{
    if (n <= 1)
        return 0;
    /* reject the lowest (2^64 mod n) values so that x mod n is uniform */
    uint64_t threshold = (0 - n) % n, x;
    do
        x = eo_rng_next(g);
    while (x < threshold);
    return x % n;
}

int64_t eo_rng_range(eo_rng *g, int64_t lo, int64_t hi)
{
    if (hi <= lo)
        return lo;
    return lo + (int64_t)eo_rng_below(g, (uint64_t)(hi - lo) + 1);
}

int eo_rng_percent(eo_rng *g, unsigned pct) { return eo_rng_below(g, 100) < pct; }

const char *eo_rp_kind_name(unsigned kind_bit)
{
    switch (kind_bit) {
    case EO_RP_RANDOM: return "random";
    case EO_RP_GRID: return "grid";
    case EO_RP_RECT: return "rect";
    case EO_RP_ORTHO: return "ortho";
    case EO_RP_DEGEN: return "degenerate";
    case EO_RP_SLOPE: return "slope";
    case EO_RP_FAR: return "far";
    case EO_RP_WOUND: return "wound";
    case EO_RP_TINY: return "tiny";
    case EO_RP_BORDER: return "border";
    case EO_RP_SHARED: return "shared";
    default: return "?";
    }
}

/* ------------------------------------------------------------- storage */
void eo_randpoly_init(eo_randpoly *rp) { memset(rp, 0, sizeof *rp); }

void eo_randpoly_free(eo_randpoly *rp)
{
    free(rp->pts);
    free(rp->start);
    memset(rp, 0, sizeof *rp);
}

eo_polygon eo_randpoly_view(const eo_randpoly *rp)
{
    eo_polygon p;
    p.pts = rp->pts;
    p.start = rp->start;
    p.ncontours = rp->ncontours;
    return p;
}

typedef struct gen {
    eo_rng g;
    int W, H;
    int samples_opt; /* 0: mix */
    uint32_t max_points;
    eo_randpoly *rp;
    int nomem;
} gen;

static int64_t clampc(int64_t v) { return v < -COORD_MAX ? -COORD_MAX : v > COORD_MAX ? COORD_MAX : v; }

static uint32_t room(const gen *G) { return G->max_points - G->rp->npoints; }

static void push(gen *G, int64_t x, int64_t y)
{
    eo_randpoly *rp = G->rp;
    if (G->nomem || rp->npoints >= G->max_points)
        return;
    if (rp->npoints == rp->pts_cap) {
        uint32_t cap = rp->pts_cap ? 2 * rp->pts_cap : 64;
        eo_point *np = realloc(rp->pts, (size_t)cap * sizeof *np);
        if (!np) {
            G->nomem = 1;
            return;
        }
        rp->pts = np;
        rp->pts_cap = cap;
    }
    rp->pts[rp->npoints].x = (int32_t)clampc(x);
    rp->pts[rp->npoints].y = (int32_t)clampc(y);
    rp->npoints++;
}

/* Closes the contour begun at start[ncontours] (empty contours are kept: they
 * are legal input and contribute nothing). */
static void end_contour(gen *G, unsigned kind)
{
    eo_randpoly *rp = G->rp;
    if (G->nomem)
        return;
    if (rp->ncontours + 2 > rp->start_cap) {
        uint32_t cap = rp->start_cap ? 2 * rp->start_cap : 16;
        uint32_t *ns = realloc(rp->start, (size_t)cap * sizeof *ns);
        if (!ns) {
            G->nomem = 1;
            return;
        }
        rp->start = ns;
        rp->start_cap = cap;
    }
    rp->ncontours++;
    rp->start[rp->ncontours] = rp->npoints;
    rp->kinds_used |= kind;
}

static int64_t rnd(gen *G, int64_t lo, int64_t hi) { return eo_rng_range(&G->g, lo, hi); }
static int pct(gen *G, unsigned p) { return eo_rng_percent(&G->g, p); }

static int pick_n(gen *G)
{
    static const int ns[3] = { 8, 16, 32 };
    return G->samples_opt ? G->samples_opt : ns[eo_rng_below(&G->g, 3)];
}

/* A sample column of N's grid: 256 i + h k + c, i in [-1, W], k in [0, N). */
static int64_t grid_x(gen *G, int N)
{
    int64_t h = 256 / N;
    return 256 * rnd(G, -1, G->W) + h * rnd(G, 0, N - 1) + h / 2;
}

/* A sample row of N's grid: h r + c, r in [-N, N*H + N). */
static int64_t grid_y(gen *G, int N)
{
    int64_t h = 256 / N;
    return h * rnd(G, -N, (int64_t)N * G->H + N - 1) + h / 2;
}

/* One coordinate on an axis of length L = 256 * pixels (x: W, y: H):
 *   28% uniform in [-512, L + 512]      (near the canvas)
 *   10% uniform in [0, L)               (inside)
 *   15% on a sample row/column of some N
 *   10% on a pixel border 256 i, i in [-1, pixels + 1]
 *   10% exactly on the clip border, 0 or L
 *   10% a sample row/column or border +-1 or +-2 (just off a tie)
 *    7% uniform in [-L - 4096, 2L + 4096] (moderately outside)
 *    6% uniform over the whole range [-(2^23-1), 2^23-1]
 *    4% an extreme, +-(2^23-1) or +-(2^23-2)                               */
static int64_t coord(gen *G, int axis)
{
    int64_t pixels = axis ? G->H : G->W, L = 256 * pixels;
    int64_t u = rnd(G, 0, 99), v;
    if (u < 28)
        v = rnd(G, -512, L + 512);
    else if (u < 38)
        v = rnd(G, 0, L - 1);
    else if (u < 53) {
        int N = pick_n(G);
        v = axis ? grid_y(G, N) : grid_x(G, N);
    } else if (u < 63)
        v = 256 * rnd(G, -1, pixels + 1);
    else if (u < 73)
        v = pct(G, 50) ? 0 : L;
    else if (u < 83) {
        int N = pick_n(G);
        int64_t b = pct(G, 70) ? (axis ? grid_y(G, N) : grid_x(G, N)) : (pct(G, 50) ? 0 : L);
        v = b + (pct(G, 50) ? 1 : -1) * rnd(G, 1, 2);
    } else if (u < 90)
        v = rnd(G, -L - 4096, 2 * L + 4096);
    else if (u < 96)
        v = rnd(G, -COORD_MAX, COORD_MAX);
    else
        v = (pct(G, 50) ? 1 : -1) * (COORD_MAX - rnd(G, 0, 1));
    return clampc(v);
}

static int64_t near_coord(gen *G, int axis)
{
    int64_t L = 256 * (int64_t)(axis ? G->H : G->W);
    return rnd(G, -256, L + 256);
}

/* ------------------------------------------------------------ contour kinds */
static void k_random(gen *G)
{
    int64_t n = rnd(G, 3, 12), px = 0, py = 0;
    for (int64_t i = 0; i < n; i++) {
        if (i > 0 && pct(G, 12)) {
            push(G, px, py); /* zero-length edge */
            continue;
        }
        px = coord(G, 0);
        py = coord(G, 1);
        push(G, px, py);
    }
    end_contour(G, EO_RP_RANDOM);
}

static void k_grid(gen *G)
{
    int N = pick_n(G);
    int64_t h = 256 / N, c = h / 2, n = rnd(G, 3, 10);
    const uint8_t *k = eo_pattern(N);
    for (int64_t q = 0; q < n; q++) {
        int64_t r = rnd(G, -N, (int64_t)N * G->H + N - 1);
        int64_t s = ((r % N) + N) % N;
        int64_t kk = pct(G, 50) ? k[s] : rnd(G, 0, N - 1); /* 50%: exactly on a sample */
        push(G, 256 * rnd(G, -1, G->W) + h * kk + c, h * r + c);
    }
    end_contour(G, EO_RP_GRID);
}

static void rect(gen *G, int64_t x0, int64_t y0, int64_t x1, int64_t y1, unsigned kind)
{
    int64_t xs[4] = { x0, x1, x1, x0 }, ys[4] = { y0, y0, y1, y1 };
    int rev = pct(G, 50);
    int64_t rot = rnd(G, 0, 3);
    for (int64_t i = 0; i < 4; i++) {
        int64_t q = rev ? (rot + 4 - i) % 4 : (rot + i) % 4;
        push(G, xs[q], ys[q]);
    }
    end_contour(G, kind);
}

static void k_rect(gen *G) { rect(G, coord(G, 0), coord(G, 1), coord(G, 0), coord(G, 1), EO_RP_RECT); }

static void k_ortho(gen *G)
{
    int64_t steps = rnd(G, 2, 8);
    int64_t x0 = coord(G, 0), y0 = coord(G, 1), x = x0, y = y0;
    push(G, x, y);
    for (int64_t i = 0; i < steps; i++) {
        if (i % 2 == 0)
            x = coord(G, 0);
        else
            y = coord(G, 1);
        push(G, x, y);
    }
    push(G, x0, y); /* the closing edges (x0,y)->(x0,y0) and this one are axis-aligned */
    end_contour(G, EO_RP_ORTHO);
}

static void k_degen(gen *G)
{
    int64_t sub = rnd(G, 0, 5);
    int64_t ax = coord(G, 0), ay = coord(G, 1);
    switch (sub) {
    case 0: /* one point */ push(G, ax, ay); break;
    case 1: /* two points: an edge and its reverse */
        push(G, ax, ay);
        push(G, coord(G, 0), coord(G, 1));
        break;
    case 2: { /* the same point repeated */
        int64_t n = rnd(G, 2, 6);
        for (int64_t i = 0; i < n; i++)
            push(G, ax, ay);
        break;
    }
    case 3: { /* collinear points A + t D, t in [-6, 6]: zero area, passes back and forth */
        int64_t dx = rnd(G, -300, 300), dy = rnd(G, -300, 300), n = rnd(G, 3, 8);
        if (pct(G, 30))
            dx = 0; /* vertical line */
        else if (pct(G, 30)) {
            int64_t hh = 256 / pick_n(G);
            dy = hh * rnd(G, -3, 3); /* steps of whole sample rows */
            dx = pct(G, 50) ? dy : -dy;
        }
        for (int64_t i = 0; i < n; i++) {
            int64_t t = rnd(G, -6, 6);
            push(G, ax + t * dx, ay + t * dy);
        }
        break;
    }
    case 4: { /* triangle with repeated vertices (zero-length edges) */
        int64_t bx = coord(G, 0), by = coord(G, 1), cx = near_coord(G, 0), cy = near_coord(G, 1);
        push(G, ax, ay);
        push(G, ax, ay);
        push(G, bx, by);
        push(G, bx, by);
        push(G, bx, by);
        push(G, cx, cy);
        if (pct(G, 50))
            push(G, ax, ay); /* last == first: zero-length closing edge */
        break;
    }
    default: { /* back and forth: A B A B ... (coincident opposite edges) */
        int64_t bx = coord(G, 0), by = coord(G, 1), n = 2 * rnd(G, 1, 4);
        for (int64_t i = 0; i < n; i++)
            push(G, i % 2 ? bx : ax, i % 2 ? by : ay);
        break;
    }
    }
    end_contour(G, EO_RP_DEGEN);
}

static void k_slope(gen *G)
{
    int N = pick_n(G);
    int64_t h = 256 / N, c = h / 2, n = rnd(G, 3, 8);
    const uint8_t *k = eo_pattern(N);
    int64_t r = rnd(G, -N, (int64_t)N * G->H + N - 1), s = ((r % N) + N) % N;
    int64_t x = 256 * rnd(G, -1, G->W) + h * k[s] + c, y = h * r + c;
    push(G, x, y);
    for (int64_t i = 1; i < n; i++) {
        int64_t m = rnd(G, 1, 3 * (int64_t)N), dy = h * m * (pct(G, 50) ? 1 : -1), dx;
        int64_t t = rnd(G, 0, 5);
        if (t <= 1)
            dx = t ? dy : -dy; /* +-1 sample column per sample row */
        else if (t == 2)
            dx = (pct(G, 50) ? 256 : -256) * m; /* +-1 pixel per sample row */
        else if (t == 3)
            dx = 0; /* vertical */
        else if (t == 4) {
            dx = h * rnd(G, -3 * (int64_t)N, 3 * (int64_t)N);
            dy = 0; /* horizontal */
        } else
            dx = (pct(G, 50) ? 1 : -1) * (dy < 0 ? -dy : dy) / 2; /* half a column per row */
        x += dx;
        y += dy;
        push(G, x, y);
    }
    end_contour(G, EO_RP_SLOPE);
}

static int64_t far_coord(gen *G)
{
    if (pct(G, 30))
        return (pct(G, 50) ? 1 : -1) * COORD_MAX;
    return rnd(G, -COORD_MAX, COORD_MAX);
}

static void k_far(gen *G)
{
    if (pct(G, 25)) { /* a huge triangle or quad around everything */
        int64_t e = COORD_MAX - rnd(G, 0, 1000);
        push(G, -e, -e);
        if (pct(G, 50))
            push(G, e, -e);
        push(G, e, e);
        push(G, -e + rnd(G, 0, 3), e);
    } else {
        int64_t n = rnd(G, 3, 8);
        for (int64_t i = 0; i < n; i++) {
            int64_t u = rnd(G, 0, 3);
            if (u == 0)
                push(G, far_coord(G), far_coord(G));
            else if (u == 1)
                push(G, far_coord(G), near_coord(G, 1));
            else if (u == 2)
                push(G, near_coord(G, 0), far_coord(G));
            else
                push(G, coord(G, 0), coord(G, 1));
        }
    }
    end_contour(G, EO_RP_FAR);
}

/* A small base contour, reproduced m times: in one contour (the point list
 * repeated, so every edge occurs m times), as m separate contours, or with
 * some copies reversed.  m is drawn around the 7-bit limits. */
static void k_wound(gen *G)
{
    static const int64_t ms[] = { 2, 3, 63, 64, 65, 127, 128, 129, 191, 192, 255, 256, 257 };
    int64_t bn = rnd(G, 3, 4), bx[4], by[4];
    if (pct(G, 40)) { /* a rectangle, so the wrap covers whole pixels */
        int64_t x0 = near_coord(G, 0), y0 = near_coord(G, 1), x1 = near_coord(G, 0), y1 = near_coord(G, 1);
        bn = 4;
        bx[0] = x0;
        by[0] = y0;
        bx[1] = x1;
        by[1] = y0;
        bx[2] = x1;
        by[2] = y1;
        bx[3] = x0;
        by[3] = y1;
    } else
        for (int64_t i = 0; i < bn; i++) {
            bx[i] = pct(G, 80) ? near_coord(G, 0) : coord(G, 0);
            by[i] = pct(G, 80) ? near_coord(G, 1) : coord(G, 1);
        }
    int64_t m = pct(G, 75) ? ms[eo_rng_below(&G->g, sizeof ms / sizeof ms[0])] : rnd(G, 2, 300);
    if (m * bn > (int64_t)room(G))
        m = (int64_t)room(G) / bn;
    if (m < 1) {
        end_contour(G, EO_RP_WOUND); /* no room: an empty contour */
        return;
    }
    int64_t mode = rnd(G, 0, 2);
    int64_t nrev = mode == 2 ? rnd(G, 0, m) : 0; /* copies reversed */
    if (mode == 0) {
        for (int64_t q = 0; q < m; q++)
            for (int64_t i = 0; i < bn; i++)
                push(G, bx[i], by[i]);
        end_contour(G, EO_RP_WOUND);
    } else {
        for (int64_t q = 0; q < m; q++) {
            int rev = q < nrev;
            for (int64_t i = 0; i < bn; i++)
                push(G, bx[rev ? bn - 1 - i : i], by[rev ? bn - 1 - i : i]);
            end_contour(G, EO_RP_WOUND);
        }
    }
}

static void k_tiny(gen *G)
{
    int N = pick_n(G);
    int64_t h = 256 / N, n = rnd(G, 3, 6);
    const uint8_t *k = eo_pattern(N);
    int64_t r = rnd(G, 0, (int64_t)N * G->H - 1), s = r % N;
    int64_t cx = 256 * rnd(G, 0, G->W - 1) + h * k[s] + h / 2, cy = h * r + h / 2;
    for (int64_t i = 0; i < n; i++)
        push(G, cx + rnd(G, -h - 1, h + 1), cy + rnd(G, -h - 1, h + 1));
    end_contour(G, EO_RP_TINY);
}

static void k_border(gen *G)
{
    int64_t LW = 256 * (int64_t)G->W, LH = 256 * (int64_t)G->H;
    switch (rnd(G, 0, 4)) {
    case 0: /* the whole canvas */ rect(G, 0, 0, LW, LH, EO_RP_BORDER); return;
    case 1: /* spans x = 0 .. 256W over random rows */ rect(G, 0, coord(G, 1), LW, coord(G, 1), EO_RP_BORDER); return;
    case 2: /* spans y = 0 .. 256H over random columns */
        rect(G, coord(G, 0), 0, coord(G, 0), LH, EO_RP_BORDER);
        return;
    case 3: { /* triangle with a vertical edge on a side border */
        int64_t bx = pct(G, 50) ? 0 : LW;
        push(G, bx, coord(G, 1));
        push(G, bx, coord(G, 1));
        push(G, coord(G, 0), coord(G, 1));
        break;
    }
    default: { /* triangle with a horizontal edge on the top or bottom border */
        int64_t by = pct(G, 50) ? 0 : LH;
        push(G, coord(G, 0), by);
        push(G, coord(G, 0), by);
        push(G, coord(G, 0), coord(G, 1));
        break;
    }
    }
    end_contour(G, EO_RP_BORDER);
}

/* m triangles (A, B, C_i): edge AB occurs m times. */
static void k_shared(gen *G)
{
    int64_t ax = coord(G, 0), ay = coord(G, 1), bx = near_coord(G, 0), by = near_coord(G, 1);
    int64_t m = pct(G, 50) ? rnd(G, 2, 8) : rnd(G, 60, 200);
    if (3 * m > (int64_t)room(G))
        m = (int64_t)room(G) / 3;
    if (m < 1) {
        end_contour(G, EO_RP_SHARED);
        return;
    }
    for (int64_t q = 0; q < m; q++) {
        push(G, ax, ay);
        push(G, bx, by);
        push(G, near_coord(G, 0), near_coord(G, 1));
        end_contour(G, EO_RP_SHARED);
    }
}

/* ---------------------------------------------------------------- driver */
typedef void (*kind_fn)(gen *);
static const struct {
    unsigned bit;
    unsigned weight;
    kind_fn fn;
} kinds[EO_RP_NKINDS] = {
    { EO_RP_RANDOM, 20, k_random }, { EO_RP_GRID, 12, k_grid },    { EO_RP_RECT, 10, k_rect },
    { EO_RP_ORTHO, 8, k_ortho },    { EO_RP_DEGEN, 10, k_degen },  { EO_RP_SLOPE, 10, k_slope },
    { EO_RP_FAR, 8, k_far },        { EO_RP_WOUND, 6, k_wound },   { EO_RP_TINY, 6, k_tiny },
    { EO_RP_BORDER, 6, k_border },  { EO_RP_SHARED, 4, k_shared },
};

int eo_randpoly_gen(eo_randpoly *rp, uint64_t seed, int W, int H, const eo_randpoly_opts *opts)
{
    if (!rp || W < 1 || H < 1 || W > EO_MAX_CANVAS || H > EO_MAX_CANVAS)
        return EO_ERR_ARG;
    gen G;
    memset(&G, 0, sizeof G);
    eo_rng_seed(&G.g, seed);
    G.W = W;
    G.H = H;
    G.rp = rp;
    G.samples_opt = opts ? opts->samples : 0;
    if (G.samples_opt != 0 && G.samples_opt != 8 && G.samples_opt != 16 && G.samples_opt != 32)
        return EO_ERR_ARG;
    G.max_points = opts && opts->max_points ? opts->max_points : 1024;
    uint32_t max_contours = opts && opts->max_contours ? opts->max_contours : 6;
    unsigned allowed = opts && opts->kinds ? opts->kinds & EO_RP_ALL : EO_RP_ALL;
    if (!allowed)
        return EO_ERR_ARG;

    rp->npoints = 0;
    rp->ncontours = 0;
    rp->kinds_used = 0;
    if (!rp->start) {
        rp->start = malloc(16 * sizeof *rp->start);
        if (!rp->start)
            return EO_ERR_NOMEM;
        rp->start_cap = 16;
    }
    rp->start[0] = 0;

    /* contours: 45% one, 30% two or three, 25% up to max_contours */
    uint64_t u = eo_rng_below(&G.g, 100), nc;
    if (u < 45)
        nc = 1;
    else if (u < 75)
        nc = 2 + eo_rng_below(&G.g, 2);
    else
        nc = 1 + eo_rng_below(&G.g, max_contours);
    if (nc > max_contours)
        nc = max_contours;

    unsigned total = 0;
    for (int q = 0; q < EO_RP_NKINDS; q++)
        if (allowed & kinds[q].bit)
            total += kinds[q].weight;
    for (uint64_t c = 0; c < nc && room(&G) > 0 && !G.nomem; c++) {
        uint64_t pick = eo_rng_below(&G.g, total);
        for (int q = 0; q < EO_RP_NKINDS; q++) {
            if (!(allowed & kinds[q].bit))
                continue;
            if (pick < kinds[q].weight) {
                kinds[q].fn(&G);
                break;
            }
            pick -= kinds[q].weight;
        }
    }
    return G.nomem ? EO_ERR_NOMEM : EO_OK;
}

/* W, H: 30% in 1..8, 45% in 9..40, 20% in 41..100, 5% in 101..200 (each
 * independently); N uniform over {8, 16, 32}; rule uniform. */
void eo_rand_config(eo_rng *g, int *W, int *H, int *samples, int *rule_evenodd)
{
    static const int ns[3] = { 8, 16, 32 };
    for (int d = 0; d < 2; d++) {
        uint64_t u = eo_rng_below(g, 100);
        int64_t v = u < 30   ? eo_rng_range(g, 1, 8)
                    : u < 75 ? eo_rng_range(g, 9, 40)
                    : u < 95 ? eo_rng_range(g, 41, 100)
                             : eo_rng_range(g, 101, 200);
        if (d == 0)
            *W = (int)v;
        else
            *H = (int)v;
    }
    *samples = ns[eo_rng_below(g, 3)];
    *rule_evenodd = (int)eo_rng_below(g, 2);
}
