/*
 * ef_vec_read.h - readers of the test-vector files of docs/vectors.md, for
 * `edgeflag check`: `$readmemh` hex files (section 3, one interface each),
 * the binary stream (section 4, every interface merged) and the manifest
 * (section 6).  The same readers take the model's expected files and an
 * RTL's dumps, which is why they are strict about framing and lenient only
 * where IEEE 1364's `$readmemh` itself is (comments, blank lines, upper-case
 * digits, `_` separators) and where a testbench's `$fwrite` differs from our
 * writer (no header).
 *
 * Contract (fuzzed by tests/fuzz/fuzz_vec_read.c): any bytes give either a
 * dump or an error naming its place - `file:line:col` for text,
 * `file: record N (byte offset O)` or `file: header (byte offset O)` for the
 * binary stream - never a crash; memory stays within a constant factor of
 * the input's size; a failed read leaves the result empty.
 *
 * Field layouts are never written out here: transactions are kept as the
 * cycle and the payload bits of include/edgeflag/ef_trace.h and decoded with
 * ef_txn_field() against the interface table (model/trace_iface.c).
 */
#ifndef EF_VEC_READ_H
#define EF_VEC_READ_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "edgeflag.h"
#include "ef_trace.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Binary stream layout constants (docs/vectors.md section 4). */
#define EF_VEC_BIN_HEADER_SIZE 104u
#define EF_VEC_BIN_VERSION 1u
#define EF_VEC_HEX_VERSION 1u
EF_API extern const uint8_t ef_vec_bin_magic[8];

/* Where a reader error is.  Records are numbered from 1, like lines. */
typedef enum ef_vec_at {
    EF_VEC_AT_FILE = 0, /* "FILE: msg" (cannot open, read error, ...) */
    EF_VEC_AT_LINE,     /* "FILE:LINE:COL: msg" */
    EF_VEC_AT_HEADER,   /* "FILE: header (byte offset O): msg" */
    EF_VEC_AT_RECORD,   /* "FILE: record N (byte offset O): msg" */
    EF_VEC_AT_END       /* "FILE: end of stream (byte offset O, after N records): msg" */
} ef_vec_at;

typedef struct ef_vec_read_error {
    ef_status status; /* EF_ERR_SYNTAX, _RANGE, _IO, _NOMEM, _UNSUPPORTED */
    ef_vec_at at;
    char file[512];
    uint64_t line, col; /* EF_VEC_AT_LINE, 1-based; col counts characters */
    uint64_t record;    /* EF_VEC_AT_RECORD, EF_VEC_AT_END */
    uint64_t offset;    /* EF_VEC_AT_HEADER, _RECORD, _END */
    char msg[256];
} ef_vec_read_error;

/* Formats the error as above into buf (always NUL-terminated). */
EF_API void ef_vec_read_error_format(const ef_vec_read_error *e, char *buf, size_t size);

/* One interface's transactions in file order. */
typedef struct ef_vec_seq {
    size_t n, cap;
    unsigned nw;     /* payload words per transaction: ceil(P / 64) */
    uint64_t *cycle; /* [n] */
    uint64_t *pay;   /* [n * nw], least significant word first */
    uint64_t *loc;   /* [n] hex: line; binary: record number */
    uint64_t *off;   /* [n] binary: the record's byte offset; NULL for hex */
} ef_vec_seq;

enum { EF_VEC_FMT_HEX = 1, EF_VEC_FMT_BIN = 2 };

/* What one file holds. */
typedef struct ef_vec_dump {
    int format;    /* EF_VEC_FMT_* */
    uint32_t mask; /* interfaces the file records (bit i = ef_iface i) */
    ef_vec_seq seq[EF_IF_COUNT];
    int has_header;        /* hex: a `// edgeflag vectors format` line was read */
    int32_t width, height; /* frame size, 0 x 0 when the file does not say */
    int samples;           /* 8/16/32, 0 when unknown */
    int rule;              /* binary: 0 nonzero, 1 evenodd, 2 each shape's own; -1 unknown */
    uint64_t seed;
} ef_vec_dump;

/* Releases everything and leaves an empty dump. */
EF_API void ef_vec_dump_destroy(ef_vec_dump *d);

/* Transaction k of interface iface as an ef_txn (for ef_txn_field). */
EF_API void ef_vec_dump_txn(const ef_vec_dump *d, int iface, size_t k, ef_txn *t);

/* The interface a file name starts with ("pix.actual.hex" -> EF_IF_PIX:
 * the name up to its first '.', after any directory), or -1. */
EF_API int ef_vec_iface_from_name(const char *path);

/* Hex file (docs/vectors.md section 3).  `want` >= 0: the file must hold that
 * interface (a header naming another is an error).  Otherwise the header
 * says which, or, when there is none, `hint` (-1: then the file is refused).
 * An empty file (0 bytes) is an error: even a dump of no transactions should
 * say so with a comment. */
EF_API ef_status ef_vec_read_hex(const char *name, const uint8_t *data, size_t len, int want, int hint,
                                 ef_vec_dump *out, ef_vec_read_error *err);

/* Binary stream (docs/vectors.md section 4): magic, version, header size,
 * header fields, header CRC, records (interface in the mask, payload length
 * of the interface, 48-bit cycle, no bits above the payload), counts, CRC of
 * the records. */
EF_API ef_status ef_vec_read_bin(const char *name, const uint8_t *data, size_t len, ef_vec_dump *out,
                                 ef_vec_read_error *err);

/* Reads the file at path, streaming (a chunk at a time, so a large dump
 * costs its transactions, not its text): a name ending in ".bin" is a binary
 * stream, anything else a hex file.  `name` is what messages call it (the
 * path when NULL). */
EF_API ef_status ef_vec_read_path(const char *path, const char *name, int want, int hint, ef_vec_dump *out,
                                  ef_vec_read_error *err);

/* The same from an open stream (binary: nonzero for the binary format),
 * read EF_VR_CHUNK bytes at a time; fp stays open. */
EF_API ef_status ef_vec_read_fp(FILE *fp, const char *name, int binary, int want, int hint, ef_vec_dump *out,
                                ef_vec_read_error *err);

/* CRC-32 of IEEE 802.3 / zlib / PNG (reflected 0xEDB88320, initial and final
 * XOR 0xFFFFFFFF): crc = ef_vec_read_crc32(0, p, n) for a whole buffer, or
 * chained over pieces by passing the previous result. */
EF_API uint32_t ef_vec_read_crc32(uint32_t crc, const void *data, size_t len);

/* ------------------------------------------------------------- manifest */
typedef struct ef_vec_manifest_file {
    char *name;   /* a plain file name (checked: no '/', no "..") */
    char *format; /* "hex", "vcd", "bin", ... or NULL */
    char *role;   /* "stim", "expected", ... or NULL */
    int iface;    /* its "interface", or -1 */
    int has_count;
    uint64_t count;
    size_t index; /* its place in "files" (from 0), for messages: files[K] */
} ef_vec_manifest_file;

typedef struct ef_vec_manifest {
    int32_t width, height; /* 0 when absent */
    size_t nfiles;
    ef_vec_manifest_file *files;
} ef_vec_manifest;

/* manifest.json (docs/vectors.md section 6), parsed by json-c: at most 1 MiB
 * and 64 levels deep, a syntax error at its FILE:LINE:COL; "files" must be
 * an array of objects whose "name" is a plain file name in the manifest's
 * own directory, and a value refused is named by its key ("FILE: files[4].
 * name: ...").  EF_ERR_UNSUPPORTED in a build without json-c (WITH_MANIFEST=0). */
EF_API ef_status ef_vec_read_manifest(const char *name, const uint8_t *data, size_t len, ef_vec_manifest *out,
                                      ef_vec_read_error *err);
EF_API ef_status ef_vec_read_manifest_path(const char *path, const char *name, ef_vec_manifest *out,
                                           ef_vec_read_error *err);
EF_API void ef_vec_manifest_destroy(ef_vec_manifest *m);

#ifdef __cplusplus
}
#endif

#endif /* EF_VEC_READ_H */
