/*
 * fuzz_dut_file.c - libFuzzer target for the reader of `edgeflag gen
 * --dut-file` (cli/dut_file.c, docs/gen.md section 11): a board's identify
 * record or a Verilog/C file defining W_MAX, H_MAX, E_MAX and NS.
 *
 * The input is the file.  Properties (each aborts, so libFuzzer keeps the
 * input):
 *  - the same bytes read twice give the same limits or the same error;
 *  - a failure leaves the limits all 0, has a message, and names a place
 *    that exists: a line of the input and a column within it (plus one, for
 *    an error at the line's end), a field of a 48-byte record from "EFB1",
 *    or the whole file; its formatted line fits any buffer (ASan);
 *  - a success holds only what docs/gen.md allows: W_MAX and H_MAX both or
 *    neither, each 1..16384, E_MAX 1..2^31-1 or 0, sample bits 3-5 only, at
 *    least one limit;
 *  - a 48-byte record from "EFB1" is read as a reference written here from
 *    docs/board.md 3.1 says (accepted exactly when version 1, a sample bit,
 *    both sizes and E_MAX in range; the same fields);
 *  - text without `define, #define, parameter or localparam defines nothing;
 *  - a success written back as `define lines reads back to the same limits.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dut_file.h"
#include "edgeflag.h"
#include "fuzz_common.h"

static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static int contains(const uint8_t *d, size_t n, const char *w)
{
    const size_t k = strlen(w);
    for (size_t i = 0; i + k <= n; i++)
        if (!memcmp(d + i, w, k))
            return 1;
    return 0;
}

/* Line l (1-based) of d: its characters (UTF-8 continuation bytes not
 * counted, a CR before the LF not counted); -1 when there is no such line. */
static long line_chars(const uint8_t *d, size_t n, uint32_t l)
{
    size_t p = 0;
    for (uint32_t i = 1; i < l; i++) {
        while (p < n && d[p] != '\n')
            p++;
        if (p == n)
            return -1;
        p++;
    }
    size_t e = p;
    while (e < n && d[e] != '\n')
        e++;
    if (e > p && d[e - 1] == '\r')
        e--;
    long c = 0;
    for (size_t i = p; i < e; i++)
        c += (d[i] & 0xC0u) != 0x80u;
    return c;
}

static void check_limits(const ef_gen_limits *lim)
{
    if ((lim->width == 0) != (lim->height == 0))
        FUZZ_FAIL("one canvas size without the other: %" PRId32 "x%" PRId32, lim->width, lim->height);
    if (lim->width < 0 || lim->width > EF_MAX_CANVAS || lim->height < 0 || lim->height > EF_MAX_CANVAS)
        FUZZ_FAIL("canvas %" PRId32 "x%" PRId32 " out of range", lim->width, lim->height);
    if (lim->edges > INT32_MAX)
        FUZZ_FAIL("E_MAX %" PRIu32 " out of range", lim->edges);
    if (lim->samples_mask & ~0x38u)
        FUZZ_FAIL("sample bits 0x%" PRIx32 " outside bits 3-5", lim->samples_mask);
    if (!lim->width && !lim->edges && !lim->samples_mask)
        FUZZ_FAIL("a success that states no limit");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ef_gen_limits lim, lim2;
    ef_dut_error err, err2;
    char line[64];
    const int rc = ef_dut_file_parse(data, size, &lim, &err);
    const int rc2 = ef_dut_file_parse(data, size, &lim2, &err2);
    if (rc != rc2 || memcmp(&lim, &lim2, sizeof lim) != 0 ||
        (rc && (err.at != err2.at || err.line != err2.line || err.col != err2.col || err.offset != err2.offset ||
                strcmp(err.msg, err2.msg) != 0)))
        FUZZ_FAIL("two reads of the same bytes differ");
    const int record = size >= 4 && !memcmp(data, "EFB1", 4);

    if (rc) {
        if (lim.width || lim.height || lim.edges || lim.samples_mask)
            FUZZ_FAIL("a failure left limits behind");
        if (!err.msg[0] || strlen(err.msg) >= sizeof err.msg)
            FUZZ_FAIL("a failure without a message");
        switch (err.at) {
        case EF_DUT_AT_LINE: {
            const long c = line_chars(data, size, err.line);
            if (record || err.line < 1 || c < 0 || err.col < 1 || (long)err.col > c + 1)
                FUZZ_FAIL("error at %" PRIu32 ":%" PRIu32 ", not a place of the input (line has %ld characters): %s",
                          err.line, err.col, c, err.msg);
            break;
        }
        case EF_DUT_AT_RECORD:
            if (!record || size != 48 ||
                (err.offset != 4 && err.offset != 16 && err.offset != 20 && err.offset != 24 && err.offset != 28))
                FUZZ_FAIL("record error at byte offset %" PRIu32 " of a %zu-byte input", err.offset, size);
            break;
        case EF_DUT_AT_FILE: break;
        default: FUZZ_FAIL("unknown place %d", (int)err.at);
        }
        ef_dut_error_format("f", &err, line, sizeof line); /* truncated, never overflowed */
        if (strncmp(line, "f", 1) != 0)
            FUZZ_FAIL("formatted error does not start with the file name");
    } else {
        check_limits(&lim);
    }

    if (record && size == 48) { /* the reference, from docs/board.md 3.1 */
        const unsigned ver = data[4] | (unsigned)data[5] << 8;
        const uint32_t sm = le32(data + 16), w = le32(data + 20), h = le32(data + 24), e = le32(data + 28);
        const int ok = ver == 1 && (sm & 0x38u) && w >= 1 && w <= EF_MAX_CANVAS && h >= 1 && h <= EF_MAX_CANVAS &&
                       e >= 1 && e <= INT32_MAX;
        if (ok != !rc)
            FUZZ_FAIL("record: read %s, the reference says %s", rc ? "failed" : "succeeded", ok ? "valid" : "invalid");
        if (ok &&
            (lim.width != (int32_t)w || lim.height != (int32_t)h || lim.edges != e || lim.samples_mask != (sm & 0x38u)))
            FUZZ_FAIL("record: limits differ from the reference's");
    } else if (record) {
        if (!rc || err.at != EF_DUT_AT_FILE)
            FUZZ_FAIL("a %zu-byte input from \"EFB1\" is not a whole-file error", size);
    } else if (size <= EF_DUT_FILE_MAX && !contains(data, size, "define") && !contains(data, size, "parameter") &&
               !contains(data, size, "localparam")) {
        if (!rc || err.at != EF_DUT_AT_FILE)
            FUZZ_FAIL("text with no directive read as limits, or failed at a place");
    }

    if (!rc) { /* written back as `define lines, it reads back the same */
        char text[256];
        int n = 0;
        ef_gen_limits back;
        ef_dut_error eb;
        if (lim.width)
            n += snprintf(text + n, sizeof text - (size_t)n, "`define W_MAX %" PRId32 "\n`define H_MAX %" PRId32 "\n",
                          lim.width, lim.height);
        if (lim.edges)
            n += snprintf(text + n, sizeof text - (size_t)n, "`define E_MAX %" PRIu32 "\n", lim.edges);
        if (lim.samples_mask) {
            /* one count only in the text form: the lowest */
            const int ns = (lim.samples_mask & 8u) ? 8 : (lim.samples_mask & 16u) ? 16 : 32;
            n += snprintf(text + n, sizeof text - (size_t)n, "`define NS %d\n", ns);
        }
        if (ef_dut_file_parse((const unsigned char *)text, (size_t)n, &back, &eb) != 0)
            FUZZ_FAIL("its own `define lines do not read back: %s", eb.msg);
        if (back.width != lim.width || back.height != lim.height || back.edges != lim.edges ||
            (back.samples_mask & lim.samples_mask) != back.samples_mask || (!back.samples_mask != !lim.samples_mask))
            FUZZ_FAIL("the `define lines read back to other limits");
    }
    return 0;
}
