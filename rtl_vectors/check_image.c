/*
 * check_image.c - `edgeflag check --diff-image`: the expected frame (every
 * expected `pix` transaction's blended colour, the last one of a pixel
 * winning, as the frame buffer would hold it) with each pixel of a
 * mismatching `pix` or `span` transaction painted opaque magenta, a colour
 * a rasterizer's coverage of real artwork rarely produces, so a glance at
 * the image shows where the RTL went wrong.  The caller writes it
 * (`edgeflag check --diff-image`: atomically, as PNG or PAM).
 */
#include "check_internal.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static const uint8_t MARK[4] = { 255, 0, 255, 255 }; /* premultiplied opaque magenta */

/* Field k of the interface called name, or -1 (meanings come from the
 * interface table, not from knowing the layouts). */
static int field_named(const ef_iface_desc *d, const char *name)
{
    for (int k = 0; k < d->nfields; k++)
        if (strcmp(d->field[k].name, name) == 0)
            return k;
    return -1;
}

void chk_mark_txn(chk_run *r, const ef_txn *t)
{
    const ef_iface_desc *d = ef_iface_get(t->iface);
    int fy = field_named(d, "y"), fx = field_named(d, "x"), fl = field_named(d, "len");
    if (fy < 0 || fx < 0)
        return; /* not a pixel interface */
    if (r->nmarks == r->capmarks) {
        size_t cap = r->capmarks ? r->capmarks * 2 : 256;
        chk_mark *nm = cap < SIZE_MAX / sizeof *nm ? realloc(r->marks, cap * sizeof *nm) : NULL;
        if (!nm) {
            r->oom = 1;
            return;
        }
        r->marks = nm;
        r->capmarks = cap;
    }
    chk_mark *m = &r->marks[r->nmarks++];
    m->y = (int32_t)ef_txn_field(t, (unsigned)fy); /* 14-bit fields: no truncation */
    m->x = (int32_t)ef_txn_field(t, (unsigned)fx);
    m->len = fl >= 0 ? (int32_t)ef_txn_field(t, (unsigned)fl) : 1;
}

/* Without a size in any header: the smallest frame holding every expected
 * pixel and every mark. */
static void bounding_size(const chk_run *r, int32_t *w, int32_t *h)
{
    const ef_iface_desc *d = ef_iface_get(EF_IF_PIX);
    int fy = field_named(d, "y"), fx = field_named(d, "x");
    int64_t mw = 0, mh = 0;
    for (size_t k = 0; r->have_bg && k < r->bg.seq[EF_IF_PIX].n; k++) {
        ef_txn t;
        ef_vec_dump_txn(&r->bg, EF_IF_PIX, k, &t);
        int64_t x = (int64_t)ef_txn_field(&t, (unsigned)fx), y = (int64_t)ef_txn_field(&t, (unsigned)fy);
        mw = x + 1 > mw ? x + 1 : mw;
        mh = y + 1 > mh ? y + 1 : mh;
    }
    for (size_t k = 0; k < r->nmarks; k++) {
        int64_t x = (int64_t)r->marks[k].x + (r->marks[k].len > 0 ? r->marks[k].len : 1);
        mw = x > mw ? x : mw;
        mh = r->marks[k].y + 1 > mh ? r->marks[k].y + 1 : mh;
    }
    *w = (int32_t)(mw > EF_MAX_CANVAS ? EF_MAX_CANVAS : mw);
    *h = (int32_t)(mh > EF_MAX_CANVAS ? EF_MAX_CANVAS : mh);
}

static void paint(ef_image *img, int64_t x, int64_t y, const uint8_t rgba[4])
{
    if (x < 0 || y < 0 || x >= img->width || y >= img->height)
        return; /* a wrong coordinate from the RTL: nothing to draw */
    memcpy(img->px + (size_t)y * img->stride + (size_t)x * 4u, rgba, 4);
}

/* Every pix transaction of d in its blended colour, the last one of a pixel winning. */
static void draw_pix(ef_image *img, const ef_vec_dump *dump)
{
    const ef_iface_desc *d = ef_iface_get(EF_IF_PIX);
    int fy = field_named(d, "y"), fx = field_named(d, "x"), fc = field_named(d, "rgba");
    for (size_t k = 0; k < dump->seq[EF_IF_PIX].n; k++) {
        ef_txn t;
        ef_vec_dump_txn(dump, EF_IF_PIX, k, &t);
        uint64_t c = ef_txn_field(&t, (unsigned)fc); /* R in bits 31:24, then G, B, A */
        uint8_t px[4] = { (uint8_t)(c >> 24), (uint8_t)(c >> 16 & 0xffu), (uint8_t)(c >> 8 & 0xffu),
                          (uint8_t)(c & 0xffu) };
        paint(img, (int64_t)ef_txn_field(&t, (unsigned)fx), (int64_t)ef_txn_field(&t, (unsigned)fy), px);
    }
}

int ef_check_frame_image(const ef_vec_dump *d, ef_image *out, char *err, size_t errsize)
{
    memset(out, 0, sizeof *out);
    if (d->width <= 0 || d->height <= 0) {
        snprintf(err, errsize, "the frame size is unknown (the results carry no size)");
        errno = 0;
        return -1;
    }
    if (ef_image_create(out, d->width, d->height) != EF_OK) {
        snprintf(err, errsize, "out of memory for a %dx%d image", (int)d->width, (int)d->height);
        errno = ENOMEM;
        return -1;
    }
    memset(out->px, 0, out->stride * (size_t)out->height);
    draw_pix(out, d);
    return 0;
}

int ef_check_diff_image(const ef_check_result *res, ef_image *out, char *err, size_t errsize)
{
    const chk_run *r = res->run;
    int32_t w, h;
    ef_image img;

    memset(out, 0, sizeof *out);
    if (!r) {
        snprintf(err, errsize, "no comparison was run");
        errno = 0;
        return -1;
    }
    w = r->width;
    h = r->height;
    if (w <= 0 || h <= 0)
        bounding_size(r, &w, &h);
    if (w <= 0 || h <= 0) {
        snprintf(err, errsize, "the frame size is unknown (no 'size WxH' header, no manifest, no pixel)");
        errno = 0;
        return -1;
    }
    if (ef_image_create(&img, w, h) != EF_OK) {
        snprintf(err, errsize, "out of memory for a %dx%d image", (int)w, (int)h);
        errno = ENOMEM;
        return -1;
    }
    memset(img.px, 0, img.stride * (size_t)img.height);
    if (r->have_bg)
        draw_pix(&img, &r->bg);
    for (size_t k = 0; k < r->nmarks; k++) {
        const chk_mark *m = &r->marks[k];
        int64_t len = m->len > 0 ? m->len : 1; /* a zero-length span still marks its place */
        for (int64_t x = m->x; x < (int64_t)m->x + len && x < w; x++)
            paint(&img, x, m->y, MARK);
    }
    *out = img;
    return 0;
}
