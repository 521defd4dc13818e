/*
 * color.c - paints, colours and opacities (SVG 1.1 4.2, CSS Color 3).
 *
 * Place in the pipeline: fill values -> the shape's straight RGBA8 colour.
 * Accepted colours: #rgb, #rrggbb, rgb()/rgba() with numbers or percentages
 * (comma- or space-separated, alpha after ',' or '/'), the 147 CSS Color 3
 * keywords (ASCII case-insensitive), "transparent" (alpha 0) and
 * currentColor.  Paints add none and url(#id) with an optional fallback.
 * Anything else is a syntax error with its offset.
 *
 * Rounding (integer only):
 *   rgb number v          -> clamp(floor(v + 1/2), 0, 255)
 *   rgb percentage p      -> floor(clamp(p, 0, 100) * 255 / 100 + 1/2), exactly
 *   opacity number v      -> clamp(v, 0, 1) in Q31.32
 *   opacity percentage p  -> clamp(p, 0, 100) / 100, rounded to nearest Q31.32
 *   alpha8(p)             -> floor(255 p + 1/2)
 */
#include <string.h>

#include "input_internal.h"

typedef struct named_color {
    const char *name;
    uint8_t r, g, b;
} named_color;

/* CSS Color Module Level 3, section 4.3 (the SVG 1.1 colour keywords), sorted
 * for binary search. */
static const named_color NAMED[] = {
    { "aliceblue", 240, 248, 255 },
    { "antiquewhite", 250, 235, 215 },
    { "aqua", 0, 255, 255 },
    { "aquamarine", 127, 255, 212 },
    { "azure", 240, 255, 255 },
    { "beige", 245, 245, 220 },
    { "bisque", 255, 228, 196 },
    { "black", 0, 0, 0 },
    { "blanchedalmond", 255, 235, 205 },
    { "blue", 0, 0, 255 },
    { "blueviolet", 138, 43, 226 },
    { "brown", 165, 42, 42 },
    { "burlywood", 222, 184, 135 },
    { "cadetblue", 95, 158, 160 },
    { "chartreuse", 127, 255, 0 },
    { "chocolate", 210, 105, 30 },
    { "coral", 255, 127, 80 },
    { "cornflowerblue", 100, 149, 237 },
    { "cornsilk", 255, 248, 220 },
    { "crimson", 220, 20, 60 },
    { "cyan", 0, 255, 255 },
    { "darkblue", 0, 0, 139 },
    { "darkcyan", 0, 139, 139 },
    { "darkgoldenrod", 184, 134, 11 },
    { "darkgray", 169, 169, 169 },
    { "darkgreen", 0, 100, 0 },
    { "darkgrey", 169, 169, 169 },
    { "darkkhaki", 189, 183, 107 },
    { "darkmagenta", 139, 0, 139 },
    { "darkolivegreen", 85, 107, 47 },
    { "darkorange", 255, 140, 0 },
    { "darkorchid", 153, 50, 204 },
    { "darkred", 139, 0, 0 },
    { "darksalmon", 233, 150, 122 },
    { "darkseagreen", 143, 188, 143 },
    { "darkslateblue", 72, 61, 139 },
    { "darkslategray", 47, 79, 79 },
    { "darkslategrey", 47, 79, 79 },
    { "darkturquoise", 0, 206, 209 },
    { "darkviolet", 148, 0, 211 },
    { "deeppink", 255, 20, 147 },
    { "deepskyblue", 0, 191, 255 },
    { "dimgray", 105, 105, 105 },
    { "dimgrey", 105, 105, 105 },
    { "dodgerblue", 30, 144, 255 },
    { "firebrick", 178, 34, 34 },
    { "floralwhite", 255, 250, 240 },
    { "forestgreen", 34, 139, 34 },
    { "fuchsia", 255, 0, 255 },
    { "gainsboro", 220, 220, 220 },
    { "ghostwhite", 248, 248, 255 },
    { "gold", 255, 215, 0 },
    { "goldenrod", 218, 165, 32 },
    { "gray", 128, 128, 128 },
    { "green", 0, 128, 0 },
    { "greenyellow", 173, 255, 47 },
    { "grey", 128, 128, 128 },
    { "honeydew", 240, 255, 240 },
    { "hotpink", 255, 105, 180 },
    { "indianred", 205, 92, 92 },
    { "indigo", 75, 0, 130 },
    { "ivory", 255, 255, 240 },
    { "khaki", 240, 230, 140 },
    { "lavender", 230, 230, 250 },
    { "lavenderblush", 255, 240, 245 },
    { "lawngreen", 124, 252, 0 },
    { "lemonchiffon", 255, 250, 205 },
    { "lightblue", 173, 216, 230 },
    { "lightcoral", 240, 128, 128 },
    { "lightcyan", 224, 255, 255 },
    { "lightgoldenrodyellow", 250, 250, 210 },
    { "lightgray", 211, 211, 211 },
    { "lightgreen", 144, 238, 144 },
    { "lightgrey", 211, 211, 211 },
    { "lightpink", 255, 182, 193 },
    { "lightsalmon", 255, 160, 122 },
    { "lightseagreen", 32, 178, 170 },
    { "lightskyblue", 135, 206, 250 },
    { "lightslategray", 119, 136, 153 },
    { "lightslategrey", 119, 136, 153 },
    { "lightsteelblue", 176, 196, 222 },
    { "lightyellow", 255, 255, 224 },
    { "lime", 0, 255, 0 },
    { "limegreen", 50, 205, 50 },
    { "linen", 250, 240, 230 },
    { "magenta", 255, 0, 255 },
    { "maroon", 128, 0, 0 },
    { "mediumaquamarine", 102, 205, 170 },
    { "mediumblue", 0, 0, 205 },
    { "mediumorchid", 186, 85, 211 },
    { "mediumpurple", 147, 112, 219 },
    { "mediumseagreen", 60, 179, 113 },
    { "mediumslateblue", 123, 104, 238 },
    { "mediumspringgreen", 0, 250, 154 },
    { "mediumturquoise", 72, 209, 204 },
    { "mediumvioletred", 199, 21, 133 },
    { "midnightblue", 25, 25, 112 },
    { "mintcream", 245, 255, 250 },
    { "mistyrose", 255, 228, 225 },
    { "moccasin", 255, 228, 181 },
    { "navajowhite", 255, 222, 173 },
    { "navy", 0, 0, 128 },
    { "oldlace", 253, 245, 230 },
    { "olive", 128, 128, 0 },
    { "olivedrab", 107, 142, 35 },
    { "orange", 255, 165, 0 },
    { "orangered", 255, 69, 0 },
    { "orchid", 218, 112, 214 },
    { "palegoldenrod", 238, 232, 170 },
    { "palegreen", 152, 251, 152 },
    { "paleturquoise", 175, 238, 238 },
    { "palevioletred", 219, 112, 147 },
    { "papayawhip", 255, 239, 213 },
    { "peachpuff", 255, 218, 185 },
    { "peru", 205, 133, 63 },
    { "pink", 255, 192, 203 },
    { "plum", 221, 160, 221 },
    { "powderblue", 176, 224, 230 },
    { "purple", 128, 0, 128 },
    { "red", 255, 0, 0 },
    { "rosybrown", 188, 143, 143 },
    { "royalblue", 65, 105, 225 },
    { "saddlebrown", 139, 69, 19 },
    { "salmon", 250, 128, 114 },
    { "sandybrown", 244, 164, 96 },
    { "seagreen", 46, 139, 87 },
    { "seashell", 255, 245, 238 },
    { "sienna", 160, 82, 45 },
    { "silver", 192, 192, 192 },
    { "skyblue", 135, 206, 235 },
    { "slateblue", 106, 90, 205 },
    { "slategray", 112, 128, 144 },
    { "slategrey", 112, 128, 144 },
    { "snow", 255, 250, 250 },
    { "springgreen", 0, 255, 127 },
    { "steelblue", 70, 130, 180 },
    { "tan", 210, 180, 140 },
    { "teal", 0, 128, 128 },
    { "thistle", 216, 191, 216 },
    { "tomato", 255, 99, 71 },
    { "turquoise", 64, 224, 208 },
    { "violet", 238, 130, 238 },
    { "wheat", 245, 222, 179 },
    { "white", 255, 255, 255 },
    { "whitesmoke", 245, 245, 245 },
    { "yellow", 255, 255, 0 },
    { "yellowgreen", 154, 205, 50 },
};

static char lower(char c) { return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c; }

/* ASCII case-insensitive comparison of s[0..n) with a lower-case literal. */
static int cmp_ci(const char *s, size_t n, const char *lit)
{
    size_t i = 0;
    for (; i < n && lit[i] != '\0'; i++) {
        char a = lower(s[i]);
        if (a != lit[i])
            return (unsigned char)a < (unsigned char)lit[i] ? -1 : 1;
    }
    if (i < n)
        return 1;
    return lit[i] == '\0' ? 0 : -1;
}

static bool eq_ci(const char *s, size_t n, const char *lit) { return cmp_ci(s, n, lit) == 0; }

static const named_color *find_named(const char *s, size_t n)
{
    size_t lo = 0, hi = sizeof NAMED / sizeof NAMED[0];
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c = cmp_ci(s, n, NAMED[mid].name);
        if (c == 0)
            return &NAMED[mid];
        if (c < 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    return NULL;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    c = lower(c);
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

static ef_status syntax(ef_error *err, size_t *err_off, size_t off, const char *what, const char *s, size_t n)
{
    *err_off = off;
    return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "%s '%.*s'", what, (int)(n > 64 ? 64 : n), s);
}

uint8_t ef_in_alpha8(ef_q32 p)
{
    int64_t v = ef_clamp_i64(p.v, 0, EF_Q32_ONE);
    return (uint8_t)ef_round_shr_i64(255 * v, 32);
}

/* A number optionally followed by '%'. */
static ef_status num_or_pct(ef_in_lex *l, ef_q32 *v, bool *pct, ef_error *err)
{
    ef_status st = ef_in_lex_number(l, v, err);
    if (st != EF_OK)
        return st;
    *pct = ef_in_lex_peek(l) == '%';
    if (*pct)
        l->pos++;
    return EF_OK;
}

static uint8_t channel(ef_q32 v, bool pct)
{
    if (pct) {
        int64_t p = ef_clamp_i64(v.v, 0, 100 * EF_Q32_ONE); /* p < 2^39: 510 p fits */
        return (uint8_t)ef_floordiv_i64(510 * p + 100 * EF_Q32_ONE, 200 * EF_Q32_ONE);
    }
    int64_t r = ef_round_shr_i64(v.v, 32);
    return (uint8_t)ef_clamp_i64(r, 0, 255);
}

static ef_q32 unit_interval(ef_q32 v, bool pct)
{
    if (pct)
        return ef_q32_raw(ef_rounddiv_i64(ef_clamp_i64(v.v, 0, 100 * EF_Q32_ONE), 100));
    return ef_q32_raw(ef_clamp_i64(v.v, 0, EF_Q32_ONE));
}

/* rgb( ... ) / rgba( ... ): s points at the first argument, l ends at ')'. */
static ef_status rgb_func(const char *s, size_t len, size_t base, ef_in_paint *out, size_t *err_off, ef_error *err)
{
    ef_in_lex l = { s, len, 0 };
    ef_q32 v[4];
    bool pct[4];
    int n = 0;
    ef_status st;
    ef_in_lex_wsp(&l);
    while (!ef_in_lex_end(&l)) {
        if (n > 0) {
            int sep = ef_in_lex_sep(&l);
            if (n == 3 && ef_in_lex_peek(&l) == '/' && sep != 2) {
                l.pos++;
                ef_in_lex_wsp(&l);
            }
        }
        if (n == 4)
            return syntax(err, err_off, base + l.pos, "too many colour arguments in", s, len);
        size_t at = l.pos;
        if ((st = num_or_pct(&l, &v[n], &pct[n], err)) != EF_OK) {
            *err_off = base + at;
            return st;
        }
        n++;
        ef_in_lex_wsp(&l);
    }
    if (n < 3)
        return syntax(err, err_off, base + l.pos, "too few colour arguments in", s, len);
    out->kind = EF_IN_PAINT_RGB;
    out->r = channel(v[0], pct[0]);
    out->g = channel(v[1], pct[1]);
    out->b = channel(v[2], pct[2]);
    out->alpha = n == 4 ? unit_interval(v[3], pct[3]) : ef_q32_raw(EF_Q32_ONE);
    return EF_OK;
}

static void trim(const char **s, size_t *len, size_t *base)
{
    while (*len > 0 && ef_in_is_wsp(**s)) {
        (*s)++;
        (*len)--;
        (*base)++;
    }
    while (*len > 0 && ef_in_is_wsp((*s)[*len - 1]))
        (*len)--;
}

static ef_status color_at(const char *s, size_t len, size_t base, ef_in_paint *out, size_t *err_off, ef_error *err)
{
    trim(&s, &len, &base);
    memset(out, 0, sizeof *out);
    out->alpha = ef_q32_raw(EF_Q32_ONE);
    if (len == 0)
        return syntax(err, err_off, base, "colour expected:", s, len);
    if (s[0] == '#') {
        int h[6];
        if (len != 4 && len != 7)
            return syntax(err, err_off, base, "bad hex colour", s, len);
        for (size_t i = 1; i < len; i++)
            if ((h[i - 1] = hexval(s[i])) < 0)
                return syntax(err, err_off, base + i, "bad hex colour", s, len);
        out->kind = EF_IN_PAINT_RGB;
        if (len == 4) {
            out->r = (uint8_t)(h[0] * 17);
            out->g = (uint8_t)(h[1] * 17);
            out->b = (uint8_t)(h[2] * 17);
        } else {
            out->r = (uint8_t)(h[0] * 16 + h[1]);
            out->g = (uint8_t)(h[2] * 16 + h[3]);
            out->b = (uint8_t)(h[4] * 16 + h[5]);
        }
        return EF_OK;
    }
    size_t fn = 0;
    while (fn < len && s[fn] != '(')
        fn++;
    if (fn < len) {
        size_t name_len = fn;
        while (name_len > 0 && ef_in_is_wsp(s[name_len - 1]))
            name_len--;
        if (!eq_ci(s, name_len, "rgb") && !eq_ci(s, name_len, "rgba"))
            return syntax(err, err_off, base, "unsupported colour function in", s, len);
        if (s[len - 1] != ')')
            return syntax(err, err_off, base + len, "')' expected in", s, len);
        return rgb_func(s + fn + 1, len - fn - 2, base + fn + 1, out, err_off, err);
    }
    if (eq_ci(s, len, "currentcolor")) {
        out->kind = EF_IN_PAINT_CURRENT;
        return EF_OK;
    }
    if (eq_ci(s, len, "transparent")) {
        out->kind = EF_IN_PAINT_RGB;
        out->alpha = ef_q32_raw(0);
        return EF_OK;
    }
    const named_color *nc = find_named(s, len);
    if (!nc)
        return syntax(err, err_off, base, "unknown colour", s, len);
    out->kind = EF_IN_PAINT_RGB;
    out->r = nc->r;
    out->g = nc->g;
    out->b = nc->b;
    return EF_OK;
}

ef_status ef_in_color_parse(const char *s, size_t len, ef_in_paint *out, size_t *err_off, ef_error *err)
{
    return color_at(s, len, 0, out, err_off, err);
}

ef_status ef_in_paint_parse(const char *s, size_t len, ef_in_paint *out, size_t *err_off, ef_error *err)
{
    size_t base = 0;
    trim(&s, &len, &base);
    if (eq_ci(s, len, "none")) {
        memset(out, 0, sizeof *out);
        out->kind = EF_IN_PAINT_NONE;
        return EF_OK;
    }
    if (len >= 4 && eq_ci(s, 4, "url(")) {
        size_t i = 4, close = 4;
        while (close < len && s[close] != ')')
            close++;
        if (close == len)
            return syntax(err, err_off, base + len, "')' expected in", s, len);
        size_t a = i, b = close;
        while (a < b && ef_in_is_wsp(s[a]))
            a++;
        while (b > a && ef_in_is_wsp(s[b - 1]))
            b--;
        if (b - a >= 2 && (s[a] == '\'' || s[a] == '"') && s[b - 1] == s[a]) {
            a++;
            b--;
        }
        if (a >= b || s[a] != '#')
            return syntax(err, err_off, base + a, "only local references url(#id) are supported:", s, len);
        ef_in_paint fb;
        memset(&fb, 0, sizeof fb);
        bool has_fb = false;
        size_t rest = close + 1;
        size_t rest_len = len - rest;
        size_t rb = base + rest;
        const char *r = s + rest;
        trim(&r, &rest_len, &rb);
        if (rest_len > 0) {
            ef_status st;
            if (eq_ci(r, rest_len, "none"))
                fb.kind = EF_IN_PAINT_NONE;
            else if ((st = color_at(r, rest_len, rb, &fb, err_off, err)) != EF_OK)
                return st;
            has_fb = true;
        }
        memset(out, 0, sizeof *out);
        out->kind = EF_IN_PAINT_URL;
        out->url_off = base + a + 1;
        out->url_len = b - a - 1;
        out->has_fallback = has_fb;
        out->fallback_kind = fb.kind;
        out->fr = fb.r;
        out->fg = fb.g;
        out->fb = fb.b;
        out->falpha = fb.alpha;
        return EF_OK;
    }
    return color_at(s, len, base, out, err_off, err);
}

ef_status ef_in_opacity_parse(const char *s, size_t len, ef_q32 *out, size_t *err_off, ef_error *err)
{
    ef_in_lex l = { s, len, 0 };
    ef_q32 v;
    bool pct;
    ef_status st;
    ef_in_lex_wsp(&l);
    size_t at = l.pos;
    if ((st = num_or_pct(&l, &v, &pct, err)) != EF_OK) {
        *err_off = at;
        return st;
    }
    ef_in_lex_wsp(&l);
    if (!ef_in_lex_end(&l))
        return syntax(err, err_off, l.pos, "unexpected text in opacity", s, len);
    *out = unit_interval(v, pct);
    return EF_OK;
}
