/*
 * common.c - the RGBA8 canvas and the compositing that FreeType's and stb's
 * adapters (and the truth renderer) share: docs/spec.md section 8, which is
 * AGG's blender_rgba_pre and edgeflag's composite.c, so that every image
 * difference between these renderers comes from coverage alone.
 */
#include <stdlib.h>
#include <string.h>

#include "bench.h"

int bcanvas_init(bcanvas *c, int w, int h)
{
    c->w = w;
    c->h = h;
    c->stride = (size_t)w * 4;
    c->px = calloc((size_t)h, c->stride);
    return c->px ? 0 : -1;
}

void bcanvas_free(bcanvas *c)
{
    free(c->px);
    memset(c, 0, sizeof *c);
}

static inline unsigned mul255(unsigned a, unsigned b)
{
    unsigned t = a * b + 128u;
    return ((t >> 8) + t) >> 8;
}

static inline void blend_px(uint8_t *p, const uint8_t P[4], unsigned cov)
{
    if (cov == 255 && P[3] == 255) {
        memcpy(p, P, 4);
        return;
    }
    unsigned sa = mul255(P[3], cov);
    for (int ch = 0; ch < 4; ch++)
        p[ch] = (uint8_t)(p[ch] + mul255(P[ch], cov) - mul255(p[ch], sa));
}

static void premul(const bshape *s, uint8_t P[4])
{
    P[0] = (uint8_t)mul255(s->r, s->a);
    P[1] = (uint8_t)mul255(s->g, s->a);
    P[2] = (uint8_t)mul255(s->b, s->a);
    P[3] = s->a;
}

void bblend_hline(const bcanvas *c, const bshape *s, int x, int y, int len, unsigned cover)
{
    if (y < 0 || y >= c->h || cover == 0)
        return;
    if (x < 0) {
        len += x;
        x = 0;
    }
    if (x + len > c->w)
        len = c->w - x;
    if (len <= 0)
        return;
    uint8_t P[4];
    premul(s, P);
    uint8_t *p = c->px + (size_t)y * c->stride + (size_t)x * 4;
    for (int i = 0; i < len; i++, p += 4)
        blend_px(p, P, cover);
}

void bblend_hspan(const bcanvas *c, const bshape *s, int x, int y, int len, const uint8_t *covers)
{
    if (y < 0 || y >= c->h)
        return;
    if (x < 0) {
        covers -= x;
        len += x;
        x = 0;
    }
    if (x + len > c->w)
        len = c->w - x;
    if (len <= 0)
        return;
    uint8_t P[4];
    premul(s, P);
    uint8_t *p = c->px + (size_t)y * c->stride + (size_t)x * 4;
    for (int i = 0; i < len; i++, p += 4)
        if (covers[i])
            blend_px(p, P, covers[i]);
}
