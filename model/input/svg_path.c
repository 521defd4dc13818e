/*
 * svg_path.c - SVG path data (SVG 1.1 8.3) and points lists (9.7.1).
 *
 * Place in the pipeline: text of a `d` or `points` attribute -> builder
 * commands in user space (Q31.32).  The grammar is SVG 1.1's BNF:
 *
 *  - the data begins with a moveto (M/m; a leading m is absolute since the
 *    current point is (0, 0)); empty or all-white-space data draws nothing;
 *  - commands M L H V C S Q T A Z, upper case absolute, lower case relative to
 *    the current point; a command letter is followed by wsp* (no comma);
 *  - argument groups repeat implicitly; extra pairs after M/m are L/l;
 *  - comma-wsp? between numbers and between repeated groups; a comma must be
 *    followed by a number of the same command; none before a command letter;
 *  - arc flags are the single characters 0 and 1 (so "a1 1 0 00 1 1" parses);
 *  - Z takes no arguments: a number after Z is an error; after Z the current
 *    point is the subpath's start, and a drawing command that is not a moveto
 *    starts a new subpath there;
 *  - S reflects the previous command's second control point if that command
 *    was C/c/S/s, else uses the current point; T likewise with Q/q/T/t.
 *
 * Relative coordinates and reflections are computed exactly in Q31.32
 * (additions); a result outside Q31.32 is a range error.  Every error gives
 * the byte offset of the offending character in the attribute value; the SVG
 * reader turns it into line:column.  Unlike SVG's "render up to the first
 * error", a malformed path rejects the file (the model never renders a
 * partial scene).
 */
#include "input_internal.h"

typedef struct path_state {
    ef_in_lex l;
    ef_in_builder *b;
    ef_error *err;
    size_t *err_off;
    ef_q32 x, y;   /* current point */
    ef_q32 sx, sy; /* start of the current subpath */
    ef_q32 cx, cy; /* last control point (for S and T) */
    char last;     /* previous command (upper case), '\0' at start */
    bool open;     /* a subpath is open (no Z since the last moveto) */
} path_state;

static ef_status fail(path_state *ps, size_t off, ef_status st, const char *msg)
{
    *ps->err_off = off;
    return ef_error_set(ps->err, st, NULL, 0, 0, "%s", msg);
}

static ef_status number(path_state *ps, ef_q32 *v)
{
    size_t at = ps->l.pos;
    ef_status st = ef_in_lex_number(&ps->l, v, ps->err);
    if (st != EF_OK)
        *ps->err_off = at;
    return st;
}

/* comma-wsp? between two numbers of one command. */
static ef_status sep_number(path_state *ps, ef_q32 *v)
{
    ef_in_lex_sep(&ps->l);
    return number(ps, v);
}

static ef_status flag(path_state *ps, bool *f)
{
    ef_in_lex_sep(&ps->l);
    char c = ef_in_lex_peek(&ps->l);
    if (c != '0' && c != '1')
        return fail(ps, ps->l.pos, EF_ERR_SYNTAX, "arc flag (0 or 1) expected");
    *f = c == '1';
    ps->l.pos++;
    return EF_OK;
}

/* v + base (relative) exactly, or v (absolute). */
static ef_status rel(path_state *ps, size_t at, bool relative, ef_q32 base, ef_q32 *v)
{
    if (!relative)
        return EF_OK;
    int64_t r;
    if (!ef_add_i64_checked(v->v, base.v, &r))
        return fail(ps, at, EF_ERR_RANGE, "coordinate out of range");
    v->v = r;
    return EF_OK;
}

/* 2 p - c (the reflection of control point c about p). */
static ef_status reflect(path_state *ps, size_t at, ef_q32 p, ef_q32 c, ef_q32 *out)
{
    int64_t t, r;
    if (!ef_add_i64_checked(p.v, p.v, &t) || c.v == INT64_MIN || !ef_add_i64_checked(t, -c.v, &r))
        return fail(ps, at, EF_ERR_RANGE, "reflected control point out of range");
    out->v = r;
    return EF_OK;
}

/* After Z, a drawing command starts a new subpath at the start point. */
static ef_status ensure_open(path_state *ps, size_t at)
{
    if (ps->open)
        return EF_OK;
    ef_status st = ef_in_build_move(ps->b, ps->x, ps->y, ps->err);
    if (st != EF_OK)
        *ps->err_off = at;
    ps->open = true;
    return st;
}

static ef_status builder_status(path_state *ps, size_t at, ef_status st)
{
    if (st != EF_OK)
        *ps->err_off = at;
    return st;
}

/* One argument group of command c (upper case) starting at `at`. */
static ef_status group(path_state *ps, char c, bool relative, size_t at)
{
    ef_status st;
    ef_q32 v[7];
    switch (c) {
    case 'M':
        if ((st = number(ps, &v[0])) || (st = sep_number(ps, &v[1])))
            return st;
        if ((st = rel(ps, at, relative, ps->x, &v[0])) || (st = rel(ps, at, relative, ps->y, &v[1])))
            return st;
        ps->x = ps->sx = v[0];
        ps->y = ps->sy = v[1];
        ps->open = true;
        return builder_status(ps, at, ef_in_build_move(ps->b, v[0], v[1], ps->err));
    case 'L':
    case 'H':
    case 'V':
        if (c == 'L') {
            if ((st = number(ps, &v[0])) || (st = sep_number(ps, &v[1])))
                return st;
            if ((st = rel(ps, at, relative, ps->x, &v[0])) || (st = rel(ps, at, relative, ps->y, &v[1])))
                return st;
        } else if (c == 'H') {
            if ((st = number(ps, &v[0])) || (st = rel(ps, at, relative, ps->x, &v[0])))
                return st;
            v[1] = ps->y;
        } else {
            if ((st = number(ps, &v[1])) || (st = rel(ps, at, relative, ps->y, &v[1])))
                return st;
            v[0] = ps->x;
        }
        if ((st = ensure_open(ps, at)))
            return st;
        ps->x = v[0];
        ps->y = v[1];
        return builder_status(ps, at, ef_in_build_line(ps->b, v[0], v[1], ps->err));
    case 'C':
    case 'S': {
        ef_q32 p[8];
        int first = c == 'C' ? 1 : 2; /* first control point read from the text */
        p[0] = ps->x;
        p[1] = ps->y;
        for (int i = first; i < 4; i++) {
            if ((st = i == first ? number(ps, &p[2 * i]) : sep_number(ps, &p[2 * i])) ||
                (st = sep_number(ps, &p[2 * i + 1])) || (st = rel(ps, at, relative, ps->x, &p[2 * i])) ||
                (st = rel(ps, at, relative, ps->y, &p[2 * i + 1])))
                return st;
        }
        if (c == 'S') {
            if (ps->last == 'C' || ps->last == 'S') {
                if ((st = reflect(ps, at, ps->x, ps->cx, &p[2])) || (st = reflect(ps, at, ps->y, ps->cy, &p[3])))
                    return st;
            } else {
                p[2] = ps->x;
                p[3] = ps->y;
            }
        }
        if ((st = ensure_open(ps, at)))
            return st;
        ps->cx = p[4];
        ps->cy = p[5];
        ps->x = p[6];
        ps->y = p[7];
        return builder_status(ps, at, ef_in_build_cubic(ps->b, p, ps->err));
    }
    case 'Q':
    case 'T': {
        ef_q32 p[6];
        p[0] = ps->x;
        p[1] = ps->y;
        if (c == 'Q') {
            if ((st = number(ps, &p[2])) || (st = sep_number(ps, &p[3])) || (st = sep_number(ps, &p[4])) ||
                (st = sep_number(ps, &p[5])))
                return st;
            for (int i = 1; i < 3; i++)
                if ((st = rel(ps, at, relative, ps->x, &p[2 * i])) ||
                    (st = rel(ps, at, relative, ps->y, &p[2 * i + 1])))
                    return st;
        } else {
            if (ps->last == 'Q' || ps->last == 'T') {
                if ((st = reflect(ps, at, ps->x, ps->cx, &p[2])) || (st = reflect(ps, at, ps->y, ps->cy, &p[3])))
                    return st;
            } else {
                p[2] = ps->x;
                p[3] = ps->y;
            }
            if ((st = number(ps, &p[4])) || (st = sep_number(ps, &p[5])))
                return st;
            if ((st = rel(ps, at, relative, ps->x, &p[4])) || (st = rel(ps, at, relative, ps->y, &p[5])))
                return st;
        }
        if ((st = ensure_open(ps, at)))
            return st;
        ps->cx = p[2];
        ps->cy = p[3];
        ps->x = p[4];
        ps->y = p[5];
        return builder_status(ps, at, ef_in_build_quad(ps->b, p, ps->err));
    }
    case 'A': {
        bool large = false, sweep = false;
        if ((st = number(ps, &v[0])) || (st = sep_number(ps, &v[1])) || (st = sep_number(ps, &v[2])) ||
            (st = flag(ps, &large)) || (st = flag(ps, &sweep)) || (st = sep_number(ps, &v[3])) ||
            (st = sep_number(ps, &v[4])))
            return st;
        if ((st = rel(ps, at, relative, ps->x, &v[3])) || (st = rel(ps, at, relative, ps->y, &v[4])))
            return st;
        if ((st = ensure_open(ps, at)))
            return st;
        ef_q32 x0 = ps->x, y0 = ps->y;
        ps->x = v[3];
        ps->y = v[4];
        return builder_status(ps, at,
                              ef_in_build_svg_arc(ps->b, x0, y0, v[0], v[1], v[2], large, sweep, v[3], v[4], ps->err));
    }
    default: return fail(ps, at, EF_ERR_SYNTAX, "unknown path command");
    }
}

static bool is_command(char c)
{
    switch (c) {
    case 'M':
    case 'm':
    case 'L':
    case 'l':
    case 'H':
    case 'h':
    case 'V':
    case 'v':
    case 'C':
    case 'c':
    case 'S':
    case 's':
    case 'Q':
    case 'q':
    case 'T':
    case 't':
    case 'A':
    case 'a':
    case 'Z':
    case 'z': return true;
    default: return false;
    }
}

ef_status ef_in_path_parse(const char *d, size_t len, ef_in_builder *b, size_t *err_off, ef_error *err)
{
    path_state ps = { { d, len, 0 }, b, err, err_off, { 0 }, { 0 }, { 0 }, { 0 }, { 0 }, { 0 }, '\0', false };
    ef_status st;
    ef_in_lex_wsp(&ps.l);
    if (ef_in_lex_end(&ps.l))
        return EF_OK;
    char first = ef_in_lex_peek(&ps.l);
    if (first != 'M' && first != 'm')
        return fail(&ps, ps.l.pos, EF_ERR_SYNTAX, "path data must begin with a moveto (M or m)");
    while (!ef_in_lex_end(&ps.l)) {
        size_t at = ps.l.pos;
        char c = ef_in_lex_peek(&ps.l);
        if (!is_command(c)) {
            if (ef_in_lex_at_number(&ps.l) && (ps.last == 'Z'))
                return fail(&ps, at, EF_ERR_SYNTAX, "closepath (Z) takes no arguments");
            if (c == ',')
                return fail(&ps, at, EF_ERR_SYNTAX, "unexpected ','");
            return fail(&ps, at, EF_ERR_SYNTAX, "path command expected");
        }
        ps.l.pos++;
        bool relative = c >= 'a';
        char C = (char)(relative ? c - ('a' - 'A') : c);
        ef_in_lex_wsp(&ps.l);
        if (C == 'Z') {
            ef_in_build_close(b);
            ps.open = false;
            ps.x = ps.sx;
            ps.y = ps.sy;
            ps.last = 'Z';
            continue;
        }
        /* First group, then implicit repeats while a number follows. */
        for (;;) {
            size_t gat = ps.l.pos;
            if (!ef_in_lex_at_number(&ps.l)) {
                if (ef_in_lex_end(&ps.l) || is_command(ef_in_lex_peek(&ps.l)))
                    return fail(&ps, at, EF_ERR_SYNTAX, "missing arguments after path command");
                return fail(&ps, gat, EF_ERR_SYNTAX, "number expected");
            }
            if ((st = group(&ps, C, relative, at)) != EF_OK)
                return st;
            ps.last = C;
            if (C == 'M')
                C = 'L'; /* implicit lineto after moveto, same relativity */
            int sep = ef_in_lex_sep(&ps.l);
            if (ef_in_lex_at_number(&ps.l)) {
                at = ps.l.pos;
                continue;
            }
            if (sep == 2)
                return fail(&ps, ps.l.pos, EF_ERR_SYNTAX, "number expected after ','");
            break;
        }
    }
    ef_in_build_close(b);
    return EF_OK;
}

ef_status ef_in_points_parse(const char *s, size_t len, ef_in_builder *b, size_t *err_off, ef_error *err)
{
    ef_in_lex l = { s, len, 0 };
    ef_status st;
    size_t n = 0;
    ef_q32 x = { 0 }, y = { 0 };
    ef_in_lex_wsp(&l);
    while (!ef_in_lex_end(&l)) {
        size_t at = l.pos;
        if (n > 0 && ef_in_lex_sep(&l) == 2 && ef_in_lex_end(&l)) {
            *err_off = l.pos;
            return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "number expected after ','");
        }
        if (ef_in_lex_end(&l))
            break;
        at = l.pos;
        ef_q32 v;
        if ((st = ef_in_lex_number(&l, &v, err)) != EF_OK) {
            *err_off = at;
            return st;
        }
        if (n % 2 == 0) {
            x = v;
        } else {
            y = v;
            st = n == 1 ? ef_in_build_move(b, x, y, err) : ef_in_build_line(b, x, y, err);
            if (st != EF_OK) {
                *err_off = at;
                return st;
            }
        }
        n++;
        ef_in_lex_wsp(&l);
    }
    if (n % 2 != 0) {
        *err_off = len;
        return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "odd number of coordinates in points list");
    }
    ef_in_build_close(b);
    return EF_OK;
}
