// r_agg.cpp - AGG 2.4 (Debian's libagg-dev) as a benchmark renderer: the one
// C++ translation unit of bench/, exposing the C renderer interface of
// bench.h.  rasterizer_scanline_aa<> (24.8 sub-pixel, exact cell area
// coverage, identity gamma, clip box = canvas) + scanline_u8 +
// render_scanlines_aa_solid onto pixfmt_rgba32_pre: premultiplied
// source-over, the arithmetic of docs/spec.md section 8.  One rasterizer and
// scanline reused for the run; move_to_d/line_to_d convert the doubles to
// 24.8 inside the timed call.
#include <cstdlib>
#include <cstring>
#include <new>

#include <agg_basics.h>
#include <agg_pixfmt_rgba.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_u.h>

#include "bench.h"

namespace
{

struct AggState {
    int w = 0, h = 0;
    unsigned char *px = nullptr;
    agg::rendering_buffer rbuf;
    agg::rasterizer_scanline_aa<> ras;
    agg::scanline_u8 sl;
};

void *agg_create(int w, int h)
{
    AggState *st = new (std::nothrow) AggState;
    if (!st)
        return nullptr;
    st->w = w;
    st->h = h;
    st->px = static_cast<unsigned char *>(std::calloc(static_cast<size_t>(w) * h, 4));
    if (!st->px) {
        delete st;
        return nullptr;
    }
    st->rbuf.attach(st->px, w, h, w * 4);
    st->ras.clip_box(0, 0, w, h);
    return st;
}

void agg_clear(void *p)
{
    AggState *st = static_cast<AggState *>(p);
    std::memset(st->px, 0, static_cast<size_t>(st->w) * st->h * 4);
}

void agg_render(void *p, const bscene *s, const bpoint *pts)
{
    AggState *st = static_cast<AggState *>(p);
    typedef agg::pixfmt_rgba32_pre PixFmt;
    PixFmt pf(st->rbuf);
    agg::renderer_base<PixFmt> rb(pf);
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const bshape &sh = s->shapes[i];
        st->ras.reset();
        st->ras.filling_rule(sh.rule == B_EVENODD ? agg::fill_even_odd : agg::fill_non_zero);
        for (uint32_t c = sh.first; c < sh.first + sh.ncontours; c++) {
            uint32_t a = s->start[c], b = s->start[c + 1];
            if (a == b)
                continue;
            st->ras.move_to_d(pts[a].x, pts[a].y);
            for (uint32_t k = a + 1; k < b; k++)
                st->ras.line_to_d(pts[k].x, pts[k].y);
            st->ras.close_polygon();
        }
        agg::rgba8 col(sh.r, sh.g, sh.b, sh.a);
        col.premultiply();
        agg::render_scanlines_aa_solid(st->ras, st->sl, rb, col);
    }
}

void agg_read(void *p, uint8_t *rgba)
{
    AggState *st = static_cast<AggState *>(p);
    std::memcpy(rgba, st->px, static_cast<size_t>(st->w) * st->h * 4);
}

void agg_destroy(void *p)
{
    AggState *st = static_cast<AggState *>(p);
    if (!st)
        return;
    std::free(st->px);
    delete st;
}

const char *agg_unsupported(const bscene *) { return nullptr; }

}   // namespace

extern "C" const brenderer br_agg = {
    "agg", agg_unsupported, agg_create, agg_clear, agg_render, agg_read, agg_destroy
};
