/*
 * vec_read_manifest.c - reader of manifest.json (docs/vectors.md section 6)
 * for `edgeflag check`'s directory mode.
 *
 * A strict RFC 8259 recursive-descent parser that keeps only what check
 * uses - the frame size and, per file, its name, format, role, interface
 * and count - instead of building a tree: the manifest is small, but it is
 * input, so the parser bounds its size (1 MiB) and depth (64) and reports
 * every error at its line and column.  A file name must be a plain name in
 * the manifest's own folder: a name with '/' or ".." would make check read
 * (and trust as expected data) a file outside it.
 */
#include "vec_read_internal.h"
#include "ef_fixed.h"   /* ef_utf8_len */

#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

#define MANIFEST_MAX (1u << 20)
#define DEPTH_MAX 64

enum { C_OTHER, C_TOP, C_FILES, C_FILE };

typedef struct jp {
    const uint8_t *p;
    size_t n, i;
    uint64_t line, col;        /* of p[i] */
    unsigned cont;             /* continuation bytes due after p[i - 1] */
    int depth;
    size_t cap;                /* of m->files */
    const char *name;
    ef_vec_manifest *m;
    ef_vec_read_error *err;
} jp;

typedef struct jstr {
    char *s;
    size_t len;
} jstr;

static ef_status fail(jp *j, ef_status st, uint64_t line, uint64_t col, const char *msg, const char *arg)
{
    return ef_vr_err_line(j->err, st, j->name, line, col, "%s%s", msg, arg ? arg : "");
}

static ef_status nomem(jp *j) { return ef_vr_err_file(j->err, EF_ERR_NOMEM, j->name, "out of memory"); }

/* Past p[i]: lines count '\n', columns count characters (a UTF-8
 * sequence's continuation bytes do not move the column). */
static void adv(jp *j)
{
    uint8_t c = j->p[j->i++];
    if (c == '\n') {
        j->line++;
        j->col = 1;
        j->cont = 0;
        return;
    }
    if (j->cont > 0 && (c & 0xC0u) == 0x80u)
        j->cont--;
    else
        j->cont = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    /* The next byte moves the column unless it continues this character. */
    if (!(j->cont > 0 && j->i < j->n && (j->p[j->i] & 0xC0u) == 0x80u))
        j->col++;
}

static void ws(jp *j)
{
    while (j->i < j->n && (j->p[j->i] == ' ' || j->p[j->i] == '\t' || j->p[j->i] == '\n' || j->p[j->i] == '\r'))
        adv(j);
}

static int peek(const jp *j) { return j->i < j->n ? j->p[j->i] : -1; }

static ef_status unexpected(jp *j, const char *what)
{
    char q[8];
    if (peek(j) < 0)
        return fail(j, EF_ERR_SYNTAX, j->line, j->col, what, " expected, end of file found");
    ef_vr_quote_byte(peek(j), q);
    return ef_vr_err_line(j->err, EF_ERR_SYNTAX, j->name, j->line, j->col, "%s expected, %s found", what, q);
}

/* A name quoted for a message: printable ASCII as is, anything else \xNN,
 * at most 80 characters. */
static void quote_name(const jstr *s, char *out, size_t size)
{
    size_t o = 0;
    for (size_t k = 0; k < s->len && o + 5 < size; k++) {
        unsigned char c = (unsigned char)s->s[k];
        if (k == 80) {
            snprintf(out + o, size - o, "...");
            return;
        }
        o += (size_t)snprintf(out + o, size - o, c >= 0x20 && c < 0x7f && c != '\\' ? "%c" : "\\x%02x", c);
    }
    out[o < size ? o : size - 1] = '\0';
}

static void put_utf8(char *d, size_t *o, uint32_t u)
{
    if (u < 0x80) {
        d[(*o)++] = (char)u;
    } else if (u < 0x800) {
        d[(*o)++] = (char)(0xC0u | (u >> 6));
        d[(*o)++] = (char)(0x80u | (u & 0x3Fu));
    } else if (u < 0x10000) {
        d[(*o)++] = (char)(0xE0u | (u >> 12));
        d[(*o)++] = (char)(0x80u | ((u >> 6) & 0x3Fu));
        d[(*o)++] = (char)(0x80u | (u & 0x3Fu));
    } else {
        d[(*o)++] = (char)(0xF0u | (u >> 18));
        d[(*o)++] = (char)(0x80u | ((u >> 12) & 0x3Fu));
        d[(*o)++] = (char)(0x80u | ((u >> 6) & 0x3Fu));
        d[(*o)++] = (char)(0x80u | (u & 0x3Fu));
    }
}

static int hex4(const jp *j, size_t at, uint32_t *u)
{
    uint32_t v = 0;
    if (at + 4 > j->n)
        return 0;
    for (size_t k = at; k < at + 4; k++) {
        int c = j->p[k];
        uint32_t d = c >= '0' && c <= '9' ? (uint32_t)(c - '0')
                     : (c | 0x20) >= 'a' && (c | 0x20) <= 'f' ? (uint32_t)((c | 0x20) - 'a' + 10)
                                                              : 16u;
        if (d > 15)
            return 0;
        v = v * 16u + d;
    }
    *u = v;
    return 1;
}

/* A string at p[i] == '"'; its decoded bytes in *out (malloc'ed, NUL-terminated). */
static ef_status string(jp *j, jstr *out)
{
    size_t cap = 16, o = 0;
    char *d = malloc(cap);
    if (!d)
        return nomem(j);
    adv(j);
    for (;;) {
        if (cap - o < 8) {
            char *nd = cap < SIZE_MAX / 2 ? realloc(d, cap * 2) : NULL;
            if (!nd) {
                free(d);
                return nomem(j);
            }
            d = nd;
            cap *= 2;
        }
        int c = peek(j);
        if (c < 0) {
            free(d);
            return fail(j, EF_ERR_SYNTAX, j->line, j->col, "unterminated string", NULL);
        }
        if (c == '"') {
            adv(j);
            break;
        }
        if (c < 0x20) {
            free(d);
            return unexpected(j, "a string character (control characters must be escaped)");
        }
        if (c == '\\') {
            uint64_t l0 = j->line, c0 = j->col;
            adv(j);
            int e = peek(j);
            const char *simple = "\"\\/bfnrt", *val = "\"\\/\b\f\n\r\t";
            const char *hit = e > 0 ? strchr(simple, e) : NULL;
            if (hit) {
                d[o++] = val[hit - simple];
                adv(j);
                continue;
            }
            uint32_t u, lo;
            if (e != 'u' || !hex4(j, j->i + 1, &u)) {
                free(d);
                return fail(j, EF_ERR_SYNTAX, l0, c0, "invalid escape in a string", NULL);
            }
            for (int k = 0; k < 5; k++)
                adv(j);
            if (u >= 0xD800 && u <= 0xDBFF && j->i + 1 < j->n && j->p[j->i] == '\\' && j->p[j->i + 1] == 'u' &&
                hex4(j, j->i + 2, &lo) && lo >= 0xDC00 && lo <= 0xDFFF) {
                for (int k = 0; k < 6; k++)
                    adv(j);
                u = 0x10000u + ((u - 0xD800u) << 10) + (lo - 0xDC00u);
            } else if (u >= 0xD800 && u <= 0xDFFF) {
                free(d);
                return fail(j, EF_ERR_SYNTAX, l0, c0, "unpaired surrogate escape in a string", NULL);
            }
            put_utf8(d, &o, u);
            continue;
        }
        size_t len = ef_utf8_len(j->p + j->i, j->n - j->i);
        if (!len) {
            free(d);
            return unexpected(j, "valid UTF-8");
        }
        for (size_t k = 0; k < len; k++) {
            d[o++] = (char)j->p[j->i];
            adv(j);
        }
    }
    d[o] = '\0';
    out->s = d;
    out->len = o;
    return EF_OK;
}

/* A number; *is_uint and *v when it is a non-negative integer below 2^64. */
static ef_status number(jp *j, int *is_uint, uint64_t *v)
{
    int neg = 0, frac = 0, big = 0;
    uint64_t x = 0;
    if (peek(j) == '-') {
        neg = 1;
        adv(j);
    }
    if (peek(j) == '0') {
        adv(j);
    } else if (peek(j) >= '1' && peek(j) <= '9') {
        while (peek(j) >= '0' && peek(j) <= '9') {
            uint64_t dg = (uint64_t)(peek(j) - '0');
            if (x > (UINT64_MAX - dg) / 10u)
                big = 1;
            else
                x = x * 10u + dg;
            adv(j);
        }
    } else {
        return unexpected(j, "a digit");
    }
    if (peek(j) == '.') {
        frac = 1;
        adv(j);
        if (!(peek(j) >= '0' && peek(j) <= '9'))
            return unexpected(j, "a digit");
        while (peek(j) >= '0' && peek(j) <= '9')
            adv(j);
    }
    if (peek(j) == 'e' || peek(j) == 'E') {
        frac = 1;
        adv(j);
        if (peek(j) == '+' || peek(j) == '-')
            adv(j);
        if (!(peek(j) >= '0' && peek(j) <= '9'))
            return unexpected(j, "a digit");
        while (peek(j) >= '0' && peek(j) <= '9')
            adv(j);
    }
    *is_uint = !neg && !frac && !big;
    *v = x;
    return EF_OK;
}

static ef_status value(jp *j, int ctx);

static int plain_name(const jstr *s)
{
    return s->len > 0 && strlen(s->s) == s->len && !strchr(s->s, '/') && !strstr(s->s, "..") &&
           strcmp(s->s, ".") != 0;
}

/* A member `key` of a file entry, at the value. */
static ef_status file_member(jp *j, const char *key)
{
    ef_vec_manifest_file *f = &j->m->files[j->m->nfiles - 1];
    uint64_t l0 = j->line, c0 = j->col;
    int is_str = peek(j) == '"', want_str = strcmp(key, "name") == 0 || strcmp(key, "format") == 0 ||
                                            strcmp(key, "role") == 0 || strcmp(key, "interface") == 0;
    if (strcmp(key, "count") == 0) {
        int u;
        if (!(peek(j) == '-' || (peek(j) >= '0' && peek(j) <= '9')))
            return unexpected(j, "a count (an integer)");
        ef_status st = number(j, &u, &f->count);
        if (st != EF_OK)
            return st;
        if (!u)
            return fail(j, EF_ERR_RANGE, l0, c0, "a file's count must be an integer 0..2^64-1", NULL);
        f->has_count = 1;
        return EF_OK;
    }
    if (!want_str || (!is_str && peek(j) == 'n'))
        return value(j, C_OTHER);   /* other members, and null ("interface": null for the VCD) */
    if (!is_str)
        return unexpected(j, "a string or null");
    jstr s;
    char q[512];
    ef_status st = string(j, &s);
    if (st != EF_OK)
        return st;
    if (strcmp(key, "name") == 0) {
        quote_name(&s, q, sizeof q);
        if (!plain_name(&s)) {
            free(s.s);
            return ef_vr_err_line(j->err, EF_ERR_SYNTAX, j->name, l0, c0,
                                  "manifest names a file outside its folder: '%s' (names must be plain file names)",
                                  q);
        }
        free(f->name);
        f->name = s.s;
        f->line = l0;
        f->col = c0;
    } else if (strcmp(key, "interface") == 0) {
        int i = ef_iface_find(s.s);
        quote_name(&s, q, sizeof q);
        free(s.s);
        if (i < 0)
            return ef_vr_err_line(j->err, EF_ERR_SYNTAX, j->name, l0, c0, "unknown interface '%s'", q);
        f->iface = i;
    } else {
        char **dst = strcmp(key, "format") == 0 ? &f->format : &f->role;
        free(*dst);
        *dst = s.s;
    }
    return EF_OK;
}

static ef_status top_member(jp *j, const char *key)
{
    uint64_t l0 = j->line, c0 = j->col;
    if (strcmp(key, "width") == 0 || strcmp(key, "height") == 0) {
        int u;
        uint64_t v;
        if (!(peek(j) == '-' || (peek(j) >= '0' && peek(j) <= '9')))
            return unexpected(j, "an integer");
        ef_status st = number(j, &u, &v);
        if (st != EF_OK)
            return st;
        if (!u || v < 1 || v > EF_MAX_CANVAS)
            return ef_vr_err_line(j->err, EF_ERR_RANGE, j->name, l0, c0, "%s must be an integer 1..%d", key,
                                  EF_MAX_CANVAS);
        *(key[0] == 'w' ? &j->m->width : &j->m->height) = (int32_t)v;
        return EF_OK;
    }
    if (strcmp(key, "files") == 0) {
        if (peek(j) != '[')
            return unexpected(j, "'files': an array");
        return value(j, C_FILES);
    }
    return value(j, C_OTHER);
}

static ef_status new_file(jp *j)
{
    ef_vec_manifest *m = j->m;
    /* Each entry took at least "{}" of the input, so this stays bounded. */
    if (m->nfiles == j->cap) {
        size_t cap = j->cap ? j->cap * 2 : 8;
        ef_vec_manifest_file *nf = realloc(m->files, cap * sizeof *nf);
        if (!nf)
            return nomem(j);
        m->files = nf;
        j->cap = cap;
    }
    ef_vec_manifest_file *nf = m->files;
    memset(&nf[m->nfiles], 0, sizeof *nf);
    nf[m->nfiles].iface = -1;
    nf[m->nfiles].line = j->line;
    nf[m->nfiles].col = j->col;
    m->nfiles++;
    return EF_OK;
}

static ef_status object(jp *j, int ctx)
{
    ef_status st;
    uint64_t l0 = j->line, c0 = j->col;
    if (ctx == C_FILE && (st = new_file(j)) != EF_OK)
        return st;
    adv(j);
    ws(j);
    if (peek(j) == '}') {
        adv(j);
    } else {
        for (;;) {
            jstr key;
            ws(j);
            if (peek(j) != '"')
                return unexpected(j, "a member name (a string)");
            if ((st = string(j, &key)) != EF_OK)
                return st;
            ws(j);
            if (peek(j) != ':') {
                free(key.s);
                return unexpected(j, "':'");
            }
            adv(j);
            ws(j);
            st = ctx == C_TOP ? top_member(j, key.s) : ctx == C_FILE ? file_member(j, key.s) : value(j, C_OTHER);
            free(key.s);
            if (st != EF_OK)
                return st;
            ws(j);
            if (peek(j) == ',') {
                adv(j);
                continue;
            }
            if (peek(j) == '}') {
                adv(j);
                break;
            }
            return unexpected(j, "',' or '}'");
        }
    }
    if (ctx == C_FILE && !j->m->files[j->m->nfiles - 1].name)
        return fail(j, EF_ERR_SYNTAX, l0, c0, "a file entry without a \"name\"", NULL);
    return EF_OK;
}

static ef_status array(jp *j, int ctx)
{
    ef_status st;
    adv(j);
    ws(j);
    if (peek(j) == ']') {
        adv(j);
        return EF_OK;
    }
    for (;;) {
        ws(j);
        if (ctx == C_FILES && peek(j) != '{')
            return unexpected(j, "a file entry (an object)");
        if ((st = value(j, ctx == C_FILES ? C_FILE : C_OTHER)) != EF_OK)
            return st;
        ws(j);
        if (peek(j) == ',') {
            adv(j);
            continue;
        }
        if (peek(j) == ']') {
            adv(j);
            return EF_OK;
        }
        return unexpected(j, "',' or ']'");
    }
}

static ef_status literal(jp *j, const char *word)
{
    size_t n = strlen(word);
    if (j->n - j->i < n || memcmp(j->p + j->i, word, n) != 0)
        return unexpected(j, "a JSON value");
    for (size_t k = 0; k < n; k++)
        adv(j);
    return EF_OK;
}

static ef_status value(jp *j, int ctx)
{
    ef_status st;
    if (j->depth >= DEPTH_MAX)
        return fail(j, EF_ERR_SYNTAX, j->line, j->col, "nested deeper than 64 levels", NULL);
    int c = peek(j);
    j->depth++;
    if (c == '{') {
        st = object(j, ctx);
    } else if (c == '[') {
        st = array(j, ctx);
    } else if (c == '"') {
        jstr s;
        st = string(j, &s);
        if (st == EF_OK)
            free(s.s);
    } else if (c == '-' || (c >= '0' && c <= '9')) {
        int u;
        uint64_t v;
        st = number(j, &u, &v);
    } else if (c == 't' || c == 'f' || c == 'n') {
        st = literal(j, c == 't' ? "true" : c == 'f' ? "false" : "null");
    } else {
        st = unexpected(j, "a JSON value");
    }
    j->depth--;
    return st;
}

void ef_vec_manifest_free(ef_vec_manifest *m)
{
    for (size_t k = 0; k < m->nfiles; k++) {
        free(m->files[k].name);
        free(m->files[k].format);
        free(m->files[k].role);
    }
    free(m->files);
    memset(m, 0, sizeof *m);
}

ef_status ef_vec_read_manifest(const char *name, const uint8_t *data, size_t len, ef_vec_manifest *out,
                               ef_vec_read_error *err)
{
    jp j;
    memset(out, 0, sizeof *out);
    if (len > MANIFEST_MAX)
        return ef_vr_err_file(err, EF_ERR_SYNTAX, name, "manifest larger than 1 MiB");
    memset(&j, 0, sizeof j);
    j.p = data;
    j.n = data ? len : 0;
    j.line = j.col = 1;
    j.name = name;
    j.m = out;
    j.err = err;
    ws(&j);
    ef_status st = peek(&j) == '{' ? value(&j, C_TOP) : unexpected(&j, "the manifest object '{'");
    if (st == EF_OK) {
        ws(&j);
        if (j.i < j.n)
            st = unexpected(&j, "the end of the file");
    }
    if (st != EF_OK)
        ef_vec_manifest_free(out);
    return st;
}

ef_status ef_vec_read_manifest_path(const char *path, const char *name, ef_vec_manifest *out,
                                    ef_vec_read_error *err)
{
    uint8_t *buf = NULL;
    size_t n = 0;
    ef_status st;
    if (!name)
        name = path;
    memset(out, 0, sizeof *out);
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return ef_vr_err_file(err, EF_ERR_IO, name, "cannot open: %s", strerror(errno));
    buf = malloc(MANIFEST_MAX + 1);
    if (!buf) {
        fclose(fp);
        return ef_vr_err_file(err, EF_ERR_NOMEM, name, "out of memory");
    }
    errno = 0;
    n = fread(buf, 1, MANIFEST_MAX + 1, fp);
    if (ferror(fp))
        st = ef_vr_err_file(err, EF_ERR_IO, name, "read error: %s", strerror(errno ? errno : EIO));
    else
        st = ef_vec_read_manifest(name, buf, n, out, err);
    free(buf);
    fclose(fp);
    return st;
}
