/*
 * dut_file.h - the reader of `edgeflag gen --dut-file FILE` (docs/gen.md
 * section 11): a board's identify record (the 48 bytes of docs/board.md 3.1,
 * as `edgeflag-host identify --save` writes them) or a Verilog or C file
 * that defines W_MAX, H_MAX, E_MAX and NS.  Apart from cmd_gen.c so that it
 * is fuzzed on its own (tests/fuzz/fuzz_dut_file.c).
 */
#ifndef EF_CLI_DUT_FILE_H
#define EF_CLI_DUT_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "ef_gen.h"

/* The largest --dut-file read. */
#define EF_DUT_FILE_MAX (1u << 20)

/* Where an error is: the whole file, a line and column of the text form
 * (1-based, columns in characters: UTF-8 continuation bytes do not count),
 * or a field of the identify record (its byte offset). */
typedef enum ef_dut_at { EF_DUT_AT_FILE, EF_DUT_AT_LINE, EF_DUT_AT_RECORD } ef_dut_at;

typedef struct ef_dut_error {
    ef_dut_at at;
    uint32_t line, col; /* EF_DUT_AT_LINE */
    uint32_t offset;    /* EF_DUT_AT_RECORD */
    char msg[256];
} ef_dut_error;

/* Reads data[0..len) (any bytes; need not be NUL-terminated).  0 and *lim
 * filled (a field 0: the file does not state it), or -1 and *err filled
 * (*lim then all 0). */
int ef_dut_file_parse(const unsigned char *data, size_t len, ef_gen_limits *lim, ef_dut_error *err);

/* "FILE:LINE:COL: MSG", "FILE: identify record (byte offset N): MSG" or
 * "FILE: MSG". */
void ef_dut_error_format(const char *file, const ef_dut_error *e, char *buf, size_t size);

#endif /* EF_CLI_DUT_FILE_H */
