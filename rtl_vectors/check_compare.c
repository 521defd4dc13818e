/*
 * check_compare.c - the heart of `edgeflag check`: one interface's expected
 * and actual transactions aligned and every difference reported.
 *
 * Both modes align the two sequences by content, in order, as a verifier's
 * scoreboard does: equal payloads pair up; a pair that differs but after
 * which both sequences agree again is one transaction with wrong fields (a
 * flipped bit is one report, not a missing and an extra); otherwise a short
 * look-ahead (LOOKAHEAD transactions each way) finds which side has
 * transactions the other lacks (missing or extra, nearest resynchronisation
 * wins); failing that, the pair is reported as differing.  `--cycles` then
 * also demands each pair's cycle stamps be equal, so a transaction one
 * cycle late is reported once, as late, rather than as a missing and an
 * extra one; `--transactions` ignores the stamps.  Payload comparisons only,
 * never field layouts: fields are decoded (ef_txn_field against the
 * interface table) just to print them.
 */
#include "check_internal.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* How far the scoreboard looks for a resynchronisation: enough for a burst
 * of dropped or inserted transactions (a span's worth of pixels), small
 * enough that two unrelated dumps cost O(n * LOOKAHEAD), not O(n^2). */
#define LOOKAHEAD 64

enum { M_DIFF, M_MISSING, M_EXTRA, M_CYCLE };

/* ---------------------------------------------------------------- strings */

typedef struct sb {
    char *p;
    size_t n, cap;
    int oom;
} sb;

static void sb_printf(sb *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static void sb_printf(sb *b, const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        size_t room = b->cap - b->n;
        va_start(ap, fmt);
        int k = b->p ? vsnprintf(b->p + b->n, room, fmt, ap) : -1;
        va_end(ap);
        if (k >= 0 && (size_t)k < room) {
            b->n += (size_t)k;
            return;
        }
        if (k < 0 && b->p) { /* an output error, not a short buffer: growing would not help */
            b->oom = 1;
            return;
        }
        size_t need = b->cap ? b->cap * 2 : 512;
        if (k >= 0 && need < b->n + (size_t)k + 1)
            need = b->n + (size_t)k + 1;
        char *np = realloc(b->p, need);
        if (!np) {
            b->oom = 1;
            return;
        }
        b->p = np;
        b->cap = need;
    }
}

/* ---------------------------------------------------------------- decoding */

/* The interface's scanline and pixel fields, by name ("y"/"row", "x"/"q"),
 * or -1: the checker knows what the fields mean only from the table. */
static void place_fields(const ef_iface_desc *d, int *row, int *col)
{
    *row = *col = -1;
    for (int k = 0; k < d->nfields; k++) {
        const char *n = d->field[k].name;
        if (*row < 0 && (strcmp(n, "y") == 0 || strcmp(n, "row") == 0))
            *row = k;
        if (*col < 0 && (strcmp(n, "x") == 0 || strcmp(n, "q") == 0))
            *col = k;
    }
}

static void put_value(sb *b, const ef_iface_desc *d, const ef_txn *t, unsigned k)
{
    const ef_field_desc *f = &d->field[k];
    if (f->is_signed)
        sb_printf(b, "%" PRId64, ef_txn_field_value(t, k));
    else if (f->width >= 32) /* masks and colours read best in hex */
        sb_printf(b, "0x%0*" PRIx64, (f->width + 3) / 4, ef_txn_field(t, k));
    else
        sb_printf(b, "%" PRIu64, ef_txn_field(t, k));
}

/* "f=v f=v ..." of t, a '*' after each field that differs from other. */
static void put_fields(sb *b, const ef_txn *t, const ef_txn *other)
{
    const ef_iface_desc *d = ef_iface_get(t->iface);
    for (unsigned k = 0; k < d->nfields; k++) {
        sb_printf(b, "%s%s=", k ? " " : "", d->field[k].name);
        put_value(b, d, t, k);
        if (other && ef_txn_field(t, k) != ef_txn_field(other, k))
            sb_printf(b, "*");
    }
}

/* "FILE:LINE" or "FILE: record N (byte offset O)". */
static void put_loc(sb *b, const ef_vec_dump *d, const char *name, int iface, size_t k)
{
    const ef_vec_seq *q = &d->seq[iface];
    if (k >= q->n)
        sb_printf(b, "%s: end", name);
    else if (d->format == EF_VEC_FMT_BIN)
        sb_printf(b, "%s: record %" PRIu64 " (byte offset %" PRIu64 ")", name, q->loc[k], q->off[k]);
    else
        sb_printf(b, "%s:%" PRIu64, name, q->loc[k]);
}

/* ": IFACE: cycle C, y Y, x X: " - where the mismatch is. */
static void put_where(sb *b, const ef_txn *t)
{
    const ef_iface_desc *d = ef_iface_get(t->iface);
    int row, col;
    place_fields(d, &row, &col);
    sb_printf(b, ": %s: cycle %" PRIu64, d->name, t->cycle);
    if (row >= 0)
        sb_printf(b, ", %s %" PRIu64, d->field[row].name, ef_txn_field(t, (unsigned)row));
    if (col >= 0)
        sb_printf(b, ", %s %" PRIu64, d->field[col].name, ef_txn_field(t, (unsigned)col));
    sb_printf(b, ": ");
}

/* ---------------------------------------------------------------- reports */

typedef struct cmp {
    chk_run *r;
    chk_case *tc;
    int iface;
    const ef_vec_dump *e, *a;
    const char *ename, *aname;
} cmp;

static void case_text(chk_run *r, chk_case *tc, const char *line, size_t n)
{
    if (tc->text_len + n + 2 > tc->text_cap) {
        size_t cap = tc->text_cap ? tc->text_cap * 2 : 1024;
        while (cap < tc->text_len + n + 2)
            cap *= 2;
        char *np = realloc(tc->text, cap);
        if (!np) {
            r->oom = 1;
            return;
        }
        tc->text = np;
        tc->text_cap = cap;
    }
    memcpy(tc->text + tc->text_len, line, n);
    tc->text_len += n;
    tc->text[tc->text_len++] = '\n';
    tc->text[tc->text_len] = '\0';
}

static void report(cmp *c, int kind, size_t i, size_t j)
{
    chk_run *r = c->r;
    ef_txn te, ta;
    ef_vec_dump_txn(c->e, c->iface, i, &te);
    ef_vec_dump_txn(c->a, c->iface, j, &ta);
    r->mismatches++;
    c->tc->mismatches++;
    if (r->a->keep_marks) {
        if (kind != M_EXTRA)
            chk_mark_txn(r, &te);
        if (kind != M_MISSING)
            chk_mark_txn(r, &ta);
    }
    if (r->a->errors && r->reported >= (uint64_t)r->a->errors)
        return; /* counted, not shown (--errors) */
    r->reported++;

    sb b = { 0 };
    switch (kind) {
    case M_DIFF:
        put_loc(&b, c->a, c->aname, c->iface, j);
        put_where(&b, &te);
        sb_printf(&b, "fields differ: expected ");
        put_fields(&b, &te, NULL);
        sb_printf(&b, "; actual ");
        put_fields(&b, &ta, &te);
        if (r->a->cycles && te.cycle != ta.cycle)
            sb_printf(&b, "; and the cycle: expected %" PRIu64 ", actual %" PRIu64, te.cycle, ta.cycle);
        sb_printf(&b, " (expected at ");
        put_loc(&b, c->e, c->ename, c->iface, i);
        sb_printf(&b, ")");
        break;
    case M_CYCLE: {
        const uint64_t d = ta.cycle > te.cycle ? ta.cycle - te.cycle : te.cycle - ta.cycle;
        put_loc(&b, c->a, c->aname, c->iface, j);
        put_where(&b, &te);
        sb_printf(&b, "cycle differs: expected %" PRIu64 ", actual %" PRIu64 " (%s by %" PRIu64 "): ", te.cycle,
                  ta.cycle, ta.cycle > te.cycle ? "late" : "early", d);
        put_fields(&b, &te, NULL);
        sb_printf(&b, " (expected at ");
        put_loc(&b, c->e, c->ename, c->iface, i);
        sb_printf(&b, ")");
        break;
    }
    case M_MISSING:
        put_loc(&b, c->e, c->ename, c->iface, i);
        put_where(&b, &te);
        sb_printf(&b, "missing transaction: expected ");
        put_fields(&b, &te, NULL);
        sb_printf(&b, "; not in %s", c->aname);
        if (j < c->a->seq[c->iface].n) {
            sb_printf(&b, " (before ");
            put_loc(&b, c->a, c->aname, c->iface, j);
            sb_printf(&b, ")");
        }
        break;
    default:
        put_loc(&b, c->a, c->aname, c->iface, j);
        put_where(&b, &ta);
        sb_printf(&b, "extra transaction: actual ");
        put_fields(&b, &ta, NULL);
        sb_printf(&b, "; not in %s", c->ename);
        break;
    }
    if (b.oom) {
        r->oom = 1;
    } else {
        if (r->a->report)
            fprintf(r->a->report, "%s\n", b.p);
        case_text(r, c->tc, b.p, b.n);
    }
    free(b.p);
}

/* ---------------------------------------------------------------- alignment */

static int same(const ef_vec_seq *e, size_t i, const ef_vec_seq *a, size_t j)
{
    return memcmp(e->pay + i * e->nw, a->pay + j * a->nw, e->nw * sizeof *e->pay) == 0;
}

/* Smallest d in 1..LOOKAHEAD with y[j + d] equal to x[i], or 0. */
static size_t find_ahead(const ef_vec_seq *x, size_t i, const ef_vec_seq *y, size_t j)
{
    for (size_t d = 1; d <= LOOKAHEAD && j + d < y->n; d++)
        if (same(x, i, y, j + d))
            return d;
    return 0;
}

void chk_compare(chk_run *r, chk_case *tc, int iface, const ef_vec_dump *e, const char *ename, const ef_vec_dump *a,
                 const char *aname)
{
    cmp c = { r, tc, iface, e, a, ename, aname };
    const ef_vec_seq *E = &e->seq[iface], *A = &a->seq[iface];
    size_t i = 0, j = 0;

    tc->expected = E->n;
    tc->actual = A->n;
    while ((i < E->n || j < A->n) && !r->oom) {
        if (i < E->n && j < A->n && same(E, i, A, j)) {
            if (r->a->cycles && E->cycle[i] != A->cycle[j])
                report(&c, M_CYCLE, i, j);
            i++, j++;
            continue;
        }
        if (i == E->n) {
            report(&c, M_EXTRA, i, j++);
            continue;
        }
        if (j == A->n) {
            report(&c, M_MISSING, i++, j);
            continue;
        }
        /* One wrong transaction, and the two agree again right after it. */
        if ((i + 1 == E->n && j + 1 == A->n) || (i + 1 < E->n && j + 1 < A->n && same(E, i + 1, A, j + 1))) {
            report(&c, M_DIFF, i++, j++);
            continue;
        }
        size_t da = find_ahead(E, i, A, j); /* E[i] further on in A: A has extras */
        size_t de = find_ahead(A, j, E, i); /* A[j] further on in E: A lacks some */
        if (da && (!de || da <= de)) {
            for (; da > 0; da--) /* not `da--`: no unsigned wrap at the end */
                report(&c, M_EXTRA, i, j++);
        } else if (de) {
            for (; de > 0; de--)
                report(&c, M_MISSING, i++, j);
        } else {
            report(&c, M_DIFF, i++, j++);
        }
    }
}

chk_case *chk_case_add(chk_run *r, const char *ename, const char *aname, const char *iface)
{
    if (r->ncases == r->capcases) {
        size_t cap = r->capcases ? r->capcases * 2 : 8;
        chk_case *nc = realloc(r->cases, cap * sizeof *nc);
        if (!nc) {
            r->oom = 1;
            return NULL;
        }
        r->cases = nc;
        r->capcases = cap;
    }
    chk_case *tc = &r->cases[r->ncases];
    memset(tc, 0, sizeof *tc);
    sb b = { 0 };
    sb_printf(&b, "%s vs %s", ename, aname);
    tc->classname = b.p;
    tc->name = malloc(strlen(iface) + 1);
    if (b.oom || !tc->name) {
        free(tc->classname);
        free(tc->name);
        r->oom = 1;
        return NULL;
    }
    strcpy(tc->name, iface);
    r->ncases++;
    return tc;
}
