/*
 * vec_read_manifest.c - reader of manifest.json (docs/vectors.md section 6)
 * for `edgeflag check`'s directory mode, by json-c (Debian's libjson-c).
 *
 * json-c parses (strict mode, UTF-8 validated, at most 64 levels deep) and
 * reports a syntax error at a byte offset, turned here into a line and a
 * column; this file then checks what check uses - the frame size and, per
 * file, its name, format, role, interface and count - and names the key of
 * a value it refuses (`files[4].name`).  json-c rather than Jansson: counts
 * and seeds go up to 2^64 - 1, and Jansson's integers are signed 64-bit (a
 * manifest of a seed of 2^63 or more would not even parse).  The manifest
 * is input, so its size is bounded (1 MiB).  A file name must be a plain
 * name in the manifest's own folder: a name with '/' or ".." would make
 * check read (and trust as expected data) a file outside it.
 *
 * Builds without the manifest (WITH_MANIFEST=0) have no json-c: the reader
 * refuses every manifest as unsupported, so check stops instead of passing.
 */
#include "vec_read_internal.h"

#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

#define MANIFEST_MAX (1u << 20)
#define DEPTH_MAX 64

#ifndef EF_NO_MANIFEST

#include <json-c/json.h>

typedef struct mctx {
    const char *name;
    ef_vec_manifest *m;
    ef_vec_read_error *err;
} mctx;

/* A name quoted for a message: printable ASCII as is, anything else \xNN,
 * at most 80 characters. */
static void quote_name(const char *s, size_t len, char *out, size_t size)
{
    size_t o = 0;
    for (size_t k = 0; k < len && o + 5 < size; k++) {
        unsigned char c = (unsigned char)s[k];
        if (k == 80) {
            snprintf(out + o, size - o, "...");
            return;
        }
        o += (size_t)snprintf(out + o, size - o, c >= 0x20 && c < 0x7f && c != '\\' ? "%c" : "\\x%02x", c);
    }
    out[o < size ? o : size - 1] = '\0';
}

/* Line and column (characters: UTF-8 continuation bytes do not move it) of
 * byte offset off. */
static void place(const uint8_t *p, size_t off, uint64_t *line, uint64_t *col)
{
    *line = *col = 1;
    for (size_t i = 0; i < off; i++) {
        if (p[i] == '\n') {
            ++*line;
            *col = 1;
        } else if ((p[i] & 0xC0u) != 0x80u) {
            ++*col;
        }
    }
}

static ef_status syntax(const mctx *c, const uint8_t *p, size_t n, size_t off, const char *what)
{
    uint64_t line, col;
    char q[8];
    place(p, off, &line, &col);
    if (off >= n)
        return ef_vr_err_line(c->err, EF_ERR_SYNTAX, c->name, line, col, "%s, end of file found", what);
    ef_vr_quote_byte(p[off], q);
    return ef_vr_err_line(c->err, EF_ERR_SYNTAX, c->name, line, col, "%s, %s found", what, q);
}

/* A value refused: "FILE: KEY: message". */
static ef_status bad_key(const mctx *c, ef_status st, const char *key, const char *msg, const char *arg)
{
    return ef_vr_err_file(c->err, st, c->name, "%s: %s%s", key, msg, arg ? arg : "");
}

static int plain_name(const char *s, size_t len)
{
    return len > 0 && strlen(s) == len && !strchr(s, '/') && !strstr(s, "..") && strcmp(s, ".") != 0;
}

/* width or height, when present: an integer 1..EF_MAX_CANVAS. */
static ef_status size_member(const mctx *c, json_object *top, const char *key, int32_t *out)
{
    json_object *v;
    if (!json_object_object_get_ex(top, key, &v))
        return EF_OK;
    if (!json_object_is_type(v, json_type_int) || json_object_get_int64(v) < 1 ||
        json_object_get_int64(v) > EF_MAX_CANVAS) {
        char msg[64];
        snprintf(msg, sizeof msg, "must be an integer 1..%d", EF_MAX_CANVAS);
        return bad_key(c, EF_ERR_RANGE, key, msg, NULL);
    }
    *out = (int32_t)json_object_get_int64(v);
    return EF_OK;
}

/* A string member ("format", "role"): absent or null leaves *out NULL. */
static ef_status string_member(const mctx *c, json_object *e, const char *path, const char *key, char **out)
{
    json_object *v;
    char k[80];
    if (!json_object_object_get_ex(e, key, &v) || !v)
        return EF_OK;
    snprintf(k, sizeof k, "%s.%s", path, key);
    if (!json_object_is_type(v, json_type_string))
        return bad_key(c, EF_ERR_SYNTAX, k, "a string or null expected", NULL);
    if ((*out = strdup(json_object_get_string(v))) == NULL)
        return ef_vr_err_file(c->err, EF_ERR_NOMEM, c->name, "out of memory");
    return EF_OK;
}

static ef_status file_entry(const mctx *c, json_object *e, size_t k, ef_vec_manifest_file *f)
{
    json_object *v;
    char path[40], key[80], q[512];
    ef_status st;

    memset(f, 0, sizeof *f);
    f->iface = -1;
    f->index = k;
    snprintf(path, sizeof path, "files[%zu]", k);
    if (!json_object_is_type(e, json_type_object))
        return bad_key(c, EF_ERR_SYNTAX, path, "a file entry (an object) expected", NULL);
    snprintf(key, sizeof key, "%s.name", path);
    if (!json_object_object_get_ex(e, "name", &v) || !v)
        return bad_key(c, EF_ERR_SYNTAX, path, "a file entry without a \"name\"", NULL);
    if (!json_object_is_type(v, json_type_string))
        return bad_key(c, EF_ERR_SYNTAX, key, "a string expected", NULL);
    const char *s = json_object_get_string(v);
    size_t len = (size_t)json_object_get_string_len(v);
    quote_name(s, len, q, sizeof q);
    if (!plain_name(s, len))
        return ef_vr_err_file(c->err, EF_ERR_SYNTAX, c->name,
                              "%s: manifest names a file outside its folder: '%s' (names must be plain file names)",
                              key, q);
    if ((f->name = strdup(s)) == NULL)
        return ef_vr_err_file(c->err, EF_ERR_NOMEM, c->name, "out of memory");
    if ((st = string_member(c, e, path, "format", &f->format)) != EF_OK ||
        (st = string_member(c, e, path, "role", &f->role)) != EF_OK)
        return st;
    if (json_object_object_get_ex(e, "interface", &v) && v) {
        snprintf(key, sizeof key, "%s.interface", path);
        if (!json_object_is_type(v, json_type_string))
            return bad_key(c, EF_ERR_SYNTAX, key, "a string or null expected", NULL);
        quote_name(json_object_get_string(v), (size_t)json_object_get_string_len(v), q, sizeof q);
        if ((f->iface = ef_iface_find(json_object_get_string(v))) < 0)
            return ef_vr_err_file(c->err, EF_ERR_SYNTAX, c->name, "%s: unknown interface '%s'", key, q);
    }
    if (json_object_object_get_ex(e, "count", &v)) {
        snprintf(key, sizeof key, "%s.count", path);
        /* json-c keeps integers of 2^63 or more as unsigned; a negative one
         * reads as a negative int64. */
        if (!v || !json_object_is_type(v, json_type_int) || json_object_get_int64(v) < 0)
            return bad_key(c, EF_ERR_RANGE, key, "a file's count must be an integer 0..2^64-1", NULL);
        f->count = json_object_get_uint64(v);
        f->has_count = 1;
    }
    return EF_OK;
}

static ef_status walk(const mctx *c, json_object *top)
{
    ef_vec_manifest *m = c->m;
    json_object *fs;
    ef_status st;

    if ((st = size_member(c, top, "width", &m->width)) != EF_OK ||
        (st = size_member(c, top, "height", &m->height)) != EF_OK)
        return st;
    if (!json_object_object_get_ex(top, "files", &fs))
        return EF_OK;
    if (!json_object_is_type(fs, json_type_array))
        return bad_key(c, EF_ERR_SYNTAX, "files", "an array expected", NULL);
    size_t n = json_object_array_length(fs);
    if (!n)
        return EF_OK;
    if ((m->files = calloc(n, sizeof *m->files)) == NULL)
        return ef_vr_err_file(c->err, EF_ERR_NOMEM, c->name, "out of memory");
    for (size_t k = 0; k < n; k++) {
        m->nfiles = k + 1;
        if ((st = file_entry(c, json_object_array_get_idx(fs, k), k, &m->files[k])) != EF_OK)
            return st;
    }
    return EF_OK;
}

ef_status ef_vec_read_manifest(const char *name, const uint8_t *data, size_t len, ef_vec_manifest *out,
                               ef_vec_read_error *err)
{
    mctx c = { name, out, err };
    struct json_tokener *tok;
    json_object *top;
    ef_status st;
    size_t first = 0, end;

    memset(out, 0, sizeof *out);
    if (len > MANIFEST_MAX)
        return ef_vr_err_file(err, EF_ERR_SYNTAX, name, "manifest larger than 1 MiB");
    if (!data)
        len = 0;
    while (first < len && (data[first] == ' ' || data[first] == '\t' || data[first] == '\n' || data[first] == '\r'))
        first++;
    if (first == len || data[first] != '{')
        return syntax(&c, data, len, first, "the manifest object '{' expected");
    /* json-c reads a NUL byte as the end of its input: refuse it here, at
     * its place, rather than take the bytes before it for the manifest. */
    const uint8_t *nul = memchr(data, 0, len);
    if ((tok = json_tokener_new_ex(DEPTH_MAX)) == NULL)
        return ef_vr_err_file(err, EF_ERR_NOMEM, name, "out of memory");
    /* Trailing bytes are json-c's to allow and ours to refuse, with a
     * clearer message than json-c's "unexpected character". */
    json_tokener_set_flags(tok, JSON_TOKENER_STRICT | JSON_TOKENER_VALIDATE_UTF8 | JSON_TOKENER_ALLOW_TRAILING_CHARS);
    top = json_tokener_parse_ex(tok, (const char *)data, nul ? (int)(nul - data) : (int)len);
    enum json_tokener_error je = json_tokener_get_error(tok);
    end = json_tokener_get_parse_end(tok);
    json_tokener_free(tok);
    if (!top) {
        if (je == json_tokener_error_depth) {
            uint64_t line, col;
            place(data, end, &line, &col);
            st = ef_vr_err_line(err, EF_ERR_SYNTAX, name, line, col, "nested deeper than 64 levels");
        } else if (je == json_tokener_continue)
            st = syntax(&c, data, len, nul ? (size_t)(nul - data) : len,
                        nul ? "JSON: a NUL byte" : "JSON: unexpected end of file (the manifest is cut short)");
        else {
            char what[96];
            snprintf(what, sizeof what, "JSON: %s", json_tokener_error_desc(je));
            st = syntax(&c, data, len, end, what);
        }
        return st;
    }
    /* Nothing but white space after the object. */
    while (end < len && (data[end] == ' ' || data[end] == '\t' || data[end] == '\n' || data[end] == '\r'))
        end++;
    if (end < len)
        st = syntax(&c, data, len, end, "the end of the file expected");
    else
        st = walk(&c, top);
    json_object_put(top);
    if (st != EF_OK)
        ef_vec_manifest_destroy(out);
    return st;
}

#else /* EF_NO_MANIFEST */

ef_status ef_vec_read_manifest(const char *name, const uint8_t *data, size_t len, ef_vec_manifest *out,
                               ef_vec_read_error *err)
{
    (void)data;
    (void)len;
    memset(out, 0, sizeof *out);
    return ef_vr_err_file(err, EF_ERR_UNSUPPORTED, name,
                          "this build reads no manifest (built with WITH_MANIFEST=0, without json-c)");
}

#endif /* EF_NO_MANIFEST */

void ef_vec_manifest_destroy(ef_vec_manifest *m)
{
    for (size_t k = 0; k < m->nfiles; k++) {
        free(m->files[k].name);
        free(m->files[k].format);
        free(m->files[k].role);
    }
    free(m->files);
    memset(m, 0, sizeof *m);
}

ef_status ef_vec_read_manifest_path(const char *path, const char *name, ef_vec_manifest *out, ef_vec_read_error *err)
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
