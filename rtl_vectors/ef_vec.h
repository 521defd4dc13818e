/*
 * ef_vec.h - the writers of `edgeflag vectors` (docs/vectors.md): a
 * collector that the model's trace sink (ef_trace.h) fills, a merge of the
 * interfaces into one cycle order, and the hex, VCD, binary and manifest
 * writers, with the CRC-32 and SHA-256 they need.
 *
 * Everything here is integer-only and prints no time, locale-dependent text
 * or path other than the input's base name: the same trace gives the same
 * bytes on every machine and build.  Field layouts always come from the
 * interface table (ef_iface_get / ef_txn_field), never from constants here.
 */
#ifndef EF_VEC_H
#define EF_VEC_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "ef_api.h"
#include "ef_trace.h"

#ifdef __cplusplus
extern "C" {
#endif

#define EF_VEC_FORMAT 1       /* "format 1" of every file (docs/vectors.md) */
#define EF_VEC_BIN_HEADER 104 /* header bytes of vectors.bin */
#define EF_VEC_HEX_MAX_DIGITS ((EF_CYCLE_BITS + 64 * EF_TXN_WORDS + 3) / 4)

/* ------------------------------------------------------------ checksums */

/* CRC-32 of IEEE 802.3 / zlib / PNG.  Chains like zlib's crc32(): start with
 * crc = 0 and pass each result back in; the CRC of "123456789" is 0xCBF43926. */
EF_API uint32_t ef_vec_crc32(uint32_t crc, const void *data, size_t n);

/* SHA-256 (FIPS 180-4), by GNU Nettle, whose state is kept in opaque
 * storage here (so this header needs no Nettle header).  Builds without the
 * manifest (WITH_MANIFEST=0: no Nettle, no json-c) have no hashing: these
 * three and ef_vec_manifest_write are then absent (a link error names them). */
typedef struct ef_vec_sha256 {
    union {
        uint64_t align;
        unsigned char bytes[128];
    } state; /* Nettle's struct sha256_ctx (vec_sha256.c checks that it fits) */
} ef_vec_sha256;
EF_API void ef_vec_sha256_init(ef_vec_sha256 *s);
EF_API void ef_vec_sha256_update(ef_vec_sha256 *s, const void *data, size_t n);
EF_API void ef_vec_sha256_final(ef_vec_sha256 *s, uint8_t digest[32]);
/* 64 lower-case hex digits and a NUL. */
EF_API void ef_vec_sha256_hex(const uint8_t digest[32], char out[65]);

/* --------------------------------------------------------------- output */

/* A buffered byte sink that counts, hashes (SHA-256) and optionally CRCs
 * what passes through, so the manifest's sizes and hashes describe exactly
 * the bytes written.  With fp NULL nothing is written (a counting pass).
 * Every ef_vec_out_init must be followed by ef_vec_out_finish (a stream's
 * verbs, like the hash's: it allocates nothing and never closes fp).  One
 * sink is used by one thread at a time. */
enum { EF_VEC_OUT_SHA = 1, EF_VEC_OUT_CRC = 2 };
#define EF_VEC_OUT_BUF (1u << 16)
typedef struct ef_vec_out {
    FILE *fp;
    unsigned flags;
    ef_vec_sha256 sha;
    uint32_t crc;
    uint64_t bytes; /* written (or counted) so far */
    int err;        /* errno of the first failed write; later writes are dropped */
    size_t used;
    unsigned char buf[EF_VEC_OUT_BUF];
} ef_vec_out;
EF_API void ef_vec_out_init(ef_vec_out *o, FILE *fp, unsigned flags);
/* Writes n bytes; a large block (a whole buffer or more) goes to the hash
 * and the file without being copied. */
EF_API void ef_vec_out_write(ef_vec_out *o, const void *data, size_t n);
/* Hands what is buffered to the hash and the file (the buffer is then empty). */
EF_API void ef_vec_out_drain(ef_vec_out *o);
/* The writers' fast path: room for n bytes (n <= EF_VEC_OUT_ROOM) at the
 * end of the buffer, filled in place and then counted with
 * ef_vec_out_advance(o, m), m <= n.  Saves a copy and a call per line. */
#define EF_VEC_OUT_ROOM 8192u
static inline unsigned char *ef_vec_out_room(ef_vec_out *o, size_t n)
{
    if (EF_VEC_OUT_BUF - o->used < n)
        ef_vec_out_drain(o);
    return o->buf + o->used;
}
static inline void ef_vec_out_advance(ef_vec_out *o, size_t n)
{
    o->used += n;
    o->bytes += n;
}
EF_API void ef_vec_out_puts(ef_vec_out *o, const char *s);
EF_API void ef_vec_out_u64(ef_vec_out *o, uint64_t v); /* decimal */
/* Pushes the buffer out and finishes the hash (digest may be NULL).
 * Returns 0, or -1 with errno set to the first write error. */
EF_API int ef_vec_out_finish(ef_vec_out *o, uint8_t digest[32]);

/* Decimal of v into buf (at least 21 bytes); returns the length. */
EF_API size_t ef_vec_u64_dec(uint64_t v, char *buf);

/* ------------------------------------------------------------ run facts */

typedef struct ef_vec_info {
    const char *input;     /* the input's base name (no directory) */
    int32_t width, height; /* the canvas rendered */
    int samples;
    int rule;        /* -1: each shape's own ("scene"); else an ef_rule */
    uint64_t seed;   /* `# seed N` of an edgeflag gen scene, else 0 */
    uint64_t cycles; /* the frame's length (ef_trace_frame_end) */
    uint32_t mask;   /* interfaces recorded, bit i = ef_iface i */
    int dump;        /* 1: written as a DUT's dumps (role "actual"), not as expected vectors */
} ef_vec_info;

/* "nonzero", "evenodd" or "scene". */
EF_API const char *ef_vec_rule_name(int rule);
/* "stim" for the command stream (what the DUT receives), else "expected". */
EF_API const char *ef_vec_role(int iface);
/* "IFACE.ROLE.hex" into buf; returns buf. */
EF_API char *ef_vec_hex_name(int iface, char *buf, size_t size);
/* The base name of a path: what follows the last '/'. */
EF_API const char *ef_vec_base_name(const char *path);
/* Text of s safe inside a one-line comment of a hex file or VCD: bytes
 * outside ' '..'~', '\' and '$' become \xNN.  Writes to o. */
EF_API void ef_vec_out_escaped(ef_vec_out *o, const char *s);
/* "generator edgeflag V; input NAME; size WxH; samples N; rule R; seed S". */
EF_API void ef_vec_out_run_line(ef_vec_out *o, const ef_vec_info *info);

/* ------------------------------------------------------------ collector */

/* One interface's transactions in arrival (= cycle) order, packed as
 * records of 1 + nw words: the cycle, then the payload's ceil(P/64) words. */
typedef struct ef_vec_list {
    uint64_t *rec;
    size_t count, cap; /* records */
    unsigned nw;
} ef_vec_list;

typedef struct ef_vec_collect {
    ef_vec_list list[EF_IF_COUNT];
    uint64_t allowed[EF_IF_COUNT][EF_TXN_WORDS]; /* payload bits within each interface's width */
    uint32_t mask;                               /* interfaces accepted */
    ef_status error;                             /* first failure: EF_ERR_NOMEM, or EF_ERR_ARG for a broken trace */
    char why[160];                               /* what was broken, for EF_ERR_ARG */
} ef_vec_collect;

/* An empty collector of the interfaces in mask (the lists allocate as
 * transactions arrive); ef_vec_collect_destroy frees them. */
EF_API void ef_vec_collect_create(ef_vec_collect *c, uint32_t mask);
EF_API void ef_vec_collect_destroy(ef_vec_collect *c);
/* Appends t.  Refuses (and remembers in c->error) an interface outside the
 * mask, a cycle >= 2^48 or not after the interface's previous one (one
 * transfer per interface per cycle), payload bits above the width, and
 * running out of memory. */
EF_API ef_status ef_vec_collect_add(ef_vec_collect *c, const ef_txn *t);
/* An ef_txn_fn: user is the ef_vec_collect. */
EF_API void ef_vec_collect_sink(void *user, const ef_txn *t);
EF_API size_t ef_vec_collect_count(const ef_vec_collect *c, int iface);
/* Transaction k of iface. */
EF_API void ef_vec_collect_get(const ef_vec_collect *c, int iface, size_t k, ef_txn *out);
/* Sum of the counts of the interfaces in mask. */
EF_API uint64_t ef_vec_collect_total(const ef_vec_collect *c, uint32_t mask);
/* Cycle of the last transaction over the interfaces in mask, +1; 0 if none. */
EF_API uint64_t ef_vec_collect_end(const ef_vec_collect *c, uint32_t mask);

/* Global cycle order over the interfaces in mask: by cycle, then interface
 * number, then production order. */
typedef struct ef_vec_merge {
    const ef_vec_collect *c;
    uint32_t mask;
    size_t pos[EF_IF_COUNT];
} ef_vec_merge;
EF_API void ef_vec_merge_init(ef_vec_merge *m, const ef_vec_collect *c, uint32_t mask);
/* The next transaction into *out: 1, or 0 at the end. */
EF_API int ef_vec_merge_next(ef_vec_merge *m, ef_txn *out);

/* -------------------------------------------------------------- writers */

/* Digits of one word of iface in a hex file: ceil((48 + P) / 4); 0 if none. */
EF_API unsigned ef_vec_hex_digits(int iface);
/* The word { cycle[47:0], payload } of t as exactly ef_vec_hex_digits
 * lower-case digits and a NUL (out holds EF_VEC_HEX_MAX_DIGITS + 1). */
EF_API unsigned ef_vec_hex_word(const ef_txn *t, char *out);
/* IFACE.ROLE.hex: header comments, then one word per line. */
EF_API void ef_vec_hex_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c, int iface);

/* vectors.vcd: every signal of the interfaces in info->mask. */
EF_API void ef_vec_vcd_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c);

/* vectors.bin: the 104-byte header (two CRCs), then the merged records
 * (built in memory first: the header's CRC covers them).  0, or -1 when out
 * of memory (nothing written then). */
EF_API int ef_vec_bin_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c);
/* The header alone (records_crc = the CRC-32 of the records). */
/* Record of t into r (docs/vectors.md section 4): interface, payload length
 * L = ceil(P/8), 48-bit cycle in 8 bytes, L payload bytes least significant
 * first.  Returns its size.  The board protocol's RESULT frames carry these. */
#define EF_VEC_BIN_RECORD_MAX (10 + 8 * EF_TXN_WORDS)
EF_API size_t ef_vec_bin_record(const ef_txn *t, uint8_t r[EF_VEC_BIN_RECORD_MAX]);
/* The header from per-interface counts (a receiver that counted the records
 * itself, as edgeflag-host does, has no ef_vec_collect). */
EF_API void ef_vec_bin_header_counts(uint8_t h[EF_VEC_BIN_HEADER], const ef_vec_info *info,
                                     const uint64_t counts[EF_IF_COUNT], uint32_t records_crc);
EF_API void ef_vec_bin_header(uint8_t h[EF_VEC_BIN_HEADER], const ef_vec_info *info, const ef_vec_collect *c,
                              uint32_t records_crc);

/* ------------------------------------------------------------ the formats */

/* The --formats bits of `edgeflag vectors`. */
enum { EF_VEC_F_HEX = 1, EF_VEC_F_VCD = 2, EF_VEC_F_BIN = 4, EF_VEC_F_ALL = 7 };
#define EF_VEC_NFORMATS 3

/* One vector file format: the table ef_vec_formats (vec_formats.c) is the
 * only place that knows them all; the writers of `vectors`, the manifest,
 * --formats and the readers of `check` go through it. */
typedef struct ef_vec_format {
    const char *name; /* "hex": --formats and the manifest's "format" */
    unsigned bit;     /* EF_VEC_F_* */
    int per_iface;    /* 1: one file per interface (IFACE.ROLE.hex); 0: one for all (vectors.EXT) */
    const char *ext;  /* ".hex" */
    /* Writes the file (iface: the interface of a per-interface file, else ignored); 0, or -1 out of memory. */
    int (*write)(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c, int iface);
    int reader; /* EF_VEC_FMT_* of ef_vec_read.h that reads it back; 0: none (VCD: GTKWave's) */
} ef_vec_format;
EF_API extern const ef_vec_format ef_vec_formats[EF_VEC_NFORMATS];
/* The format called name, or NULL. */
EF_API const ef_vec_format *ef_vec_format_named(const char *name);
/* The format of a file name by its extension, or NULL. */
EF_API const ef_vec_format *ef_vec_format_of_path(const char *path);

/* One file written, as the manifest lists it. */
typedef struct ef_vec_file {
    char name[32];
    const char *format; /* "hex", "vcd", "bin", "png", "pam" */
    int iface;          /* -1: not one interface */
    const char *role;   /* "stim", "expected", "all" */
    uint64_t count, bytes;
    char sha256[65];
} ef_vec_file;
/* manifest.json, by json-c (docs/vectors.md section 6).  0, or -1 when out
 * of memory (nothing written then). */
EF_API int ef_vec_manifest_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c,
                                 const ef_vec_file *files, size_t nfiles);

/* ----------------------------------------------------------------- seed */

/* The N of the first `# seed N` line in the leading comment block (lines
 * that are blank or start with '#') of an edgeflag gen scene: 1 and *seed,
 * or 0 when there is none.  N must be decimal <= 2^64-1, followed by the end
 * of the line, ',', a space or a tab. */
EF_API int ef_vec_scene_seed(const char *text, size_t len, uint64_t *seed);
/* The same, reading at most the first 64 KiB of the file at path.  0 when
 * the file has no such line or cannot be read (it was just loaded: an
 * error here is not this reader's to report). */
EF_API int ef_vec_file_seed(const char *path, uint64_t *seed);

/* ------------------------------------------------------- RTL headers */

/* The Verilog header ef_ifaces.vh (sv 0) or the SystemVerilog package
 * ef_ifaces_pkg.sv (sv 1) of docs/vectors.md section 8, from the interface
 * table; the caller checks f for write errors. */
EF_API void ef_vec_rtl_header_write(FILE *f, int sv);

#ifdef __cplusplus
}
#endif

#endif /* EF_VEC_H */
