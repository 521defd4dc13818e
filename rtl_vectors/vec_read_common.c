/*
 * vec_read_common.c - the parts of the vector readers that are not a format:
 * byte sources (memory or a file in chunks), the per-interface transaction
 * arrays, errors and their "file:line:col" / "file: record N" form, CRC-32,
 * and the entry points that pick hex or binary.
 */
#include "vec_read_internal.h"
#include "ef_vec.h"

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

const uint8_t ef_vec_bin_magic[8] = { 0x89, 'E', 'F', 'V', '\r', '\n', 0x1a, '\n' };

/* ---------------------------------------------------------------- CRC-32 */

/* The writers' CRC-32 (vec_crc32.c): one implementation for both sides. */
uint32_t ef_vec_read_crc32(uint32_t crc, const void *data, size_t len) { return ef_vec_crc32(crc, data, len); }

/* ---------------------------------------------------------------- sources */

void ef_vr_src_mem(ef_vr_src *s, const uint8_t *data, size_t len)
{
    memset(s, 0, sizeof *s);
    s->p = data;
    s->n = data ? len : 0;
    s->size = s->n;
}

void ef_vr_crc_start(ef_vr_src *s)
{
    s->crc_on = 1;
    s->crc = 0;
    s->crc_from = s->pos;
}

uint32_t ef_vr_crc_end(ef_vr_src *s)
{
    if (s->crc_on && s->pos > s->crc_from)
        s->crc = ef_vec_read_crc32(s->crc, s->p + s->crc_from, s->pos - s->crc_from);
    s->crc_from = s->pos;
    return s->crc;
}

int ef_vr_refill(ef_vr_src *s)
{
    if (!s->fp || s->ioerr)
        return -1;
    if (s->crc_on) { /* the chunk is used up: all of it is consumed */
        s->crc = ef_vec_read_crc32(s->crc, s->p + s->crc_from, s->n - s->crc_from);
        s->crc_from = 0;
    }
    s->base += s->n;
    s->n = s->pos = 0;
    errno = 0;
    size_t got = fread(s->buf, 1, EF_VR_CHUNK, s->fp);
    if (got == 0) {
        if (ferror(s->fp))
            s->ioerr = errno ? errno : EIO;
        return -1;
    }
    s->p = s->buf;
    s->n = got;
    s->pos = 1;
    return s->p[0];
}

size_t ef_vr_read(ef_vr_src *s, uint8_t *dst, size_t n)
{
    size_t done = 0;
    while (done < n) {
        if (s->pos == s->n) {
            int c = ef_vr_refill(s);
            if (c < 0)
                break;
            dst[done++] = (uint8_t)c;
            continue;
        }
        size_t k = s->n - s->pos;
        if (k > n - done)
            k = n - done;
        memcpy(dst + done, s->p + s->pos, k);
        s->pos += k;
        done += k;
    }
    return done;
}

/* ---------------------------------------------------------------- dumps */

void ef_vr_dump_init(ef_vec_dump *d, int format)
{
    memset(d, 0, sizeof *d);
    d->format = format;
    d->rule = -1;
}

void ef_vr_dump_add_iface(ef_vec_dump *d, int iface)
{
    const ef_iface_desc *desc = ef_iface_get(iface);
    d->mask |= 1u << iface;
    d->seq[iface].nw = (desc->width + 63u) / 64u;
}

/* Grows one array to cap elements of size sz; 0 or -1. */
static int grow(void *pp, size_t cap, size_t sz)
{
    void **p = pp;
    if (cap > SIZE_MAX / sz)
        return -1;
    void *np = realloc(*p, cap * sz);
    if (!np)
        return -1;
    *p = np;
    return 0;
}

void ef_vr_reserve(ef_vec_dump *d, int iface, uint64_t n, uint64_t size, unsigned min_bytes, int with_off)
{
    ef_vec_seq *q = &d->seq[iface];
    if (size / min_bytes < n)
        n = size / min_bytes;
    if (n <= q->cap || n > SIZE_MAX / 8u / (q->nw ? q->nw : 1u))
        return;
    if (grow(&q->cycle, (size_t)n, sizeof *q->cycle) || grow(&q->pay, (size_t)n * q->nw, sizeof *q->pay) ||
        grow(&q->loc, (size_t)n, sizeof *q->loc) || (with_off && grow(&q->off, (size_t)n, sizeof *q->off)))
        return; /* the arrays that did grow are still valid at the old capacity */
    q->cap = (size_t)n;
}

/* The full arrays of q doubled: 0, or -1 when out of memory. */
int ef_vr_grow(ef_vec_seq *q, int with_off)
{
    /* Doubling: the memory stays within twice what the transactions
     * need, and the transactions within a constant factor of the input
     * (every transaction took at least two bytes of it). */
    if (q->cap > SIZE_MAX / 2u)
        return -1;
    size_t cap = q->cap ? q->cap * 2u : 64u;
    if (cap > SIZE_MAX / (q->nw ? q->nw : 1u))
        return -1;
    if (grow(&q->cycle, cap, sizeof *q->cycle) || grow(&q->pay, cap * q->nw, sizeof *q->pay) ||
        grow(&q->loc, cap, sizeof *q->loc) || (with_off && grow(&q->off, cap, sizeof *q->off)))
        return -1;
    q->cap = cap;
    return 0;
}

void ef_vec_dump_destroy(ef_vec_dump *d)
{
    for (int i = 0; i < EF_IF_COUNT; i++) {
        free(d->seq[i].cycle);
        free(d->seq[i].pay);
        free(d->seq[i].loc);
        free(d->seq[i].off);
    }
    ef_vr_dump_init(d, 0);
}

void ef_vec_dump_txn(const ef_vec_dump *d, int iface, size_t k, ef_txn *t)
{
    const ef_vec_seq *q = &d->seq[iface];
    memset(t, 0, sizeof *t);
    t->iface = (uint8_t)iface;
    if (k >= q->n)
        return;
    t->cycle = q->cycle[k];
    memcpy(t->w, q->pay + k * q->nw, q->nw * sizeof *t->w);
}

unsigned ef_vr_word_digits(int iface) { return (EF_CYCLE_BITS + ef_iface_get(iface)->width + 3u) / 4u; }

int ef_vec_iface_from_name(const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *dot = strchr(base, '.');
    size_t n = dot ? (size_t)(dot - base) : strlen(base);
    char nm[16];
    if (n >= sizeof nm)
        return -1;
    memcpy(nm, base, n);
    nm[n] = '\0';
    return ef_iface_find(nm); /* reads the old name `edge` too */
}

/* ---------------------------------------------------------------- errors */

void ef_vr_quote_byte(int c, char out[8])
{
    if (c >= 0x20 && c < 0x7f && c != '\'' && c != '\\')
        snprintf(out, 8, "'%c'", c);
    else
        snprintf(out, 8, "'\\x%02x'", (unsigned)c & 0xffu);
}

static void set_common(ef_vec_read_error *e, ef_status st, const char *name, ef_vec_at at, const char *fmt, va_list ap)
{
    memset(e, 0, sizeof *e);
    e->status = st;
    e->at = at;
    snprintf(e->file, sizeof e->file, "%s", name ? name : "");
    vsnprintf(e->msg, sizeof e->msg, fmt, ap);
}

ef_status ef_vr_err_file(ef_vec_read_error *e, ef_status st, const char *name, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    set_common(e, st, name, EF_VEC_AT_FILE, fmt, ap);
    va_end(ap);
    return st;
}

ef_status ef_vr_err_line(ef_vec_read_error *e, ef_status st, const char *name, uint64_t line, uint64_t col,
                         const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    set_common(e, st, name, EF_VEC_AT_LINE, fmt, ap);
    va_end(ap);
    e->line = line;
    e->col = col;
    return st;
}

ef_status ef_vr_err_bin(ef_vec_read_error *e, ef_status st, const char *name, ef_vec_at at, uint64_t record,
                        uint64_t offset, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    set_common(e, st, name, at, fmt, ap);
    va_end(ap);
    e->record = record;
    e->offset = offset;
    return st;
}

void ef_vec_read_error_format(const ef_vec_read_error *e, char *buf, size_t size)
{
    if (!size)
        return;
    switch (e->at) {
    case EF_VEC_AT_LINE: snprintf(buf, size, "%s:%" PRIu64 ":%" PRIu64 ": %s", e->file, e->line, e->col, e->msg); break;
    case EF_VEC_AT_HEADER:
        snprintf(buf, size, "%s: header (byte offset %" PRIu64 "): %s", e->file, e->offset, e->msg);
        break;
    case EF_VEC_AT_RECORD:
        snprintf(buf, size, "%s: record %" PRIu64 " (byte offset %" PRIu64 "): %s", e->file, e->record, e->offset,
                 e->msg);
        break;
    case EF_VEC_AT_END:
        snprintf(buf, size, "%s: end of stream (byte offset %" PRIu64 ", after %" PRIu64 " records): %s", e->file,
                 e->offset, e->record, e->msg);
        break;
    default: snprintf(buf, size, "%s: %s", e->file, e->msg); break;
    }
}

/* ---------------------------------------------------------------- entry points */

ef_status ef_vec_read_hex(const char *name, const uint8_t *data, size_t len, int want, int hint, ef_vec_dump *out,
                          ef_vec_read_error *err)
{
    ef_vr_src s;
    ef_vr_src_mem(&s, data, len);
    return ef_vr_hex(&s, name, want, hint, out, err);
}

ef_status ef_vec_read_bin(const char *name, const uint8_t *data, size_t len, ef_vec_dump *out, ef_vec_read_error *err)
{
    ef_vr_src s;
    ef_vr_src_mem(&s, data, len);
    return ef_vr_bin(&s, name, out, err);
}

ef_status ef_vec_read_fp(FILE *fp, const char *name, int binary, int want, int hint, ef_vec_dump *out,
                         ef_vec_read_error *err)
{
    ef_vr_src s;
    ef_status st;

    ef_vr_dump_init(out, 0);
    memset(&s, 0, sizeof s);
    s.fp = fp;
    struct stat sb;
    if (fstat(fileno(fp), &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_size > 0)
        s.size = (uint64_t)sb.st_size;
    s.buf = malloc(EF_VR_CHUNK);
    if (!s.buf)
        return ef_vr_err_file(err, EF_ERR_NOMEM, name, "out of memory");
    s.p = s.buf;
    st = binary ? ef_vr_bin(&s, name, out, err) : ef_vr_hex(&s, name, want, hint, out, err);
    /* A read error (EISDIR for a directory, EIO) outranks whatever the parser
     * made of the bytes before it: they were not the whole file. */
    if (s.ioerr) {
        ef_vec_dump_destroy(out);
        st = ef_vr_err_file(err, EF_ERR_IO, name, "read error: %s", strerror(s.ioerr));
    }
    free(s.buf);
    return st;
}

ef_status ef_vec_read_path(const char *path, const char *name, int want, int hint, ef_vec_dump *out,
                           ef_vec_read_error *err)
{
    if (!name)
        name = path;
    ef_vr_dump_init(out, 0);
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return ef_vr_err_file(err, EF_ERR_IO, name, "cannot open: %s", strerror(errno));
    const ef_vec_format *fm = ef_vec_format_of_path(path);
    ef_status st = ef_vec_read_fp(fp, name, fm && fm->reader == EF_VEC_FMT_BIN, want, hint, out, err);
    fclose(fp);
    return st;
}
