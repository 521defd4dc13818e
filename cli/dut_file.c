/*
 * dut_file.c - `edgeflag gen --dut-file FILE` (dut_file.h; the grammar is
 * docs/gen.md section 11's): an identify record, or the lines of a Verilog
 * or C file that define W_MAX, H_MAX, E_MAX and NS.  Every error names its
 * place: the line and column of the text, the byte offset of the record's
 * field, or the whole file.  A value is a plain decimal number or nothing:
 * what is not read is an error, never a silent default.
 */
#include "dut_file.h"

#include "edgeflag.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

enum { K_W, K_H, K_E, K_NS, K_COUNT };
static const char *const KEYS[K_COUNT] = { "W_MAX", "H_MAX", "E_MAX", "NS" };

typedef struct reader {
    const unsigned char *d;
    size_t ls;     /* the line's first byte */
    uint32_t line; /* 1-based */
    int32_t got[K_COUNT];
    uint32_t got_line[K_COUNT], got_col[K_COUNT];
    ef_dut_error *err;
} reader;

static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static int blank(unsigned char c) { return c == ' ' || c == '\t'; }
static int ident(unsigned char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}
static int digit(unsigned char c) { return c >= '0' && c <= '9'; }

/* The column of byte pos of the current line: characters before it, plus 1. */
static uint32_t col_of(const reader *r, size_t pos)
{
    uint32_t c = 1;
    for (size_t i = r->ls; i < pos; i++)
        c += (r->d[i] & 0xC0u) != 0x80u;
    return c;
}

__attribute__((format(printf, 3, 4))) static int fail_at(reader *r, size_t pos, const char *fmt, ...)
{
    va_list ap;
    r->err->at = EF_DUT_AT_LINE;
    r->err->line = r->line;
    r->err->col = col_of(r, pos);
    va_start(ap, fmt);
    vsnprintf(r->err->msg, sizeof r->err->msg, fmt, ap);
    va_end(ap);
    return -1;
}

__attribute__((format(printf, 3, 4))) static int fail_where(ef_dut_error *e, ef_dut_at at, const char *fmt, ...)
{
    va_list ap;
    e->at = at;
    va_start(ap, fmt);
    vsnprintf(e->msg, sizeof e->msg, fmt, ap);
    va_end(ap);
    return -1;
}

__attribute__((format(printf, 3, 4))) static int fail_record(ef_dut_error *e, uint32_t offset, const char *fmt, ...)
{
    va_list ap;
    e->at = EF_DUT_AT_RECORD;
    e->offset = offset;
    va_start(ap, fmt);
    vsnprintf(e->msg, sizeof e->msg, fmt, ap);
    va_end(ap);
    return -1;
}

/* d[p..end) up to the next blank, ',', ';' or ')' (at most 24 characters),
 * made safe for a terminal (other than printable ASCII as \xNN). */
static void token(const unsigned char *d, size_t p, size_t end, char *buf, size_t size)
{
    size_t k = 0, n = 0;
    for (; p < end && !blank(d[p]) && d[p] != ',' && d[p] != ';' && d[p] != ')' && n < 24 && k + 8 < size; p++, n++) {
        if (d[p] >= 0x20 && d[p] < 0x7f && d[p] != '\\')
            buf[k++] = (char)d[p];
        else
            k += (size_t)snprintf(buf + k, size - k, "\\x%02X", d[p]);
    }
    if (p < end && !blank(d[p]) && d[p] != ',' && d[p] != ';' && d[p] != ')' && k + 4 < size)
        k += (size_t)snprintf(buf + k, size - k, "...");
    buf[k] = '\0';
}

/* d[p..end) starts with the word w (followed by a blank or the line's end). */
static int word(const unsigned char *d, size_t p, size_t end, const char *w)
{
    const size_t n = strlen(w);
    return end - p >= n && !memcmp(d + p, w, n) && (p + n == end || blank(d[p + n]));
}

/* A name that is KEY or ends in _KEY. */
static int key_of(const unsigned char *name, size_t len)
{
    for (int q = 0; q < K_COUNT; q++) {
        const size_t k = strlen(KEYS[q]);
        if ((len == k || (len > k && name[len - k - 1] == '_')) && !memcmp(name + len - k, KEYS[q], k))
            return q;
    }
    return -1;
}

static size_t skip_blanks(const unsigned char *d, size_t p, size_t end)
{
    while (p < end && blank(d[p]))
        p++;
    return p;
}

/* One value: a decimal number, or one in parentheses.  p at its first byte;
 * returns the position after it, or 0 after an error. */
static size_t value(reader *r, size_t p, size_t end, int key, const unsigned char *name, size_t nlen)
{
    const unsigned char *d = r->d;
    const size_t v0 = p;
    int paren = 0;
    char tok[128];
    if (p < end && d[p] == '(') {
        paren = 1;
        p = skip_blanks(d, p + 1, end);
    }
    const size_t ds = p;
    while (p < end && digit(d[p]))
        p++;
    if (p == ds || (p < end && (ident(d[p]) || d[p] == '\'' || d[p] == '.'))) {
        token(d, v0, end, tok, sizeof tok);
        if (!tok[0])
            fail_at(r, v0, "%.*s: no value (a decimal number)", (int)nlen, (const char *)name);
        else
            fail_at(r, v0, "%.*s: the value must be a plain decimal number, not '%s'", (int)nlen, (const char *)name,
                    tok);
        return 0;
    }
    /* at most 10 digits after leading zeros, and then within int32 */
    size_t z = ds;
    while (z + 1 < p && d[z] == '0')
        z++;
    int64_t v = 0;
    if (p - z <= 10)
        for (size_t i = z; i < p; i++)
            v = v * 10 + (d[i] - '0');
    if (p - z > 10 || v > INT32_MAX || v < 1 || (key <= K_H && v > EF_MAX_CANVAS) ||
        (key == K_NS && v != 8 && v != 16 && v != 32)) {
        token(d, ds, end, tok, sizeof tok);
        fail_at(r, ds, "%.*s = %s is out of range (%s)", (int)nlen, (const char *)name, tok,
                key <= K_H    ? "1..16384"
                : key == K_NS ? "8, 16 or 32"
                              : "1..2147483647");
        return 0;
    }
    if (paren) {
        p = skip_blanks(d, p, end);
        if (p == end || d[p] != ')') {
            fail_at(r, p, "%.*s = (%" PRId64 ": ')' expected", (int)nlen, (const char *)name, v);
            return 0;
        }
        p++;
    }
    if (r->got[key] && r->got[key] != (int32_t)v) {
        fail_at(r, (size_t)(name - d), "%s defined twice: %" PRId64 " here, %" PRId32 " at %" PRIu32 ":%" PRIu32,
                KEYS[key], v, r->got[key], r->got_line[key], r->got_col[key]);
        return 0;
    }
    if (!r->got[key]) {
        r->got[key] = (int32_t)v;
        r->got_line[key] = r->line;
        r->got_col[key] = col_of(r, (size_t)(name - d));
    }
    return p;
}

/* One line d[ls..end): a `define, #define, parameter or localparam of ours,
 * or anything else (not read).  0, or -1 after an error. */
static int line(reader *r, size_t end)
{
    const unsigned char *d = r->d;
    size_t p = skip_blanks(d, r->ls, end);
    int param;
    if (word(d, p, end, "`define") || word(d, p, end, "#define"))
        p += 7, param = 0;
    else if (word(d, p, end, "parameter"))
        p += 9, param = 1;
    else if (word(d, p, end, "localparam"))
        p += 10, param = 1;
    else
        return 0;
    p = skip_blanks(d, p, end);
    if (param && word(d, p, end, "integer"))
        p = skip_blanks(d, p + 7, end);
    if (param && p < end && d[p] == '[') { /* a range: [31:0] */
        while (p < end && d[p] != ']')
            p++;
        if (p == end)
            return 0;
        p = skip_blanks(d, p + 1, end);
    }
    for (;;) {
        const size_t n0 = p;
        while (p < end && ident(d[p]))
            p++;
        const size_t nlen = p - n0;
        const int key = nlen ? key_of(d + n0, nlen) : -1;
        if (key < 0)
            return 0; /* not ours: the rest of the line is not read */
        p = skip_blanks(d, p, end);
        if (param) {
            if (p == end || d[p] != '=')
                return fail_at(r, p, "%.*s: '=' and a value expected", (int)nlen, (const char *)(d + n0));
            p = skip_blanks(d, p + 1, end);
        }
        if (!(p = value(r, p, end, key, d + n0, nlen)))
            return -1;
        p = skip_blanks(d, p, end);
        if (param && p < end && d[p] == ',') { /* parameter A = 1, B = 2 */
            p = skip_blanks(d, p + 1, end);
            continue;
        }
        if (p == end || d[p] == ';' || d[p] == ',' || d[p] == ')' ||
            (end - p >= 2 && d[p] == '/' && (d[p + 1] == '/' || d[p + 1] == '*')))
            return 0;
        char tok[128];
        token(d, p, end, tok, sizeof tok);
        return fail_at(r, p, "%s = %" PRId32 ": unexpected '%s' after the value", KEYS[key], r->got[key], tok);
    }
}

int ef_dut_file_parse(const unsigned char *d, size_t len, ef_gen_limits *lim, ef_dut_error *err)
{
    memset(lim, 0, sizeof *lim);
    memset(err, 0, sizeof *err);
    if (len > EF_DUT_FILE_MAX)
        return fail_where(err, EF_DUT_AT_FILE, "larger than %u bytes", EF_DUT_FILE_MAX);
    if (len >= 4 && !memcmp(d, "EFB1", 4)) {
        if (len != 48)
            return fail_where(err, EF_DUT_AT_FILE,
                              "begins with \"EFB1\" but has %zu bytes: an identify record has 48 (docs/board.md 3.1)",
                              len);
        const unsigned version = d[4] | (unsigned)d[5] << 8;
        const uint32_t sm = le32(d + 16), w = le32(d + 20), h = le32(d + 24), e = le32(d + 28);
        if (version != 1)
            return fail_record(err, 4, "protocol version %u (this edgeflag reads version 1's record)", version);
        if (!(sm & 0x38u))
            return fail_record(err, 16, "sample counts 0x%08" PRIx32 ": none of 8, 16, 32 (bits 3-5)", sm);
        if (w < 1 || w > EF_MAX_CANVAS)
            return fail_record(err, 20, "W_MAX %" PRIu32 " is out of range (1..16384)", w);
        if (h < 1 || h > EF_MAX_CANVAS)
            return fail_record(err, 24, "H_MAX %" PRIu32 " is out of range (1..16384)", h);
        if (e < 1 || e > INT32_MAX)
            return fail_record(err, 28, "E_MAX %" PRIu32 " is out of range (1..2147483647)", e);
        lim->samples_mask = sm & 0x38u;
        lim->width = (int32_t)w;
        lim->height = (int32_t)h;
        lim->edges = e;
        return 0;
    }
    reader r;
    memset(&r, 0, sizeof r);
    r.d = d;
    r.err = err;
    r.line = 1;
    for (size_t pos = 0; pos < len; r.line++) {
        size_t le = pos;
        while (le < len && d[le] != '\n')
            le++;
        size_t end = le;
        if (end > pos && d[end - 1] == '\r')
            end--;
        r.ls = pos;
        if (line(&r, end) < 0)
            return -1;
        pos = le + 1;
    }
    if (!r.got[K_W] && !r.got[K_H] && !r.got[K_E] && !r.got[K_NS])
        return fail_where(err, EF_DUT_AT_FILE,
                          "neither an identify record (48 bytes from \"EFB1\") nor a file that defines W_MAX, H_MAX, "
                          "E_MAX or NS");
    if (!r.got[K_W] != !r.got[K_H]) {
        const int k = r.got[K_W] ? K_W : K_H;
        err->at = EF_DUT_AT_LINE;
        err->line = r.got_line[k];
        err->col = r.got_col[k];
        snprintf(err->msg, sizeof err->msg, "%s is defined and %s is not: the canvas needs both", KEYS[k],
                 KEYS[K_W + K_H - k]);
        return -1;
    }
    lim->width = r.got[K_W];
    lim->height = r.got[K_H];
    lim->edges = (uint32_t)r.got[K_E];
    lim->samples_mask = r.got[K_NS] ? 1u << (r.got[K_NS] == 8 ? 3 : r.got[K_NS] == 16 ? 4 : 5) : 0;
    return 0;
}

void ef_dut_error_format(const char *file, const ef_dut_error *e, char *buf, size_t size)
{
    if (!size)
        return;
    switch (e->at) {
    case EF_DUT_AT_LINE: snprintf(buf, size, "%s:%" PRIu32 ":%" PRIu32 ": %s", file, e->line, e->col, e->msg); break;
    case EF_DUT_AT_RECORD:
        snprintf(buf, size, "%s: identify record (byte offset %" PRIu32 "): %s", file, e->offset, e->msg);
        break;
    default: snprintf(buf, size, "%s: %s", file, e->msg); break;
    }
}
