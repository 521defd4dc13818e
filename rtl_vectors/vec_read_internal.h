/*
 * vec_read_internal.h - what the vector readers (vec_read_*.c) share: a byte
 * source that is either a memory buffer (the fuzz target, tests) or a file
 * read a chunk at a time (large dumps), the growable per-interface
 * transaction arrays, and the error setters.  Not installed.
 */
#ifndef EF_VEC_READ_INTERNAL_H
#define EF_VEC_READ_INTERNAL_H

#include <stdio.h>

#include "ef_vec_read.h"

/* Bytes from memory, or from a FILE in chunks of EF_VR_CHUNK.  The fuzz
 * build makes chunks tiny (tests/fuzz/module.mk), so that every token and
 * record of its inputs straddles a chunk boundary somewhere. */
#ifndef EF_VR_CHUNK
#define EF_VR_CHUNK 65536u
#endif
typedef struct ef_vr_src {
    FILE *fp;         /* NULL: memory */
    const uint8_t *p; /* the current chunk (the whole buffer in memory mode) */
    size_t n, pos;    /* its length and the read position in it */
    uint64_t base;    /* bytes of the input before the current chunk */
    uint8_t *buf;     /* file mode: the chunk buffer */
    int ioerr;        /* errno of a failed read, else 0 */
    uint64_t size;    /* the whole input's bytes when known (memory, a regular file), else 0 */
    int crc_on;       /* taking the CRC-32 of what is consumed (ef_vr_crc_start) */
    uint32_t crc;     /* of the bytes consumed before crc_from */
    size_t crc_from;  /* the first byte of the current chunk not in crc */
} ef_vr_src;

void ef_vr_src_mem(ef_vr_src *s, const uint8_t *data, size_t len);
/* Loads the next chunk; its first byte, or -1 at the end or on an error. */
int ef_vr_refill(ef_vr_src *s);
static inline int ef_vr_getc(ef_vr_src *s) { return s->pos < s->n ? s->p[s->pos++] : ef_vr_refill(s); }
/* The CRC-32 of every byte consumed from now on, taken a chunk at a time as
 * the chunks are used up (not a record at a time: the binary reader's
 * records are 12 to 43 bytes, too short for the CRC's fast loop), and its
 * value over everything consumed up to ef_vr_crc_end. */
void ef_vr_crc_start(ef_vr_src *s);
uint32_t ef_vr_crc_end(ef_vr_src *s);
/* Up to n bytes into dst; fewer only at the end (or on an error). */
size_t ef_vr_read(ef_vr_src *s, uint8_t *dst, size_t n);
/* Offset of the next byte. */
static inline uint64_t ef_vr_tell(const ef_vr_src *s) { return s->base + s->pos; }

/* Parsers over a source (ef_vec_read_hex/_bin/_path call these). */
ef_status ef_vr_hex(ef_vr_src *s, const char *name, int want, int hint, ef_vec_dump *out, ef_vec_read_error *err);
ef_status ef_vr_bin(ef_vr_src *s, const char *name, ef_vec_dump *out, ef_vec_read_error *err);

/* An empty dump of the given format (no interface yet). */
void ef_vr_dump_init(ef_vec_dump *d, int format);
/* Marks iface present and sets its word count. */
void ef_vr_dump_add_iface(ef_vec_dump *d, int iface);
/* Makes room for n transactions of iface at once, when a header announces
 * them: the arrays are then not grown (and copied) a doubling at a time.  n
 * is cut to what the input's size could hold (size / min_bytes, when the
 * size is known; else nothing is reserved), so a lying header cannot make a
 * small file claim large memory.  Best effort: when it fails, appending
 * grows the arrays as before. */
void ef_vr_reserve(ef_vec_dump *d, int iface, uint64_t n, uint64_t size, unsigned min_bytes, int with_off);
/* Appends one transaction (off ignored unless with_off); inline, as it is
 * called once for every transaction read.  0, or -1 when out
 * of memory. */
int ef_vr_grow(ef_vec_seq *q, int with_off);
static inline int ef_vr_append(ef_vec_dump *d, int iface, uint64_t cycle, const uint64_t *pay, uint64_t loc,
                               uint64_t off, int with_off)
{
    ef_vec_seq *q = &d->seq[iface];
    if (q->n == q->cap && ef_vr_grow(q, with_off) != 0)
        return -1;
    q->cycle[q->n] = cycle;
    for (unsigned k = 0; k < q->nw; k++) /* 1 to 4 words: no memcpy call */
        q->pay[q->n * q->nw + k] = pay[k];
    q->loc[q->n] = loc;
    if (with_off)
        q->off[q->n] = off;
    q->n++;
    return 0;
}

/* Error setters: fill err (file name, place, printf message) and return
 * status, for `return ef_vr_err_*(...)`. */
ef_status ef_vr_err_file(ef_vec_read_error *e, ef_status st, const char *name, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
ef_status ef_vr_err_line(ef_vec_read_error *e, ef_status st, const char *name, uint64_t line, uint64_t col,
                         const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;
ef_status ef_vr_err_bin(ef_vec_read_error *e, ef_status st, const char *name, ef_vec_at at, uint64_t record,
                        uint64_t offset, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 7, 8)))
#endif
    ;

/* A byte of input quoted for a message: 'c' when printable ASCII, else
 * '\xNN' (control characters and stray bytes never reach the terminal). */
void ef_vr_quote_byte(int c, char out[8]);

/* Payload bits P of iface, hex digits of a word, ceil((48 + P) / 4). */
unsigned ef_vr_word_digits(int iface);

#endif /* EF_VEC_READ_INTERNAL_H */
