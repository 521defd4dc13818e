/*
 * test_vec_read.c - the readers of `edgeflag check` (rtl_vectors/ef_vec_read.h)
 * against words and streams written out by hand from docs/vectors.md
 * (sections 3, 4, 6): the CRC-32 check value, field positions of a pix and a
 * span word, the `$readmemh` leniencies (case, `_`, comments, CR LF) giving
 * the same transaction, every refusal at its line:col or record and byte
 * offset, a hand-built binary stream and its damage, the manifest's rules
 * (null members, escapes, names outside the folder, depth), and the file
 * reader's chunked streaming equal to the in-memory read across chunk
 * boundaries.  The CLI's behaviour is tests/check/run.sh.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ef_vec_read.h"

/* pix: cycle 5, y 3, x 2, alpha 0x80, rgba 0x11223344 (116 bits, 29 digits). */
static const char PIX_WORD[] = "000000000005000c0028011223344";
/* span: cycle 1000, y 7, x 12, len 5, mask 0xff (123 bits, 31 digits). */
static const char SPAN_WORD[] = "0000000001f4000e0060005000000ff";

static ef_status hex(const char *text, int want, int hint, ef_vec_dump *d, ef_vec_read_error *e)
{
    return ef_vec_read_hex("t.hex", (const uint8_t *)text, strlen(text), want, hint, d, e);
}

static void expect_error(const char *text, int want, int hint, ef_status st, uint64_t line, uint64_t col,
                         const char *msg_start)
{
    ef_vec_dump d;
    ef_vec_read_error e;
    ef_status got = hex(text, want, hint, &d, &e);
    if (got != st || e.at != EF_VEC_AT_LINE || e.line != line || e.col != col ||
        strncmp(e.msg, msg_start, strlen(msg_start)) != 0)
        fail_msg("'%s': status %d at %d %llu:%llu '%s', want %d at %llu:%llu '%s...'", text, (int)got, (int)e.at,
                 (unsigned long long)e.line, (unsigned long long)e.col, e.msg, (int)st, (unsigned long long)line,
                 (unsigned long long)col, msg_start);
    assert_int_equal(d.mask, 0);
}

static void test_crc32(void **state)
{
    (void)state;
    assert_int_equal(ef_vec_read_crc32(0, "123456789", 9), 0xCBF43926u);
    assert_int_equal(ef_vec_read_crc32(ef_vec_read_crc32(0, "1234", 4), "56789", 5), 0xCBF43926u);
    assert_int_equal(ef_vec_read_crc32(0, "", 0), 0);
}

static void test_pix_word_fields(void **state)
{
    ef_vec_dump d;
    ef_vec_read_error e;
    ef_txn t;
    char text[64];
    (void)state;
    snprintf(text, sizeof text, "%s\n", PIX_WORD);
    assert_int_equal(hex(text, -1, EF_IF_PIX, &d, &e), EF_OK);
    assert_int_equal(d.mask, 1u << EF_IF_PIX);
    assert_int_equal(d.seq[EF_IF_PIX].n, 1);
    assert_int_equal(d.seq[EF_IF_PIX].loc[0], 1);
    ef_vec_dump_txn(&d, EF_IF_PIX, 0, &t);
    assert_int_equal(t.cycle, 5);
    assert_int_equal(ef_txn_field(&t, 0), 3);    /* y */
    assert_int_equal(ef_txn_field(&t, 1), 2);    /* x */
    assert_int_equal(ef_txn_field(&t, 2), 0x80); /* alpha */
    assert_int_equal(ef_txn_field(&t, 3), 0x11223344u);
    ef_vec_dump_destroy(&d);
}

static void test_span_word_and_header(void **state)
{
    ef_vec_dump d;
    ef_vec_read_error e;
    ef_txn t;
    char text[512];
    (void)state;
    snprintf(text, sizeof text,
             "// edgeflag vectors format 1: interface span (FILL -> COV), role expected\n"
             "// generator edgeflag 0.1.0; input a b.svg; size 640x480; samples 16; rule scene; seed 0\n"
             "// word 123 bits: cycle[122:75] y[74:61] x[60:47] len[46:32] mask[31:0]\n"
             "// count 1\n%s\n",
             SPAN_WORD);
    assert_int_equal(hex(text, -1, -1, &d, &e), EF_OK);
    assert_true(d.has_header);
    assert_int_equal(d.width, 640);
    assert_int_equal(d.height, 480);
    assert_int_equal(d.samples, 16);
    assert_int_equal(d.seq[EF_IF_SPAN].loc[0], 5);
    ef_vec_dump_txn(&d, EF_IF_SPAN, 0, &t);
    assert_int_equal(t.cycle, 1000);
    assert_int_equal(ef_txn_field(&t, 0), 7);
    assert_int_equal(ef_txn_field(&t, 1), 12);
    assert_int_equal(ef_txn_field(&t, 2), 5);
    assert_int_equal(ef_txn_field(&t, 3), 0xff);
    ef_vec_dump_destroy(&d);
}

/* What `$readmemh` accepts reads to the same transaction. */
static void test_readmemh_leniency(void **state)
{
    static const char *const forms[] = {
        "000000000005000C0028011223344\n",
        "000000000005_000c_0028_0112_23344\r\n",
        "\n\n  /* a comment */ 000000000005000c0028011223344 // trailing\n",
        "/* multi\n line */\n000000000005000c0028011223344",
        "5000c0028011223344\n",                    /* leading zeros may be left out */
        "00000000000000000005000c0028011223344\n", /* or added: a 128-bit register's %h */
    };
    (void)state;
    for (size_t k = 0; k < sizeof forms / sizeof forms[0]; k++) {
        ef_vec_dump d;
        ef_vec_read_error e;
        ef_txn t;
        if (hex(forms[k], EF_IF_PIX, -1, &d, &e) != EF_OK)
            fail_msg("form %zu: %s", k, e.msg);
        assert_int_equal(d.seq[EF_IF_PIX].n, 1);
        ef_vec_dump_txn(&d, EF_IF_PIX, 0, &t);
        assert_int_equal(t.cycle, 5);
        assert_int_equal(ef_txn_field(&t, 3), 0x11223344u);
        ef_vec_dump_destroy(&d);
    }
}

static void test_hex_refusals(void **state)
{
    (void)state;
    expect_error("000000000005000c00280112233x4\n", EF_IF_PIX, -1, EF_ERR_SYNTAX, 1, 28, "unknown value");
    expect_error("\n  00000000000z\n", EF_IF_PIX, -1, EF_ERR_SYNTAX, 2, 14, "unknown value");
    expect_error("1000000000005000c0028011223344\n", EF_IF_PIX, -1, EF_ERR_RANGE, 1, 1, "too many digits");
    expect_error("8000000001f4000e0060005000000ff\n", EF_IF_SPAN, -1, EF_ERR_RANGE, 1, 1, "value too wide");
    expect_error("@0\n", EF_IF_PIX, -1, EF_ERR_UNSUPPORTED, 1, 1, "address specifiers");
    expect_error("0 /* open\n\n", EF_IF_PIX, -1, EF_ERR_SYNTAX, 1, 3, "unterminated /* comment");
    expect_error("0 / 1\n", EF_IF_PIX, -1, EF_ERR_SYNTAX, 1, 3, "invalid character '/'");
    expect_error("0g\n", EF_IF_PIX, -1, EF_ERR_SYNTAX, 1, 2, "invalid character in a hex word: 'g'");
    /* Columns count characters: the UTF-8 e-acute in the comment is one. */
    expect_error("/* \xc3\xa9 */ \x01", EF_IF_PIX, -1, EF_ERR_SYNTAX, 1, 9, "invalid character '\\x01'");
    expect_error("", EF_IF_PIX, -1, EF_ERR_SYNTAX, 1, 1, "empty file");
    expect_error("0\n", -1, -1, EF_ERR_SYNTAX, 1, 1, "cannot tell which interface");
    expect_error("// edgeflag vectors format 1: interface span (x)\n0\n", EF_IF_PIX, -1, EF_ERR_SYNTAX, 1, 41,
                 "the header names interface 'span', expected 'pix'");
    expect_error("// edgeflag vectors format 2: interface pix\n", -1, -1, EF_ERR_UNSUPPORTED, 1, 28,
                 "vector format 2 is not supported");
    expect_error("// edgeflag vectors format 1: interface pix\n// count 2\n0\n", -1, -1, EF_ERR_SYNTAX, 2, 10,
                 "the header says count 2, the file holds 1 words");
    expect_error("// edgeflag vectors format 1: interface pix\n// word 115 bits: x\n", -1, -1, EF_ERR_SYNTAX, 2, 9,
                 "malformed header");
    /* An RTL's own comment that merely looks like a header line is not one. */
    ef_vec_dump d;
    ef_vec_read_error e;
    assert_int_equal(hex("// count 7 pixels\n0\n", EF_IF_PIX, -1, &d, &e), EF_OK);
    ef_vec_dump_destroy(&d);
    /* A dump of nothing that says so is fine. */
    assert_int_equal(hex("// no transactions\n", EF_IF_PIX, -1, &d, &e), EF_OK);
    assert_int_equal(d.mask, 1u << EF_IF_PIX);
    assert_int_equal(d.seq[EF_IF_PIX].n, 0);
    ef_vec_dump_destroy(&d);
}

static void put_le(uint8_t *p, unsigned n, uint64_t v)
{
    for (unsigned i = 0; i < n; i++)
        p[i] = (uint8_t)(v >> (8 * i) & 0xffu);
}

/* A stream of two pix records (cycles 5 and 9), as section 4 lays it out. */
static size_t build_bin(uint8_t *b)
{
    memset(b, 0, 104 + 2 * 19);
    memcpy(b,
           "\x89"
           "EFV\r\n\x1a\n",
           8);
    put_le(b + 8, 2, 1);
    put_le(b + 10, 2, 104);
    b[12] = 8;
    b[13] = 2;
    put_le(b + 16, 4, 6);
    put_le(b + 20, 4, 4);
    put_le(b + 32, 4, 1u << EF_IF_PIX);
    put_le(b + 40 + 8 * EF_IF_PIX, 8, 2);
    for (unsigned r = 0; r < 2; r++) {
        uint8_t *p = b + 104 + 19 * r;
        p[0] = EF_IF_PIX;
        p[1] = 9; /* ceil(68 / 8) */
        put_le(p + 2, 8, r ? 9 : 5);
        put_le(p + 10, 8, UINT64_C(0x0c0028011223344) + r); /* y 3, x 2, alpha 0x80, rgba */
    }
    put_le(b + 96, 4, ef_vec_read_crc32(0, b + 104, 38));
    put_le(b + 100, 4, ef_vec_read_crc32(0, b, 100));
    return 104 + 38;
}

static void expect_bin_error(const uint8_t *b, size_t n, ef_vec_at at, uint64_t record, uint64_t offset,
                             const char *msg_start)
{
    ef_vec_dump d;
    ef_vec_read_error e;
    ef_status st = ef_vec_read_bin("t.bin", b, n, &d, &e);
    if (st == EF_OK || e.at != at || e.record != record || e.offset != offset ||
        strncmp(e.msg, msg_start, strlen(msg_start)) != 0)
        fail_msg("status %d at %d record %llu offset %llu '%s', want '%s...'", (int)st, (int)e.at,
                 (unsigned long long)e.record, (unsigned long long)e.offset, e.msg, msg_start);
    assert_int_equal(d.mask, 0);
}

static void test_binary(void **state)
{
    uint8_t b[200], c[200];
    ef_vec_dump d;
    ef_vec_read_error e;
    ef_txn t;
    char buf[512];
    (void)state;
    size_t n = build_bin(b);
    assert_int_equal(ef_vec_read_bin("t.bin", b, n, &d, &e), EF_OK);
    assert_int_equal(d.width, 6);
    assert_int_equal(d.seq[EF_IF_PIX].n, 2);
    assert_int_equal(d.seq[EF_IF_PIX].loc[1], 2);
    assert_int_equal(d.seq[EF_IF_PIX].off[1], 123);
    ef_vec_dump_txn(&d, EF_IF_PIX, 1, &t);
    assert_int_equal(t.cycle, 9);
    assert_int_equal(ef_txn_field(&t, 0), 3);
    assert_int_equal(ef_txn_field(&t, 3), 0x11223345u);
    ef_vec_dump_destroy(&d);

    memcpy(c, b, n);
    c[3] = 'X';
    expect_bin_error(c, n, EF_VEC_AT_HEADER, 0, 0, "bad magic: not an edgeflag");
    expect_bin_error(b, 60, EF_VEC_AT_HEADER, 0, 60, "truncated header: 60 of 104");
    expect_bin_error(b, n - 1, EF_VEC_AT_RECORD, 2, 123, "truncated record: 18 of 19 bytes");
    expect_bin_error(b, n - 19, EF_VEC_AT_END, 1, 123, "the header counts 2 pix records, the stream holds 1");
    memcpy(c, b, n);
    c[104 + 12] ^= 1;
    expect_bin_error(c, n, EF_VEC_AT_HEADER, 0, 96, "records CRC mismatch");
    memcpy(c, b, n);
    c[20] = 5;
    expect_bin_error(c, n, EF_VEC_AT_HEADER, 0, 100, "header CRC mismatch");
    memcpy(c, b, n);
    c[104 + 19 + 1] = 8;
    expect_bin_error(c, n, EF_VEC_AT_RECORD, 2, 123, "payload length 8, interface pix has 9 bytes");
    memcpy(c, b, n);
    c[104 + 18] = 0x10; /* bit 68 of record 1's payload */
    put_le(c + 96, 4, ef_vec_read_crc32(0, c + 104, 38));
    put_le(c + 100, 4, ef_vec_read_crc32(0, c, 100));
    expect_bin_error(c, n, EF_VEC_AT_RECORD, 1, 104, "payload bits above bit 67");

    ef_vec_read_error_format(&e, buf, sizeof buf);
    e.at = EF_VEC_AT_RECORD;
    e.record = 3;
    e.offset = 77;
    snprintf(e.file, sizeof e.file, "v.bin");
    snprintf(e.msg, sizeof e.msg, "m");
    ef_vec_read_error_format(&e, buf, sizeof buf);
    assert_string_equal(buf, "v.bin: record 3 (byte offset 77): m");
}

static ef_status manifest(const char *text, ef_vec_manifest *m, ef_vec_read_error *e)
{
    return ef_vec_read_manifest("manifest.json", (const uint8_t *)text, strlen(text), m, e);
}

static void test_manifest(void **state)
{
    ef_vec_manifest m;
    ef_vec_read_error e;
    (void)state;
    assert_int_equal(manifest("{ \"width\": 160, \"height\": 120, \"interfaces\": [ { \"name\": \"cmd\" } ],\n"
                              "  \"files\": [ { \"name\": \"pix.expected.hex\", \"format\": \"hex\", \"interface\": "
                              "\"pix\", \"role\": \"expected\", \"count\": 12, \"sha256\": \"ab\" },\n"
                              "    { \"name\": \"vectors.vcd\", \"interface\": null, \"extra\": [1.5e3, true, {}] },\n"
                              "    { \"name\": \"caf\\u00e9\\ud83d\\ude00.hex\" } ] }",
                              &m, &e),
                     EF_OK);
    assert_int_equal(m.width, 160);
    assert_int_equal(m.nfiles, 3);
    assert_string_equal(m.files[0].name, "pix.expected.hex");
    assert_int_equal(m.files[0].iface, EF_IF_PIX);
    assert_true(m.files[0].has_count && m.files[0].count == 12);
    assert_int_equal(m.files[2].index, 2);
    assert_int_equal(m.files[1].iface, -1);
    assert_string_equal(m.files[2].name, "caf\xc3\xa9\xf0\x9f\x98\x80.hex");
    ef_vec_manifest_destroy(&m);

    /* line 0: a value refused after parsing, named by its key (FILE: KEY: ...);
     * else a syntax error at LINE:COL. */
    static const struct {
        const char *text;
        uint64_t line, col;
        const char *msg;
    } bad[] = {
        { "{ \"files\": [ { \"name\": \"../x.hex\" } ] }", 0, 0,
          "files[0].name: manifest names a file outside its folder" },
        { "{ \"files\": [ { \"name\": \"a/b.hex\" } ] }", 0, 0,
          "files[0].name: manifest names a file outside its folder" },
        { "{ \"files\": [ { \"name\": \"a\\u0000b\" } ] }", 0, 0,
          "files[0].name: manifest names a file outside its folder: 'a\\x00b'" },
        { "{ \"files\": [ { \"name\": \"ok\" }, { \"format\": \"hex\" } ] }", 0, 0,
          "files[1]: a file entry without a \"name\"" },
        { "{ \"files\": [ 1 ] }", 0, 0, "files[0]: a file entry (an object) expected" },
        { "{ \"files\": { } }", 0, 0, "files: an array expected" },
        { "{ \"files\": [ { \"name\": \"a\", \"interface\": \"foo\" } ] }", 0, 0,
          "files[0].interface: unknown interface 'foo'" },
        { "{ \"files\": [ { \"name\": \"a\", \"count\": -1 } ] }", 0, 0,
          "files[0].count: a file's count must be an integer 0..2^64-1" },
        { "{ \"files\": [ { \"name\": \"a\", \"count\": 1.5 } ] }", 0, 0,
          "files[0].count: a file's count must be an integer 0..2^64-1" },
        { "{ \"files\": [ { \"name\": \"a\", \"role\": 3 } ] }", 0, 0, "files[0].role: a string or null expected" },
        { "{ \"width\": 0 }", 0, 0, "width: must be an integer 1..16384" },
        { "{ \"height\": \"1\" }", 0, 0, "height: must be an integer 1..16384" },
        { "{ \"x\": 1 } x", 1, 12, "the end of the file expected, 'x' found" },
        { "{ \"x\": 1,\n  }", 2, 3, "JSON: unexpected character, '}' found" },
        { "{ \"x\": [1 2] }", 1, 11, "JSON: array value separator ',' expected, '2' found" },
        { "{ \"x\": 1", 1, 9, "JSON: unexpected end of file (the manifest is cut short), end of file found" },
        { "[]", 1, 1, "the manifest object '{' expected, '[' found" },
        { "  ", 1, 3, "the manifest object '{' expected, end of file found" },
        { "{ \"\xc3\xa9\": \"\xff\" }", 1, 9, "JSON: invalid utf-8 string, '\\xff' found" },
        { "{ \"x\": /* c */ 1 }", 1, 8, "JSON: unexpected character, '/' found" },
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        ef_status st = manifest(bad[k].text, &m, &e);
        int where_ok = bad[k].line ? e.at == EF_VEC_AT_LINE && e.line == bad[k].line && e.col == bad[k].col
                                   : e.at == EF_VEC_AT_FILE;
        if (st == EF_OK || !where_ok || strncmp(e.msg, bad[k].msg, strlen(bad[k].msg)) != 0)
            fail_msg("'%s': %d at %llu:%llu '%s', want %llu:%llu '%s'", bad[k].text, (int)st,
                     (unsigned long long)e.line, (unsigned long long)e.col, e.msg, (unsigned long long)bad[k].line,
                     (unsigned long long)bad[k].col, bad[k].msg);
        assert_int_equal(m.nfiles, 0);
    }
    /* A NUL byte (json-c would end its input there) is refused at its place. */
    static const char nul[] = "{ \"x\": \"a\0b\" }";
    assert_int_equal(ef_vec_read_manifest("manifest.json", (const uint8_t *)nul, sizeof nul - 1, &m, &e),
                     EF_ERR_SYNTAX);
    assert_true(e.line == 1 && e.col == 10 && strncmp(e.msg, "JSON: a NUL byte", 16) == 0);
    static const char nul_after[] = "{ }\n\0";
    assert_int_equal(ef_vec_read_manifest("manifest.json", (const uint8_t *)nul_after, sizeof nul_after - 1, &m, &e),
                     EF_ERR_SYNTAX);
    assert_true(e.line == 2 && e.col == 1 && strncmp(e.msg, "the end of the file expected", 28) == 0);
    /* Counts and sizes beyond 32 bits, up to 2^64 - 1, are read exactly. */
    assert_int_equal(manifest("{ \"files\": [ { \"name\": \"a\", \"count\": 18446744073709551615 },"
                              " { \"name\": \"b\", \"count\": 9223372036854775808 } ] }",
                              &m, &e),
                     EF_OK);
    assert_true(m.files[0].count == UINT64_MAX && m.files[1].count == UINT64_C(9223372036854775808));
    ef_vec_manifest_destroy(&m);
    char deep[200];
    memset(deep, '[', 100);
    snprintf(deep + 100, sizeof deep - 100, "%s", "");
    char text[256];
    snprintf(text, sizeof text, "{ \"x\": %s", deep);
    assert_int_equal(manifest(text, &m, &e), EF_ERR_SYNTAX);
    assert_string_equal(e.msg, "nested deeper than 64 levels");
}

/* The file reader streams in chunks: a dump larger than one chunk, with
 * words and comments across chunk boundaries, reads as in memory. */
static void test_streaming(void **state)
{
    (void)state;
    size_t cap = 200000, n = 0;
    char *text = malloc(cap);
    assert_non_null(text);
    n += (size_t)snprintf(text + n, cap - n, "// edgeflag vectors format 1: interface pix (COV -> memory)\n");
    for (unsigned k = 0; n + 80 < cap; k++) {
        if (k % 7 == 0) /* comments of both kinds between and after words */
            n += (size_t)snprintf(text + n, cap - n, "/* %u */ ", k);
        n += (size_t)snprintf(text + n, cap - n, "%012x%017x%s\n", k, 0x1234u + k, k % 7 ? "" : " // c");
    }
    FILE *f = fmemopen(text, n, "rb");
    assert_non_null(f);
    ef_vec_dump a, b;
    ef_vec_read_error e;
    assert_int_equal(ef_vec_read_fp(f, "s.hex", 0, -1, -1, &a, &e), EF_OK);
    fclose(f);
    assert_int_equal(ef_vec_read_hex("s.hex", (const uint8_t *)text, n, -1, -1, &b, &e), EF_OK);
    assert_true(a.seq[EF_IF_PIX].n > 5000);
    assert_int_equal(a.seq[EF_IF_PIX].n, b.seq[EF_IF_PIX].n);
    assert_memory_equal(a.seq[EF_IF_PIX].pay, b.seq[EF_IF_PIX].pay, a.seq[EF_IF_PIX].n * 16);
    assert_memory_equal(a.seq[EF_IF_PIX].loc, b.seq[EF_IF_PIX].loc, a.seq[EF_IF_PIX].n * 8);
    ef_vec_dump_destroy(&a);
    ef_vec_dump_destroy(&b);
    free(text);
}

static void test_iface_from_name(void **state)
{
    (void)state;
    assert_int_equal(ef_vec_iface_from_name("dir/pix.actual.hex"), EF_IF_PIX);
    assert_int_equal(ef_vec_iface_from_name("et_wr.expected.hex"), EF_IF_ET_WR);
    assert_int_equal(ef_vec_iface_from_name("pixel.hex"), -1);
    assert_int_equal(ef_vec_iface_from_name("a.pix/span"), EF_IF_SPAN);
    assert_int_equal(ef_vec_iface_from_name(""), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crc32),
        cmocka_unit_test(test_pix_word_fields),
        cmocka_unit_test(test_span_word_and_header),
        cmocka_unit_test(test_readmemh_leniency),
        cmocka_unit_test(test_hex_refusals),
        cmocka_unit_test(test_binary),
        cmocka_unit_test(test_manifest),
        cmocka_unit_test(test_streaming),
        cmocka_unit_test(test_iface_from_name),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
