/*
 * cmd_coverage.c - `edgeflag coverage DIR...`: the functional coverage of
 * vector sets (issue 27).  The cover points are dv/coverage/points.tsv
 * (name, spec section, definition), compiled in by the build
 * (coverage_points.h, generated from it); each is sampled here from the
 * transactions of `edgeflag vectors` output, which is the model's trace:
 * cmd.stim.hex and the IFACE.expected.hex files, or vectors.bin.  What the
 * points need beyond the files (unclipped sample rows, the DDA's unclamped
 * cells, true winding numbers) is recomputed from spec 5, 6.1 and 6.3 out of
 * the seg, et_wr and plot transactions.  Prints every point with its hit
 * count; --require makes a miss an exit status of 1.  docs/cli.md.
 */
#include "cli.h"

#include "ef_trace.h"
#include "ef_vec_read.h"
#include "edgeflag.h"

#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *const CMD = "coverage";

typedef struct cov_point {
    const char *name, *section, *definition;
} cov_point;

static const cov_point points[] = {
#include "coverage_points.h"
};
#define NPOINTS (sizeof points / sizeof points[0])

/* The points this file samples, by name: every one of points.tsv must be
 * here and nothing else (checked at start, so the table and the code cannot
 * drift apart). */
enum {
    P_HORIZONTAL,
    P_BETWEEN,
    P_DIR_DOWN,
    P_DIR_UP,
    P_CLIP_TOP,
    P_CLIP_BOTTOM,
    P_DROP_ABOVE,
    P_DROP_BELOW,
    P_LONGEST,
    P_CLAMP_LEFT,
    P_CLAMP_RIGHT,
    P_CELL0,
    P_SINK,
    P_QS_ZERO,
    P_QS_MINUS1,
    P_QS_BIG,
    P_RS_ZERO,
    P_E_ZERO,
    P_E_MAX,
    P_DY_ONE,
    P_DY_BIG,
    P_X_NEG,
    P_X_BIG,
    P_WRAP_UP,
    P_WRAP_DOWN,
    P_PAD_DOWN,
    P_OVF_UP,
    P_OVF_DOWN,
    P_ACC_CARRY,
    P_ACC_OVF,
    P_TRUE63,
    P_TRUE64,
    P_TRUE128,
    P_EO_ODD,
    P_SPAN_X0,
    P_SPAN_RIGHT,
    P_SPAN_ROW,
    P_SPAN_LEN1,
    P_SPAN_SOLID,
    P_SPAN_PARTIAL,
    P_ALPHA_FULL,
    P_ALPHA_PARTIAL,
    P_OVERDRAW,
    P_SHAPE_ALPHA0,
    P_SHAPE_ALPHA_PART,
    P_SHAPE_EMPTY,
    P_NO_RECORDS,
    P_DEGENERATE,
    P_ONE_ROW,
    P_EDGES_4096,
    P_FRAME_EMPTY,
    P_MANY_SHAPES,
    P_ONE_PX,
    P_SLOT_MULTI,
    P_JOIN_LATE,
    P_FIXED_COUNT,
    P_MODE = P_FIXED_COUNT /* then 36 mode points: rule x NS x filter x subpixel */
};
#define NMODES 36
static const char *const fixed_names[P_FIXED_COUNT] = {
    "setup.horizontal",
    "setup.between_rows",
    "setup.dir_down",
    "setup.dir_up",
    "clip.top",
    "clip.bottom",
    "clip.drop_above",
    "clip.drop_below",
    "edge.longest",
    "clamp.left",
    "clamp.right",
    "plot.cell0",
    "plot.sink",
    "div.qs_zero",
    "div.qs_minus1",
    "div.qs_big",
    "div.rs_zero",
    "div.e_zero",
    "div.e_max",
    "div.dy_one",
    "div.dy_big",
    "div.x_neg",
    "div.x_big",
    "wind.plot_wrap_up",
    "wind.plot_wrap_down",
    "wind.plot_pad_carry_down",
    "wind.plot_ovf_up",
    "wind.plot_ovf_down",
    "wind.acc_pad_carry",
    "wind.acc_ovf",
    "wind.true_63",
    "wind.true_64",
    "wind.true_mod128",
    "eo.odd_gt1",
    "span.x0",
    "span.right",
    "span.full_row",
    "span.len1",
    "span.solid",
    "span.partial",
    "pix.alpha_full",
    "pix.alpha_partial",
    "pix.overdraw",
    "shape.alpha0",
    "shape.alpha_partial",
    "shape.empty",
    "shape.no_records",
    "shape.degenerate",
    "shape.one_row",
    "shape.edges_4096",
    "frame.empty",
    "frame.many_shapes",
    "canvas.one_px",
    "et.slot_multi",
    "et.join_late",
};

#define NSAMPLED (P_FIXED_COUNT + NMODES)
static char sampled_name[NSAMPLED][48];
static size_t table_index[NSAMPLED]; /* sampled point -> row of points[] */
static uint64_t hits[NPOINTS];

static int mode_index(int rule, int ns, int filter, int subpixel)
{
    int n = ns == 8 ? 0 : ns == 16 ? 1 : 2;
    return ((rule * 3 + n) * 2 + filter) * 3 + subpixel;
}

static int bind_points(void)
{
    static const char *const rules[2] = { "nonzero", "evenodd" };
    static const char *const filters[2] = { "box", "tent" };
    static const char *const subs[3] = { "none", "rgb", "bgr" };
    int ok = 1;
    for (int i = 0; i < P_FIXED_COUNT; i++)
        snprintf(sampled_name[i], sizeof sampled_name[i], "%s", fixed_names[i]);
    for (int r = 0; r < 2; r++)
        for (int n = 8; n <= 32; n *= 2)
            for (int f = 0; f < 2; f++)
                for (int s = 0; s < 3; s++)
                    snprintf(sampled_name[P_MODE + mode_index(r, n, f, s)], sizeof sampled_name[0],
                             "mode.%s.ns%d.%s.%s", rules[r], n, filters[f], subs[s]);
    for (int i = 0; i < NSAMPLED; i++) {
        size_t k = 0;
        while (k < NPOINTS && strcmp(points[k].name, sampled_name[i]) != 0)
            k++;
        if (k == NPOINTS) {
            ef_cli_error("coverage: the sampler's point '%s' is not in dv/coverage/points.tsv", sampled_name[i]);
            ok = 0;
        }
        table_index[i] = k;
    }
    for (size_t k = 0; k < NPOINTS; k++) {
        int found = 0;
        for (int i = 0; i < NSAMPLED && !found; i++)
            found = strcmp(points[k].name, sampled_name[i]) == 0;
        if (!found) {
            ef_cli_error("coverage: point '%s' of dv/coverage/points.tsv has no sampler", points[k].name);
            ok = 0;
        }
    }
    return ok;
}

static void hit(int p) { hits[table_index[p]]++; }

/* ------------------------------------------------------------ the reading */
typedef struct fields {
    int idx[EF_IF_COUNT][EF_IF_MAX_FIELDS];
} fields;

/* The fields read below by position, checked against the interface table
 * (docs/microarch.md 3) by name before anything is read. */
static const struct {
    int iface, k;
    const char *name;
} field_pos[] = {
    { EF_IF_CMD, 0, "op" },    { EF_IF_CMD, 1, "a" },     { EF_IF_CMD, 2, "b" },    { EF_IF_CMD, 3, "c" },
    { EF_IF_SEG, 0, "eos" },   { EF_IF_SEG, 2, "ya" },    { EF_IF_SEG, 4, "yb" },   { EF_IF_ET_WR, 0, "eos" },
    { EF_IF_ET_WR, 2, "r0" },  { EF_IF_ET_WR, 3, "r1" },  { EF_IF_ET_WR, 4, "x" },  { EF_IF_ET_WR, 5, "e" },
    { EF_IF_ET_WR, 6, "qs" },  { EF_IF_ET_WR, 7, "rs" },  { EF_IF_ET_WR, 8, "dy" }, { EF_IF_ET_WR, 9, "dir" },
    { EF_IF_ET_RD, 0, "row" }, { EF_IF_PLOT, 0, "last" }, { EF_IF_PLOT, 2, "s" },   { EF_IF_PLOT, 3, "q" },
    { EF_IF_PLOT, 4, "dir" },  { EF_IF_SPAN, 0, "y" },    { EF_IF_SPAN, 1, "x" },   { EF_IF_SPAN, 2, "len" },
    { EF_IF_SPAN, 3, "mask" }, { EF_IF_PIX, 0, "y" },     { EF_IF_PIX, 1, "x" },    { EF_IF_PIX, 2, "alpha" },
};

static int check_fields(void)
{
    for (size_t i = 0; i < sizeof field_pos / sizeof field_pos[0]; i++) {
        const ef_iface_desc *d = ef_iface_get(field_pos[i].iface);
        if (!d || field_pos[i].k >= d->nfields || strcmp(d->field[field_pos[i].k].name, field_pos[i].name) != 0) {
            ef_cli_error("coverage: interface %d has no field '%s' at %d", field_pos[i].iface, field_pos[i].name,
                         field_pos[i].k);
            return 0;
        }
    }
    return 1;
}

typedef struct vset {
    ef_vec_dump d[EF_IF_COUNT]; /* interface i in d[i].seq[i] (hex), or all in d[0] (binary) */
    int binary;
    const ef_vec_seq *seq[EF_IF_COUNT];
    int samples;
} vset;

static void vset_free(vset *v)
{
    for (int i = 0; i < EF_IF_COUNT; i++)
        ef_vec_dump_destroy(&v->d[i]);
}

static int is_file(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

static int read_one(const char *path, int want, ef_vec_dump *out)
{
    ef_vec_read_error err;
    char msg[1024];
    if (ef_vec_read_path(path, NULL, want, want, out, &err) != EF_OK) {
        ef_vec_read_error_format(&err, msg, sizeof msg);
        ef_cli_error("%s", msg);
        return 0;
    }
    return 1;
}

/* Reads DIR's hex files (cmd.stim.hex and IFACE.expected.hex), or its
 * vectors.bin when it has no cmd.stim.hex.  0 after an error (reported). */
static int vset_read(const char *dir, vset *v)
{
    char path[4096];
    memset(v, 0, sizeof *v);
    snprintf(path, sizeof path, "%s/cmd.stim.hex", dir);
    if (is_file(path)) {
        for (int i = 0; i < EF_IF_COUNT; i++) {
            const ef_iface_desc *desc = ef_iface_get(i);
            if (i == EF_IF_CMD)
                snprintf(path, sizeof path, "%s/cmd.stim.hex", dir);
            else
                snprintf(path, sizeof path, "%s/%s.expected.hex", dir, desc->name);
            if (!is_file(path)) {
                fprintf(stderr, "edgeflag: coverage: %s: no %s.expected.hex: the points of %s are not sampled\n", dir,
                        desc->name, desc->name);
                continue;
            }
            if (!read_one(path, i, &v->d[i]))
                return 0;
            v->seq[i] = &v->d[i].seq[i];
            if (v->d[i].samples)
                v->samples = v->d[i].samples;
        }
    } else {
        snprintf(path, sizeof path, "%s/vectors.bin", dir);
        if (!is_file(path)) {
            ef_cli_error("coverage: %s: neither cmd.stim.hex nor vectors.bin (not a vectors directory)", dir);
            return 0;
        }
        if (!read_one(path, -1, &v->d[0]))
            return 0;
        v->binary = 1;
        for (int i = 0; i < EF_IF_COUNT; i++)
            if (v->d[0].mask & (1u << i))
                v->seq[i] = &v->d[0].seq[i];
        v->samples = v->d[0].samples;
    }
    if (!v->seq[EF_IF_CMD]) {
        ef_cli_error("coverage: %s: no cmd transactions", dir);
        return 0;
    }
    if (v->samples != 8 && v->samples != 16 && v->samples != 32) {
        ef_cli_error("coverage: %s: the files do not say the sample count (no vectors header)", dir);
        return 0;
    }
    return 1;
}

static const ef_vec_dump *dump_of(const vset *v, int iface) { return v->binary ? &v->d[0] : &v->d[iface]; }

static int64_t fv(const vset *v, int iface, size_t k, int field)
{
    ef_txn t;
    ef_vec_dump_txn(dump_of(v, iface), iface, k, &t);
    return ef_txn_field_value(&t, (unsigned)field);
}

static uint64_t cyc(const vset *v, int iface, size_t k) { return v->seq[iface]->cycle[k]; }

/* floor(a / b), b > 0 */
static int64_t floordiv(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
static int64_t ceildiv(int64_t a, int64_t b) { return -floordiv(-a, b); }

static int sext7(unsigned v) { return (v & 64) ? (int)v - 128 : (int)v; }

/* ------------------------------------------------------------ the sampling */
typedef struct shape_ctx {
    int rule, ns, w, h;
    uint64_t lo, hi; /* cycle window [lo, hi) of the shape's transactions */
    size_t records, spans;
    int64_t span_row;
    int multi_row;
} shape_ctx;

/* The scanline buffer replayed from the plots (spec 6.2, 6.3, 7.2). */
typedef struct slb {
    int w, ns;
    uint8_t *raw;  /* [(w+1) * ns] 7-bit lanes */
    int32_t *tru;  /* true winding (non-zero) or crossing count (even-odd) */
    uint8_t *mark; /* cell touched in this row */
    int32_t *list;
    size_t nlist;
} slb;

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

static void slb_fill_row(slb *b, int nonzero)
{
    int32_t acct[32] = { 0 };
    unsigned accr[32] = { 0 };
    qsort(b->list, b->nlist, sizeof b->list[0], cmp_i32);
    for (size_t i = 0; i < b->nlist; i++) {
        int32_t q = b->list[i];
        for (int s = 0; s < b->ns; s++) {
            size_t at = (size_t)q * (size_t)b->ns + (size_t)s;
            if (nonzero) {
                unsigned sum = accr[s] + b->raw[at];
                int ss = sext7(accr[s]) + sext7(b->raw[at]);
                if (sum >= 128)
                    hit(P_ACC_CARRY);
                if (ss > 63 || ss < -64)
                    hit(P_ACC_OVF);
                accr[s] = sum & 127u;
                acct[s] += b->tru[at];
                int32_t a = acct[s] < 0 ? -acct[s] : acct[s];
                if (a == 63)
                    hit(P_TRUE63);
                if (a == 64)
                    hit(P_TRUE64);
                if (a != 0 && a % 128 == 0)
                    hit(P_TRUE128);
            } else {
                acct[s] += b->tru[at];
                if (acct[s] >= 3 && acct[s] % 2 == 1)
                    hit(P_EO_ODD);
            }
            b->raw[at] = 0;
            b->tru[at] = 0;
        }
        b->mark[q] = 0;
    }
    b->nlist = 0;
}

static void slb_plot(slb *b, int nonzero, int32_t q, int s, int dir)
{
    size_t at = (size_t)q * (size_t)b->ns + (size_t)s;
    if (!b->mark[q]) {
        b->mark[q] = 1;
        b->list[b->nlist++] = q;
    }
    if (!nonzero) {
        b->tru[at]++;
        return;
    }
    unsigned r = b->raw[at];
    if (dir == 0) {
        if (r == 127)
            hit(P_WRAP_UP);
        if (r == 63)
            hit(P_OVF_UP);
        b->raw[at] = (uint8_t)((r + 1) & 127u);
        b->tru[at]++;
    } else {
        if (r == 0)
            hit(P_WRAP_DOWN);
        else
            hit(P_PAD_DOWN);
        if (r == 64)
            hit(P_OVF_DOWN);
        b->raw[at] = (uint8_t)((r + 127) & 127u);
        b->tru[at]--;
    }
}

typedef struct counters {
    uint64_t dirs, frames, shapes, transactions;
} counters;

/* Samples one shape's geometry: seg, et_wr, et_rd, plot, span and pix in
 * [sh->lo, sh->hi).  pos[i] is the next transaction of interface i. */
static int sample_shape(const vset *v, const fields *f, shape_ctx *sh, size_t *pos, slb *b, uint8_t *written)
{
    const uint8_t *k = ef_pattern(sh->ns);
    const int64_t h = 256 / sh->ns, c = h / 2, nh = (int64_t)sh->ns * sh->h;
    const ef_vec_seq *q;
    if ((q = v->seq[EF_IF_SEG]) != NULL)
        for (; pos[EF_IF_SEG] < q->n && q->cycle[pos[EF_IF_SEG]] < sh->hi; pos[EF_IF_SEG]++) {
            size_t i = pos[EF_IF_SEG];
            if (fv(v, EF_IF_SEG, i, f->idx[EF_IF_SEG][0]))
                continue; /* eos */
            int64_t ya = fv(v, EF_IF_SEG, i, f->idx[EF_IF_SEG][2]), yb = fv(v, EF_IF_SEG, i, f->idx[EF_IF_SEG][4]);
            if (ya == yb) {
                hit(P_HORIZONTAL);
                continue;
            }
            int64_t y0 = ya < yb ? ya : yb, y1 = ya < yb ? yb : ya;
            int64_t r0 = ceildiv(y0 - c, h), r1 = ceildiv(y1 - c, h) - 1;
            if (r0 > r1)
                hit(P_BETWEEN);
            else if (r1 < 0)
                hit(P_DROP_ABOVE);
            else if (r0 > nh - 1)
                hit(P_DROP_BELOW);
            else {
                if (r0 < 0)
                    hit(P_CLIP_TOP);
                if (r1 > nh - 1)
                    hit(P_CLIP_BOTTOM);
            }
        }
    if ((q = v->seq[EF_IF_ET_WR]) != NULL)
        for (; pos[EF_IF_ET_WR] < q->n && q->cycle[pos[EF_IF_ET_WR]] < sh->hi; pos[EF_IF_ET_WR]++) {
            size_t i = pos[EF_IF_ET_WR];
            const int *fi = f->idx[EF_IF_ET_WR];
            if (fv(v, EF_IF_ET_WR, i, fi[0]))
                continue;
            sh->records++;
            int64_t r0 = fv(v, EF_IF_ET_WR, i, fi[2]), r1 = fv(v, EF_IF_ET_WR, i, fi[3]);
            int64_t x = fv(v, EF_IF_ET_WR, i, fi[4]), e = fv(v, EF_IF_ET_WR, i, fi[5]);
            int64_t qs = fv(v, EF_IF_ET_WR, i, fi[6]), rs = fv(v, EF_IF_ET_WR, i, fi[7]);
            int64_t dy = fv(v, EF_IF_ET_WR, i, fi[8]), dir = fv(v, EF_IF_ET_WR, i, fi[9]);
            hit(dir ? P_DIR_UP : P_DIR_DOWN);
            if (r0 == 0 && r1 == nh - 1)
                hit(P_LONGEST);
            if (qs == 0)
                hit(P_QS_ZERO);
            if (qs == -1)
                hit(P_QS_MINUS1);
            if (qs >= (1 << 20) || qs <= -(1 << 20))
                hit(P_QS_BIG);
            if (rs == 0 && qs != 0)
                hit(P_RS_ZERO);
            if (e == 0)
                hit(P_E_ZERO);
            if (e == dy - 1)
                hit(P_E_MAX);
            if (dy == 1)
                hit(P_DY_ONE);
            if (dy >= (1 << 20))
                hit(P_DY_BIG);
            if (x < 0)
                hit(P_X_NEG);
            if (x >= (1 << 22) || x <= -(1 << 22))
                hit(P_X_BIG);
            if (dy <= 0 || r0 < 0 || r1 >= nh || r0 > r1) {
                ef_cli_error("coverage: et_wr transaction %zu (cycle %" PRIu64
                             ") is not a record of spec 5 (dy %" PRId64 ", r0 %" PRId64 ", r1 %" PRId64 ")",
                             i + 1, q->cycle[i], dy, r0, r1);
                return 0;
            }
            for (int64_t r = r0; r <= r1; r++) { /* spec 6.1, unclamped */
                int64_t off = 256 - h * k[r % sh->ns] - c, cell = floordiv(x + off, 256);
                if (cell < 0)
                    hit(P_CLAMP_LEFT);
                if (cell > sh->w)
                    hit(P_CLAMP_RIGHT);
                x += qs;
                e += rs;
                if (e >= dy) {
                    e -= dy;
                    x++;
                }
            }
        }
    if ((q = v->seq[EF_IF_ET_RD]) != NULL) {
        int64_t first = -1, last = -1;
        int run = 0;
        for (; pos[EF_IF_ET_RD] < q->n && q->cycle[pos[EF_IF_ET_RD]] < sh->hi; pos[EF_IF_ET_RD]++) {
            int64_t row = fv(v, EF_IF_ET_RD, pos[EF_IF_ET_RD], f->idx[EF_IF_ET_RD][0]);
            if (first < 0)
                first = row;
            else if (row > first)
                hit(P_JOIN_LATE);
            run = row == last ? run + 1 : 1;
            if (run == 2)
                hit(P_SLOT_MULTI);
            last = row;
        }
    }
    if ((q = v->seq[EF_IF_PLOT]) != NULL)
        for (; pos[EF_IF_PLOT] < q->n && q->cycle[pos[EF_IF_PLOT]] < sh->hi; pos[EF_IF_PLOT]++) {
            size_t i = pos[EF_IF_PLOT];
            const int *fi = f->idx[EF_IF_PLOT];
            int64_t last = fv(v, EF_IF_PLOT, i, fi[0]), s = fv(v, EF_IF_PLOT, i, fi[2]);
            int64_t cell = fv(v, EF_IF_PLOT, i, fi[3]), dir = fv(v, EF_IF_PLOT, i, fi[4]);
            if (cell < 0 || cell > sh->w || s < 0 || s >= sh->ns) {
                ef_cli_error("coverage: plot transaction %zu (cycle %" PRIu64 ") outside the canvas (q %" PRId64 ")",
                             i + 1, q->cycle[i], cell);
                return 0;
            }
            if (cell == 0)
                hit(P_CELL0);
            if (cell == sh->w)
                hit(P_SINK);
            slb_plot(b, sh->rule == 0, (int32_t)cell, (int)s, (int)dir);
            if (last)
                slb_fill_row(b, sh->rule == 0);
        }
    if (b->nlist)
        slb_fill_row(b, sh->rule == 0);
    if ((q = v->seq[EF_IF_SPAN]) != NULL)
        for (; pos[EF_IF_SPAN] < q->n && q->cycle[pos[EF_IF_SPAN]] < sh->hi; pos[EF_IF_SPAN]++) {
            size_t i = pos[EF_IF_SPAN];
            const int *fi = f->idx[EF_IF_SPAN];
            int64_t y = fv(v, EF_IF_SPAN, i, fi[0]), x = fv(v, EF_IF_SPAN, i, fi[1]);
            int64_t len = fv(v, EF_IF_SPAN, i, fi[2]);
            uint64_t mask = (uint64_t)fv(v, EF_IF_SPAN, i, fi[3]) & 0xffffffffu;
            uint64_t full = sh->ns == 32 ? 0xffffffffu : ((1u << sh->ns) - 1u);
            if (x == 0)
                hit(P_SPAN_X0);
            if (x + len == sh->w)
                hit(P_SPAN_RIGHT);
            if (x == 0 && len == sh->w)
                hit(P_SPAN_ROW);
            if (len == 1)
                hit(P_SPAN_LEN1);
            if (mask == full)
                hit(P_SPAN_SOLID);
            else if (mask)
                hit(P_SPAN_PARTIAL);
            if (sh->spans++ == 0)
                sh->span_row = y;
            else if (y != sh->span_row)
                sh->multi_row = 1;
        }
    if ((q = v->seq[EF_IF_PIX]) != NULL)
        for (; pos[EF_IF_PIX] < q->n && q->cycle[pos[EF_IF_PIX]] < sh->hi; pos[EF_IF_PIX]++) {
            size_t i = pos[EF_IF_PIX];
            const int *fi = f->idx[EF_IF_PIX];
            int64_t y = fv(v, EF_IF_PIX, i, fi[0]), x = fv(v, EF_IF_PIX, i, fi[1]);
            int64_t alpha = fv(v, EF_IF_PIX, i, fi[2]);
            if (alpha == 255)
                hit(P_ALPHA_FULL);
            else if (alpha > 0)
                hit(P_ALPHA_PARTIAL);
            if (x >= 0 && x < sh->w && y >= 0 && y < sh->h) {
                size_t at = (size_t)y * (size_t)sh->w + (size_t)x;
                if (written[at / 8] & (1u << (at % 8)))
                    hit(P_OVERDRAW);
                written[at / 8] |= (uint8_t)(1u << (at % 8));
            }
        }
    return 1;
}

static void skip_to(const vset *v, size_t *pos, uint64_t hi)
{
    for (int i = 1; i < EF_IF_COUNT; i++)
        if (v->seq[i])
            while (pos[i] < v->seq[i]->n && v->seq[i]->cycle[pos[i]] < hi)
                pos[i]++;
}

/* One vectors directory. */
static int sample_dir(const char *dir, counters *cnt)
{
    vset v;
    fields f;
    int rc = EF_CLI_EXIT_OK;
    if (!vset_read(dir, &v)) {
        vset_free(&v);
        return EF_CLI_EXIT_INPUT;
    }
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        for (int k = 0; k < d->nfields; k++)
            f.idx[i][k] = k;
        if (v.seq[i])
            cnt->transactions += v.seq[i]->n;
    }
    cnt->dirs++;
    const ef_vec_seq *cmd = v.seq[EF_IF_CMD];
    size_t pos[EF_IF_COUNT] = { 0 };
    slb b = { 0 };
    uint8_t *written = NULL;
    int w = 0, h = 0, opts = 0, nshapes = 0, rule = 0;
    size_t edges = 0;
    uint64_t shape_lo = 0;
    for (size_t i = 0; i < cmd->n && rc == EF_CLI_EXIT_OK; i++) {
        int op = (int)fv(&v, EF_IF_CMD, i, 0);
        int64_t a = fv(&v, EF_IF_CMD, i, 1), bb = fv(&v, EF_IF_CMD, i, 2), cc = fv(&v, EF_IF_CMD, i, 3);
        (void)bb;
        switch (op) {
        case EF_OP_FRAME:
            w = (int)a;
            h = (int)fv(&v, EF_IF_CMD, i, 2);
            opts = (int)cc;
            nshapes = 0;
            cnt->frames++;
            if (w < 1 || h < 1 || w > 16384 || h > 16384 || opts < 0 || (opts >> 1) > 2) {
                ef_cli_error("coverage: %s: cmd transaction %zu: a FRAME of %dx%d, options %d", dir, i + 1, w, h, opts);
                rc = EF_CLI_EXIT_INPUT;
                break;
            }
            if (w == 1 || h == 1)
                hit(P_ONE_PX);
            free(b.raw);
            free(b.tru);
            free(b.mark);
            free(b.list);
            free(written);
            b.w = w;
            b.ns = v.samples;
            b.nlist = 0;
            b.raw = calloc((size_t)(w + 1) * (size_t)v.samples, 1);
            b.tru = calloc((size_t)(w + 1) * (size_t)v.samples, sizeof *b.tru);
            b.mark = calloc((size_t)w + 1, 1);
            b.list = calloc((size_t)w + 1, sizeof *b.list);
            written = calloc((size_t)w * (size_t)h / 8 + 1, 1);
            if (!b.raw || !b.tru || !b.mark || !b.list || !written) {
                ef_cli_error("coverage: out of memory");
                rc = EF_CLI_EXIT_INTERNAL;
            }
            break;
        case EF_OP_SHAPE:
            rule = (int)a;
            nshapes++;
            cnt->shapes++;
            edges = 0;
            shape_lo = cyc(&v, EF_IF_CMD, i);
            if (rule != 0 && rule != 1) {
                ef_cli_error("coverage: %s: cmd transaction %zu: a SHAPE of rule %d", dir, i + 1, rule);
                rc = EF_CLI_EXIT_INPUT;
                break;
            }
            hit(P_MODE + mode_index(rule, v.samples, opts & 1, opts >> 1));
            if (cc == 0)
                hit(P_SHAPE_ALPHA0);
            else if (cc < 255)
                hit(P_SHAPE_ALPHA_PART);
            break;
        case EF_OP_EDGE: edges++; break;
        case EF_OP_SHAPE_END: {
            shape_ctx sh = { rule, v.samples, w, h, shape_lo, UINT64_MAX, 0, 0, 0, 0 };
            if (i + 1 < cmd->n)
                sh.hi = cyc(&v, EF_IF_CMD, i + 1);
            if (edges == 0)
                hit(P_SHAPE_EMPTY);
            if (edges >= 4096)
                hit(P_EDGES_4096);
            if (opts != 0) {
                skip_to(&v, pos, sh.hi);
                break;
            }
            if (!sample_shape(&v, &f, &sh, pos, &b, written)) {
                rc = EF_CLI_EXIT_INPUT;
                break;
            }
            if (edges > 0 && sh.records == 0)
                hit(P_NO_RECORDS);
            if (sh.records > 0 && sh.spans == 0)
                hit(P_DEGENERATE);
            if (sh.spans > 0 && !sh.multi_row)
                hit(P_ONE_ROW);
            break;
        }
        case EF_OP_FRAME_END:
            if (nshapes == 0)
                hit(P_FRAME_EMPTY);
            if (nshapes >= 100)
                hit(P_MANY_SHAPES);
            break;
        default: ef_cli_error("coverage: %s: cmd transaction %zu: op %d", dir, i + 1, op); rc = EF_CLI_EXIT_INPUT;
        }
    }
    free(b.raw);
    free(b.tru);
    free(b.mark);
    free(b.list);
    free(written);
    vset_free(&v);
    return rc;
}

/* ------------------------------------------------------------ the command */
typedef struct cov_args {
    const char **dirs;
    int ndirs;
    const char *require; /* NULL, "all" or NAME[,NAME...] (NAME* a prefix) */
    int missed;          /* --missed: list only the points not hit */
    int list;            /* --list: print the points and exit */
} cov_args;

enum { OPT_REQUIRE = 300, OPT_MISSED, OPT_LIST };
static const struct option cov_options[] = {
    { "require", required_argument, NULL, OPT_REQUIRE },
    { "missed", no_argument, NULL, OPT_MISSED },
    { "list", no_argument, NULL, OPT_LIST },
    { 0, 0, 0, 0 },
};

static void usage(FILE *f)
{
    fputs("usage: edgeflag coverage DIR... [--require all|NAME[,NAME...]] [--missed]\n"
          "       edgeflag coverage --list\n"
          "\n"
          "Functional coverage of vector sets: samples the cover points of\n"
          "dv/coverage/points.tsv (named after docs/spec.md and docs/microarch.md\n"
          "sections) from each DIR written by `edgeflag vectors` (cmd.stim.hex and the\n"
          "IFACE.expected.hex files, or vectors.bin) and prints every point with its\n"
          "hit count, then 'coverage: H of P points hit'.\n"
          "\n"
          "options:\n"
          "  --require R  exit 1 when a required point is missed: 'all', or a\n"
          "               comma-separated list of names (NAME* for every name that\n"
          "               starts with NAME)\n"
          "  --missed     list only the points that were missed\n"
          "  --list       print the points (name, section, definition) and exit\n"
          "  -h, --help   show this text\n"
          "\n"
          "exit codes: 0 done, 1 a required point missed, 2 usage, 3 a directory\n"
          "unreadable or not vectors, 70 internal error.\n",
          f);
}

static int cov_option(void *p, int val, const char *value)
{
    cov_args *a = p;
    switch (val) {
    case OPT_REQUIRE: a->require = value; return -1;
    case OPT_MISSED: a->missed = 1; return -1;
    case OPT_LIST: a->list = 1; return -1;
    default: return ef_cli_usage_error(CMD, "unknown option");
    }
}

static int cov_operand(void *p, const char *arg)
{
    cov_args *a = p;
    const char **d = realloc(a->dirs, (size_t)(a->ndirs + 1) * sizeof *d);
    if (!d) {
        ef_cli_error("coverage: out of memory");
        return EF_CLI_EXIT_INTERNAL;
    }
    a->dirs = d;
    a->dirs[a->ndirs++] = arg;
    return -1;
}

static int cov_finish(void *p)
{
    cov_args *a = p;
    if (a->list && a->ndirs)
        return ef_cli_usage_error(CMD, "--list takes no DIR");
    if (!a->list && a->ndirs == 0)
        return ef_cli_usage_error(CMD, "no vectors directory given");
    return -1;
}

static const ef_cli_command cov_command = {
    CMD, cov_options, 1, usage, cov_option, cov_operand, NULL, cov_finish, NULL,
};

/* 1 when point k is required by spec R; names of R not matching any point are
 * a usage error (reported, *bad set). */
static int required(const char *r, size_t k)
{
    if (!r)
        return 0;
    if (strcmp(r, "all") == 0)
        return 1;
    const char *name = points[k].name;
    for (const char *p = r; *p;) {
        size_t n = strcspn(p, ",");
        if (n > 0 && p[n - 1] == '*' ? strncmp(name, p, n - 1) == 0 : (strlen(name) == n && strncmp(name, p, n) == 0))
            return 1;
        p += n;
        if (*p == ',')
            p++;
    }
    return 0;
}

static int check_require(const char *r)
{
    if (!r || strcmp(r, "all") == 0)
        return 1;
    for (const char *p = r;;) {
        size_t n = strcspn(p, ",");
        int any = 0;
        for (size_t k = 0; k < NPOINTS && !any; k++) {
            const char *name = points[k].name;
            any = n > 0 && p[n - 1] == '*' ? strncmp(name, p, n - 1) == 0
                                           : (strlen(name) == n && strncmp(name, p, n) == 0);
        }
        if (!any) {
            ef_cli_usage_error(CMD, "--require: '%.*s' names no cover point (edgeflag coverage --list)", (int)n, p);
            return 0;
        }
        p += n;
        if (!*p)
            return 1;
        p++;
    }
}

int ef_cli_coverage(int argc, char **argv)
{
    cov_args a = { 0 };
    int rc = ef_cli_getopt(&cov_command, argc, argv, &a);
    if (rc >= 0) {
        free(a.dirs);
        return rc;
    }
    if (!bind_points() || !check_fields()) {
        free(a.dirs);
        return EF_CLI_EXIT_INTERNAL;
    }
    if (a.list) {
        for (size_t k = 0; k < NPOINTS; k++)
            printf("%s\t%s\t%s\n", points[k].name, points[k].section, points[k].definition);
        return EF_CLI_EXIT_OK;
    }
    if (!check_require(a.require)) {
        free(a.dirs);
        return EF_CLI_EXIT_USAGE;
    }
    counters cnt = { 0 };
    for (int i = 0; i < a.ndirs; i++) {
        rc = sample_dir(a.dirs[i], &cnt);
        if (rc != EF_CLI_EXIT_OK) {
            free(a.dirs);
            return rc;
        }
    }
    free(a.dirs);
    size_t nhit = 0, nreq = 0, nreq_missed = 0;
    for (size_t k = 0; k < NPOINTS; k++) {
        int req = required(a.require, k);
        nhit += hits[k] > 0;
        nreq += req;
        nreq_missed += req && hits[k] == 0;
        if (!a.missed || hits[k] == 0)
            printf("%-5s %-34s %10" PRIu64 "  %s\n", hits[k] ? "hit" : "MISS", points[k].name, hits[k],
                   points[k].section);
    }
    size_t pm = nhit * 1000 / NPOINTS;
    printf("coverage: %zu of %zu points hit (%zu.%zu %%) over %" PRIu64 " directories, %" PRIu64 " frames, %" PRIu64
           " shapes, %" PRIu64 " transactions\n",
           nhit, NPOINTS, pm / 10, pm % 10, cnt.dirs, cnt.frames, cnt.shapes, cnt.transactions);
    if (a.require) {
        printf("coverage: %zu of %zu required points missed\n", nreq_missed, nreq);
        if (nreq_missed)
            return 1;
    }
    return EF_CLI_EXIT_OK;
}
