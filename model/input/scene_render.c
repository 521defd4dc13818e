/*
 * scene_render.c - paints a scene's shapes in order (source-over), each with
 * its own fill rule unless the caller overrides it.
 */
#include "ef_scene.h"

ef_status ef_scene_render(ef_ctx *ctx, const ef_scene *s, int rule_override, ef_image *img)
{
    for (uint32_t i = 0; i < s->nshapes; i++) {
        ef_polygon poly = ef_scene_polygon(s, i);
        ef_rule rule = rule_override < 0 ? s->shapes[i].rule : (ef_rule)rule_override;
        ef_status st = ef_fill(ctx, img, &poly, rule, s->shapes[i].color);
        if (st != EF_OK)
            return st;
    }
    return EF_OK;
}
