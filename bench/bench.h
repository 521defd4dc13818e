/*
 * bench.h - the side-by-side benchmark (bench/): scenes in double precision,
 * the per-frame transform of peerbench's SPEC section 3, and one small
 * interface that every renderer (edgeflag at 8/16/32 samples, AGG, Cairo,
 * FreeType's smooth rasterizer, stb_truetype) implements.
 *
 * The benchmark is outside the model, so it may use floating point: the peers
 * take double vertices.  Every renderer receives the same vertices, which are
 * exact multiples of 1/256 px, and composites a solid colour premultiplied
 * source-over onto an RGBA8 buffer cleared to transparent (docs/spec.md 8).
 */
#ifndef EF_BENCH_H
#define EF_BENCH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { B_NONZERO = 0, B_EVENODD = 1 }; /* the same values as ef_rule */

typedef struct bpoint {
    double x, y;
} bpoint;

typedef struct bshape {
    int rule;           /* B_NONZERO or B_EVENODD */
    uint8_t r, g, b, a; /* straight colour, a = opacity */
    uint32_t first;     /* first contour (index into bscene.start) */
    uint32_t ncontours;
} bshape;

/* A scene: contour c is pts[start[c] .. start[c+1]-1] (implicitly closed),
 * shape i owns contours first .. first+ncontours-1.  The frame transform
 * changes only the points, so a frame is this topology plus a point array. */
typedef struct bscene {
    char name[64];
    double w, h; /* the scene's own canvas (the transform fits it) */
    bshape *shapes;
    uint32_t nshapes;
    uint32_t *start; /* ncontours + 1 entries */
    uint32_t ncontours;
    bpoint *pts;
    uint32_t npoints;
    uint32_t max_shape_points, max_shape_contours;
    int has_evenodd;
} bscene;

/* ---- scenes (scene.c) ---- */
/* SVG or .scene/.txt through ef_scene_load_file, fitted to fit_w x fit_h
 * (exact Q16.8 device polygons), each vertex converted to v / 256.0. */
int bscene_load(bscene *s, const char *path, int fit_w, int fit_h, char *err, size_t errlen);
/* A paragraph of DejaVu Sans text, one shape (non-zero) per glyph, outlines
 * from FreeType flattened to polygons (textscene.c). */
int bscene_text(bscene *s, const char *font_path, char *err, size_t errlen);
/* rule < 0 keeps the file's rules; else every shape gets `rule`. */
void bscene_set_rule(bscene *s, int rule);
void bscene_free(bscene *s);
/* Recomputes the derived fields (max_shape_*, has_evenodd) after building. */
void bscene_finish(bscene *s);
/* Puts an opaque white rectangle, larger than the canvas in every frame, under
 * the scene as its first shape and appends "_white" to its name.  -1: out of
 * memory (the scene is unchanged). */
int bscene_add_background(bscene *s);
/* peerbench SPEC section 3: fit into W x H, rotate k*0.1 degree about the
 * canvas centre, move (0.05k, 0.03k) px, snap to 1/256 px.  out has
 * s->npoints entries. */
void bscene_frame(const bscene *s, int W, int H, int k, bpoint *out);

/* ---- renderers ---- */
typedef struct brenderer {
    const char *name;
    /* NULL if the renderer can draw s, else why not. */
    const char *(*unsupported)(const bscene *s);
    void *(*create)(int w, int h);                                /* untimed */
    void (*clear)(void *st);                                      /* untimed: transparent */
    void (*render)(void *st, const bscene *s, const bpoint *pts); /* timed */
    /* The result as premultiplied RGBA8, w*h*4 bytes, rows top down. */
    void (*read)(void *st, uint8_t *rgba);
    void (*destroy)(void *st);
} brenderer;

extern const brenderer br_agg, br_cairo, br_cairo_noaa, br_freetype, br_stb, br_ef8, br_ef16, br_ef32, br_truth;
/* The spec 10 options (r_edgeflag.c) and their dense filtered truths
 * (truth_filter.c): tent; box with RGB offsets; tent with RGB offsets.
 * bench_truth_of names the truth a renderer is measured against. */
extern const brenderer br_ef8t, br_ef16t, br_ef32t, br_ef16rgb, br_ef16trgb;
extern const brenderer br_truth_tent, br_truth_rgb, br_truth_trgb;
const brenderer *bench_truth_of(const brenderer *r);

/* r_edgeflag.c: hashes of edgeflag's image (ef_fill) and span stream
 * (ef_rasterize) for one frame, and its diagnostics (edges in, dropped,
 * winding overflows); returns 0, 1 if the two paths' diagnostics differ. */
int bench_ef_hash(int samples, int w, int h, const bscene *s, const bpoint *pts, uint64_t *img_hash, uint64_t *spans,
                  uint64_t diag[3]);

/* ---- shared helpers ---- */
/* An RGBA8 premultiplied canvas used by several renderers. */
typedef struct bcanvas {
    uint8_t *px;
    int w, h;
    size_t stride;
} bcanvas;
int bcanvas_init(bcanvas *c, int w, int h);
void bcanvas_free(bcanvas *c);
/* docs/spec.md section 8 (AGG's blender_rgba_pre), clipped to the canvas. */
void bblend_hline(const bcanvas *c, const bshape *s, int x, int y, int len, unsigned cover);
void bblend_hspan(const bcanvas *c, const bshape *s, int x, int y, int len, const uint8_t *covers);

#ifdef __cplusplus
}
#endif

#endif /* EF_BENCH_H */
