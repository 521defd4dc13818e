/*
 * gen_fit.c - a generated case fitted to a DUT's limits, or refused
 * (`edgeflag gen --dut-*`, docs/gen.md section 11).
 *
 * Three limits, as a board's identify states them (docs/board.md 3.1): the
 * largest canvas (W_MAX x H_MAX), the most EDGE commands of one shape
 * (E_MAX) and the sample counts.  In this order:
 *   1. a grid-dependent directed case built for a sample count the DUT does
 *      not take is refused;
 *   2. a canvas over W_MAX x H_MAX is scaled by 1/2^k, the smallest k that
 *      fits: the canvas becomes ceil(W/2^k) x ceil(H/2^k) and every vertex
 *      floor((v + 2^(k-1)) / 2^k) (Q16.8, integers only): a smaller case,
 *      not the same picture, so its stated expectations are dropped;
 *   3. a shape of more than E_MAX edges (the points of its contours: one
 *      EDGE command per contour edge, docs/microarch.md 3.1) is split, in
 *      order, into shapes of whole contours of at most E_MAX edges each --
 *      only if the model renders the split scene to the same bytes as the
 *      unsplit one at every sample count the DUT takes, with the shapes' own
 *      rules and with either rule forced; otherwise, or when one contour alone
 *      is over E_MAX, the case is refused.
 * Integer only; the result depends on the case and the limits alone.
 */
#include "ef_gen.h"

#include "ef_scene_container.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A split is checked by rendering: canvases larger than this are refused
 * instead (the check would allocate 4 bytes per pixel, twice). */
#define FIT_CHECK_MAX_PIXELS (1u << 24)

static const int SAMPLE_COUNTS[3] = { 8, 16, 32 };

int ef_gen_limits_takes(const ef_gen_limits *lim, int samples)
{
    if (!lim->samples_mask)
        return 1;
    switch (samples) {
    case 8: return (int)((lim->samples_mask >> 3) & 1u);
    case 16: return (int)((lim->samples_mask >> 4) & 1u);
    case 32: return (int)((lim->samples_mask >> 5) & 1u);
    default: return 0;
    }
}

/* floor((v + 2^(k-1)) / 2^k) for k >= 1, with no right shift of a negative. */
static int32_t scale_down(int32_t v, unsigned k)
{
    const int64_t x = (int64_t)v + ((int64_t)1 << (k - 1)), d = (int64_t)1 << k;
    return (int32_t)(x >= 0 ? x / d : -((-x + d - 1) / d));
}

static void list_samples(const ef_gen_limits *lim, char *buf, size_t size)
{
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < 3; i++)
        if (ef_gen_limits_takes(lim, SAMPLE_COUNTS[i]) && n < size)
            n += (size_t)snprintf(buf + n, size - n, "%s%d", n ? "," : "", SAMPLE_COUNTS[i]);
}

/* A copy of s with every shape's contours, canvas w x h, vertices scaled by
 * 1/2^k (k = 0: as they are), and shapes split at the contour indexes where
 * cut[c] is set (a new shape of the same rule and colour starts there). */
static ef_status rebuild(const ef_scene *s, int32_t w, int32_t h, unsigned k, const unsigned char *cut, ef_scene *out)
{
    ef_point *tmp = NULL;
    uint32_t cap = 0;
    ef_status st = EF_OK;
    ef_scene_create(out, w, h);
    for (uint32_t i = 0; i < s->nshapes && st == EF_OK; i++) {
        const ef_shape *sh = &s->shapes[i];
        st = ef_scene_begin_shape(out, sh->rule, sh->color);
        for (uint32_t c = sh->first_contour; c < sh->first_contour + sh->ncontours && st == EF_OK; c++) {
            const uint32_t b = s->start[c], n = s->start[c + 1] - b;
            if (cut && cut[c] && c != sh->first_contour)
                st = ef_scene_begin_shape(out, sh->rule, sh->color);
            if (st != EF_OK)
                break;
            if (n > cap) {
                ef_point *p = realloc(tmp, (size_t)n * sizeof *p);
                if (!p) {
                    st = EF_ERR_NOMEM;
                    break;
                }
                tmp = p;
                cap = n;
            }
            for (uint32_t p = 0; p < n; p++) {
                tmp[p] = s->points[b + p];
                if (k) {
                    tmp[p].x = scale_down(tmp[p].x, k);
                    tmp[p].y = scale_down(tmp[p].y, k);
                }
            }
            st = ef_scene_add_contour(out, tmp, n);
        }
    }
    free(tmp);
    return st;
}

/* 1 when a and b render to the same bytes at every sample count lim takes,
 * under the shapes' own rules and either rule forced; 0 when not (where[]
 * says at which); < 0 an ef_status. */
static int same_picture(const ef_gen_limits *lim, const ef_scene *a, const ef_scene *b, char *where, size_t size)
{
    static const int rules[3] = { -1, EF_RULE_NONZERO, EF_RULE_EVENODD };
    static const char *const rule_names[3] = { "its own rules", "nonzero", "evenodd" };
    ef_image ia, ib;
    int same = 1;
    memset(&ia, 0, sizeof ia);
    memset(&ib, 0, sizeof ib);
    for (int si = 0; si < 3 && same == 1; si++) {
        if (!ef_gen_limits_takes(lim, SAMPLE_COUNTS[si]))
            continue;
        for (int r = 0; r < 3 && same == 1; r++) {
            ef_ctx *ctx = NULL;
            ef_status st = ef_ctx_create(&ctx, a->width, a->height, SAMPLE_COUNTS[si]);
            if (st == EF_OK)
                st = ef_image_create(&ia, a->width, a->height);
            if (st == EF_OK)
                st = ef_image_create(&ib, a->width, a->height);
            if (st == EF_OK)
                st = ef_scene_render(ctx, a, rules[r], &ia);
            if (st == EF_OK)
                st = ef_scene_render(ctx, b, rules[r], &ib);
            if (st != EF_OK) {
                same = -(int)st;
            } else if (memcmp(ia.px, ib.px, ia.stride * (size_t)ia.height) != 0) {
                same = 0;
                snprintf(where, size, "%d samples, %s", SAMPLE_COUNTS[si], rule_names[r]);
            }
            ef_ctx_destroy(ctx);
            ef_image_destroy(&ia);
            ef_image_destroy(&ib);
        }
    }
    return same;
}

ef_status ef_gen_fit(const ef_gen_limits *lim, ef_gen_case *gc, ef_gen_fit_result *res)
{
    ef_scene *s = &gc->scene;
    char list[16];
    unsigned k = 0;
    int32_t w = s->width, h = s->height;
    size_t n = 0;
    ef_status st = EF_OK;

    *res = EF_GEN_FIT_AS_IS;
    gc->fit_note[0] = '\0';
    list_samples(lim, list, sizeof list);
    /* 1. the sample grid */
    if (gc->grid && !ef_gen_limits_takes(lim, gc->grid)) {
        snprintf(gc->fit_note, sizeof gc->fit_note, "built for the %d-sample grid, the DUT takes %s samples per pixel",
                 gc->grid, list);
        *res = EF_GEN_FIT_REFUSED;
        return EF_OK;
    }
    /* 2. the canvas */
    while ((lim->width && w > lim->width) || (lim->height && h > lim->height)) {
        k++;
        w = (int32_t)(((int64_t)s->width + ((int64_t)1 << k) - 1) >> k);
        h = (int32_t)(((int64_t)s->height + ((int64_t)1 << k) - 1) >> k);
    }
    if (k) {
        ef_scene scaled;
        if ((st = rebuild(s, w, h, k, NULL, &scaled)) != EF_OK) {
            ef_scene_destroy(&scaled);
            return st;
        }
        n += (size_t)snprintf(gc->fit_note + n, sizeof gc->fit_note - n,
                              "canvas %" PRId32 "x%" PRId32 " scaled by 1/%u to %" PRId32 "x%" PRId32
                              " (the DUT's largest is %" PRId32 "x%" PRId32 ")",
                              s->width, s->height, 1u << k, w, h, lim->width, lim->height);
        ef_scene_destroy(s);
        *s = scaled;
        gc->expect.kind = EF_GEN_EXPECT_ANY; /* a smaller picture: the stated expectations no longer hold */
        gc->expect.overflow = -1;
        *res = EF_GEN_FIT_FITTED;
    }
    /* 3. edges per shape */
    if (lim->edges) {
        unsigned char *cut = NULL;
        uint32_t nsplit = 0, nnew = 0;
        for (uint32_t i = 0; i < s->nshapes; i++) {
            const ef_shape *sh = &s->shapes[i];
            uint64_t total = 0, run = 0;
            uint32_t pieces = 1;
            for (uint32_t c = sh->first_contour; c < sh->first_contour + sh->ncontours; c++)
                total += s->start[c + 1] - s->start[c];
            if (total <= lim->edges)
                continue;
            if (!cut && !(cut = calloc(s->ncontours ? s->ncontours : 1, 1)))
                return EF_ERR_NOMEM;
            for (uint32_t c = sh->first_contour; c < sh->first_contour + sh->ncontours; c++) {
                const uint32_t e = s->start[c + 1] - s->start[c];
                if (e > lim->edges) {
                    snprintf(gc->fit_note, sizeof gc->fit_note,
                             "shape %" PRIu32 " has %" PRIu64 " edges, over the DUT's %" PRIu32
                             ", and its contour %" PRIu32 " alone has %" PRIu32 " (a contour is never split)",
                             i, total, lim->edges, c - sh->first_contour, e);
                    free(cut);
                    *res = EF_GEN_FIT_REFUSED;
                    return EF_OK;
                }
                if (run + e > lim->edges) {
                    cut[c] = 1;
                    pieces++;
                    run = 0;
                }
                run += e;
            }
            nsplit++;
            nnew += pieces - 1;
        }
        if (nsplit) {
            ef_scene split;
            char where[64];
            int same;
            if ((uint64_t)s->width * (uint64_t)s->height > FIT_CHECK_MAX_PIXELS) {
                snprintf(gc->fit_note, sizeof gc->fit_note,
                         "%" PRIu32 " shape(s) over the DUT's %" PRIu32
                         " edges, and a split cannot be checked on a canvas of more than %u pixels",
                         nsplit, lim->edges, FIT_CHECK_MAX_PIXELS);
                free(cut);
                *res = EF_GEN_FIT_REFUSED;
                return EF_OK;
            }
            st = rebuild(s, s->width, s->height, 0, cut, &split);
            free(cut);
            if (st != EF_OK) {
                ef_scene_destroy(&split);
                return st;
            }
            same = same_picture(lim, s, &split, where, sizeof where);
            if (same < 0) {
                ef_scene_destroy(&split);
                return (ef_status)-same;
            }
            if (!same) {
                ef_scene_destroy(&split);
                snprintf(gc->fit_note, sizeof gc->fit_note,
                         "%" PRIu32 " shape(s) over the DUT's %" PRIu32
                         " edges, and splitting them into whole contours changes the picture (%s)",
                         nsplit, lim->edges, where);
                *res = EF_GEN_FIT_REFUSED;
                return EF_OK;
            }
            ef_scene_destroy(s);
            *s = split;
            gc->expect.overflow = -1; /* the same picture; the overflow count may differ */
            snprintf(gc->fit_note + n, sizeof gc->fit_note - n,
                     "%s%" PRIu32 " shape(s) over the DUT's %" PRIu32 " edges split into %" PRIu32
                     " more, whole contours each (the same picture at %s samples, every rule setting)",
                     n ? "; " : "", nsplit, lim->edges, nnew, list);
            *res = EF_GEN_FIT_FITTED;
        } else {
            free(cut);
        }
    }
    return EF_OK;
}
