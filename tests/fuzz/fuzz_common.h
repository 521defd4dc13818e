/*
 * fuzz_common.h - what the libFuzzer targets in tests/fuzz/ share: a loud
 * failure (abort, so libFuzzer saves the input), the invariants every reader
 * result must satisfy, and the exact scene text writer used for round trips.
 *
 * A target states properties, not just "does not crash":
 *  - a failed load leaves the scene empty and names its place (line:col
 *    >= 1) and a message, and its status is the one returned;
 *  - a successful load gives a canvas within 1..EF_MAX_CANVAS, contours that
 *    index their points consistently and vertices inside EF_COORD_LIMIT;
 *  - the same input gives the same result twice (no hidden state).
 * docs/fuzzing.md lists the targets and what each checks.
 */
#ifndef EF_FUZZ_COMMON_H
#define EF_FUZZ_COMMON_H

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ef_scene.h"

#define FUZZ_FAIL(...) \
    do { \
        fprintf(stderr, "fuzz: %s:%d: property violated: ", __FILE__, __LINE__); \
        fprintf(stderr, __VA_ARGS__); \
        fputc('\n', stderr); \
        abort(); \
    } while (0)
#define FUZZ_CHECK(cond, ...) \
    do { \
        if (!(cond)) \
            FUZZ_FAIL(__VA_ARGS__); \
    } while (0)

/* An empty scene, as every failed load must leave behind. */
static inline void fuzz_check_empty(const ef_scene *s)
{
    FUZZ_CHECK(s->nshapes == 0 && s->ncontours == 0 && s->npoints == 0 && !s->shapes && !s->start && !s->points,
               "a failed load left a partial scene (%" PRIu32 " shapes)", s->nshapes);
}

/* A reader error: the returned status, a message and a position. */
static inline void fuzz_check_error(ef_status st, const ef_error *e, const char *name)
{
    FUZZ_CHECK(st != EF_OK, "not an error");
    FUZZ_CHECK(e->status == st, "error status %d differs from the returned %d", (int)e->status, (int)st);
    FUZZ_CHECK(e->msg[0] != '\0', "error without a message");
    FUZZ_CHECK(strcmp(e->file, name) == 0, "error names file '%s', not '%s'", e->file, name);
    /* Out of memory may come without a place; everything else has one. */
    if (st != EF_ERR_NOMEM)
        FUZZ_CHECK(e->line >= 1 && e->col >= 1, "error without line:col: %" PRIu32 ":%" PRIu32 ": %s", e->line, e->col,
                   e->msg);
    char buf[sizeof e->file + sizeof e->msg + 64];
    ef_error_format(e, buf, sizeof buf);
    FUZZ_CHECK(strncmp(buf, name, strlen(name)) == 0, "formatted error does not start with the file name");
}

/* A loaded scene's structural invariants. */
static inline void fuzz_check_scene(const ef_scene *s)
{
    FUZZ_CHECK(s->width >= 1 && s->width <= EF_MAX_CANVAS && s->height >= 1 && s->height <= EF_MAX_CANVAS,
               "canvas %" PRId32 "x%" PRId32 " outside 1..%d", s->width, s->height, EF_MAX_CANVAS);
    FUZZ_CHECK(s->npoints <= EF_MAX_POINTS_PER_SCENE, "too many points");
    if (s->nshapes == 0)
        return;
    FUZZ_CHECK(s->start && s->start[0] == 0 && s->start[s->ncontours] == s->npoints, "contour starts inconsistent");
    for (uint32_t c = 0; c < s->ncontours; c++)
        FUZZ_CHECK(s->start[c] <= s->start[c + 1], "contour %" PRIu32 " has a negative length", c);
    uint32_t next = 0;
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const ef_shape *sh = &s->shapes[i];
        FUZZ_CHECK(sh->rule == EF_RULE_NONZERO || sh->rule == EF_RULE_EVENODD, "bad rule");
        FUZZ_CHECK(sh->first_contour == next, "shapes do not tile the contours");
        next += sh->ncontours;
        FUZZ_CHECK(next <= s->ncontours, "shape past the contours");
        uint64_t edges = (uint64_t)s->start[sh->first_contour + sh->ncontours] - s->start[sh->first_contour];
        FUZZ_CHECK(edges <= EF_MAX_EDGES_PER_SHAPE, "shape with more edges than the model takes");
    }
    FUZZ_CHECK(next == s->ncontours, "contours outside any shape");
    for (uint32_t k = 0; k < s->npoints; k++) {
        ef_point p = s->points[k];
        FUZZ_CHECK(p.x > -EF_COORD_LIMIT && p.x < EF_COORD_LIMIT && p.y > -EF_COORD_LIMIT && p.y < EF_COORD_LIMIT,
                   "vertex %" PRIu32 " (%" PRId32 ", %" PRId32 ") outside the device range", k, p.x, p.y);
    }
}

static inline int fuzz_scene_equal(const ef_scene *a, const ef_scene *b)
{
    if (a->width != b->width || a->height != b->height || a->nshapes != b->nshapes || a->ncontours != b->ncontours ||
        a->npoints != b->npoints)
        return 0;
    for (uint32_t i = 0; i < a->nshapes; i++)
        if (a->shapes[i].rule != b->shapes[i].rule || a->shapes[i].ncontours != b->shapes[i].ncontours ||
            a->shapes[i].first_contour != b->shapes[i].first_contour ||
            memcmp(&a->shapes[i].color, &b->shapes[i].color, sizeof a->shapes[i].color) != 0)
            return 0;
    if (a->nshapes && memcmp(a->start, b->start, (size_t)(a->ncontours + 1) * sizeof *a->start) != 0)
        return 0;
    return a->npoints == 0 || memcmp(a->points, b->points, (size_t)a->npoints * sizeof *a->points) == 0;
}

/* ------------------------------------------------------------ text writer
 * The scene as `.scene` text with every coordinate the exact decimal of its
 * Q16.8 value (as tests/tools/scene_dump.c writes it), so reading it back
 * must give the same vertices.  Contours of fewer than 3 points, which the
 * format cannot hold and which cover nothing, are left out. */
typedef struct fuzz_buf {
    char *p;
    size_t n, cap;
} fuzz_buf;

static inline void fuzz_buf_put(fuzz_buf *b, const char *s, size_t n)
{
    if (b->n + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (cap < b->n + n + 1)
            cap *= 2;
        char *np = realloc(b->p, cap);
        FUZZ_CHECK(np != NULL, "out of memory in the fuzz harness");
        b->p = np;
        b->cap = cap;
    }
    memcpy(b->p + b->n, s, n);
    b->n += n;
    b->p[b->n] = '\0';
}

static inline void fuzz_buf_q8(fuzz_buf *b, int32_t v)
{
    char t[48];
    int64_t a = v < 0 ? -(int64_t)v : v;
    int n = snprintf(t, sizeof t, " %s%" PRId64, v < 0 ? "-" : "", a / 256);
    if (a % 256) {
        /* frac/256 = frac * 390625 / 10^8 */
        n += snprintf(t + n, sizeof t - (size_t)n, ".%08" PRId64, (a % 256) * 390625);
        while (t[n - 1] == '0')
            t[--n] = '\0';
    }
    fuzz_buf_put(b, t, (size_t)n);
}

static inline void fuzz_scene_text(const ef_scene *s, fuzz_buf *b)
{
    char t[96];
    b->n = 0;
    int n = snprintf(t, sizeof t, "scene %" PRId32 " %" PRId32 "\n", s->width, s->height);
    fuzz_buf_put(b, t, (size_t)n);
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const ef_shape *sh = &s->shapes[i];
        n = snprintf(t, sizeof t, "shape %s %u %u %u %u\n", sh->rule == EF_RULE_EVENODD ? "evenodd" : "nonzero",
                     sh->color.r, sh->color.g, sh->color.b, sh->color.a);
        fuzz_buf_put(b, t, (size_t)n);
        for (uint32_t c = sh->first_contour; c < sh->first_contour + sh->ncontours; c++) {
            uint32_t k0 = s->start[c], k1 = s->start[c + 1];
            if (k1 - k0 < 3)
                continue;
            fuzz_buf_put(b, "contour", 7);
            for (uint32_t k = k0; k < k1; k++) {
                fuzz_buf_q8(b, s->points[k].x);
                fuzz_buf_q8(b, s->points[k].y);
            }
            fuzz_buf_put(b, "\n", 1);
        }
    }
}

/* The points of s with contours of fewer than 3 points removed, compared
 * with t (the re-read text). */
static inline int fuzz_same_geometry(const ef_scene *s, const ef_scene *t)
{
    if (s->width != t->width || s->height != t->height || s->nshapes != t->nshapes)
        return 0;
    uint32_t tc = 0;
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const ef_shape *a = &s->shapes[i], *b = &t->shapes[i];
        if (a->rule != b->rule || memcmp(&a->color, &b->color, sizeof a->color) != 0)
            return 0;
        uint32_t kept = 0;
        for (uint32_t c = a->first_contour; c < a->first_contour + a->ncontours; c++) {
            uint32_t n = s->start[c + 1] - s->start[c];
            if (n < 3)
                continue;
            kept++;
            if (tc >= t->ncontours || t->start[tc + 1] - t->start[tc] != n ||
                memcmp(s->points + s->start[c], t->points + t->start[tc], (size_t)n * sizeof(ef_point)) != 0)
                return 0;
            tc++;
        }
        if (kept != b->ncontours)
            return 0;
    }
    return tc == t->ncontours;
}

/* The readers' shared contract: loading the same bytes twice gives the same
 * status and the same scene or error; a failure leaves the scene empty with a
 * positioned message; a success is a consistent scene of the requested fit.
 * Returns 1 with *s loaded (the caller frees it), 0 after a checked failure. */
typedef ef_status (*fuzz_loader)(const char *name, const char *data, size_t len, const ef_load_opts *opts,
                                 ef_scene *out, ef_error *err);
static inline int fuzz_load_checked(fuzz_loader load, const char *name, const char *data, size_t size,
                                    const ef_load_opts *opts, ef_scene *s)
{
    ef_scene s2;
    ef_error e, e2;
    memset(&e, 0, sizeof e);
    ef_status st = load(name, data, size, opts, s, &e);
    ef_status st2 = load(name, data, size, opts, &s2, &e2);
    FUZZ_CHECK(st == st2, "second load gave status %d, first %d", (int)st2, (int)st);
    if (st != EF_OK) {
        fuzz_check_error(st, &e, name);
        fuzz_check_empty(s);
        FUZZ_CHECK(e.line == e2.line && e.col == e2.col && strcmp(e.msg, e2.msg) == 0, "error not deterministic");
        return 0;
    }
    fuzz_check_scene(s);
    FUZZ_CHECK(fuzz_scene_equal(s, &s2), "second load gave a different scene");
    ef_scene_destroy(&s2);
    if (opts && opts->fit_width)
        FUZZ_CHECK(s->width == opts->fit_width && s->height == opts->fit_height, "fit size not honoured");
    return 1;
}

#endif /* EF_FUZZ_COMMON_H */
