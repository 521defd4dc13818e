/*
 * gen_random.c - the seeded random cases of `edgeflag gen` (docs/gen.md
 * section 6).
 *
 * Random case j draws everything from one splitmix64 stream seeded with
 * ef_gen_case_seed(seed, j), in a fixed order, with integer arithmetic only:
 * a canvas (mostly small, some up to 16384 on one side), 1..12 shapes of
 * either rule and any colour and alpha, and contours of ten kinds --
 * uniform random (self-intersecting), snapped to a sample grid (with
 * +-1-unit nudges), on half pixels, rectilinear, stars and polygons from an
 * integer cosine table, random walks, far-outside vertices, sub-pixel tiny
 * ones, slivers, and repeats of the previous contour (coincident edges,
 * sometimes 126..130 times: winding overflow).  Vertices are sometimes
 * repeated (zero-length edges).  A range draw is `next mod n`: its bias
 * (< n / 2^64) is irrelevant, and it is the same on every platform.
 */
#include "gen_internal.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Points per random case, at most: keeps every file small (well under 1 MiB). */
#define MAX_POINTS 20000u

typedef struct rng {
    uint64_t s;
} rng;

static uint64_t next(rng *r) { return ef_gen_splitmix64(&r->s); }
/* 0 .. n-1 (n >= 1). */
static uint32_t below(rng *r, uint32_t n) { return (uint32_t)(next(r) % n); }
/* lo .. hi inclusive (lo <= hi). */
static int32_t between(rng *r, int32_t lo, int32_t hi)
{
    return (int32_t)((int64_t)lo + (int64_t)(next(r) % (uint64_t)((int64_t)hi - lo + 1)));
}
static int chance(rng *r, uint32_t percent) { return below(r, 100) < percent; }

static int32_t clamp_lim(int64_t v) { return v < -EF_GEN_LIM ? -EF_GEN_LIM : v > EF_GEN_LIM ? EF_GEN_LIM : (int32_t)v; }

/* round(16384 cos(2 pi i / 32)); sin(2 pi i / 32) = cos32[(i + 24) % 32]. */
static const int32_t cos32[32] = { 16384, 16069,  15137,  13623,  11585,  9102,   6270,   3196,   0,      -3196,  -6270,
                                   -9102, -11585, -13623, -15137, -16069, -16384, -16069, -15137, -13623, -11585, -9102,
                                   -6270, -3196,  0,      3196,   6270,   9102,   11585,  13623,  15137,  16069 };

typedef enum mode {
    M_RANDOM,
    M_SNAP,
    M_HALFPX,
    M_RECTI,
    M_STAR,
    M_WALK,
    M_FAR,
    M_TINY,
    M_SLIVER,
    M_REPEAT,
    M_COUNT
} mode;
static const char *const mode_names[M_COUNT] = { "random", "snap", "half-px", "rectilinear", "star",
                                                 "walk",   "far",  "tiny",    "sliver",      "repeat" };
/* Weights of the contour kinds (out of 100). */
static const uint32_t mode_weight[M_COUNT] = { 22, 14, 8, 10, 10, 8, 8, 6, 7, 7 };

typedef struct rcase {
    rng r;
    ef_genb *b;
    int32_t w, h;           /* canvas, px */
    int32_t x0, x1, y0, y1; /* the "near" box: canvas plus a quarter each side, Q16.8 */
    int grid, gh, gc;       /* snapping grid, h, c */
    const uint8_t *k;
    uint32_t points; /* so far in this case */
    ef_point *prev;  /* the previous contour of the current shape */
    uint32_t nprev, capprev;
    ef_point *cur; /* the contour being made */
    uint32_t ncur, capcur;
    ef_status st;
} rcase;

static void push(rcase *c, int64_t x, int64_t y)
{
    if (c->st)
        return;
    if (c->ncur == c->capcur) {
        uint32_t nc = c->capcur ? c->capcur * 2 : 64;
        ef_point *p = realloc(c->cur, (size_t)nc * sizeof *p);
        if (!p) {
            c->st = EF_ERR_NOMEM;
            return;
        }
        c->cur = p;
        c->capcur = nc;
    }
    c->cur[c->ncur].x = clamp_lim(x);
    c->cur[c->ncur].y = clamp_lim(y);
    c->ncur++;
}

static int32_t near_x(rcase *c) { return between(&c->r, c->x0, c->x1); }
static int32_t near_y(rcase *c) { return between(&c->r, c->y0, c->y1); }
static int32_t far_v(rcase *c)
{
    if (chance(&c->r, 20))
        return chance(&c->r, 50) ? -EF_GEN_LIM : EF_GEN_LIM;
    return between(&c->r, -EF_GEN_LIM, EF_GEN_LIM);
}
/* A vertex count 3..3+m-1, sometimes up to 200. */
static uint32_t count(rcase *c, uint32_t m) { return 3 + (chance(&c->r, 8) ? below(&c->r, 198) : below(&c->r, m)); }

static void gen_random(rcase *c)
{
    uint32_t n = count(c, 10);
    for (uint32_t i = 0; i < n; i++) {
        int32_t x = near_x(c);
        push(c, x, near_y(c));
    }
}

static void gen_snap(rcase *c)
{
    uint32_t n = count(c, 10);
    int32_t rows = c->grid * c->h;
    for (uint32_t i = 0; i < n; i++) {
        /* one draw per statement: C leaves the order of operands unspecified */
        int64_t x = (int64_t)EF_GEN_PX * between(&c->r, -1, c->w);
        int64_t y;
        x += (int64_t)c->gh * below(&c->r, (uint32_t)c->grid) + c->gc;
        y = (int64_t)c->gh * between(&c->r, -c->grid, rows + c->grid - 1) + c->gc;
        if (chance(&c->r, 15))
            x += chance(&c->r, 50) ? 1 : -1;
        if (chance(&c->r, 15))
            y += chance(&c->r, 50) ? 1 : -1;
        push(c, x, y);
    }
}

static void gen_halfpx(rcase *c)
{
    uint32_t n = count(c, 8);
    for (uint32_t i = 0; i < n; i++) {
        int32_t x = near_x(c) / 128 * 128;
        push(c, x, near_y(c) / 128 * 128);
    }
}

static void gen_recti(rcase *c)
{
    uint32_t m = 2 + below(&c->r, 7);
    int32_t xs[9], ys[9];
    int snap = chance(&c->r, 50);
    for (uint32_t i = 0; i < m; i++) {
        xs[i] = near_x(c);
        ys[i] = near_y(c);
        if (snap) {
            xs[i] = xs[i] / EF_GEN_PX * EF_GEN_PX;
            ys[i] = ys[i] / EF_GEN_PX * EF_GEN_PX;
        }
    }
    /* (x0,y0) (x1,y0) (x1,y1) (x2,y1) ... (x_{m-1},y_{m-1}) (x0,y_{m-1}): all edges axis-aligned */
    for (uint32_t i = 0; i < m; i++) {
        push(c, xs[i], ys[i]);
        push(c, xs[(i + 1) % m], ys[i]);
    }
}

static void gen_star(rcase *c)
{
    static const uint32_t sizes[4] = { 4, 8, 16, 32 };
    uint32_t n = sizes[below(&c->r, 4)];
    uint32_t m = n == 4 ? 1 : 1 + 2 * below(&c->r, n / 4); /* odd, so coprime with n: {n/m} */
    uint32_t rot = below(&c->r, 32), stride = 32 / n;
    int64_t cx = near_x(c), cy = near_y(c);
    int32_t span = (c->w > c->h ? c->w : c->h) * EF_GEN_PX;
    int64_t rx = 1 + below(&c->r, (uint32_t)span), ry = chance(&c->r, 30) ? 1 + below(&c->r, (uint32_t)span) : rx;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t a = (rot + i * m * stride) % 32;
        push(c, cx + rx * cos32[a] / 16384, cy + ry * cos32[(a + 24) % 32] / 16384);
    }
}

static void gen_walk(rcase *c)
{
    uint32_t n = 10 + below(&c->r, 290);
    int64_t x = near_x(c), y = near_y(c);
    for (uint32_t i = 0; i < n; i++) {
        int32_t step = chance(&c->r, 20) ? 512 : 64;
        push(c, x, y);
        x = clamp_lim(x + between(&c->r, -step, step));
        y = clamp_lim(y + between(&c->r, -step, step));
    }
}

static void gen_far(rcase *c)
{
    uint32_t n = 3 + below(&c->r, 6);
    for (uint32_t i = 0; i < n; i++) {
        int32_t x = chance(&c->r, 40) ? far_v(c) : near_x(c);
        int32_t y = chance(&c->r, 40) ? far_v(c) : near_y(c);
        push(c, x, y);
    }
}

static void gen_tiny(rcase *c)
{
    uint32_t n = 3 + below(&c->r, 4);
    int64_t px = (int64_t)EF_GEN_PX * below(&c->r, (uint32_t)c->w);
    int64_t py = (int64_t)EF_GEN_PX * below(&c->r, (uint32_t)c->h);
    for (uint32_t i = 0; i < n; i++) {
        int32_t x = (int32_t)below(&c->r, 256);
        push(c, px + x, py + below(&c->r, 256));
    }
}

static void gen_sliver(rcase *c)
{
    int64_t ax = chance(&c->r, 20) ? far_v(c) : near_x(c), ay = chance(&c->r, 20) ? far_v(c) : near_y(c);
    int64_t bx = near_x(c), by = near_y(c);
    int32_t dx = between(&c->r, -3, 3), dy = between(&c->r, -3, 3);
    if (dx == 0 && dy == 0)
        dx = 1;
    push(c, ax, ay);
    push(c, bx, by);
    push(c, bx + dx, by + dy);
    if (chance(&c->r, 50))
        push(c, ax + dx, ay + dy); /* a thin parallelogram */
}

/* Inserts copies of random vertices: zero-length edges. */
static void add_repeats(rcase *c)
{
    uint32_t extra = 1 + below(&c->r, 3);
    for (uint32_t e = 0; e < extra && !c->st; e++) {
        uint32_t at = below(&c->r, c->ncur);
        ef_point p = c->cur[at];
        push(c, 0, 0);
        if (c->st)
            return;
        memmove(c->cur + at + 1, c->cur + at, (size_t)(c->ncur - 1 - at) * sizeof *c->cur);
        c->cur[at] = p;
    }
}

static void keep_prev(rcase *c)
{
    if (c->st)
        return;
    if (c->ncur > c->capprev) {
        ef_point *p = realloc(c->prev, (size_t)c->ncur * sizeof *p);
        if (!p) {
            c->st = EF_ERR_NOMEM;
            return;
        }
        c->prev = p;
        c->capprev = c->ncur;
    }
    memcpy(c->prev, c->cur, (size_t)c->ncur * sizeof *c->cur);
    c->nprev = c->ncur;
}

/* Adds c->cur to the shape; returns 0 if the point budget refused it. */
static int commit(rcase *c)
{
    if (c->st || c->ncur < 3 || c->points + c->ncur > MAX_POINTS)
        return 0;
    for (uint32_t i = 0; i < c->ncur; i++)
        ef_genb_pt(c->b, c->cur[i].x, c->cur[i].y);
    ef_genb_end(c->b);
    c->points += c->ncur;
    return 1;
}

static mode pick_mode(rcase *c)
{
    uint32_t t = below(&c->r, 100);
    for (int m = 0; m < M_COUNT; m++) {
        if (t < mode_weight[m])
            return (mode)m;
        t -= mode_weight[m];
    }
    return M_RANDOM;
}

/* Appends "s" to desc if it fits, else "..." once. */
static void desc_add(char *desc, size_t size, const char *s)
{
    size_t n = strlen(desc), m = strlen(s);
    if (n + m + 4 < size) {
        memcpy(desc + n, s, m + 1);
    } else if (n + 4 < size && (n < 3 || strcmp(desc + n - 3, "...") != 0)) {
        memcpy(desc + n, "...", 4);
    }
}

ef_status ef_gen_random_build(uint64_t case_seed, ef_scene *s, char *desc, size_t desc_size, int *grid)
{
    rcase c;
    ef_genb b;
    char buf[160], modes[640] = "";
    uint32_t nshapes, ncontours = 0, t;

    memset(&c, 0, sizeof c);
    c.r.s = case_seed;
    c.b = &b;
    *grid = 0;

    /* the canvas: mostly small, some medium, a few very wide or very tall */
    t = below(&c.r, 100);
    if (t < 50) {
        c.w = 1 + (int32_t)below(&c.r, 48);
        c.h = 1 + (int32_t)below(&c.r, 48);
    } else if (t < 80) {
        c.w = 1 + (int32_t)below(&c.r, 256);
        c.h = 1 + (int32_t)below(&c.r, 256);
    } else if (t < 95) {
        c.w = 1 + (int32_t)below(&c.r, 1024);
        c.h = 1 + (int32_t)below(&c.r, 1024);
    } else {
        int32_t big = 1024 + (int32_t)below(&c.r, EF_MAX_CANVAS - 1024 + 1), small = 1 + (int32_t)below(&c.r, 64);
        int wide = chance(&c.r, 50);
        c.w = wide ? big : small;
        c.h = wide ? small : big;
    }
    c.x0 = -c.w * (EF_GEN_PX / 4) - EF_GEN_PX;
    c.x1 = c.w * (EF_GEN_PX * 5 / 4) + EF_GEN_PX;
    c.y0 = -c.h * (EF_GEN_PX / 4) - EF_GEN_PX;
    c.y1 = c.h * (EF_GEN_PX * 5 / 4) + EF_GEN_PX;
    c.grid = 8 << below(&c.r, 3);
    c.gh = EF_GEN_PX / c.grid;
    c.gc = c.gh / 2;
    c.k = ef_pattern(c.grid);

    ef_genb_init(&b, s, 0, 0);
    ef_genb_canvas(&b, c.w, c.h);

    t = below(&c.r, 100);
    nshapes = t < 40 ? 1 : t < 70 ? 2 : t < 88 ? 3 : t < 98 ? 4 : 5 + below(&c.r, 8);
    for (uint32_t si = 0; si < nshapes && !c.st && !b.st; si++) {
        ef_rule rule = chance(&c.r, 50) ? EF_RULE_EVENODD : EF_RULE_NONZERO;
        uint8_t r = (uint8_t)below(&c.r, 256), g = (uint8_t)below(&c.r, 256), bl = (uint8_t)below(&c.r, 256), a;
        uint32_t nc;
        t = below(&c.r, 20);
        a = t < 10 ? 255 : t < 17 ? (uint8_t)(1 + below(&c.r, 254)) : t == 17 ? 128 : t == 18 ? 1 : 0;
        ef_genb_shape(&b, rule, r, g, bl, a);
        t = below(&c.r, 10);
        nc = t < 5 ? 1 : t < 8 ? 2 : t < 9 ? 3 : 4 + below(&c.r, 5);
        c.nprev = 0;
        for (uint32_t ci = 0; ci < nc && !c.st && !b.st; ci++) {
            mode m = pick_mode(&c);
            uint32_t copies = 1;
            int reversed = 0;
            if (m == M_REPEAT && c.nprev == 0)
                m = M_RANDOM;
            c.ncur = 0;
            switch (m) {
            case M_RANDOM: gen_random(&c); break;
            case M_SNAP: gen_snap(&c); break;
            case M_HALFPX: gen_halfpx(&c); break;
            case M_RECTI: gen_recti(&c); break;
            case M_STAR: gen_star(&c); break;
            case M_WALK: gen_walk(&c); break;
            case M_FAR: gen_far(&c); break;
            case M_TINY: gen_tiny(&c); break;
            case M_SLIVER: gen_sliver(&c); break;
            case M_REPEAT:
            default:
                copies = chance(&c.r, 90) ? 1 + below(&c.r, 3) : 126 + below(&c.r, 5);
                reversed = chance(&c.r, 50);
                for (uint32_t i = 0; i < c.nprev; i++) {
                    const ef_point *p = &c.prev[reversed ? c.nprev - 1 - i : i];
                    push(&c, p->x, p->y);
                }
                break;
            }
            if (m != M_REPEAT && chance(&c.r, 10))
                add_repeats(&c);
            if (c.st)
                break;
            {
                uint32_t done = 0;
                while (done < copies && commit(&c))
                    done++;
                if (done == 0)
                    continue; /* over the point budget: left out */
                if (m == M_SNAP)
                    snprintf(buf, sizeof buf, "%s%s/%d", ncontours ? ", " : "", mode_names[m], c.grid);
                else if (m == M_REPEAT)
                    snprintf(buf, sizeof buf, "%s%s x%" PRIu32 "%s", ncontours ? ", " : "", mode_names[m], done,
                             reversed ? " reversed" : "");
                else
                    snprintf(buf, sizeof buf, "%s%s", ncontours ? ", " : "", mode_names[m]);
                ncontours++;
                desc_add(modes, sizeof modes, buf);
            }
            if (m != M_REPEAT)
                keep_prev(&c);
        }
    }
    if (!c.st)
        c.st = b.st;
    snprintf(desc, desc_size,
             "Random: %" PRId32 " x %" PRId32 " canvas, %" PRIu32 " shape%s, %" PRIu32 " contour%s, %" PRIu32
             " points; contours: ",
             c.w, c.h, s->nshapes, s->nshapes == 1 ? "" : "s", s->ncontours, s->ncontours == 1 ? "" : "s", s->npoints);
    desc_add(desc, desc_size, modes);
    desc_add(desc, desc_size, ".");
    ef_genb_free(&b);
    free(c.cur);
    free(c.prev);
    return c.st;
}
