/*
 * ef_scene.h - the readers: scenes (ef_scene_container.h) from SVG and
 * peerbench `.scene` text.
 *
 * The readers are the only place text becomes numbers: every number is parsed
 * exactly into Q31.32 (fixed/ef_fixed.h), transformed and flattened in fixed
 * point, and rounded once to the device format Q16.8 (docs/spec.md section 3).
 * Errors carry file, line and column.
 */
#ifndef EF_SCENE_H
#define EF_SCENE_H

#include "ef_scene_container.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Error report: where and what.  line/col are 1-based; 0 when unknown. */
typedef struct ef_error {
    ef_status status;
    char file[256];
    uint32_t line, col;
    char msg[256];
} ef_error;
/* Formats "file:line:col: message" into buf (always NUL-terminated). */
EF_API void ef_error_format(const ef_error *e, char *buf, size_t size);
/* Sets e's fields (printf-style message); returns status for tail calls. */
EF_API ef_status ef_error_set(ef_error *e, ef_status status, const char *file, uint32_t line, uint32_t col,
                              const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

/* Notes about features that were ignored (strokes, text, ...), one call per
 * kind and file: "file:line:col: note: ...".  May be NULL. */
typedef void (*ef_note_fn)(void *user, const char *file, uint32_t line, uint32_t col, const char *msg);

typedef struct ef_load_opts {
    int32_t fit_width, fit_height; /* 0, 0: the file's own size; else fit into WxH */
    ef_note_fn note;
    void *note_user;
} ef_load_opts;

/* ----- reading ----- */
/* By extension: ".svg" (SVG 1.1 subset, docs/input.md) or ".scene"/".txt"
 * (peerbench scene format).  On failure *err says where and why, and the
 * scene is left empty. */
EF_API ef_status ef_scene_load_file(const char *path, const ef_load_opts *opts, ef_scene *out, ef_error *err);
EF_API ef_status ef_scene_load_svg(const char *name, const char *data, size_t len, const ef_load_opts *opts,
                                   ef_scene *out, ef_error *err);
EF_API ef_status ef_scene_load_text(const char *name, const char *data, size_t len, const ef_load_opts *opts,
                                    ef_scene *out, ef_error *err);

#ifdef __cplusplus
}
#endif

#endif /* EF_SCENE_H */
