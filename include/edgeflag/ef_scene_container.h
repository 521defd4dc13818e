/*
 * ef_scene_container.h - a scene: painted shapes of polygons in device space
 * (Q16.8), the container that the readers (ef_scene.h) and generated scenes
 * (edgeflag gen) fill and that ef_scene_render paints.  It holds no text and
 * knows no file format: this header is the scene layer's data, the readers'
 * API is ef_scene.h.
 */
#ifndef EF_SCENE_CONTAINER_H
#define EF_SCENE_CONTAINER_H

#include "edgeflag.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ef_shape {
    ef_rule rule;
    ef_rgba8 color;         /* straight colour, a = fill opacity x opacity */
    uint32_t first_contour; /* into ef_scene.start */
    uint32_t ncontours;
} ef_shape;

/* A scene, read-only to its users: the arrays belong to the library (they grow
 * only through ef_scene_begin_shape and ef_scene_add_contour, and how much
 * room they have is the library's business, not a field). */
typedef struct ef_scene {
    int32_t width, height; /* canvas in pixels */
    ef_shape *shapes;
    uint32_t nshapes;
    uint32_t *start; /* contour c = points[start[c] .. start[c+1]-1] */
    uint32_t ncontours;
    ef_point *points;
    uint32_t npoints;
    uint32_t notes; /* count of ignored features reported to the note callback */
} ef_scene;

/* ----- building (used by the readers and by generated scenes) ----- */
/* An empty scene of a width x height canvas in *s (nothing allocated yet). */
EF_API void ef_scene_create(ef_scene *s, int32_t width, int32_t height);
/* Frees the arrays and leaves an empty 0 x 0 scene. */
EF_API void ef_scene_destroy(ef_scene *s);
EF_API ef_status ef_scene_begin_shape(ef_scene *s, ef_rule rule, ef_rgba8 color);
/* Appends a contour to the current shape; fewer than 3 points is allowed
 * (it contributes nothing: docs/spec.md 5.1). */
EF_API ef_status ef_scene_add_contour(ef_scene *s, const ef_point *pts, uint32_t n);
/* The polygon of shape i, valid until the scene changes. */
EF_API ef_polygon ef_scene_polygon(const ef_scene *s, uint32_t i);

/* ----- rendering a whole scene ----- */
/* Paints every shape in order, source-over, onto img (cleared by the caller).
 * rule_override < 0 keeps each shape's rule. */
EF_API ef_status ef_scene_render(ef_ctx *ctx, const ef_scene *s, int rule_override, ef_image *img);

#ifdef __cplusplus
}
#endif

#endif /* EF_SCENE_CONTAINER_H */
