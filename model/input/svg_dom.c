/*
 * svg_dom.c - the XML document as a small tree, read with expat.
 *
 * Place in the pipeline: first stage of the SVG reader.  A tree (rather than
 * drawing while parsing) because <use> may point forward, <style> may come
 * after the elements it styles, and gradients are usually defined late.
 * Nodes, attributes and strings live in three flat arrays (indices, not
 * pointers, so growing them is safe).
 *
 * Hostile input:
 *  - any <!ENTITY> declaration (general or parameter) stops the parse with an
 *    error at the declaration, so no entity is ever expanded ("billion
 *    laughs" fails at its first line); parameter entities and external DTDs
 *    are never read (XML_PARAM_ENTITY_PARSING_NEVER); a reference to an
 *    undefined entity is an error even where XML would let it be skipped;
 *    a plain <!DOCTYPE svg PUBLIC ...> (the SLEFA files) is fine;
 *  - nesting deeper than EF_IN_MAX_DEPTH and more than EF_IN_MAX_ELEMENTS
 *    elements are errors (EF_ERR_LIMIT);
 *  - malformed XML and bad UTF-8 are expat errors, reported at expat's
 *    line:column.
 * Positions: expat gives the line and (0-based, in characters) column of
 * each start tag; we store them 1-based with the byte offset of the '<', and
 * ef_in_dom_locate rescans the raw start tag to find the column of a
 * character inside an attribute value.
 */
#ifndef EF_NO_SVG
#include <expat.h>
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_internal.h"

#ifndef EF_NO_SVG

#define SVG_NS "http://www.w3.org/2000/svg"

typedef struct dom_ctx {
    XML_Parser p;
    ef_in_dom *dom;
    const char *name;
    ef_error *err;
    ef_status st;
    uint32_t cur; /* innermost open element */
    uint32_t depth;
    char *text; /* character data of the open <style> */
    size_t text_len, text_cap;
} dom_ctx;

static void fail(dom_ctx *c, ef_status st, const char *fmt, const char *arg)
{
    if (c->st != EF_OK)
        return;
    c->st = ef_error_set(c->err, st, c->name, (uint32_t)XML_GetCurrentLineNumber(c->p),
                         (uint32_t)XML_GetCurrentColumnNumber(c->p) + 1, fmt, arg);
    XML_StopParser(c->p, XML_FALSE);
}

/* Appends s[0..n) and a NUL to the pool; EF_IN_NONE on failure. */
static uint32_t pool_add(dom_ctx *c, const char *s, size_t n)
{
    ef_in_dom *d = c->dom;
    if (n >= UINT32_MAX - 1 - d->pool_len) {
        fail(c, EF_ERR_LIMIT, "document too large%s", "");
        return EF_IN_NONE;
    }
    if (d->pool_len + n + 1 > d->pool_cap) {
        size_t cap = d->pool_cap ? d->pool_cap : 4096;
        while (cap < d->pool_len + n + 1)
            cap *= 2;
        if (cap > UINT32_MAX)
            cap = UINT32_MAX;
        char *np = realloc(d->pool, cap);
        if (!np) {
            fail(c, EF_ERR_NOMEM, "out of memory%s", "");
            return EF_IN_NONE;
        }
        d->pool = np;
        d->pool_cap = cap;
    }
    uint32_t off = (uint32_t)d->pool_len;
    memcpy(d->pool + off, s, n);
    d->pool[off + n] = '\0';
    d->pool_len += n + 1;
    return off;
}

static bool grow(dom_ctx *c, void **arr, uint32_t *cap, uint32_t need, size_t elt)
{
    if (need <= *cap)
        return true;
    uint64_t nc = *cap ? (uint64_t)*cap * 2 : 64;
    while (nc < need)
        nc *= 2;
    void *p = nc > SIZE_MAX / elt ? NULL : realloc(*arr, (size_t)nc * elt);
    if (!p) {
        fail(c, EF_ERR_NOMEM, "out of memory%s", "");
        return false;
    }
    *arr = p;
    *cap = (uint32_t)nc;
    return true;
}

static bool is_style(const dom_ctx *c, uint32_t n)
{
    return n != EF_IN_NONE && c->dom->nodes[n].svg &&
           strcmp(ef_in_dom_str(c->dom, c->dom->nodes[n].name), "style") == 0;
}

static void XMLCALL on_start(void *ud, const XML_Char *name, const XML_Char **atts)
{
    dom_ctx *c = ud;
    ef_in_dom *d = c->dom;
    if (c->st != EF_OK)
        return;
    char lim[24];
    if (++c->depth > EF_IN_MAX_DEPTH) {
        snprintf(lim, sizeof lim, "%u", (unsigned)EF_IN_MAX_DEPTH);
        fail(c, EF_ERR_LIMIT, "elements nested deeper than %s levels", lim);
        return;
    }
    if (d->nnodes >= EF_IN_MAX_ELEMENTS) {
        snprintf(lim, sizeof lim, "%u", (unsigned)EF_IN_MAX_ELEMENTS);
        fail(c, EF_ERR_LIMIT, "more than %s elements", lim);
        return;
    }
    if (!grow(c, (void **)&d->nodes, &d->nodes_cap, d->nnodes + 1, sizeof *d->nodes))
        return;

    /* "uri local" (namespaced) or "local". */
    const char *sp = strrchr(name, ' ');
    const char *local = sp ? sp + 1 : name;
    bool svg = !sp || ((size_t)(sp - name) == strlen(SVG_NS) && memcmp(name, SVG_NS, strlen(SVG_NS)) == 0);
    uint32_t nm = pool_add(c, local, strlen(local));
    if (nm == EF_IN_NONE)
        return;

    uint32_t na = 0;
    while (atts[2 * na])
        na++;
    if (!grow(c, (void **)&d->attrs, &d->attrs_cap, d->nattrs + na, sizeof *d->attrs))
        return;
    uint32_t a0 = d->nattrs;
    for (uint32_t i = 0; i < na; i++) {
        size_t vl = strlen(atts[2 * i + 1]);
        uint32_t an = pool_add(c, atts[2 * i], strlen(atts[2 * i]));
        uint32_t av = an == EF_IN_NONE ? EF_IN_NONE : pool_add(c, atts[2 * i + 1], vl);
        if (av == EF_IN_NONE)
            return;
        d->attrs[d->nattrs].name = an;
        d->attrs[d->nattrs].value = av;
        d->attrs[d->nattrs].value_len = (uint32_t)vl;
        d->nattrs++;
    }

    uint32_t id = d->nnodes++;
    ef_in_node *n = &d->nodes[id];
    memset(n, 0, sizeof *n);
    n->name = nm;
    n->parent = c->cur;
    n->first_child = n->last_child = n->next = EF_IN_NONE;
    n->attr0 = a0;
    n->nattr = na;
    n->line = (uint32_t)XML_GetCurrentLineNumber(c->p);
    n->col = (uint32_t)XML_GetCurrentColumnNumber(c->p) + 1;
    XML_Index bi = XML_GetCurrentByteIndex(c->p);
    n->byte = bi < 0 ? 0 : (size_t)bi;
    n->text = EF_IN_NONE;
    n->svg = svg;
    if (c->cur != EF_IN_NONE) {
        ef_in_node *pn = &d->nodes[c->cur];
        if (pn->last_child == EF_IN_NONE)
            pn->first_child = id;
        else
            d->nodes[pn->last_child].next = id;
        pn->last_child = id;
    }
    c->cur = id;
    if (is_style(c, id))
        c->text_len = 0;
}

static void XMLCALL on_end(void *ud, const XML_Char *name)
{
    dom_ctx *c = ud;
    (void)name;
    if (c->st != EF_OK || c->cur == EF_IN_NONE)
        return;
    c->depth--;
    if (is_style(c, c->cur)) {
        uint32_t t = pool_add(c, c->text ? c->text : "", c->text_len);
        if (t == EF_IN_NONE)
            return;
        c->dom->nodes[c->cur].text = t;
        c->dom->nodes[c->cur].text_len = (uint32_t)c->text_len;
    }
    c->cur = c->dom->nodes[c->cur].parent;
}

static void XMLCALL on_text(void *ud, const XML_Char *s, int len)
{
    dom_ctx *c = ud;
    if (c->st != EF_OK || len <= 0 || !is_style(c, c->cur))
        return;
    if (c->text_len + (size_t)len > c->text_cap) {
        size_t cap = c->text_cap ? c->text_cap : 1024;
        while (cap < c->text_len + (size_t)len)
            cap *= 2;
        char *nt = realloc(c->text, cap);
        if (!nt) {
            fail(c, EF_ERR_NOMEM, "out of memory%s", "");
            return;
        }
        c->text = nt;
        c->text_cap = cap;
    }
    memcpy(c->text + c->text_len, s, (size_t)len);
    c->text_len += (size_t)len;
}

static void XMLCALL on_entity_decl(void *ud, const XML_Char *entity, int is_param, const XML_Char *value, int value_len,
                                   const XML_Char *base, const XML_Char *system_id, const XML_Char *public_id,
                                   const XML_Char *notation)
{
    (void)is_param;
    (void)value;
    (void)value_len;
    (void)base;
    (void)system_id;
    (void)public_id;
    (void)notation;
    fail(ud, EF_ERR_UNSUPPORTED, "entity declarations are not supported (entity '%s'): entities are never expanded",
         entity);
}

static void XMLCALL on_skipped_entity(void *ud, const XML_Char *entity, int is_param)
{
    (void)is_param;
    fail(ud, EF_ERR_SYNTAX, "undefined entity '%s'", entity);
}

ef_status ef_in_dom_parse(ef_in_dom *dom, const char *name, const char *data, size_t len, ef_error *err)
{
    memset(dom, 0, sizeof *dom);
    dom->data = data;
    dom->len = len;
    if (len > EF_IN_MAX_FILE_BYTES)
        return ef_error_set(err, EF_ERR_LIMIT, name, 0, 0, "document larger than %u MiB",
                            (unsigned)(EF_IN_MAX_FILE_BYTES >> 20));
    XML_Parser p = XML_ParserCreateNS(NULL, ' ');
    if (!p)
        return ef_error_set(err, EF_ERR_NOMEM, name, 0, 0, "out of memory");
    dom_ctx c = { p, dom, name, err, EF_OK, EF_IN_NONE, 0, NULL, 0, 0 };
    XML_SetUserData(p, &c);
    XML_SetElementHandler(p, on_start, on_end);
    XML_SetCharacterDataHandler(p, on_text);
    XML_SetEntityDeclHandler(p, on_entity_decl);
    XML_SetSkippedEntityHandler(p, on_skipped_entity);
    XML_SetParamEntityParsing(p, XML_PARAM_ENTITY_PARSING_NEVER);
    enum XML_Status xs = XML_Parse(p, data ? data : "", (int)len, 1);
    if (xs != XML_STATUS_OK && c.st == EF_OK) {
        c.st =
            ef_error_set(err, EF_ERR_SYNTAX, name, (uint32_t)XML_GetCurrentLineNumber(p),
                         (uint32_t)XML_GetCurrentColumnNumber(p) + 1, "XML: %s", XML_ErrorString(XML_GetErrorCode(p)));
    }
    XML_ParserFree(p);
    free(c.text);
    if (c.st == EF_OK && dom->nnodes == 0)
        c.st = ef_error_set(err, EF_ERR_SYNTAX, name, 1, 1, "no root element");
    if (c.st != EF_OK)
        ef_in_dom_free(dom);
    return c.st;
}

#else /* EF_NO_SVG: a build without expat (WITH_SVG=0, e.g. the 32-bit bit-exact check) */

ef_status ef_in_dom_parse(ef_in_dom *dom, const char *name, const char *data, size_t len, ef_error *err)
{
    (void)data;
    (void)len;
    memset(dom, 0, sizeof *dom);
    return ef_error_set(err, EF_ERR_UNSUPPORTED, name, 0, 0,
                        "this edgeflag was built without SVG support (WITH_SVG=0)");
}

#endif /* EF_NO_SVG */

void ef_in_dom_free(ef_in_dom *dom)
{
    free(dom->nodes);
    free(dom->attrs);
    free(dom->pool);
    memset(dom, 0, sizeof *dom);
}

const char *ef_in_dom_attr(const ef_in_dom *dom, uint32_t node, const char *name, size_t *len)
{
    const ef_in_node *n = &dom->nodes[node];
    for (uint32_t i = 0; i < n->nattr; i++) {
        const ef_in_attr *a = &dom->attrs[n->attr0 + i];
        if (strcmp(dom->pool + a->name, name) == 0) {
            if (len)
                *len = a->value_len;
            return dom->pool + a->value;
        }
    }
    return NULL;
}

/* ---------------------------------------------------------- positions */

static bool name_char(char c)
{
    return !(c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '=' || c == '>' || c == '/' || c == '\0');
}

void ef_in_dom_locate(const ef_in_dom *dom, uint32_t node, const char *attr, size_t idx, uint32_t *line, uint32_t *col)
{
    const ef_in_node *n = &dom->nodes[node];
    const char *s = dom->data;
    size_t len = dom->len, i = n->byte, target = n->byte;
    *line = n->line;
    *col = n->col;
    if (!s || i >= len || s[i] != '<')
        return;
    i++;
    while (i < len && name_char(s[i]))
        i++; /* element name */
    size_t alen = strlen(attr);
    for (;;) {
        while (i < len && ef_in_is_wsp(s[i]))
            i++;
        if (i >= len || s[i] == '>' || s[i] == '/')
            return; /* not found */
        size_t n0 = i;
        while (i < len && name_char(s[i]))
            i++;
        size_t n1 = i;
        while (i < len && ef_in_is_wsp(s[i]))
            i++;
        if (i >= len || s[i] != '=')
            return;
        i++;
        while (i < len && ef_in_is_wsp(s[i]))
            i++;
        if (i >= len || (s[i] != '"' && s[i] != '\''))
            return;
        char q = s[i++];
        size_t v0 = i;
        while (i < len && s[i] != q)
            i++;
        if (i >= len)
            return;
        size_t v1 = i++;
        if (n1 - n0 != alen || memcmp(s + n0, attr, alen) != 0)
            continue;
        /* Map index idx of the normalised value to a raw offset: CR LF is one
         * character there; a reference makes the mapping unknown. */
        size_t r = v0, k = 0;
        target = v0;
        while (k < idx && r < v1) {
            if (s[r] == '&')
                break;
            r += (s[r] == '\r' && r + 1 < v1 && s[r + 1] == '\n') ? 2 : 1;
            k++;
        }
        if (k == idx)
            target = r;
        break;
    }
    /* Line and column of target, counting from the start tag as expat does
     * (CR, LF and CR LF end a line; UTF-8 continuation bytes add no column). */
    uint32_t ln = n->line, cl = n->col;
    for (size_t j = n->byte; j < target; j++) {
        if (s[j] == '\n' || s[j] == '\r') {
            if (s[j] == '\r' && j + 1 < target && s[j + 1] == '\n')
                j++;
            ln++;
            cl = 1;
        } else if (((unsigned char)s[j] & 0xC0u) != 0x80u) {
            cl++;
        }
    }
    *line = ln;
    *col = cl;
}
