/*
 * input_internal.h - what the front-end sources (model/input/) share and
 * nobody else sees.  Not installed; symbols are ef_in_ (library-internal) or
 * static.
 *
 * Data flow inside the front end:
 *
 *   text --(lexer.c: numbers, separators)--> Q31.32 user coordinates
 *        --(svg_path.c / scene_text.c / svg.c shapes)--> path commands
 *        --(flatten.c builder: transform.c CTM, Bezier flattening;
 *           arc.c: elliptical arcs)--> device Q16.8 contours
 *        --(scene.c)--> ef_scene
 *
 * docs/input.md is the contract for everything here.
 */
#ifndef EF_INPUT_INTERNAL_H
#define EF_INPUT_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ef_fixed.h"
#include "ef_scene.h"

/* ------------------------------------------------------------------ limits
 * (docs/input.md "Limits"; every one gives EF_ERR_LIMIT when exceeded) */
#define EF_IN_MAX_FILE_BYTES ((size_t)64 << 20) /* ef_scene_load_file */
#define EF_IN_MAX_DEPTH 256u                    /* XML nesting, and nesting through <use> */
#define EF_IN_MAX_ELEMENTS (1u << 20)           /* XML elements per SVG file */
#define EF_IN_MAX_VISITS (1u << 21)             /* element instances walked, <use> included */
#define EF_IN_MAX_SHAPES (1u << 24)             /* shapes per scene */
#ifndef EF_IN_MAX_WORK_LOG2                     /* SVG reading cost (svg.c, charge()); the fuzz */
#define EF_IN_MAX_WORK_LOG2 28u                 /* build lowers it to keep every input fast */
#endif
#define EF_IN_MAX_WORK ((uint64_t)1 << EF_IN_MAX_WORK_LOG2)
#define EF_IN_CURVE_MAX_SEGMENTS 256u /* Bezier flattening cap */
#define EF_IN_ARC_MAX_SEGMENTS 4096u  /* arc flattening cap */

/* Flattening tolerance: 1/16 px, in Q47.16 units. */
#define EF_IN_TOL_Q16 ((int64_t)1 << 12)

/* uint64 -> int64 modulo 2^64 and |v| as uint64: ef_wrap_i64, ef_abs_u64 (fixed/ef_fixed.h). */

/* ------------------------------------------------------- 128-bit helpers
 * Exact sums of the 128-bit products ef_mul_i64_wide returns.  Callers keep
 * every operand's magnitude below 2^125 so no sum of three wraps. */
static inline ef_i128 ef_in_i128_add(ef_i128 a, ef_i128 b)
{
    ef_i128 r;
    r.lo = a.lo + b.lo;
    uint64_t carry = r.lo < a.lo ? 1u : 0u;
    r.hi = ef_wrap_i64((uint64_t)a.hi + (uint64_t)b.hi + carry); /* bounded: no wrap */
    return r;
}
/* v * 2^s for a non-negative 64-bit shift into 128 bits (0 <= s < 64). */
static inline ef_i128 ef_in_i128_from_i64_shl(int64_t v, unsigned s)
{
    ef_i128 r;
    if (s == 0) {
        r.lo = (uint64_t)v;
        r.hi = v < 0 ? -1 : 0;
    } else {
        r.lo = (uint64_t)v << s;
        r.hi = ef_asr_i64(v, 64u - s);
    }
    return r;
}
/* floor(v / 2^n + 1/2) (ties toward +inf) for 1 <= n <= 126; false if the
 * result does not fit int64. */
bool ef_in_i128_round_shr(ef_i128 v, unsigned n, int64_t *out);
/* True when |v| >= 2^bits (1 <= bits <= 126): a quick range test. */
bool ef_in_i128_exceeds(ef_i128 v, unsigned bits);

/* ----------------------------------------------------------------- lexer
 * Separators and numbers of the SVG attribute grammars (SVG 1.1 8.3.9:
 * wsp = space, tab, CR, LF; comma-wsp = wsp+ ','? wsp* | ',' wsp*). */
typedef struct ef_in_lex {
    const char *s;
    size_t len, pos;
} ef_in_lex;

static inline bool ef_in_is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
static inline bool ef_in_lex_end(const ef_in_lex *l) { return l->pos >= l->len; }
static inline char ef_in_lex_peek(const ef_in_lex *l) { return l->pos < l->len ? l->s[l->pos] : '\0'; }
/* Skips wsp*; returns how many characters were skipped. */
size_t ef_in_lex_wsp(ef_in_lex *l);
/* Skips comma-wsp?; returns 0 (nothing), 1 (white space only) or 2 (a comma). */
int ef_in_lex_sep(ef_in_lex *l);
/* Could a number start here ([+-.0-9])? */
bool ef_in_lex_at_number(const ef_in_lex *l);
/* Parses one number (ef_parse_decimal_q32 grammar).  On failure pos stays at
 * the number and err holds EF_ERR_SYNTAX or EF_ERR_RANGE (no position). */
ef_status ef_in_lex_number(ef_in_lex *l, ef_q32 *out, ef_error *err);

/* -------------------------------------------------------------- affine
 * x' = a x + c y + e, y' = b x + d y + f; coefficients Q31.32. */
typedef struct ef_in_affine {
    ef_q32 a, b, c, d, e, f;
} ef_in_affine;

ef_in_affine ef_in_affine_identity(void);
ef_in_affine ef_in_affine_scale_translate(ef_q32 sx, ef_q32 sy, ef_q32 tx, ef_q32 ty);
/* out = m * n (n applied first).  Each coefficient is a sum of exact 128-bit
 * products rounded once to Q31.32 (ties toward +inf).  EF_ERR_RANGE if a
 * coefficient leaves Q31.32. */
ef_status ef_in_affine_mul(const ef_in_affine *m, const ef_in_affine *n, ef_in_affine *out);
/* p*q + r*s + t rounded once to Q31.32 (ties toward +inf) from the exact
 * 128-bit sum; false if the result leaves Q31.32. */
bool ef_in_q32_dot2(ef_q32 p, ef_q32 q, ef_q32 r, ef_q32 s, ef_q32 t, ef_q32 *out);
/* The image rounded once to device Q16.8 (floor(v / 2^56 + 1/2)); EF_ERR_RANGE
 * unless |x|, |y| < EF_COORD_LIMIT. */
ef_status ef_in_affine_apply_dev(const ef_in_affine *m, ef_q32 x, ef_q32 y, ef_point *out);
/* The image rounded once to Q47.16 (floor(v / 2^48 + 1/2)); EF_ERR_RANGE
 * unless |x|, |y| < 2^31 (32768 px). */
ef_status ef_in_affine_apply_q16(const ef_in_affine *m, ef_q32 x, ef_q32 y, int64_t *X, int64_t *Y);
/* The image rounded once to Q31.32; EF_ERR_RANGE outside Q31.32. */
ef_status ef_in_affine_apply_q32(const ef_in_affine *m, ef_q32 x, ef_q32 y, ef_q32 *X, ef_q32 *Y);
/* Parses an SVG transform list into *out (identity for an empty list).  On
 * error err holds the message and *err_off the offset in s. */
ef_status ef_in_transform_parse(const char *s, size_t len, ef_in_affine *out, size_t *err_off, ef_error *err);

/* sin, cos of an angle in degrees (Q31.32) as Q31.32 values. */
void ef_in_sincos_deg(ef_q32 deg, ef_q32 *s, ef_q32 *c);

/* ----------------------------------------------------- geometry builder
 * Collects the contours of one element in device space.  Points equal to the
 * previous one are not repeated, a closing point equal to the first is
 * dropped, and contours left with fewer than 3 points are dropped: all of
 * these change no sample (docs/spec.md 5.1). */
typedef struct ef_in_builder {
    ef_in_affine ctm;
    ef_point *pts;
    uint32_t npts, pts_cap;
    uint32_t *start; /* contour c = pts[start[c] .. start[c+1]-1] */
    uint32_t ncont, start_cap;
    uint32_t cur;    /* first point of the open contour */
    bool open;       /* a contour is open */
    uint32_t budget; /* points the scene can still take */
} ef_in_builder;

void ef_in_builder_init(ef_in_builder *b);
void ef_in_builder_free(ef_in_builder *b);
/* Empties the builder and sets the CTM and the point budget. */
void ef_in_builder_reset(ef_in_builder *b, const ef_in_affine *ctm, uint32_t budget);
/* Starts a new contour at user point (x, y) (closing the open one). */
ef_status ef_in_build_move(ef_in_builder *b, ef_q32 x, ef_q32 y, ef_error *err);
/* Appends user point (x, y), rounded once to Q16.8. */
ef_status ef_in_build_line(ef_in_builder *b, ef_q32 x, ef_q32 y, ef_error *err);
/* Appends an already-rounded device point. */
ef_status ef_in_build_point(ef_in_builder *b, ef_point p, ef_error *err);
/* Flattens a quadratic / cubic Bezier with user-space control points; the
 * first point is the current point (already emitted). */
ef_status ef_in_build_quad(ef_in_builder *b, const ef_q32 p[6], ef_error *err);
ef_status ef_in_build_cubic(ef_in_builder *b, const ef_q32 p[8], ef_error *err);
/* Closes the open contour (if any). */
void ef_in_build_close(ef_in_builder *b);
/* Closes, then appends the element's contours as one shape of s (nothing if
 * no contour survived). */
ef_status ef_in_builder_commit(ef_in_builder *b, ef_scene *s, ef_rule rule, ef_rgba8 color, ef_error *err);

/* ------------------------------------------------------------------ arcs */
/* An arc of the ellipse centre + R(phi) (rx cos t, ry sin t), t from t0 over
 * |delta| (0 < |delta| <= 2^32 binary-angle units) in direction dir (+1: t
 * increasing), ending exactly at user point (ex, ey). */
typedef struct ef_in_ellarc {
    ef_q32 cx, cy, rx, ry;
    int32_t cos_phi, sin_phi; /* Q1.30 */
    ef_angle t0;
    int64_t delta; /* magnitude, 1 .. 2^32 */
    int dir;       /* +1 or -1 */
    ef_q32 ex, ey;
} ef_in_ellarc;
ef_status ef_in_build_ellarc(ef_in_builder *b, const ef_in_ellarc *arc, ef_error *err);
/* SVG elliptical arc command from (x0, y0) to (x, y) (SVG 1.1 F.6.5/F.6.6). */
ef_status ef_in_build_svg_arc(ef_in_builder *b, ef_q32 x0, ef_q32 y0, ef_q32 rx, ef_q32 ry, ef_q32 phi_deg, bool large,
                              bool sweep, ef_q32 x, ef_q32 y, ef_error *err);
/* sqrt(a^2 + b^2) in Q31.32 without intermediate overflow; false past range. */
bool ef_in_hypot_q32(ef_q32 a, ef_q32 b, ef_q32 *out);

/* ------------------------------------------------------------ path data */
/* Parses SVG path data and feeds the builder.  *err_off: offset of the error. */
ef_status ef_in_path_parse(const char *d, size_t len, ef_in_builder *b, size_t *err_off, ef_error *err);
/* Parses a points list (polygon/polyline) into one contour. */
ef_status ef_in_points_parse(const char *s, size_t len, ef_in_builder *b, size_t *err_off, ef_error *err);

/* ---------------------------------------------------------------- colour */
typedef enum ef_in_paint_kind {
    EF_IN_PAINT_NONE = 0,
    EF_IN_PAINT_RGB,
    EF_IN_PAINT_CURRENT, /* currentColor */
    EF_IN_PAINT_URL      /* url(#id) [fallback] */
} ef_in_paint_kind;

typedef struct ef_in_paint {
    ef_in_paint_kind kind;
    uint8_t r, g, b;
    ef_q32 alpha; /* [0, 1]: rgba() alpha, 0 for "transparent" */
    /* url: the id (offset/length into the parsed string) and the fallback */
    size_t url_off, url_len;
    ef_in_paint_kind fallback_kind; /* NONE when there is no fallback */
    uint8_t fr, fg, fb;
    ef_q32 falpha;
    bool has_fallback;
} ef_in_paint;

/* Parses a paint (fill) value: none | currentColor | <color> | url(#id) [none|currentColor|<color>]. */
ef_status ef_in_paint_parse(const char *s, size_t len, ef_in_paint *out, size_t *err_off, ef_error *err);
/* Parses a <color> (no none/url); currentColor gives EF_IN_PAINT_CURRENT. */
ef_status ef_in_color_parse(const char *s, size_t len, ef_in_paint *out, size_t *err_off, ef_error *err);
/* Parses an opacity: <number> or <percentage>, clamped to [0, 1]. */
ef_status ef_in_opacity_parse(const char *s, size_t len, ef_q32 *out, size_t *err_off, ef_error *err);
/* round(255 * p) for p in [0, 1] (Q31.32), ties toward +inf. */
uint8_t ef_in_alpha8(ef_q32 p);

/* ------------------------------------------------------------ scene glue */
/* Points (= edges) of the scene's last shape; 0 before the first shape. */
static inline uint32_t ef_in_shape_points(const ef_scene *s)
{
    return s->nshapes ? s->npoints - s->start[s->shapes[s->nshapes - 1].first_contour] : 0;
}
/* Notes: one call per kind and file (ef_load_opts.note). */
void ef_in_note(const ef_load_opts *opts, ef_scene *s, const char *file, uint32_t line, uint32_t col, const char *msg);
/* Canvas size ceil(v) for a positive Q31.32 value; EF_ERR_LIMIT outside
 * 1 .. EF_MAX_CANVAS. */
ef_status ef_in_canvas_size(ef_q32 v, int32_t *out);
/* Column (1-based) of byte offset `off` of a line starting at `line_start`,
 * counting UTF-8 characters as expat does. */
uint32_t ef_in_utf8_col(const char *line_start, size_t off);

/* ------------------------------------------------------------- XML tree
 * svg_dom.c: the document as a tree (expat), kept with the input so that
 * attribute errors can be located to the character. */
#define EF_IN_NONE UINT32_MAX

typedef struct ef_in_attr {
    uint32_t name; /* pool offset: "local" or "namespace-uri local" */
    uint32_t value, value_len;
} ef_in_attr;

typedef struct ef_in_node {
    uint32_t name; /* pool offset of the local name */
    uint32_t parent, first_child, last_child, next;
    uint32_t attr0, nattr;
    uint32_t line, col;      /* 1-based position of the '<' */
    size_t byte;             /* byte offset of the '<' in the input */
    uint32_t text, text_len; /* character data of <style> elements */
    bool svg;                /* SVG namespace, or no namespace */
    bool active;             /* on the current walk path (cycle check) */
} ef_in_node;

typedef struct ef_in_dom {
    const char *data;
    size_t len;
    ef_in_node *nodes;
    uint32_t nnodes, nodes_cap;
    ef_in_attr *attrs;
    uint32_t nattrs, attrs_cap;
    char *pool;
    size_t pool_len, pool_cap;
} ef_in_dom;

#define EF_IN_XLINK_HREF "http://www.w3.org/1999/xlink href"

/* Parses data (UTF-8/UTF-16 with BOM or declaration, as expat reads it) into
 * dom.  Entity declarations, undefined entities, nesting deeper than
 * EF_IN_MAX_DEPTH and more than EF_IN_MAX_ELEMENTS elements are errors. */
ef_status ef_in_dom_parse(ef_in_dom *dom, const char *name, const char *data, size_t len, ef_error *err);
void ef_in_dom_free(ef_in_dom *dom);
static inline const char *ef_in_dom_str(const ef_in_dom *dom, uint32_t off) { return dom->pool + off; }
/* Value of attribute `name` of node (NULL if absent); *len its length. */
const char *ef_in_dom_attr(const ef_in_dom *dom, uint32_t node, const char *name, size_t *len);
/* Line and column of character `idx` of the value of unprefixed attribute
 * `attr` of node, from the raw input; the element's position if the
 * attribute cannot be found or the value holds references before idx. */
void ef_in_dom_locate(const ef_in_dom *dom, uint32_t node, const char *attr, size_t idx, uint32_t *line, uint32_t *col);

/* ------------------------------------------------------------------ CSS
 * svg_css.c: declarations ("name: value; ...") and simple stylesheets.
 * Pointers point into the text given to the parser (style attributes) or
 * into the stylesheet's own copies (<style> contents). */
typedef struct ef_in_decl {
    const char *name, *value;
    size_t name_len, value_len;
    size_t value_off; /* offset of the value in the parsed text */
} ef_in_decl;

typedef struct ef_in_decls {
    ef_in_decl *d;
    uint32_t n, cap;
} ef_in_decls;

/* Appends the declarations of s[0..len) to out.  Empty declarations are
 * skipped and "!important" is dropped; a declaration without ':' is an
 * error at *err_off. */
ef_status ef_in_css_decls(const char *s, size_t len, ef_in_decls *out, size_t *err_off, ef_error *err);

typedef struct ef_in_css_rule {
    const char *tag, *cls, *id; /* NULL: not part of the selector */
    size_t tag_len, cls_len, id_len;
    uint32_t specificity;  /* ids << 16 | classes << 8 | types */
    uint32_t order;        /* source order */
    uint32_t decl0, ndecl; /* into ef_in_css.decls */
    uint32_t node;         /* the <style> element (error positions) */
} ef_in_css_rule;

typedef struct ef_in_css {
    ef_in_css_rule *rules;
    uint32_t nrules, rules_cap;
    ef_in_decls decls;
    char **texts; /* owned copies of the style sheets */
    uint32_t ntexts, texts_cap;
} ef_in_css;

/* Adds the rules of one style sheet.  Selectors other than type, .class,
 * #id, type.class and * are skipped and so are at-rules: *unsupported is
 * set when that happens. */
ef_status ef_in_css_add(ef_in_css *css, const char *text, size_t len, uint32_t node, bool *unsupported, ef_error *err);
void ef_in_css_free(ef_in_css *css);
/* Does rule r select an element with this tag, class attribute and id? */
bool ef_in_css_match(const ef_in_css_rule *r, const char *tag, const char *cls, size_t cls_len, const char *id,
                     size_t id_len);

#endif /* EF_INPUT_INTERNAL_H */
