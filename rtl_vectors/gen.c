/*
 * gen.c - the scene generator's frame: configuration and levels, global case
 * numbering and shards, the splitmix64 PRNG, the scene builder, and the
 * exact text of a case file and of index.tsv (docs/gen.md).
 *
 * Numbering: cases 0 .. D-1 are the directed table (gen_cases.c) expanded
 * per level -- row by row, each grid-dependent row once per grid (8, 16, 32
 * in that order), each level-2 row then again with its rules swapped; cases
 * D .. D+R-1 are random case j = k - D (gen_random.c), seeded with
 * ef_gen_case_seed(seed, j).  So raising the random count only appends
 * cases, and shard I/N (k mod N == I-1) is an exact partition.
 *
 * Integer-only and locale-free: numbers are formatted by hand, never with
 * printf's %f, and nothing depends on the clock, a path or the platform.
 */
#include "gen_internal.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ PRNG */

uint64_t ef_gen_splitmix64(uint64_t *state)
{
    uint64_t z = (*state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

uint64_t ef_gen_case_seed(uint64_t seed, uint32_t j)
{
    /* The stream's state before output j is seed + j * gamma (mod 2^64). */
    uint64_t st = seed + (uint64_t)j * UINT64_C(0x9E3779B97F4A7C15);
    return ef_gen_splitmix64(&st);
}

/* ------------------------------------------------------------ categories */

static const char *const cat_names[EF_GEN_NCATEGORIES] = {
    "sample-grid",   "horizontal", "vertical",         "zero-length",  "slope",   "degenerate",
    "coincident",    "cancel",     "winding-overflow", "coord-limits", "outside", "clip-border",
    "edges-per-row", "canvas",     "compositing",      "random",
};

const char *ef_gen_category_name(ef_gen_category c) { return (unsigned)c < EF_GEN_NCATEGORIES ? cat_names[c] : NULL; }

/* --------------------------------------------------------- configuration */

uint32_t ef_gen_level_random(int level)
{
    return level == 1 ? EF_GEN_LEVEL1_RANDOM : level == 2 ? EF_GEN_LEVEL2_RANDOM : 0;
}

ef_status ef_gen_config_defaults(ef_gen_config *c, int level)
{
    memset(c, 0, sizeof *c);
    c->seed = EF_GEN_DEFAULT_SEED;
    c->level = level;
    c->grid = 0;
    c->rules_swapped = level == 2;
    c->nrandom = ef_gen_level_random(level);
    return c->nrandom ? EF_OK : EF_ERR_ARG;
}

/* The grids a grid-dependent row is built at, in order; returns how many. */
static int grids_of(const ef_gen_config *c, int out[3])
{
    if (c->grid) {
        out[0] = c->grid;
        return 1;
    }
    if (c->level == 1) {
        out[0] = 16;
        return 1;
    }
    out[0] = 8;
    out[1] = 16;
    out[2] = 32;
    return 3;
}

static int row_in_level(const ef_gen_config *c, const ef_gen_dcase *d)
{
    return !(d->flags & EF_GEN_F_LEVEL2) || c->level >= 2;
}

static int row_swaps(const ef_gen_config *c, const ef_gen_dcase *d)
{
    return c->rules_swapped && c->level >= 2 && !(d->flags & EF_GEN_F_NOSWAP) ? 2 : 1;
}

/* Directed case number d -> (row, grid, swap); 0 if d is past the table. */
static int directed_locate(const ef_gen_config *c, uint32_t d, const ef_gen_dcase **row, int *grid, int *swap)
{
    int grids[3], ng = grids_of(c, grids);
    for (uint32_t i = 0; i < ef_gen_ndcases; i++) {
        const ef_gen_dcase *r = &ef_gen_dcases[i];
        if (!row_in_level(c, r))
            continue;
        int gn = (r->flags & EF_GEN_F_GRID) ? ng : 1;
        int sn = row_swaps(c, r);
        uint32_t n = (uint32_t)(gn * sn);
        if (d < n) {
            *row = r;
            *grid = (r->flags & EF_GEN_F_GRID) ? grids[d / (uint32_t)sn] : 0;
            *swap = (int)(d % (uint32_t)sn);
            return 1;
        }
        d -= n;
    }
    return 0;
}

uint32_t ef_gen_directed_count(const ef_gen_config *c)
{
    int grids[3], ng = grids_of(c, grids);
    uint32_t n = 0;
    for (uint32_t i = 0; i < ef_gen_ndcases; i++) {
        const ef_gen_dcase *r = &ef_gen_dcases[i];
        if (row_in_level(c, r))
            n += (uint32_t)(((r->flags & EF_GEN_F_GRID) ? ng : 1) * row_swaps(c, r));
    }
    return n;
}

ef_status ef_gen_config_check(const ef_gen_config *c)
{
    if (c->level != 1 && c->level != 2)
        return EF_ERR_ARG;
    if (c->grid != 0 && !ef_samples_valid(c->grid))
        return EF_ERR_ARG;
    if (c->nrandom < ef_gen_level_random(c->level))
        return EF_ERR_ARG; /* -n can raise the level's count, never lower it */
    if (c->nrandom > EF_GEN_MAX_CASES || ef_gen_directed_count(c) > EF_GEN_MAX_CASES - c->nrandom)
        return EF_ERR_LIMIT;
    return EF_OK;
}

uint32_t ef_gen_total(const ef_gen_config *c) { return ef_gen_directed_count(c) + c->nrandom; }

int ef_gen_in_shard(uint32_t k, uint32_t index, uint32_t count)
{
    return count >= 1 && index >= 1 && index <= count && k % count == index - 1;
}

/* ---------------------------------------------------------------- builder */

void ef_genb_init(ef_genb *b, ef_scene *s, int grid, int swap)
{
    memset(b, 0, sizeof *b);
    b->s = s;
    b->grid = grid;
    b->swap = swap;
    if (grid) {
        b->h = EF_GEN_PX / grid;
        b->c = b->h / 2;
        b->k = ef_pattern(grid);
        if (!b->k)
            b->st = EF_ERR_ARG;
    }
}

void ef_genb_free(ef_genb *b)
{
    free(b->pts);
    b->pts = NULL;
    b->n = b->cap = 0;
}

void ef_genb_canvas(ef_genb *b, int32_t w, int32_t h)
{
    if (b->st)
        return;
    if (w < 1 || h < 1 || w > EF_MAX_CANVAS || h > EF_MAX_CANVAS) {
        b->st = EF_ERR_LIMIT;
        return;
    }
    b->s->width = w;
    b->s->height = h;
}

void ef_genb_shape(ef_genb *b, ef_rule rule, uint8_t r, uint8_t g, uint8_t bl, uint8_t a)
{
    ef_rgba8 col = { r, g, bl, a };
    if (b->st)
        return;
    if (b->swap)
        rule = rule == EF_RULE_EVENODD ? EF_RULE_NONZERO : EF_RULE_EVENODD;
    b->st = ef_scene_begin_shape(b->s, rule, col);
}

void ef_genb_pt(ef_genb *b, int32_t x, int32_t y)
{
    if (b->st)
        return;
    if (x < -EF_GEN_LIM || x > EF_GEN_LIM || y < -EF_GEN_LIM || y > EF_GEN_LIM) {
        b->st = EF_ERR_RANGE;
        return;
    }
    if (b->n == b->cap) {
        uint32_t nc = b->cap ? b->cap * 2 : 64;
        ef_point *p = realloc(b->pts, (size_t)nc * sizeof *p);
        if (!p) {
            b->st = EF_ERR_NOMEM;
            return;
        }
        b->pts = p;
        b->cap = nc;
    }
    b->pts[b->n].x = x;
    b->pts[b->n].y = y;
    b->n++;
}

void ef_genb_end(ef_genb *b)
{
    if (!b->st)
        b->st = b->n < 3 ? EF_ERR_ARG : ef_scene_add_contour(b->s, b->pts, b->n);
    b->n = 0;
}

void ef_genb_rect(ef_genb *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    ef_genb_pt(b, x0, y0);
    ef_genb_pt(b, x1, y0);
    ef_genb_pt(b, x1, y1);
    ef_genb_pt(b, x0, y1);
    ef_genb_end(b);
}

void ef_genb_poly(ef_genb *b, const int32_t *xy, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++)
        ef_genb_pt(b, xy[2 * i], xy[2 * i + 1]);
    ef_genb_end(b);
}

/* ------------------------------------------------------------- one case */

void ef_gen_case_destroy(ef_gen_case *gc) { ef_scene_destroy(&gc->scene); }

ef_status ef_gen_build(const ef_gen_config *c, uint32_t k, ef_gen_case *out)
{
    uint32_t nd;
    ef_status st;

    memset(out, 0, sizeof *out);
    ef_scene_create(&out->scene, 1, 1);
    if (ef_gen_config_check(c) != EF_OK)
        return EF_ERR_ARG;
    nd = ef_gen_directed_count(c);
    if (k >= nd + c->nrandom)
        return EF_ERR_ARG;
    out->number = k;
    out->total = nd + c->nrandom;
    out->expect.overflow = -1;

    if (k < nd) {
        const ef_gen_dcase *row = NULL;
        int grid = 0, swap = 0;
        ef_genb b;
        if (!directed_locate(c, k, &row, &grid, &swap))
            return EF_ERR_ARG;
        out->directed = 1;
        out->index = k;
        out->category = row->cat;
        out->name = row->name;
        out->grid = grid;
        out->rules_swapped = swap;
        if (!swap)
            out->expect = row->expect;
        snprintf(out->desc, sizeof out->desc, "%s%s", row->desc,
                 swap ? " [Rules swapped: every evenodd shape is nonzero and every nonzero one evenodd.]" : "");
        ef_genb_init(&b, &out->scene, grid, swap);
        row->build(&b, row->arg);
        st = b.st;
        ef_genb_free(&b);
        return st;
    }
    out->directed = 0;
    out->index = k - nd;
    out->category = EF_GEN_CAT_RANDOM;
    out->name = "random";
    out->case_seed = ef_gen_case_seed(c->seed, out->index);
    return ef_gen_random_build(out->case_seed, &out->scene, out->desc, sizeof out->desc, &out->grid);
}

/* ------------------------------------------------------------------ text */

void ef_gen_text_destroy(ef_gen_text *t)
{
    free(t->data);
    t->data = NULL;
    t->len = t->cap = 0;
}

static ef_status reserve(ef_gen_text *t, size_t more)
{
    if (t->cap - t->len > more)
        return EF_OK;
    size_t nc = t->cap ? t->cap : 4096;
    while (nc - t->len <= more) {
        if (nc > SIZE_MAX / 2)
            return EF_ERR_NOMEM;
        nc *= 2;
    }
    char *p = realloc(t->data, nc);
    if (!p)
        return EF_ERR_NOMEM;
    t->data = p;
    t->cap = nc;
    return EF_OK;
}

static ef_status put(ef_gen_text *t, const char *s, size_t n)
{
    if (reserve(t, n))
        return EF_ERR_NOMEM;
    memcpy(t->data + t->len, s, n);
    t->len += n;
    t->data[t->len] = '\0';
    return EF_OK;
}

static ef_status puts_(ef_gen_text *t, const char *s) { return put(t, s, strlen(s)); }

ef_status ef_gen_text_append(ef_gen_text *t, const char *s) { return puts_(t, s); }

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static ef_status
putf(ef_gen_text *t, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(buf, sizeof buf, fmt, ap); /* only integers and strings: no locale */
    va_end(ap);
    if (n < 0)
        return EF_ERR_ARG;
    return put(t, buf, (size_t)n < sizeof buf ? (size_t)n : sizeof buf - 1);
}

ef_status ef_gen_append_q8(ef_gen_text *t, int32_t v)
{
    /* v/256 = ip + frac/256 and frac/256 = frac * 390625 / 10^8 exactly. */
    char buf[32];
    uint32_t a = v < 0 ? (uint32_t)0 - (uint32_t)v : (uint32_t)v;
    uint32_t ip = a >> 8, frac = a & 255u;
    int n = snprintf(buf, sizeof buf, "%s%" PRIu32, v < 0 ? "-" : "", ip);
    if (frac) {
        uint32_t f = frac * 390625u; /* < 10^8 */
        char d[9];
        int nd = 8;
        for (int i = 7; i >= 0; i--) {
            d[i] = (char)('0' + f % 10u);
            f /= 10u;
        }
        while (nd > 0 && d[nd - 1] == '0')
            nd--;
        buf[n++] = '.';
        memcpy(buf + n, d, (size_t)nd);
        n += nd;
    }
    return put(t, buf, (size_t)n);
}

/* Writes text as "# " comment lines of at most ~100 columns, broken at spaces. */
static ef_status put_wrapped(ef_gen_text *t, const char *text)
{
    const size_t width = 98;
    ef_status st = EF_OK;
    while (*text && !st) {
        size_t n = strlen(text), cut = n;
        if (n > width) {
            cut = width;
            while (cut > 0 && text[cut] != ' ')
                cut--;
            if (cut == 0)
                cut = width; /* one long word */
        }
        st = puts_(t, "# ");
        if (!st)
            st = put(t, text, cut);
        if (!st)
            st = puts_(t, "\n");
        text += cut;
        while (*text == ' ')
            text++;
    }
    return st;
}

static ef_status put_expect(ef_gen_text *t, const ef_gen_expect *e)
{
    ef_status st = EF_OK;
    if (e->kind == EF_GEN_EXPECT_ANY && e->overflow < 0)
        return EF_OK;
    st = puts_(t, "# expect (any sample count):");
    if (!st && e->kind == EF_GEN_EXPECT_EMPTY)
        st = puts_(t, " every pixel stays 0 0 0 0;");
    else if (!st && e->kind == EF_GEN_EXPECT_FULL)
        st = puts_(t, " every pixel has alpha 255;");
    else if (!st && e->kind == EF_GEN_EXPECT_PROBE)
        st = putf(t, " pixel (%" PRId32 ", %" PRId32 ") has alpha %u;", e->x, e->y, (unsigned)e->alpha);
    if (!st && e->overflow == 1)
        st = puts_(t, " winding overflows counted (docs/spec.md 6.4)");
    else if (!st && e->overflow == 0)
        st = puts_(t, " no winding overflow");
    if (!st && t->len && t->data[t->len - 1] == ';')
        t->len--, t->data[t->len] = '\0';
    return st ? st : puts_(t, "\n");
}

static ef_status put_header(const ef_gen_config *c, const ef_gen_case *gc, ef_gen_text *t)
{
    ef_status st;
    st = putf(t, "# edgeflag gen: generator %d, edgeflag %s (docs/gen.md)\n", EF_GEN_VERSION, EF_VERSION_STRING);
    if (!st)
        st = putf(t,
                  "# seed %" PRIu64 ", level %d, case %" PRIu32 " of %" PRIu32 " (shard I/N holds the cases with "
                  "case mod N = I-1)\n",
                  c->seed, c->level, gc->number, gc->total);
    if (!st && gc->directed) {
        st = putf(t, "# directed case %" PRIu32 " of %" PRIu32 ": %s (%s)", gc->index, ef_gen_directed_count(c),
                  gc->name, ef_gen_category_name(gc->category));
        if (!st && gc->grid)
            st = putf(t, ", built for the %d-sample grid", gc->grid);
        if (!st && gc->rules_swapped)
            st = puts_(t, ", rules swapped");
        if (!st)
            st = puts_(t, "\n");
    } else if (!st) {
        st = putf(t, "# random case %" PRIu32 " of %" PRIu32 ", case seed 0x%016" PRIx64 "\n", gc->index, c->nrandom,
                  gc->case_seed);
    }
    if (!st)
        st = put_wrapped(t, gc->desc);
    if (!st && gc->fit_note[0]) {
        char note[sizeof gc->fit_note + 32];
        snprintf(note, sizeof note, "Fitted to the DUT's limits: %s.", gc->fit_note);
        st = put_wrapped(t, note);
    }
    if (!st)
        st = put_expect(t, &gc->expect);
    if (!st && gc->grid)
        st = putf(t,
                  "# grid: built for %d samples per pixel: sample row r at y = %d r + %d, sample column k of\n"
                  "# pixel i at x = 256 i + %d k + %d (Q16.8 units); any sample count renders it\n",
                  gc->grid, 256 / gc->grid, 128 / gc->grid, 256 / gc->grid, 128 / gc->grid);
    return st;
}

ef_status ef_gen_format(const ef_gen_config *c, const ef_gen_case *gc, ef_gen_text *t)
{
    const ef_scene *s = &gc->scene;
    ef_status st;

    t->len = 0;
    if ((st = reserve(t, 1)))
        return st;
    t->data[0] = '\0';
    if ((st = put_header(c, gc, t)))
        return st;
    if ((st = putf(t, "scene %" PRId32 " %" PRId32 "\n", s->width, s->height)))
        return st;
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const ef_shape *sh = &s->shapes[i];
        st = putf(t, "shape %s %u %u %u %u\n", sh->rule == EF_RULE_EVENODD ? "evenodd" : "nonzero",
                  (unsigned)sh->color.r, (unsigned)sh->color.g, (unsigned)sh->color.b, (unsigned)sh->color.a);
        for (uint32_t ci = sh->first_contour; !st && ci < sh->first_contour + sh->ncontours; ci++) {
            uint32_t b = s->start[ci], e = s->start[ci + 1];
            if (e - b < 3)
                return EF_ERR_ARG;
            st = puts_(t, "contour");
            for (uint32_t p = b; !st && p < e; p++) {
                st = put(t, " ", 1);
                if (!st)
                    st = ef_gen_append_q8(t, s->points[p].x);
                if (!st)
                    st = put(t, " ", 1);
                if (!st)
                    st = ef_gen_append_q8(t, s->points[p].y);
            }
            if (!st)
                st = put(t, "\n", 1);
        }
        if (st)
            return st;
    }
    return EF_OK;
}

void ef_gen_file_name(uint32_t k, char *buf, size_t size) { snprintf(buf, size, "case_%06" PRIu32 ".scene", k); }

ef_status ef_gen_index_header(const ef_gen_config *c, uint32_t shard_index, uint32_t shard_count, ef_gen_text *t)
{
    ef_status st;
    char grid[16];
    if (c->grid)
        snprintf(grid, sizeof grid, "%d", c->grid);
    else
        snprintf(grid, sizeof grid, "%s", c->level == 1 ? "16" : "8,16,32");
    st = putf(t,
              "# edgeflag gen: generator %d, edgeflag %s; seed %" PRIu64 ", level %d, grid %s, %" PRIu32
              " cases (%" PRIu32 " directed, %" PRIu32 " random); shard %" PRIu32 "/%" PRIu32 "\n",
              EF_GEN_VERSION, EF_VERSION_STRING, c->seed, c->level, grid, ef_gen_total(c), ef_gen_directed_count(c),
              c->nrandom, shard_index, shard_count);
    if (!st)
        st = puts_(t, "case\tfile\tkind\tcategory\tname\tgrid\tseed\tdescription\n");
    return st;
}

ef_status ef_gen_index_row(const ef_gen_case *gc, ef_gen_text *t)
{
    char file[32], seed[24];
    ef_status st;
    ef_gen_file_name(gc->number, file, sizeof file);
    if (gc->directed)
        snprintf(seed, sizeof seed, "-");
    else
        snprintf(seed, sizeof seed, "0x%016" PRIx64, gc->case_seed);
    st = putf(t, "%" PRIu32 "\t%s\t%s\t%s\t%s%s\t%d\t%s\t", gc->number, file, gc->directed ? "directed" : "random",
              ef_gen_category_name(gc->category), gc->name, gc->rules_swapped ? "/swapped" : "", gc->grid, seed);
    if (!st && gc->fit_note[0])
        st = putf(t, "[fitted to the DUT's limits: %s] ", gc->fit_note);
    if (!st)
        st = puts_(t, gc->desc);
    if (!st)
        st = puts_(t, "\n");
    return st;
}
