/*
 * svg.c - the SVG reader: canvas and viewport, the element walk, properties
 * and their inheritance, and shapes to contours.
 *
 * Place in the pipeline: svg_dom.c has parsed the XML into a tree; this file
 * walks it from the root <svg>, keeps the CTM (Q31.32) and the inherited
 * properties, and hands every filled shape's geometry to the builder
 * (flatten.c, arc.c), which produces device Q16.8 contours.  The subset and
 * every choice made where SVG leaves room are documented in docs/input.md;
 * in short:
 *
 *  - drawn: path, rect (rx/ry corners as quarter arcs), circle, ellipse,
 *    polygon, polyline (filled as a closed polygon); line has no area;
 *  - containers: svg, g, a, switch (first child without a requiredExtensions
 *    or systemLanguage test); <use> of any element by id (x, y, transform;
 *    a <symbol> target draws its children);
 *  - properties: fill, fill-opacity, fill-rule, opacity (multiplied down the
 *    tree into the shape's alpha: no group compositing), color, visibility,
 *    display; from presentation attributes, then <style> rules in order of
 *    specificity, then the style attribute; "inherit" is understood;
 *  - url(#gradient) fills use the average of the gradient's stop colours and
 *    stop opacities; patterns use the fallback colour, if any;
 *  - ignored, with one note per kind and file: strokes, text, image,
 *    foreignObject, clipping, masks, filters, unsupported CSS, nested-svg
 *    clipping, symbol viewBox, unknown elements.
 *
 * Any error (syntax, range, limit) rejects the whole file with file:line:col;
 * the scene is left empty.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_internal.h"

/* Note kinds: each is reported once per file. */
enum {
    NOTE_STROKE = 1u << 0,
    NOTE_TEXT = 1u << 1,
    NOTE_IMAGE = 1u << 2,
    NOTE_CLIP = 1u << 3,
    NOTE_MASK = 1u << 4,
    NOTE_FILTER = 1u << 5,
    NOTE_GRADIENT = 1u << 6,
    NOTE_PATTERN = 1u << 7,
    NOTE_UNRESOLVED = 1u << 8,
    NOTE_ELEMENT = 1u << 9,
    NOTE_FOREIGN = 1u << 10,
    NOTE_CSS = 1u << 11,
    NOTE_NESTED_SVG = 1u << 12,
    NOTE_SYMBOL = 1u << 13,
    NOTE_USE_MISSING = 1u << 14
};

typedef struct svg_paint {
    ef_in_paint p;
    uint32_t ref; /* url(#id) target node, EF_IN_NONE if missing */
} svg_paint;

/* Inherited properties. */
typedef struct svg_style {
    svg_paint fill;
    ef_q32 fill_opacity;
    ef_rule rule;
    bool stroke;        /* stroke is not none */
    uint8_t cr, cg, cb; /* the 'color' property (for currentColor) */
    ef_q32 calpha;
    bool visible;
} svg_style;

/* Properties that are not inherited, for one element. */
typedef struct svg_local {
    ef_q32 opacity;
    bool display_none;
    bool clip, mask, filter;
    ef_in_paint stop_color; /* kind NONE until set */
    bool stop_color_set;
    ef_q32 stop_opacity;
} svg_local;

/* What a child sees of its parent. */
typedef struct svg_frame {
    ef_in_affine ctm;
    svg_style style;
    ef_q32 opacity;       /* product of the ancestors' opacity */
    ef_q32 vpw, vph, vpd; /* viewport size for percentages; vpd = diagonal / sqrt 2 */
} svg_frame;

typedef struct id_entry {
    const char *id;
    uint32_t node;
} id_entry;

typedef struct svg_ctx {
    const char *name;
    const ef_load_opts *opts;
    ef_error *err;
    ef_scene *scene;
    ef_in_dom dom;
    ef_in_css css;
    ef_in_builder b;
    id_entry *ids;
    uint32_t nids;
    uint32_t noted;
    uint64_t visits;
    uint64_t work;     /* reading cost so far (charge()) */
    ef_in_decls decls; /* scratch: a style attribute's declarations */
    uint64_t *matched; /* scratch: matching CSS rules, specificity << 32 | index */
    uint32_t nmatched, matched_cap;
} svg_ctx;

/* --------------------------------------------------------------- helpers */

static const char *tag_of(const svg_ctx *c, uint32_t node) { return ef_in_dom_str(&c->dom, c->dom.nodes[node].name); }
static bool is(const char *a, const char *b) { return strcmp(a, b) == 0; }

static void note(svg_ctx *c, uint32_t kind, uint32_t node, const char *msg)
{
    if (c->noted & kind)
        return;
    c->noted |= kind;
    const ef_in_node *n = &c->dom.nodes[node];
    ef_in_note(c->opts, c->scene, c->name, n->line, n->col, msg);
}

/* Puts the position on an error whose status and message are already set:
 * the character `off` of attribute `attr` (or the element when attr is NULL),
 * and names the attribute and element. */
static ef_status locate(svg_ctx *c, uint32_t node, const char *attr, size_t off)
{
    ef_error *e = c->err;
    uint32_t line, col;
    if (attr)
        ef_in_dom_locate(&c->dom, node, attr, off, &line, &col);
    else {
        line = c->dom.nodes[node].line;
        col = c->dom.nodes[node].col;
    }
    char orig[sizeof e->msg];
    memcpy(orig, e->msg, sizeof orig);
    orig[sizeof orig - 1] = '\0';
    ef_status st = e->status;
    if (attr)
        ef_error_set(e, st, c->name, line, col, "%.190s (attribute '%.24s' of <%.24s>)", orig, attr, tag_of(c, node));
    else
        ef_error_set(e, st, c->name, line, col, "%.190s (in <%.24s>)", orig, tag_of(c, node));
    return st;
}

static ef_status fail(svg_ctx *c, uint32_t node, const char *attr, size_t off, ef_status st, const char *msg)
{
    ef_error_set(c->err, st, NULL, 0, 0, "%s", msg);
    return locate(c, node, attr, off);
}

/* Reading cost.  <use> re-reads its target for every instance and every
 * element is tested against every style rule, so a small file can ask for
 * an unbounded amount of work (a 100 KB path used 2^20 times through a tree
 * of <use>, 2^17 rules times 2^17 elements).  Each element instance is
 * charged for its attributes (count and bytes: the text it may parse), the
 * style rules and declarations it is matched against, the points it makes
 * and the children it scans; past EF_IN_MAX_WORK units the file is rejected
 * (docs/limits.md), which bounds the run time to seconds. */
static ef_status charge(svg_ctx *c, uint32_t node, uint64_t units)
{
    c->work += units;
    if (c->work <= EF_IN_MAX_WORK)
        return EF_OK;
    ef_error_set(
        c->err, EF_ERR_LIMIT, NULL, 0, 0,
        "document too costly to read: more than 2^%u work units (attributes and path data read again for every <use> "
        "instance, style rules times elements; docs/limits.md)",
        (unsigned)EF_IN_MAX_WORK_LOG2);
    return locate(c, node, NULL, 0);
}

static int key_cmp(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static int id_cmp(const void *a, const void *b)
{
    const id_entry *x = a, *y = b;
    int r = strcmp(x->id, y->id);
    if (r)
        return r;
    return x->node < y->node ? -1 : x->node > y->node;
}

/* The first element (in document order) with this id, or EF_IN_NONE. */
static uint32_t find_id(const svg_ctx *c, const char *id, size_t len)
{
    size_t lo = 0, hi = c->nids;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const char *s = c->ids[mid].id;
        int r = strncmp(s, id, len);
        if (r == 0 && s[len] != '\0')
            r = 1;
        if (r < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < c->nids && strncmp(c->ids[lo].id, id, len) == 0 && c->ids[lo].id[len] == '\0')
        return c->ids[lo].node;
    return EF_IN_NONE;
}

/* "#id" (href) -> node. */
static uint32_t href_target(const svg_ctx *c, uint32_t node)
{
    size_t n;
    const char *h = ef_in_dom_attr(&c->dom, node, EF_IN_XLINK_HREF, &n);
    if (!h)
        h = ef_in_dom_attr(&c->dom, node, "href", &n);
    if (!h)
        return EF_IN_NONE;
    while (n > 0 && ef_in_is_wsp(*h)) {
        h++;
        n--;
    }
    while (n > 0 && ef_in_is_wsp(h[n - 1]))
        n--;
    if (n < 2 || h[0] != '#')
        return EF_IN_NONE;
    return find_id(c, h + 1, n - 1);
}

static bool span_is(const char *s, size_t n, const char *lit) { return strlen(lit) == n && memcmp(s, lit, n) == 0; }

static void trim(const char **s, size_t *n, size_t *off)
{
    while (*n > 0 && ef_in_is_wsp(**s)) {
        (*s)++;
        (*n)--;
        (*off)++;
    }
    while (*n > 0 && ef_in_is_wsp((*s)[*n - 1]))
        (*n)--;
}

/* ------------------------------------------------------------- lengths */

typedef enum axis { AX_X, AX_Y, AX_D } axis;

/* <length>: number, then px pt pc mm cm in em ex or %; user units = px.
 * Conversions are exact ratios rounded once to Q31.32 (96 px per inch;
 * em = 16 px and ex = 8 px since fonts are not modelled). */
static ef_status parse_length(const char *s, size_t len, axis ax, const svg_frame *f, ef_q32 *out, size_t *err_off,
                              ef_error *err)
{
    ef_in_lex l = { s, len, 0 };
    ef_q32 v;
    ef_status st;
    ef_in_lex_wsp(&l);
    size_t at = l.pos;
    if ((st = ef_in_lex_number(&l, &v, err)) != EF_OK) {
        *err_off = at;
        return st;
    }
    size_t u0 = l.pos;
    while (!ef_in_lex_end(&l) && ((l.s[l.pos] >= 'a' && l.s[l.pos] <= 'z') || l.s[l.pos] == '%'))
        l.pos++;
    const char *u = s + u0;
    size_t un = l.pos - u0;
    int64_t num = 1, den = 1;
    if (un == 0 || span_is(u, un, "px")) {
    } else if (span_is(u, un, "in"))
        num = 96;
    else if (span_is(u, un, "cm")) {
        num = 4800;
        den = 127;
    } else if (span_is(u, un, "mm")) {
        num = 480;
        den = 127;
    } else if (span_is(u, un, "pt")) {
        num = 4;
        den = 3;
    } else if (span_is(u, un, "pc"))
        num = 16;
    else if (span_is(u, un, "em"))
        num = 16;
    else if (span_is(u, un, "ex"))
        num = 8;
    else if (span_is(u, un, "%")) {
        if (!f) {
            *err_off = u0;
            return ef_error_set(err, EF_ERR_UNSUPPORTED, NULL, 0, 0, "percentage not allowed here");
        }
        num = (ax == AX_X ? f->vpw : ax == AX_Y ? f->vph : f->vpd).v;
        den = (int64_t)100 << 32;
    } else {
        *err_off = u0;
        return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "unknown unit '%.*s'", (int)(un > 8 ? 8 : un), u);
    }
    ef_in_lex_wsp(&l);
    if (!ef_in_lex_end(&l)) {
        *err_off = l.pos;
        return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "unexpected text after length");
    }
    int64_t r = v.v;
    if ((num != 1 || den != 1) && !ef_muldiv_i64(v.v, num, den, &r)) {
        *err_off = at;
        return ef_error_set(err, EF_ERR_RANGE, NULL, 0, 0, "length out of range");
    }
    if (r == INT64_MIN)
        r++; /* keep negation safe downstream */
    *out = ef_q32_raw(r);
    return EF_OK;
}

/* Attribute length; *present false (and *out = 0) when absent. */
static ef_status length_attr(svg_ctx *c, uint32_t node, const char *attr, axis ax, const svg_frame *f, ef_q32 *out,
                             bool *present)
{
    size_t n, off = 0;
    const char *v = ef_in_dom_attr(&c->dom, node, attr, &n);
    *out = ef_q32_raw(0);
    if (present)
        *present = v != NULL;
    if (!v)
        return EF_OK;
    ef_status st = parse_length(v, n, ax, f, out, &off, c->err);
    return st == EF_OK ? EF_OK : locate(c, node, attr, off);
}

/* ------------------------------------------------------------ properties */

static bool prop_known(const char *n, size_t len)
{
    /* clang-format off */
    static const char *const names[] = { "fill", "fill-opacity", "fill-rule", "opacity", "stroke", "color",
                                         "visibility", "display", "clip-path", "mask", "filter", "stop-color",
                                         "stop-opacity" };
    /* clang-format on */
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (span_is(n, len, names[i]))
            return true;
    return false;
}

/* Where a value came from, to locate its errors. */
typedef struct src {
    uint32_t node;
    const char *attr; /* NULL: a <style> sheet, located at the element */
    size_t base;      /* offset of the value inside the attribute */
} src;

static ef_status value_error(svg_ctx *c, const src *w, size_t off)
{
    return locate(c, w->node, w->attr, w->attr ? w->base + off : 0);
}

static ef_status apply(svg_ctx *c, const char *name, size_t nlen, const char *v, size_t vlen, const src *w,
                       svg_style *st, const svg_style *parent, svg_local *loc)
{
    size_t off = 0, eoff = 0;
    ef_status s;
    trim(&v, &vlen, &off);
    bool inherit = span_is(v, vlen, "inherit");
    if (span_is(name, nlen, "fill")) {
        if (inherit) {
            st->fill = parent->fill;
            return EF_OK;
        }
        ef_in_paint p;
        if ((s = ef_in_paint_parse(v, vlen, &p, &eoff, c->err)) != EF_OK)
            return value_error(c, w, off + eoff);
        st->fill.p = p;
        st->fill.ref = p.kind == EF_IN_PAINT_URL ? find_id(c, v + p.url_off, p.url_len) : EF_IN_NONE;
    } else if (span_is(name, nlen, "fill-opacity") || span_is(name, nlen, "opacity") ||
               span_is(name, nlen, "stop-opacity")) {
        ef_q32 o = ef_q32_raw(EF_Q32_ONE);
        if (inherit) {
            /* Inherited value for fill-opacity; opacity and stop-opacity are
             * not inherited and the ancestors' opacity is already applied. */
            if (name[0] == 'f')
                st->fill_opacity = parent->fill_opacity;
            return EF_OK;
        }
        if ((s = ef_in_opacity_parse(v, vlen, &o, &eoff, c->err)) != EF_OK)
            return value_error(c, w, off + eoff);
        if (name[0] == 'f')
            st->fill_opacity = o;
        else if (name[0] == 'o')
            loc->opacity = o;
        else
            loc->stop_opacity = o;
    } else if (span_is(name, nlen, "fill-rule")) {
        if (inherit)
            st->rule = parent->rule;
        else if (span_is(v, vlen, "nonzero"))
            st->rule = EF_RULE_NONZERO;
        else if (span_is(v, vlen, "evenodd"))
            st->rule = EF_RULE_EVENODD;
        else {
            ef_error_set(c->err, EF_ERR_SYNTAX, NULL, 0, 0, "fill-rule must be nonzero or evenodd");
            return value_error(c, w, off);
        }
    } else if (span_is(name, nlen, "stroke")) {
        st->stroke = inherit ? parent->stroke : !span_is(v, vlen, "none");
    } else if (span_is(name, nlen, "color")) {
        if (inherit) {
            st->cr = parent->cr;
            st->cg = parent->cg;
            st->cb = parent->cb;
            st->calpha = parent->calpha;
            return EF_OK;
        }
        ef_in_paint p;
        if ((s = ef_in_color_parse(v, vlen, &p, &eoff, c->err)) != EF_OK)
            return value_error(c, w, off + eoff);
        if (p.kind != EF_IN_PAINT_RGB)
            p = (ef_in_paint){
                .kind = EF_IN_PAINT_RGB, .r = parent->cr, .g = parent->cg, .b = parent->cb, .alpha = parent->calpha
            };
        /* color: currentColor means the inherited colour */
        st->cr = p.r;
        st->cg = p.g;
        st->cb = p.b;
        st->calpha = p.alpha;
    } else if (span_is(name, nlen, "visibility")) {
        if (inherit)
            st->visible = parent->visible;
        else if (span_is(v, vlen, "visible"))
            st->visible = true;
        else if (span_is(v, vlen, "hidden") || span_is(v, vlen, "collapse"))
            st->visible = false;
        else {
            ef_error_set(c->err, EF_ERR_SYNTAX, NULL, 0, 0, "visibility must be visible, hidden or collapse");
            return value_error(c, w, off);
        }
    } else if (span_is(name, nlen, "display")) {
        loc->display_none = span_is(v, vlen, "none");
    } else if (span_is(name, nlen, "clip-path")) {
        loc->clip = !span_is(v, vlen, "none") && !inherit;
    } else if (span_is(name, nlen, "mask")) {
        loc->mask = !span_is(v, vlen, "none") && !inherit;
    } else if (span_is(name, nlen, "filter")) {
        loc->filter = !span_is(v, vlen, "none") && !inherit;
    } else if (span_is(name, nlen, "stop-color")) {
        ef_in_paint p;
        if (inherit)
            return EF_OK;
        if (span_is(v, vlen, "none")) {
            memset(&p, 0, sizeof p);
            p.kind = EF_IN_PAINT_RGB; /* treated as transparent black */
            p.alpha = ef_q32_raw(0);
        } else if ((s = ef_in_color_parse(v, vlen, &p, &eoff, c->err)) != EF_OK) {
            return value_error(c, w, off + eoff);
        }
        loc->stop_color = p;
        loc->stop_color_set = true;
    }
    return EF_OK;
}

/* Applies presentation attributes, then matching <style> rules (by
 * specificity, then source order), then the style attribute. */
static ef_status cascade(svg_ctx *c, uint32_t node, svg_style *st, const svg_style *parent, svg_local *loc)
{
    ef_status s;
    const ef_in_node *n = &c->dom.nodes[node];
    /* Every attribute may be parsed (style, transform, d, ...) and every
     * rule and declaration of the style sheets tested, at every visit. */
    uint64_t cost = 1u + (uint64_t)n->nattr + c->css.nrules + c->css.decls.n;
    for (uint32_t i = 0; i < n->nattr; i++)
        cost += c->dom.attrs[n->attr0 + i].value_len;
    if ((s = charge(c, node, cost)) != EF_OK)
        return s;
    *st = *parent;
    loc->opacity = ef_q32_raw(EF_Q32_ONE);
    loc->display_none = loc->clip = loc->mask = loc->filter = false;
    loc->stop_color_set = false;
    memset(&loc->stop_color, 0, sizeof loc->stop_color);
    loc->stop_opacity = ef_q32_raw(EF_Q32_ONE);

    for (uint32_t i = 0; i < n->nattr; i++) {
        const ef_in_attr *a = &c->dom.attrs[n->attr0 + i];
        const char *an = ef_in_dom_str(&c->dom, a->name);
        size_t anl = strlen(an);
        if (!prop_known(an, anl))
            continue;
        src w = { node, an, 0 };
        if ((s = apply(c, an, anl, ef_in_dom_str(&c->dom, a->value), a->value_len, &w, st, parent, loc)))
            return s;
    }

    if (c->css.nrules > 0) {
        size_t cl = 0, il = 0;
        const char *cls = ef_in_dom_attr(&c->dom, node, "class", &cl);
        const char *id = ef_in_dom_attr(&c->dom, node, "id", &il);
        const char *tag = tag_of(c, node);
        c->nmatched = 0;
        for (uint32_t r = 0; r < c->css.nrules; r++) {
            if (!ef_in_css_match(&c->css.rules[r], tag, cls, cl, id, il))
                continue;
            if (c->nmatched == c->matched_cap) {
                uint32_t nc = c->matched_cap ? c->matched_cap * 2 : 16;
                uint64_t *nm = realloc(c->matched, (size_t)nc * sizeof *nm);
                if (!nm)
                    return fail(c, node, NULL, 0, EF_ERR_NOMEM, "out of memory");
                c->matched = nm;
                c->matched_cap = nc;
            }
            c->matched[c->nmatched++] = (uint64_t)c->css.rules[r].specificity << 32 | r;
        }
        /* By specificity, then source order (the index): keys are distinct, so
         * the order is total and qsort's instability does not matter; n log n,
         * where inserting one by one was quadratic in the matching rules. */
        if (c->nmatched > 1)
            qsort(c->matched, c->nmatched, sizeof *c->matched, key_cmp);
        for (uint32_t m = 0; m < c->nmatched; m++) {
            const ef_in_css_rule *r = &c->css.rules[(uint32_t)c->matched[m]];
            for (uint32_t d = 0; d < r->ndecl; d++) {
                const ef_in_decl *dc = &c->css.decls.d[r->decl0 + d];
                src w = { r->node, NULL, 0 };
                if ((s = apply(c, dc->name, dc->name_len, dc->value, dc->value_len, &w, st, parent, loc)))
                    return s;
            }
        }
    }

    size_t sl;
    const char *style = ef_in_dom_attr(&c->dom, node, "style", &sl);
    if (style) {
        size_t off = 0;
        c->decls.n = 0;
        if ((s = ef_in_css_decls(style, sl, &c->decls, &off, c->err)) != EF_OK)
            return locate(c, node, "style", off);
        for (uint32_t d = 0; d < c->decls.n; d++) {
            const ef_in_decl *dc = &c->decls.d[d];
            src w = { node, "style", dc->value_off };
            if ((s = apply(c, dc->name, dc->name_len, dc->value, dc->value_len, &w, st, parent, loc)))
                return s;
        }
    }
    if (loc->clip)
        note(c, NOTE_CLIP, node, "clip-path ignored");
    if (loc->mask)
        note(c, NOTE_MASK, node, "mask ignored");
    if (loc->filter)
        note(c, NOTE_FILTER, node, "filter ignored");
    return EF_OK;
}

static svg_style initial_style(void)
{
    svg_style s;
    memset(&s, 0, sizeof s);
    s.fill.p.kind = EF_IN_PAINT_RGB; /* fill: black */
    s.fill.p.alpha = ef_q32_raw(EF_Q32_ONE);
    s.fill.ref = EF_IN_NONE;
    s.fill_opacity = ef_q32_raw(EF_Q32_ONE);
    s.rule = EF_RULE_NONZERO;
    s.stroke = false;
    s.calpha = ef_q32_raw(EF_Q32_ONE); /* color: black */
    s.visible = true;
    return s;
}

/* --------------------------------------------------------------- paints */

static bool is_gradient(const svg_ctx *c, uint32_t node)
{
    const char *t = tag_of(c, node);
    return c->dom.nodes[node].svg && (is(t, "linearGradient") || is(t, "radialGradient"));
}

/* Average colour of a gradient's stops (following href for the stops).
 * false: no stops (the paint is none).  Each stop's stop-color and
 * stop-opacity come from its own attributes, <style> rules and style
 * attribute (not inherited); currentColor is the stop's color, else black. */
static ef_status gradient_color(svg_ctx *c, uint32_t g, uint8_t rgb[3], ef_q32 *alpha, bool *found)
{
    *found = false;
    for (int hop = 0; hop < 16 && g != EF_IN_NONE && is_gradient(c, g); hop++) {
        uint64_t sr = 0, sg = 0, sb = 0;
        int64_t so = 0;
        uint32_t n = 0;
        for (uint32_t k = c->dom.nodes[g].first_child; k != EF_IN_NONE; k = c->dom.nodes[k].next) {
            ef_status cs = charge(c, k, 1);
            if (cs != EF_OK)
                return cs;
            if (!c->dom.nodes[k].svg || !is(tag_of(c, k), "stop"))
                continue;
            svg_style st, base = initial_style();
            svg_local loc;
            ef_status s = cascade(c, k, &st, &base, &loc);
            if (s != EF_OK)
                return s;
            ef_in_paint p = loc.stop_color;
            if (!loc.stop_color_set) {
                memset(&p, 0, sizeof p);
                p.kind = EF_IN_PAINT_RGB;
                p.alpha = ef_q32_raw(EF_Q32_ONE);
            } else if (p.kind == EF_IN_PAINT_CURRENT) {
                p.kind = EF_IN_PAINT_RGB;
                p.r = st.cr;
                p.g = st.cg;
                p.b = st.cb;
                p.alpha = st.calpha;
            }
            ef_q32 o;
            if (!ef_q32_mul(p.alpha, loc.stop_opacity, &o))
                o = ef_q32_raw(0);
            sr += p.r;
            sg += p.g;
            sb += p.b;
            so += o.v;
            n++;
        }
        if (n > 0) {
            rgb[0] = (uint8_t)((sr + n / 2) / n);
            rgb[1] = (uint8_t)((sg + n / 2) / n);
            rgb[2] = (uint8_t)((sb + n / 2) / n);
            *alpha = ef_q32_raw(so / (int64_t)n);
            *found = true;
            return EF_OK;
        }
        g = href_target(c, g);
    }
    return EF_OK;
}

/* The shape's straight colour; *draw false when nothing is painted. */
static ef_status fill_color(svg_ctx *c, uint32_t node, const svg_style *st, ef_q32 opacity, ef_rgba8 *out, bool *draw)
{
    ef_in_paint p = st->fill.p;
    *draw = false;
    if (p.kind == EF_IN_PAINT_URL) {
        uint32_t ref = st->fill.ref;
        if (ref != EF_IN_NONE && is_gradient(c, ref)) {
            uint8_t rgb[3];
            ef_q32 a;
            bool found;
            ef_status s = gradient_color(c, ref, rgb, &a, &found);
            if (s != EF_OK)
                return s;
            note(c, NOTE_GRADIENT, node, "gradient fill approximated by the average of its stop colours");
            if (!found)
                return EF_OK;
            p.kind = EF_IN_PAINT_RGB;
            p.r = rgb[0];
            p.g = rgb[1];
            p.b = rgb[2];
            p.alpha = a;
        } else {
            if (ref != EF_IN_NONE && c->dom.nodes[ref].svg && is(tag_of(c, ref), "pattern"))
                note(c, NOTE_PATTERN, node, "pattern fill not supported: fallback colour used, else not drawn");
            else
                note(c, NOTE_UNRESOLVED, node,
                     "fill references a missing or unsupported element: fallback colour "
                     "used, else not drawn");
            if (!p.has_fallback)
                return EF_OK;
            p.kind = p.fallback_kind;
            p.r = p.fr;
            p.g = p.fg;
            p.b = p.fb;
            p.alpha = p.falpha;
        }
    }
    if (p.kind == EF_IN_PAINT_NONE)
        return EF_OK;
    if (p.kind == EF_IN_PAINT_CURRENT) {
        p.r = st->cr;
        p.g = st->cg;
        p.b = st->cb;
        p.alpha = st->calpha;
    }
    ef_q32 a1, a2;
    if (!ef_q32_mul(p.alpha, st->fill_opacity, &a1) || !ef_q32_mul(a1, opacity, &a2))
        return EF_OK;
    out->r = p.r;
    out->g = p.g;
    out->b = p.b;
    out->a = ef_in_alpha8(a2);
    *draw = out->a != 0; /* fully transparent: paints nothing */
    return EF_OK;
}

/* -------------------------------------------------------------- shapes */

static ef_status builder_error(svg_ctx *c, uint32_t node, const char *attr, size_t off)
{
    return locate(c, node, attr, off);
}

static ef_status add(int64_t a, int64_t b, ef_q32 *out)
{
    int64_t r;
    if (!ef_add_i64_checked(a, b, &r))
        return EF_ERR_RANGE;
    *out = ef_q32_raw(r);
    return EF_OK;
}

/* A quarter arc of the corner ellipse centred at (cx, cy) from angle t0
 * (binary) in the increasing direction, ending at (ex, ey). */
static ef_status corner(svg_ctx *c, ef_q32 cx, ef_q32 cy, ef_q32 rx, ef_q32 ry, ef_angle t0, ef_q32 ex, ef_q32 ey)
{
    ef_in_ellarc a = { cx, cy, rx, ry, EF_Q30_ONE, 0, t0, (int64_t)EF_ANGLE_QUARTER_TURN, 1, ex, ey };
    return ef_in_build_ellarc(&c->b, &a, c->err);
}

static ef_status rect_geometry(svg_ctx *c, uint32_t node, const svg_frame *f)
{
    ef_q32 x, y, w, h, rx, ry;
    bool hrx, hry;
    ef_status s;
    if ((s = length_attr(c, node, "x", AX_X, f, &x, NULL)) || (s = length_attr(c, node, "y", AX_Y, f, &y, NULL)) ||
        (s = length_attr(c, node, "width", AX_X, f, &w, NULL)) ||
        (s = length_attr(c, node, "height", AX_Y, f, &h, NULL)) ||
        (s = length_attr(c, node, "rx", AX_X, f, &rx, &hrx)) || (s = length_attr(c, node, "ry", AX_Y, f, &ry, &hry)))
        return s;
    if (w.v < 0 || h.v < 0 || rx.v < 0 || ry.v < 0)
        return fail(c, node, NULL, 0, EF_ERR_RANGE, "negative width, height, rx or ry");
    if (w.v == 0 || h.v == 0)
        return EF_OK; /* disables rendering */
    if (!hrx)
        rx = ry; /* SVG 1.1 9.2: one radius gives both */
    if (!hry)
        ry = rx;
    ef_q32 hw = ef_q32_raw(ef_asr_i64(w.v, 1)), hh = ef_q32_raw(ef_asr_i64(h.v, 1));
    if (rx.v > hw.v)
        rx = hw;
    if (ry.v > hh.v)
        ry = hh;
    ef_q32 x1, y1;
    if (add(x.v, w.v, &x1) || add(y.v, h.v, &y1))
        return fail(c, node, NULL, 0, EF_ERR_RANGE, "rectangle out of range");
    ef_error *e = c->err;
    if (rx.v == 0 || ry.v == 0) {
        if ((s = ef_in_build_move(&c->b, x, y, e)) || (s = ef_in_build_line(&c->b, x1, y, e)) ||
            (s = ef_in_build_line(&c->b, x1, y1, e)) || (s = ef_in_build_line(&c->b, x, y1, e)))
            return builder_error(c, node, NULL, 0);
        ef_in_build_close(&c->b);
        return EF_OK;
    }
    /* SVG 2's equivalent path: M x+rx,y H x+w-rx A.. x+w,y+ry V y+h-ry A.. x+w-rx,y+h
     * H x+rx A.. x,y+h-ry V y+ry A.. x+rx,y Z, corners as quarter arcs. */
    ef_q32 xl = ef_q32_raw(x.v + rx.v), xr = ef_q32_raw(x1.v - rx.v);
    ef_q32 yt = ef_q32_raw(y.v + ry.v), yb = ef_q32_raw(y1.v - ry.v);
    if ((s = ef_in_build_move(&c->b, xl, y, e)) || (s = ef_in_build_line(&c->b, xr, y, e)) ||
        (s = corner(c, xr, yt, rx, ry, 3u * EF_ANGLE_QUARTER_TURN, x1, yt)) ||
        (s = ef_in_build_line(&c->b, x1, yb, e)) || (s = corner(c, xr, yb, rx, ry, 0, xr, y1)) ||
        (s = ef_in_build_line(&c->b, xl, y1, e)) || (s = corner(c, xl, yb, rx, ry, EF_ANGLE_QUARTER_TURN, x, yb)) ||
        (s = ef_in_build_line(&c->b, x, yt, e)) || (s = corner(c, xl, yt, rx, ry, EF_ANGLE_HALF_TURN, xl, y)))
        return builder_error(c, node, NULL, 0);
    ef_in_build_close(&c->b);
    return EF_OK;
}

static ef_status ellipse_geometry(svg_ctx *c, uint32_t node, const svg_frame *f, bool circle)
{
    ef_q32 cx, cy, rx, ry;
    ef_status s;
    if ((s = length_attr(c, node, "cx", AX_X, f, &cx, NULL)) || (s = length_attr(c, node, "cy", AX_Y, f, &cy, NULL)))
        return s;
    if (circle) {
        if ((s = length_attr(c, node, "r", AX_D, f, &rx, NULL)))
            return s;
        ry = rx;
    } else if ((s = length_attr(c, node, "rx", AX_X, f, &rx, NULL)) ||
               (s = length_attr(c, node, "ry", AX_Y, f, &ry, NULL))) {
        return s;
    }
    if (rx.v < 0 || ry.v < 0)
        return fail(c, node, NULL, 0, EF_ERR_RANGE, "negative radius");
    if (rx.v == 0 || ry.v == 0)
        return EF_OK; /* disables rendering */
    ef_q32 x0;
    if (add(cx.v, rx.v, &x0))
        return fail(c, node, NULL, 0, EF_ERR_RANGE, "ellipse out of range");
    /* Starts at (cx + rx, cy), one full turn in the positive direction. */
    ef_in_ellarc a = { cx, cy, rx, ry, EF_Q30_ONE, 0, 0, (int64_t)1 << 32, 1, x0, cy };
    if ((s = ef_in_build_move(&c->b, x0, cy, c->err)) || (s = ef_in_build_ellarc(&c->b, &a, c->err)))
        return builder_error(c, node, NULL, 0);
    ef_in_build_close(&c->b);
    return EF_OK;
}

static ef_status draw_shape(svg_ctx *c, uint32_t node, const char *tag, const svg_frame *f, const svg_style *st,
                            ef_q32 opacity)
{
    ef_status s;
    if (st->stroke)
        note(c, NOTE_STROKE, node, "stroke ignored");
    if (is(tag, "line") || !st->visible)
        return EF_OK;
    ef_rgba8 col;
    bool draw;
    if ((s = fill_color(c, node, st, opacity, &col, &draw)) != EF_OK || !draw)
        return s;

    uint32_t budget = EF_MAX_POINTS_PER_SCENE - c->scene->npoints;
    ef_in_builder_reset(&c->b, &f->ctm, budget);
    size_t off = 0, n;
    const char *v;
    if (is(tag, "path")) {
        if (!(v = ef_in_dom_attr(&c->dom, node, "d", &n)))
            return EF_OK;
        if ((s = ef_in_path_parse(v, n, &c->b, &off, c->err)) != EF_OK)
            return locate(c, node, "d", off);
    } else if (is(tag, "polygon") || is(tag, "polyline")) {
        if (!(v = ef_in_dom_attr(&c->dom, node, "points", &n)))
            return EF_OK;
        if ((s = ef_in_points_parse(v, n, &c->b, &off, c->err)) != EF_OK)
            return locate(c, node, "points", off);
    } else if (is(tag, "rect")) {
        if ((s = rect_geometry(c, node, f)) != EF_OK)
            return s;
    } else if ((s = ellipse_geometry(c, node, f, is(tag, "circle"))) != EF_OK) {
        return s;
    }
    if ((s = charge(c, node, c->b.npts)) != EF_OK)
        return s; /* the points it made */
    if ((s = ef_in_builder_commit(&c->b, c->scene, st->rule, col, c->err)) != EF_OK)
        return locate(c, node, NULL, 0);
    return EF_OK;
}

/* ------------------------------------------------------------ viewports */

typedef struct par {
    int ax, ay; /* 0 min, 1 mid, 2 max */
    bool none, slice;
} par;

static ef_status parse_par(svg_ctx *c, uint32_t node, par *p)
{
    size_t n;
    const char *v = ef_in_dom_attr(&c->dom, node, "preserveAspectRatio", &n);
    p->ax = p->ay = 1;
    p->none = p->slice = false;
    if (!v)
        return EF_OK;
    ef_in_lex l = { v, n, 0 };
    ef_in_lex_wsp(&l);
    const char *w = v + l.pos;
    size_t wl = 0;
    while (l.pos + wl < n && !ef_in_is_wsp(w[wl]))
        wl++;
    if (span_is(w, wl, "defer")) {
        l.pos += wl;
        ef_in_lex_wsp(&l);
        w = v + l.pos;
        wl = 0;
        while (l.pos + wl < n && !ef_in_is_wsp(w[wl]))
            wl++;
    }
    size_t at = l.pos;
    if (span_is(w, wl, "none")) {
        p->none = true;
    } else if (wl == 8 && w[0] == 'x' && w[4] == 'Y') {
        static const char *const k[3] = { "Min", "Mid", "Max" };
        p->ax = p->ay = -1;
        for (int i = 0; i < 3; i++) {
            if (memcmp(w + 1, k[i], 3) == 0)
                p->ax = i;
            if (memcmp(w + 5, k[i], 3) == 0)
                p->ay = i;
        }
        if (p->ax < 0 || p->ay < 0)
            goto bad;
    } else {
        goto bad;
    }
    l.pos += wl;
    ef_in_lex_wsp(&l);
    w = v + l.pos;
    wl = 0;
    while (l.pos + wl < n && !ef_in_is_wsp(w[wl]))
        wl++;
    if (span_is(w, wl, "slice"))
        p->slice = true;
    else if (wl > 0 && !span_is(w, wl, "meet")) {
        at = l.pos;
        goto bad;
    }
    l.pos += wl;
    ef_in_lex_wsp(&l);
    if (!ef_in_lex_end(&l)) {
        at = l.pos;
        goto bad;
    }
    return EF_OK;
bad:
    return fail(c, node, "preserveAspectRatio", at, EF_ERR_SYNTAX, "invalid preserveAspectRatio");
}

/* viewBox="min-x min-y width height"; *present false when absent. */
static ef_status parse_viewbox(svg_ctx *c, uint32_t node, ef_q32 vb[4], bool *present)
{
    size_t n;
    const char *v = ef_in_dom_attr(&c->dom, node, "viewBox", &n);
    *present = v != NULL;
    if (!v)
        return EF_OK;
    ef_in_lex l = { v, n, 0 };
    ef_in_lex_wsp(&l);
    for (int i = 0; i < 4; i++) {
        if (i > 0)
            ef_in_lex_sep(&l);
        size_t at = l.pos;
        if (ef_in_lex_number(&l, &vb[i], c->err) != EF_OK)
            return locate(c, node, "viewBox", at);
    }
    ef_in_lex_wsp(&l);
    if (!ef_in_lex_end(&l))
        return fail(c, node, "viewBox", l.pos, EF_ERR_SYNTAX, "viewBox takes four numbers");
    if (vb[2].v <= 0 || vb[3].v <= 0)
        return fail(c, node, "viewBox", 0, EF_ERR_RANGE, "viewBox width and height must be positive");
    return EF_OK;
}

/* The viewBox-to-viewport transform (SVG 1.1 7.8) for a W x H viewport at
 * the origin.  Q31.32 throughout: scales are rounded quotients, products
 * rounded, the centring halves floored. */
static bool viewbox_ctm(const ef_q32 vb[4], ef_q32 W, ef_q32 H, const par *p, ef_in_affine *out)
{
    ef_q32 sx, sy, vsx, vsy, ox, oy;
    if (!ef_q32_div(W, vb[2], &sx) || !ef_q32_div(H, vb[3], &sy))
        return false;
    if (!p->none) {
        bool x_smaller = sx.v < sy.v;
        ef_q32 s = (x_smaller != p->slice) ? sx : sy; /* meet: min, slice: max */
        sx = sy = s;
    }
    if (!ef_q32_mul(vb[2], sx, &vsx) || !ef_q32_mul(vb[3], sy, &vsy) || !ef_q32_mul(vb[0], sx, &ox) ||
        !ef_q32_mul(vb[1], sy, &oy))
        return false;
    int64_t slack_x = W.v - vsx.v, slack_y = H.v - vsy.v; /* both in Q31.32 range: no overflow */
    int64_t tx = p->none ? 0 : p->ax == 1 ? ef_asr_i64(slack_x, 1) : p->ax == 2 ? slack_x : 0;
    int64_t ty = p->none ? 0 : p->ay == 1 ? ef_asr_i64(slack_y, 1) : p->ay == 2 ? slack_y : 0;
    if (!ef_add_i64_checked(tx, -ox.v, &tx) || !ef_add_i64_checked(ty, -oy.v, &ty))
        return false;
    *out = ef_in_affine_scale_translate(sx, sy, ef_q32_raw(tx), ef_q32_raw(ty));
    return true;
}

/* Percentage references of a viewport of w x h user units. */
static void set_viewport(svg_frame *f, ef_q32 w, ef_q32 h)
{
    ef_q32 hyp, d;
    f->vpw = w;
    f->vph = h;
    /* sqrt((w^2 + h^2) / 2) = hypot(w, h) / sqrt(2) */
    if (!ef_in_hypot_q32(w, h, &hyp) || !ef_q32_div(hyp, ef_q32_sqrt(ef_q32_from_int(2)), &d))
        d = w;
    f->vpd = d;
}

/* Absolute width/height attribute of an <svg>; percentages count as absent. */
static ef_status svg_size_attr(svg_ctx *c, uint32_t node, const char *attr, ef_q32 *out, bool *present)
{
    size_t n;
    const char *v = ef_in_dom_attr(&c->dom, node, attr, &n);
    *present = false;
    if (!v)
        return EF_OK;
    size_t k = n;
    while (k > 0 && ef_in_is_wsp(v[k - 1]))
        k--;
    if (k > 0 && v[k - 1] == '%')
        return EF_OK;
    ef_status s = length_attr(c, node, attr, AX_X, NULL, out, present);
    if (s != EF_OK)
        return s;
    if (out->v <= 0)
        return fail(c, node, attr, 0, EF_ERR_RANGE, "width and height must be positive");
    return EF_OK;
}

/* --------------------------------------------------------------- walk */

static ef_status walk(svg_ctx *c, uint32_t node, const svg_frame *f, unsigned depth);

static ef_status walk_children(svg_ctx *c, uint32_t node, const svg_frame *f, unsigned depth)
{
    ef_status s;
    for (uint32_t k = c->dom.nodes[node].first_child; k != EF_IN_NONE; k = c->dom.nodes[k].next)
        if ((s = walk(c, k, f, depth + 1)) != EF_OK)
            return s;
    return EF_OK;
}

static bool never_rendered(const char *t)
{
    /* clang-format off */
    static const char *const names[] = { "defs", "symbol", "linearGradient", "radialGradient", "stop", "pattern",
                                         "marker", "metadata", "title", "desc", "style", "script", "font",
                                         "font-face", "glyph", "missing-glyph", "view", "cursor", "animate",
                                         "animateColor", "animateMotion", "animateTransform", "set", "mpath",
                                         "color-profile", "altGlyphDef" };
    /* clang-format on */
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (is(t, names[i]))
            return true;
    return false;
}

static ef_status walk(svg_ctx *c, uint32_t node, const svg_frame *f, unsigned depth)
{
    ef_status s;
    ef_in_node *n = &c->dom.nodes[node];
    if (!n->svg)
        return EF_OK; /* foreign namespaces: not SVG content */
    if (depth >= EF_IN_MAX_DEPTH)
        return fail(c, node, NULL, 0, EF_ERR_LIMIT, "nesting deeper than 256 levels (through <use>)");
    if (++c->visits > EF_IN_MAX_VISITS)
        return fail(c, node, NULL, 0, EF_ERR_LIMIT, "too many element instances (more than 2^21, through <use>)");
    const char *tag = tag_of(c, node);

    if (never_rendered(tag))
        return EF_OK;
    if (is(tag, "clipPath")) {
        note(c, NOTE_CLIP, node, "<clipPath> ignored");
        return EF_OK;
    }
    if (is(tag, "mask")) {
        note(c, NOTE_MASK, node, "<mask> ignored");
        return EF_OK;
    }
    if (is(tag, "filter")) {
        note(c, NOTE_FILTER, node, "<filter> ignored");
        return EF_OK;
    }
    if (is(tag, "text")) {
        note(c, NOTE_TEXT, node, "<text> ignored");
        return EF_OK;
    }
    if (is(tag, "image")) {
        note(c, NOTE_IMAGE, node, "<image> ignored");
        return EF_OK;
    }
    if (is(tag, "foreignObject")) {
        note(c, NOTE_FOREIGN, node, "<foreignObject> ignored");
        return EF_OK;
    }
    bool container = is(tag, "g") || is(tag, "a") || is(tag, "switch") || is(tag, "svg");
    bool shape = is(tag, "path") || is(tag, "rect") || is(tag, "circle") || is(tag, "ellipse") || is(tag, "polygon") ||
                 is(tag, "polyline") || is(tag, "line");
    bool use = is(tag, "use");
    if (!container && !shape && !use) {
        char msg[128];
        snprintf(msg, sizeof msg, "unsupported element <%.64s> ignored", tag);
        note(c, NOTE_ELEMENT, node, msg);
        return EF_OK;
    }

    svg_frame cf = *f;
    svg_local loc;
    if ((s = cascade(c, node, &cf.style, &f->style, &loc)) != EF_OK)
        return s;
    if (loc.display_none)
        return EF_OK;
    if (!ef_q32_mul(f->opacity, loc.opacity, &cf.opacity))
        cf.opacity = ef_q32_raw(0);
    size_t tl;
    const char *tr = ef_in_dom_attr(&c->dom, node, "transform", &tl);
    if (tr) {
        ef_in_affine t;
        size_t off = 0;
        if ((s = ef_in_transform_parse(tr, tl, &t, &off, c->err)) != EF_OK)
            return locate(c, node, "transform", off);
        if (ef_in_affine_mul(&f->ctm, &t, &cf.ctm) != EF_OK)
            return fail(c, node, "transform", 0, EF_ERR_RANGE, "transform out of range");
    }

    if (shape)
        return draw_shape(c, node, tag, &cf, &cf.style, cf.opacity);

    n->active = true;
    if (use) {
        uint32_t t = href_target(c, node);
        if (t == EF_IN_NONE) {
            note(c, NOTE_USE_MISSING, node, "<use> of a missing element ignored");
        } else if (c->dom.nodes[t].active) {
            n->active = false;
            return fail(c, node, NULL, 0, EF_ERR_SYNTAX, "<use> refers to an element that contains it (cycle)");
        } else {
            ef_q32 x, y;
            if ((s = length_attr(c, node, "x", AX_X, &cf, &x, NULL)) ||
                (s = length_attr(c, node, "y", AX_Y, &cf, &y, NULL))) {
                n->active = false;
                return s;
            }
            ef_in_affine tt = ef_in_affine_scale_translate(ef_q32_raw(EF_Q32_ONE), ef_q32_raw(EF_Q32_ONE), x, y);
            if (ef_in_affine_mul(&cf.ctm, &tt, &cf.ctm) != EF_OK) {
                n->active = false;
                return fail(c, node, NULL, 0, EF_ERR_RANGE, "use offset out of range");
            }
            if (c->dom.nodes[t].svg && is(tag_of(c, t), "symbol")) {
                if (ef_in_dom_attr(&c->dom, t, "viewBox", NULL))
                    note(c, NOTE_SYMBOL, t, "<symbol> viewBox ignored (drawn in the <use> coordinates)");
                c->dom.nodes[t].active = true;
                svg_frame sf = cf;
                svg_local sl;
                s = cascade(c, t, &sf.style, &cf.style, &sl);
                if (s == EF_OK && !sl.display_none && ef_q32_mul(cf.opacity, sl.opacity, &sf.opacity))
                    s = walk_children(c, t, &sf, depth + 1);
                c->dom.nodes[t].active = false;
            } else {
                s = walk(c, t, &cf, depth + 1);
            }
        }
    } else if (is(tag, "switch")) {
        s = EF_OK;
        for (uint32_t k = n->first_child; k != EF_IN_NONE; k = c->dom.nodes[k].next) {
            if ((s = charge(c, k, 1u + c->dom.nodes[k].nattr)) != EF_OK)
                break;
            if (!c->dom.nodes[k].svg || ef_in_dom_attr(&c->dom, k, "requiredExtensions", NULL) ||
                ef_in_dom_attr(&c->dom, k, "systemLanguage", NULL))
                continue;
            s = walk(c, k, &cf, depth + 1);
            break;
        }
    } else if (is(tag, "svg")) {
        /* Nested viewport: x, y, and the viewBox when width and height are
         * given; its clipping is not modelled. */
        note(c, NOTE_NESTED_SVG, node, "nested <svg>: viewport clipping ignored");
        ef_q32 x, y, w, h, vb[4];
        bool hw, hh, hvb;
        par p;
        s = EF_OK;
        if ((s = length_attr(c, node, "x", AX_X, &cf, &x, NULL)) ||
            (s = length_attr(c, node, "y", AX_Y, &cf, &y, NULL)) ||
            (s = length_attr(c, node, "width", AX_X, &cf, &w, &hw)) ||
            (s = length_attr(c, node, "height", AX_Y, &cf, &h, &hh)) || (s = parse_viewbox(c, node, vb, &hvb)) ||
            (s = parse_par(c, node, &p))) {
            n->active = false;
            return s;
        }
        ef_in_affine m = ef_in_affine_scale_translate(ef_q32_raw(EF_Q32_ONE), ef_q32_raw(EF_Q32_ONE), x, y), v;
        if (ef_in_affine_mul(&cf.ctm, &m, &cf.ctm) != EF_OK)
            s = fail(c, node, NULL, 0, EF_ERR_RANGE, "out of range");
        if (s == EF_OK && hvb && hw && hh && w.v > 0 && h.v > 0) {
            if (!viewbox_ctm(vb, w, h, &p, &v) || ef_in_affine_mul(&cf.ctm, &v, &cf.ctm) != EF_OK)
                s = fail(c, node, "viewBox", 0, EF_ERR_RANGE, "viewBox transform out of range");
            set_viewport(&cf, vb[2], vb[3]);
        }
        if (s == EF_OK)
            s = walk_children(c, node, &cf, depth);
    } else {
        s = walk_children(c, node, &cf, depth);
    }
    n->active = false;
    return s;
}

/* ---------------------------------------------------------------- root */

static ef_status collect(svg_ctx *c)
{
    ef_status s;
    uint32_t nid = 0;
    for (uint32_t i = 0; i < c->dom.nnodes; i++)
        if (ef_in_dom_attr(&c->dom, i, "id", NULL))
            nid++;
    if (nid > 0) {
        c->ids = malloc((size_t)nid * sizeof *c->ids);
        if (!c->ids)
            return ef_error_set(c->err, EF_ERR_NOMEM, c->name, 0, 0, "out of memory");
        for (uint32_t i = 0; i < c->dom.nnodes; i++) {
            const char *id = ef_in_dom_attr(&c->dom, i, "id", NULL);
            if (id) {
                c->ids[c->nids].id = id;
                c->ids[c->nids].node = i;
                c->nids++;
            }
        }
        qsort(c->ids, c->nids, sizeof *c->ids, id_cmp);
    }
    for (uint32_t i = 0; i < c->dom.nnodes; i++) {
        const ef_in_node *n = &c->dom.nodes[i];
        if (!n->svg || !is(tag_of(c, i), "style") || n->text == EF_IN_NONE)
            continue;
        const char *type = ef_in_dom_attr(&c->dom, i, "type", NULL);
        if (type && !is(type, "text/css"))
            continue;
        bool unsupported = false;
        s = ef_in_css_add(&c->css, ef_in_dom_str(&c->dom, n->text), n->text_len, i, &unsupported, c->err);
        if (s != EF_OK)
            return locate(c, i, NULL, 0);
        if (unsupported)
            note(c, NOTE_CSS, i, "unsupported CSS (selectors or at-rules) ignored");
    }
    return EF_OK;
}

static ef_status load_root(svg_ctx *c)
{
    ef_status s;
    const uint32_t root = 0;
    if (!c->dom.nodes[root].svg || !is(tag_of(c, root), "svg"))
        return fail(c, root, NULL, 0, EF_ERR_SYNTAX, "the root element must be <svg>");
    if ((s = collect(c)) != EF_OK)
        return s;

    ef_q32 W, H, vb[4];
    bool hw, hh, hvb;
    par p;
    if ((s = svg_size_attr(c, root, "width", &W, &hw)) || (s = svg_size_attr(c, root, "height", &H, &hh)) ||
        (s = parse_viewbox(c, root, vb, &hvb)) || (s = parse_par(c, root, &p)))
        return s;
    /* Missing sizes: the viewBox's (keeping its aspect ratio when one size
     * is given), else 100 px. */
    if (hvb) {
        if (!hw && !hh) {
            W = vb[2];
            H = vb[3];
        } else if (!hw) {
            int64_t t;
            if (!ef_muldiv_i64(H.v, vb[2].v, vb[3].v, &t))
                return fail(c, root, "height", 0, EF_ERR_RANGE, "size out of range");
            W = ef_q32_raw(t);
        } else if (!hh) {
            int64_t t;
            if (!ef_muldiv_i64(W.v, vb[3].v, vb[2].v, &t))
                return fail(c, root, "width", 0, EF_ERR_RANGE, "size out of range");
            H = ef_q32_raw(t);
        }
    } else {
        if (!hw)
            W = ef_q32_from_int(100);
        if (!hh)
            H = ef_q32_from_int(100);
    }

    svg_frame f;
    f.ctm = ef_in_affine_identity();
    f.style = initial_style();
    f.opacity = ef_q32_raw(EF_Q32_ONE);
    ef_in_affine v = ef_in_affine_identity();
    const ef_load_opts *o = c->opts;
    if (o && o->fit_width > 0) {
        /* Fit the viewBox (or 0 0 width height) into the requested canvas:
         * uniform scale min(W/vw, H/vh), centred. */
        c->scene->width = o->fit_width;
        c->scene->height = o->fit_height;
        ef_q32 box[4] = { ef_q32_raw(0), ef_q32_raw(0), W, H };
        if (hvb)
            memcpy(box, vb, sizeof box);
        par centred = { 1, 1, false, false };
        if (box[2].v <= 0 || box[3].v <= 0 ||
            !viewbox_ctm(box, ef_q32_from_int(o->fit_width), ef_q32_from_int(o->fit_height), &centred, &v))
            return fail(c, root, NULL, 0, EF_ERR_RANGE, "cannot fit the picture to the requested size");
        set_viewport(&f, box[2], box[3]);
    } else {
        if (ef_in_canvas_size(W, &c->scene->width) != EF_OK || ef_in_canvas_size(H, &c->scene->height) != EF_OK)
            return fail(c, root, NULL, 0, EF_ERR_LIMIT, "canvas size outside 1..16384 pixels");
        if (hvb && !viewbox_ctm(vb, W, H, &p, &v))
            return fail(c, root, "viewBox", 0, EF_ERR_RANGE, "viewBox transform out of range");
        if (hvb)
            set_viewport(&f, vb[2], vb[3]);
        else
            set_viewport(&f, W, H);
    }

    /* The root's own properties and transform (SVG 2: applied outside the
     * viewBox mapping, M = T V). */
    svg_local loc;
    svg_style base = f.style;
    if ((s = cascade(c, root, &f.style, &base, &loc)) != EF_OK)
        return s;
    if (loc.display_none)
        return EF_OK;
    f.opacity = loc.opacity;
    size_t tl;
    const char *tr = ef_in_dom_attr(&c->dom, root, "transform", &tl);
    if (tr) {
        ef_in_affine t;
        size_t off = 0;
        if ((s = ef_in_transform_parse(tr, tl, &t, &off, c->err)) != EF_OK)
            return locate(c, root, "transform", off);
        if (ef_in_affine_mul(&t, &v, &v) != EF_OK)
            return fail(c, root, "transform", 0, EF_ERR_RANGE, "transform out of range");
    }
    f.ctm = v;
    c->dom.nodes[root].active = true;
    c->visits = 1;
    return walk_children(c, root, &f, 0);
}

ef_status ef_scene_load_svg(const char *name, const char *data, size_t len, const ef_load_opts *opts, ef_scene *out,
                            ef_error *err)
{
    ef_error local;
    if (!err)
        err = &local;
    if (!name)
        name = "<svg>";
    ef_scene_create(out, 0, 0);
    if (opts && ((opts->fit_width != 0) != (opts->fit_height != 0) || opts->fit_width < 0 || opts->fit_height < 0))
        return ef_error_set(err, EF_ERR_ARG, name, 0, 0, "fit size must be two positive values or none");
    if (opts && (opts->fit_width > EF_MAX_CANVAS || opts->fit_height > EF_MAX_CANVAS))
        return ef_error_set(err, EF_ERR_LIMIT, name, 0, 0, "fit size larger than %d pixels", EF_MAX_CANVAS);

    svg_ctx c;
    memset(&c, 0, sizeof c);
    c.name = name;
    c.opts = opts;
    c.err = err;
    c.scene = out;
    ef_in_builder_init(&c.b);
    ef_status s = ef_in_dom_parse(&c.dom, name, data, len, err);
    if (s == EF_OK)
        s = load_root(&c);
    ef_in_builder_free(&c.b);
    ef_in_css_free(&c.css);
    ef_in_dom_free(&c.dom);
    free(c.ids);
    free(c.decls.d);
    free(c.matched);
    if (s != EF_OK) {
        uint32_t notes = out->notes;
        ef_scene_destroy(out);
        out->notes = notes;
    }
    return s;
}
