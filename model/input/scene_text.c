/*
 * scene_text.c - reader of the peerbench `.scene` text format
 * (tools/peerbench/SPEC.md section 1).
 *
 * Place in the pipeline: text -> device Q16.8 contours, no curves.
 *
 *   scene <width> <height>                      first directive, exactly once
 *   shape <evenodd|nonzero> <r> <g> <b> <a>     integers 0..255 (digits only)
 *   contour <x0> <y0> ... <xn> <yn>             >= 3 points, even count
 *
 * '#' starts a comment anywhere on a line; blank lines are ignored; tokens
 * are separated by spaces or tabs; keywords are case-sensitive.  Lines end
 * with LF; a CR before the LF and a UTF-8 byte order mark at the start of
 * the file are accepted (and nothing else: any other character outside a
 * comment is an error).  A number is ef_parse_decimal_q32's grammar and must
 * fill its whole token; its exact value is rounded once to Q31.32.
 *
 * Coordinates map to the device by the identity (rounded once to Q16.8,
 * floor(v * 256 + 1/2)), or with fit options to a W x H canvas by SPEC.md
 * section 3 at frame 0: s = min(W/w0, H/h0) and X = s x + (W - s w0)/2,
 * Y = s y + (H - s h0)/2, with s rounded to nearest Q31.32 and the offsets
 * computed in Q31.32 (docs/input.md).  Every error names file:line:col.
 */
#include <stdlib.h>
#include <string.h>

#include "input_internal.h"

typedef struct text_reader {
    const char *name;
    const char *line; /* start of the current line */
    uint32_t lineno;
    ef_error *err;
    ef_point *pts;
    uint32_t npts, cap;
} text_reader;

/* The token is quoted with its control characters escaped, NUL included
 * (printf's %.*s would stop there); ef_error_set escapes invalid UTF-8. */
static ef_status fail_at(text_reader *r, const char *at, ef_status st, const char *fmt, const char *tok, size_t n)
{
    char q[4 * 48 + 1];
    size_t k = 0;
    for (size_t i = 0; i < n && i < 48; i++) {
        unsigned char c = (unsigned char)tok[i];
        if (c < 0x20 || c == 0x7F) {
            static const char hex[] = "0123456789ABCDEF";
            q[k++] = '\\';
            q[k++] = 'x';
            q[k++] = hex[c >> 4];
            q[k++] = hex[c & 15];
        } else {
            q[k++] = (char)c;
        }
    }
    q[k] = '\0';
    return ef_error_set(r->err, st, r->name, r->lineno, ef_in_utf8_col(r->line, (size_t)(at - r->line)), fmt, (int)k,
                        q);
}

static bool is_sep(char c) { return c == ' ' || c == '\t'; }

/* Next token in [*p, end): returns its length (0 at the end of the line). */
static size_t next_token(const char **p, const char *end, const char **tok)
{
    const char *s = *p;
    while (s < end && is_sep(*s))
        s++;
    const char *t = s;
    while (s < end && !is_sep(*s))
        s++;
    *tok = t;
    *p = s;
    return (size_t)(s - t);
}

static ef_status number(text_reader *r, const char *tok, size_t n, ef_q32 *v)
{
    size_t used = 0;
    ef_num_status ns = ef_parse_decimal_q32(tok, n, v, &used);
    if (ns == EF_NUM_RANGE)
        return fail_at(r, tok, EF_ERR_RANGE, "number out of range (|v| must be below 2^31): '%.*s'", tok, n);
    if (ns != EF_NUM_OK || used != n)
        return fail_at(r, tok, EF_ERR_SYNTAX, "not a number: '%.*s'", tok, n);
    return EF_OK;
}

static ef_status byte_value(text_reader *r, const char *tok, size_t n, uint8_t *v)
{
    unsigned x = 0;
    if (n == 0)
        return fail_at(r, tok, EF_ERR_SYNTAX, "integer 0..255 expected%.*s", "", 0);
    for (size_t i = 0; i < n; i++) {
        if (tok[i] < '0' || tok[i] > '9' || (x = x * 10 + (unsigned)(tok[i] - '0')) > 255)
            return fail_at(r, tok, EF_ERR_SYNTAX, "integer 0..255 expected: '%.*s'", tok, n);
    }
    *v = (uint8_t)x;
    return EF_OK;
}

static ef_status push_point(text_reader *r, ef_point p)
{
    if (r->npts == r->cap) {
        uint32_t nc = r->cap ? r->cap * 2 : 64;
        ef_point *np = realloc(r->pts, (size_t)nc * sizeof *np);
        if (!np)
            return ef_error_set(r->err, EF_ERR_NOMEM, r->name, r->lineno, 0, "out of memory");
        r->pts = np;
        r->cap = nc;
    }
    r->pts[r->npts++] = p;
    return EF_OK;
}

/* The fit transform of SPEC.md section 3 at frame 0. */
static ef_status fit_ctm(ef_q32 w0, ef_q32 h0, int32_t W, int32_t H, ef_in_affine *m)
{
    ef_q32 sx, sy, ws, hs;
    if (!ef_q32_div(ef_q32_from_int(W), w0, &sx) || !ef_q32_div(ef_q32_from_int(H), h0, &sy))
        return EF_ERR_RANGE;
    ef_q32 s = sx.v < sy.v ? sx : sy;
    if (!ef_q32_mul(w0, s, &ws) || !ef_q32_mul(h0, s, &hs))
        return EF_ERR_RANGE;
    /* (W - s w0) / 2, halving by floor on the Q31.32 value. */
    ef_q32 tx = ef_q32_raw(ef_asr_i64(ef_q32_from_int(W).v - ws.v, 1));
    ef_q32 ty = ef_q32_raw(ef_asr_i64(ef_q32_from_int(H).v - hs.v, 1));
    *m = ef_in_affine_scale_translate(s, s, tx, ty);
    return EF_OK;
}

ef_status ef_scene_load_text(const char *name, const char *data, size_t len, const ef_load_opts *opts, ef_scene *out,
                             ef_error *err)
{
    ef_error local;
    if (!err)
        err = &local;
    if (!name)
        name = "<scene>";
    ef_scene_create(out, 0, 0);
    if (!data && len > 0)
        return ef_error_set(err, EF_ERR_ARG, name, 0, 0, "no data");
    if (len > EF_IN_MAX_FILE_BYTES)
        return ef_error_set(err, EF_ERR_LIMIT, name, 0, 0, "input larger than %u MiB",
                            (unsigned)(EF_IN_MAX_FILE_BYTES >> 20));
    if (opts && ((opts->fit_width != 0) != (opts->fit_height != 0) || opts->fit_width < 0 || opts->fit_height < 0 ||
                 opts->fit_width > EF_MAX_CANVAS || opts->fit_height > EF_MAX_CANVAS))
        return ef_error_set(err,
                            opts->fit_width < 0 || opts->fit_height < 0 ||
                                    (opts->fit_width != 0) != (opts->fit_height != 0)
                                ? EF_ERR_ARG
                                : EF_ERR_LIMIT,
                            name, 0, 0, "fit size must be two values in 1..%d", EF_MAX_CANVAS);
    bool fit = opts && opts->fit_width > 0;

    text_reader r = { name, data, 0, err, NULL, 0, 0 };
    ef_in_affine ctm = ef_in_affine_identity();
    bool have_scene = false;
    ef_status st = EF_OK;
    const char *p = data, *end = data + len;
    if (len >= 3 && (unsigned char)p[0] == 0xEF && (unsigned char)p[1] == 0xBB && (unsigned char)p[2] == 0xBF)
        p += 3;

    while (p < end) {
        r.lineno++;
        r.line = p;
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        const char *next = eol ? eol + 1 : end;
        if (!eol)
            eol = end;
        if (eol > p && eol[-1] == '\r')
            eol--; /* CRLF */
        /* eol >= p always; the explicit guard keeps gcc -O3's bounds analysis quiet. */
        const char *hash = eol > p ? memchr(p, '#', (size_t)(eol - p)) : NULL;
        if (hash)
            eol = hash;

        const char *cur = p, *tok;
        size_t n = next_token(&cur, eol, &tok);
        if (n == 0) {
            p = next;
            continue;
        }
        if (n == 5 && memcmp(tok, "scene", 5) == 0) {
            if (have_scene) {
                st = fail_at(&r, tok, EF_ERR_SYNTAX, "duplicate 'scene' directive%.*s", "", 0);
                goto fail;
            }
            ef_q32 wh[2];
            for (int i = 0; i < 2; i++) {
                n = next_token(&cur, eol, &tok);
                if (n == 0) {
                    st = fail_at(&r, tok, EF_ERR_SYNTAX, "scene needs a width and a height%.*s", "", 0);
                    goto fail;
                }
                if ((st = number(&r, tok, n, &wh[i])) != EF_OK)
                    goto fail;
                if (wh[i].v <= 0) {
                    st = fail_at(&r, tok, EF_ERR_RANGE, "scene size must be positive: '%.*s'", tok, n);
                    goto fail;
                }
            }
            if ((n = next_token(&cur, eol, &tok)) != 0) {
                st = fail_at(&r, tok, EF_ERR_SYNTAX, "unexpected token after scene size: '%.*s'", tok, n);
                goto fail;
            }
            int32_t W, H;
            if (fit) {
                W = opts->fit_width;
                H = opts->fit_height;
                if (fit_ctm(wh[0], wh[1], W, H, &ctm) != EF_OK) {
                    st = ef_error_set(err, EF_ERR_RANGE, name, r.lineno, 1, "scene size cannot be fitted");
                    goto fail;
                }
            } else if (ef_in_canvas_size(wh[0], &W) != EF_OK || ef_in_canvas_size(wh[1], &H) != EF_OK) {
                st = ef_error_set(err, EF_ERR_LIMIT, name, r.lineno, 1, "canvas larger than %d x %d pixels",
                                  EF_MAX_CANVAS, EF_MAX_CANVAS);
                goto fail;
            }
            out->width = W;
            out->height = H;
            have_scene = true;
        } else if (!have_scene) {
            st = fail_at(&r, tok, EF_ERR_SYNTAX, "the first directive must be 'scene', not '%.*s'", tok, n);
            goto fail;
        } else if (n == 5 && memcmp(tok, "shape", 5) == 0) {
            ef_rule rule;
            n = next_token(&cur, eol, &tok);
            if (n == 7 && memcmp(tok, "evenodd", 7) == 0)
                rule = EF_RULE_EVENODD;
            else if (n == 7 && memcmp(tok, "nonzero", 7) == 0)
                rule = EF_RULE_NONZERO;
            else {
                st = fail_at(&r, tok, EF_ERR_SYNTAX, "fill rule 'evenodd' or 'nonzero' expected%.*s", "", 0);
                goto fail;
            }
            uint8_t c[4];
            for (int i = 0; i < 4; i++) {
                n = next_token(&cur, eol, &tok);
                if ((st = byte_value(&r, tok, n, &c[i])) != EF_OK)
                    goto fail;
            }
            if ((n = next_token(&cur, eol, &tok)) != 0) {
                st = fail_at(&r, tok, EF_ERR_SYNTAX, "unexpected token after shape colour: '%.*s'", tok, n);
                goto fail;
            }
            ef_rgba8 col = { c[0], c[1], c[2], c[3] };
            if ((st = ef_scene_begin_shape(out, rule, col)) != EF_OK) {
                ef_error_set(err, st, name, r.lineno, 1, st == EF_ERR_NOMEM ? "out of memory" : "too many shapes");
                goto fail;
            }
        } else if (n == 7 && memcmp(tok, "contour", 7) == 0) {
            if (out->nshapes == 0) {
                st = fail_at(&r, tok, EF_ERR_SYNTAX, "'contour' before any 'shape'%.*s", "", 0);
                goto fail;
            }
            const char *first = tok;
            r.npts = 0;
            uint32_t count = 0;
            ef_q32 x = { 0 };
            for (;;) {
                n = next_token(&cur, eol, &tok);
                if (n == 0)
                    break;
                ef_q32 v;
                if ((st = number(&r, tok, n, &v)) != EF_OK)
                    goto fail;
                if (count++ % 2 == 0) {
                    x = v;
                    continue;
                }
                ef_point d;
                if (ef_in_affine_apply_dev(&ctm, x, v, &d) != EF_OK) {
                    st = fail_at(&r, tok, EF_ERR_RANGE,
                                 "point out of range (|x|, |y| must be below 32768 px after fitting)%.*s", "", 0);
                    goto fail;
                }
                if (out->npoints + r.npts >= EF_MAX_POINTS_PER_SCENE) {
                    st = fail_at(&r, tok, EF_ERR_LIMIT, "too many points in the scene (the limit is 2^24)%.*s", "", 0);
                    goto fail;
                }
                if (ef_in_shape_points(out) + r.npts >= EF_MAX_EDGES_PER_SHAPE) {
                    st = fail_at(&r, tok, EF_ERR_LIMIT,
                                 "too many edges in one shape (the model takes at most 2^22 = 4194304)%.*s", "", 0);
                    goto fail;
                }
                if ((st = push_point(&r, d)) != EF_OK)
                    goto fail;
            }
            if (count % 2 != 0) {
                st = fail_at(&r, eol, EF_ERR_SYNTAX, "odd number of coordinates%.*s", "", 0);
                goto fail;
            }
            if (count < 6) {
                st = fail_at(&r, first, EF_ERR_SYNTAX, "a contour needs at least 3 points%.*s", "", 0);
                goto fail;
            }
            if ((st = ef_scene_add_contour(out, r.pts, r.npts)) != EF_OK) {
                fail_at(&r, first, st, st == EF_ERR_NOMEM ? "out of memory%.*s" : "too many points or contours%.*s", "",
                        0);
                goto fail;
            }
        } else {
            st = fail_at(&r, tok, EF_ERR_SYNTAX, "unknown directive '%.*s'", tok, n);
            goto fail;
        }
        p = next;
    }
    if (!have_scene) {
        st = ef_error_set(err, EF_ERR_SYNTAX, name, r.lineno ? r.lineno : 1, 1, "no 'scene' directive");
        goto fail;
    }
    free(r.pts);
    return EF_OK;
fail:
    free(r.pts);
    ef_scene_destroy(out);
    return st;
}
