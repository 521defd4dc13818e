/*
 * svg_css.c - the CSS the SVG reader understands: declaration lists (style
 * attributes, rule bodies) and <style> sheets of simple rules.
 *
 * Place in the pipeline: feeds the property cascade in svg.c.  Supported
 * selectors: `type`, `.class`, `#id`, `type.class` and `*`, in comma-
 * separated lists; specificity is CSS's (ids, classes, types).  Comments and
 * the <!-- --> tokens are skipped.  Anything else - combinators, attribute
 * selectors, pseudo-classes, at-rules - is skipped (reported once per file as
 * a note), as a CSS parser skips what it does not understand.
 */
#include <stdlib.h>
#include <string.h>

#include "input_internal.h"

static bool css_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

static void trim(const char **s, size_t *n)
{
    while (*n > 0 && css_wsp(**s)) {
        (*s)++;
        (*n)--;
    }
    while (*n > 0 && css_wsp((*s)[*n - 1]))
        (*n)--;
}

static bool ident_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
           (unsigned char)c >= 0x80;
}

static char lower(char c) { return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c; }

ef_status ef_in_css_decls(const char *s, size_t len, ef_in_decls *out, size_t *err_off, ef_error *err)
{
    size_t i = 0;
    while (i < len) {
        size_t d0 = i;
        while (i < len && s[i] != ';')
            i++;
        const char *decl = s + d0;
        size_t dn = i - d0;
        if (i < len)
            i++; /* ';' */
        const char *t = decl;
        size_t tn = dn;
        trim(&t, &tn);
        if (tn == 0)
            continue;
        const char *colon = memchr(t, ':', tn);
        if (!colon) {
            *err_off = (size_t)(t - s);
            return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "':' expected in style declaration '%.*s'",
                                (int)(tn > 40 ? 40 : tn), t);
        }
        const char *name = t, *value = colon + 1;
        size_t name_len = (size_t)(colon - t), value_len = tn - name_len - 1;
        trim(&name, &name_len);
        trim(&value, &value_len);
        /* "!important" changes precedence in CSS; we apply declarations in
         * order, so it is dropped. */
        if (value_len >= 10) {
            size_t k = value_len;
            const char *imp = "important";
            size_t m = 9;
            bool match = true;
            for (size_t j = 0; j < m; j++)
                if (lower(value[k - m + j]) != imp[j])
                    match = false;
            if (match) {
                size_t b = k - m;
                while (b > 0 && css_wsp(value[b - 1]))
                    b--;
                if (b > 0 && value[b - 1] == '!') {
                    value_len = b - 1;
                    trim(&value, &value_len);
                }
            }
        }
        if (name_len == 0) {
            *err_off = (size_t)(t - s);
            return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "property name expected in '%.*s'",
                                (int)(tn > 40 ? 40 : tn), t);
        }
        if (out->n == out->cap) {
            uint32_t nc = out->cap ? out->cap * 2 : 16;
            ef_in_decl *nd = realloc(out->d, (size_t)nc * sizeof *nd);
            if (!nd)
                return ef_error_set(err, EF_ERR_NOMEM, NULL, 0, 0, "out of memory");
            out->d = nd;
            out->cap = nc;
        }
        ef_in_decl *d = &out->d[out->n++];
        d->name = name;
        d->name_len = name_len;
        d->value = value;
        d->value_len = value_len;
        d->value_off = (size_t)(value - s);
    }
    return EF_OK;
}

/* Parses one simple selector; false if unsupported. */
static bool selector(const char *s, size_t n, ef_in_css_rule *r)
{
    size_t i = 0;
    r->tag = r->cls = r->id = NULL;
    r->tag_len = r->cls_len = r->id_len = 0;
    r->specificity = 0;
    if (n == 1 && s[0] == '*')
        return true;
    if (i < n && ident_char(s[i])) {
        size_t t0 = i;
        while (i < n && ident_char(s[i]))
            i++;
        r->tag = s + t0;
        r->tag_len = i - t0;
        r->specificity += 1;
    }
    if (i < n && (s[i] == '.' || s[i] == '#')) {
        char k = s[i++];
        size_t t0 = i;
        while (i < n && ident_char(s[i]))
            i++;
        if (i == t0)
            return false;
        if (k == '.') {
            r->cls = s + t0;
            r->cls_len = i - t0;
            r->specificity += 1u << 8;
        } else {
            if (r->tag)
                return false; /* type#id: keep the grammar small */
            r->id = s + t0;
            r->id_len = i - t0;
            r->specificity += 1u << 16;
        }
    }
    return i == n && (r->tag || r->cls || r->id);
}

ef_status ef_in_css_add(ef_in_css *css, const char *text, size_t len, uint32_t node, bool *unsupported, ef_error *err)
{
    /* Own a copy with comments blanked out (same length, so offsets hold). */
    if (css->ntexts == css->texts_cap) {
        uint32_t nc = css->texts_cap ? css->texts_cap * 2 : 4;
        char **nt = realloc(css->texts, (size_t)nc * sizeof *nt);
        if (!nt)
            return ef_error_set(err, EF_ERR_NOMEM, NULL, 0, 0, "out of memory");
        css->texts = nt;
        css->texts_cap = nc;
    }
    char *s = malloc(len + 1);
    if (!s)
        return ef_error_set(err, EF_ERR_NOMEM, NULL, 0, 0, "out of memory");
    memcpy(s, text, len);
    s[len] = '\0';
    css->texts[css->ntexts++] = s;
    for (size_t i = 0; i + 1 < len; i++) {
        if (s[i] == '/' && s[i + 1] == '*') {
            size_t j = i + 2;
            while (j + 1 < len && !(s[j] == '*' && s[j + 1] == '/'))
                j++;
            size_t end = j + 1 < len ? j + 2 : len;
            memset(s + i, ' ', end - i);
            i = end - 1;
        }
    }

    size_t i = 0;
    while (i < len) {
        while (i < len && css_wsp(s[i]))
            i++;
        if (i >= len)
            break;
        if (len - i >= 4 && memcmp(s + i, "<!--", 4) == 0) {
            i += 4;
            continue;
        }
        if (len - i >= 3 && memcmp(s + i, "-->", 3) == 0) {
            i += 3;
            continue;
        }
        if (s[i] == '@') { /* at-rule: skip statement or block */
            *unsupported = true;
            while (i < len && s[i] != ';' && s[i] != '{')
                i++;
            if (i < len && s[i] == '{') {
                int depth = 0;
                for (; i < len; i++) {
                    if (s[i] == '{')
                        depth++;
                    else if (s[i] == '}' && --depth == 0)
                        break;
                }
            }
            i++;
            continue;
        }
        size_t sel0 = i;
        while (i < len && s[i] != '{')
            i++;
        if (i >= len) {
            *unsupported = true;
            break;
        }
        size_t sel1 = i++;
        size_t body0 = i;
        while (i < len && s[i] != '}')
            i++;
        size_t body1 = i;
        if (i < len)
            i++;

        uint32_t d0 = css->decls.n;
        size_t off;
        ef_status st = ef_in_css_decls(s + body0, body1 - body0, &css->decls, &off, err);
        if (st != EF_OK)
            return st;
        uint32_t nd = css->decls.n - d0;

        size_t a = sel0;
        while (a <= sel1) {
            size_t b = a;
            while (b < sel1 && s[b] != ',')
                b++;
            const char *one = s + a;
            size_t on = b - a;
            trim(&one, &on);
            ef_in_css_rule r;
            if (on > 0 && selector(one, on, &r)) {
                if (css->nrules == css->rules_cap) {
                    uint32_t nc = css->rules_cap ? css->rules_cap * 2 : 16;
                    ef_in_css_rule *nr = realloc(css->rules, (size_t)nc * sizeof *nr);
                    if (!nr)
                        return ef_error_set(err, EF_ERR_NOMEM, NULL, 0, 0, "out of memory");
                    css->rules = nr;
                    css->rules_cap = nc;
                }
                r.order = css->nrules;
                r.decl0 = d0;
                r.ndecl = nd;
                r.node = node;
                css->rules[css->nrules++] = r;
            } else {
                *unsupported = true;
            }
            a = b + 1;
        }
    }
    return EF_OK;
}

void ef_in_css_free(ef_in_css *css)
{
    for (uint32_t i = 0; i < css->ntexts; i++)
        free(css->texts[i]);
    free(css->texts);
    free(css->rules);
    free(css->decls.d);
    memset(css, 0, sizeof *css);
}

static bool has_class(const char *list, size_t n, const char *cls, size_t cn)
{
    size_t i = 0;
    while (i < n) {
        while (i < n && css_wsp(list[i]))
            i++;
        size_t t0 = i;
        while (i < n && !css_wsp(list[i]))
            i++;
        if (i - t0 == cn && memcmp(list + t0, cls, cn) == 0)
            return true;
    }
    return false;
}

bool ef_in_css_match(const ef_in_css_rule *r, const char *tag, const char *cls, size_t cls_len, const char *id,
                     size_t id_len)
{
    if (r->tag && (strlen(tag) != r->tag_len || memcmp(tag, r->tag, r->tag_len) != 0))
        return false;
    if (r->cls && (!cls || !has_class(cls, cls_len, r->cls, r->cls_len)))
        return false;
    if (r->id && (!id || id_len != r->id_len || memcmp(id, r->id, id_len) != 0))
        return false;
    return true;
}
