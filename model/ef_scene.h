/*
 * ef_scene.h - scenes (painted shapes of polygons in device space) and the
 * readers that build them from SVG and peerbench `.scene` text.
 *
 * The readers are the only place text becomes numbers: every number is parsed
 * exactly into Q31.32 (fixed/ef_fixed.h), transformed and flattened in fixed
 * point, and rounded once to the device format Q16.8 (docs/spec.md section 3).
 * Errors carry file, line and column.
 */
#ifndef EF_SCENE_H
#define EF_SCENE_H

#include "edgeflag.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ef_shape {
    ef_rule rule;
    ef_rgba8 color;          /* straight colour, a = fill opacity x opacity */
    uint32_t first_contour;  /* into ef_scene.start */
    uint32_t ncontours;
} ef_shape;

typedef struct ef_scene {
    int32_t width, height;   /* canvas in pixels */
    ef_shape *shapes;
    uint32_t nshapes, shapes_cap;
    uint32_t *start;         /* contour c = points[start[c] .. start[c+1]-1] */
    uint32_t ncontours, start_cap;
    ef_point *points;
    uint32_t npoints, points_cap;
    uint32_t notes;          /* count of ignored features reported to the note callback */
} ef_scene;

/* Error report: where and what.  line/col are 1-based; 0 when unknown. */
typedef struct ef_error {
    ef_status status;
    char file[256];
    uint32_t line, col;
    char msg[256];
} ef_error;
/* Formats "file:line:col: message" into buf (always NUL-terminated). */
void ef_error_format(const ef_error *e, char *buf, size_t size);
/* Sets e's fields (printf-style message); returns status for tail calls. */
ef_status ef_error_set(ef_error *e, ef_status status, const char *file, uint32_t line,
                       uint32_t col, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

/* Notes about features that were ignored (strokes, text, ...), one call per
 * kind and file: "file:line:col: note: ...".  May be NULL. */
typedef void (*ef_note_fn)(void *user, const char *file, uint32_t line, uint32_t col, const char *msg);

typedef struct ef_load_opts {
    int32_t fit_width, fit_height;  /* 0, 0: the file's own size; else fit into WxH */
    ef_note_fn note;
    void *note_user;
} ef_load_opts;

/* ----- building (used by the readers and by generated scenes) ----- */
void ef_scene_init(ef_scene *s, int32_t width, int32_t height);
void ef_scene_free(ef_scene *s);
ef_status ef_scene_begin_shape(ef_scene *s, ef_rule rule, ef_rgba8 color);
/* Appends a contour to the current shape; fewer than 3 points is allowed
 * (it contributes nothing: docs/spec.md 5.1). */
ef_status ef_scene_add_contour(ef_scene *s, const ef_point *pts, uint32_t n);
/* The polygon of shape i, valid until the scene changes. */
ef_polygon ef_scene_polygon(const ef_scene *s, uint32_t i);

/* ----- reading ----- */
/* By extension: ".svg" (SVG 1.1 subset, docs/input.md) or ".scene"/".txt"
 * (peerbench scene format).  On failure *err says where and why, and the
 * scene is left empty. */
ef_status ef_scene_load_file(const char *path, const ef_load_opts *opts, ef_scene *out, ef_error *err);
ef_status ef_scene_load_svg(const char *name, const char *data, size_t len, const ef_load_opts *opts,
                            ef_scene *out, ef_error *err);
ef_status ef_scene_load_text(const char *name, const char *data, size_t len, const ef_load_opts *opts,
                             ef_scene *out, ef_error *err);

/* ----- rendering a whole scene ----- */
/* Paints every shape in order, source-over, onto img (cleared by the caller).
 * rule_override < 0 keeps each shape's rule. */
ef_status ef_scene_render(ef_ctx *ctx, const ef_scene *s, int rule_override, ef_image *img);

#ifdef __cplusplus
}
#endif

#endif /* EF_SCENE_H */
