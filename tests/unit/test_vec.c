/*
 * test_vec.c - the vector writers of rtl_vectors/ (ef_vec.h, docs/vectors.md)
 * on hand-built transactions: CRC-32 and SHA-256 against published values
 * (FIPS 180-4's examples, the CRC catalogue's check value) and against
 * Python's hashlib/zlib for the block-boundary lengths, hex word layout
 * including fields that straddle 64-bit words and negative fields, the
 * collector's refusals, the merge order (cycle, then interface), the binary
 * header byte by byte, a complete small VCD, the manifest's JSON escaping
 * and the `# seed N` reader.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ef_vec.h"
#include "ef_vec_read.h" /* EF_VEC_FMT_* of the table's readers */

/* ------------------------------------------------------------ helpers */

static ef_txn txn(int iface, uint64_t cycle, const int64_t *fields)
{
    ef_txn t;
    memset(&t, 0, sizeof t);
    t.iface = (uint8_t)iface;
    t.cycle = cycle;
    for (unsigned k = 0; k < ef_iface_get(iface)->nfields; k++)
        ef_txn_set_field(&t, k, (uint64_t)fields[k]);
    return t;
}

/* Runs a writer into memory; returns the bytes (caller frees), *n their count. */
typedef void (*writer_fn)(ef_vec_out *o, const void *arg);
static char *capture(writer_fn fn, const void *arg, size_t *n, ef_vec_out *keep)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *fp = open_memstream(&buf, &len);
    ef_vec_out *o = malloc(sizeof *o);
    assert_non_null(fp);
    assert_non_null(o);
    ef_vec_out_init(o, fp, EF_VEC_OUT_SHA | EF_VEC_OUT_CRC);
    fn(o, arg);
    assert_int_equal(ef_vec_out_finish(o, NULL), 0);
    assert_int_equal(fclose(fp), 0);
    assert_true(o->bytes == len);
    if (keep)
        *keep = *o;
    free(o);
    *n = len;
    return buf;
}

static void sha_hex(const void *data, size_t n, char out[65])
{
    ef_vec_sha256 s;
    uint8_t d[32];
    ef_vec_sha256_init(&s);
    ef_vec_sha256_update(&s, data, n);
    ef_vec_sha256_final(&s, d);
    ef_vec_sha256_hex(d, out);
}

/* ------------------------------------------------------------ CRC-32 */

static void test_crc32(void **state)
{
    const char *fox = "The quick brown fox jumps over the lazy dog";
    uint8_t all[768];
    uint32_t c = 0;
    (void)state;
    assert_true(ef_vec_crc32(0, "123456789", 9) == UINT32_C(0xCBF43926)); /* the catalogue's check */
    assert_true(ef_vec_crc32(0, "", 0) == 0);
    assert_true(ef_vec_crc32(0, fox, strlen(fox)) == UINT32_C(0x414FA339));
    for (int i = 0; i < 768; i++)
        all[i] = (uint8_t)i;
    assert_true(ef_vec_crc32(0, all, sizeof all) == UINT32_C(0xB0C0DF2A)); /* zlib.crc32 */
    for (size_t i = 0; i < sizeof all; i += 7)                             /* chained in pieces */
        c = ef_vec_crc32(c, all + i, sizeof all - i < 7 ? sizeof all - i : 7);
    assert_true(c == UINT32_C(0xB0C0DF2A));
}

/* ------------------------------------------------------------ SHA-256 */

static void test_sha256_fips(void **state)
{
    char h[65];
    (void)state;
    /* FIPS 180-4 examples (NIST CSRC "Examples with intermediate values"). */
    sha_hex("abc", 3, h);
    assert_string_equal(h, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    sha_hex("", 0, h);
    assert_string_equal(h, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    sha_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq", 56, h);
    assert_string_equal(h, "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    sha_hex("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsm"
            "nopqrstnopqrstu",
            112, h);
    assert_string_equal(h, "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
}

static void test_sha256_million_a(void **state)
{
    ef_vec_sha256 s;
    uint8_t d[32];
    char h[65], a[1000];
    size_t done = 0, step = 1;
    (void)state;
    memset(a, 'a', sizeof a);
    ef_vec_sha256_init(&s);
    while (done < 1000000) { /* uneven pieces: 1, 2, ... 999 bytes */
        size_t n = step < 1000000 - done ? step : 1000000 - done;
        ef_vec_sha256_update(&s, a, n);
        done += n;
        step = step % 999 + 1;
    }
    ef_vec_sha256_final(&s, d);
    ef_vec_sha256_hex(d, h);
    assert_string_equal(h, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

/* Lengths around the padding's boundaries (55/56 bytes need one or two final
 * blocks), against Python's hashlib, whole and byte by byte. */
static void test_sha256_boundaries(void **state)
{
    static const struct {
        size_t n;
        const char *hex;
    } v[] = {
        { 55, "e7313d333c272e639f790978283f9eb392e843d0f29b7016828bb1daa4aac70b" },
        { 56, "4324d65f3c103567f5589c710bc08f8523f929a9272e3af36fc968e52abc6c27" },
        { 63, "81c80242132f230c3bd41b3e63bbcff16107339549214a99614ff26664625055" },
        { 64, "39e3d7b6b5d075d37d053ad89b24b41bef4f3c29760c84447cab3f3be1882241" },
        { 65, "aacca6ff74fdbb296d165a45cecfa04e5127bc008770fbbdd48006f2d2fae95e" },
        { 119, "9ce7368e4daf32341631b492e80359dc9f594b48453cd0dd5bf0b19279cc177e" },
        { 120, "7836b787757e95e58b3ca5aec90b1b004e8deba1e50e9675af9cabf1a13a04b5" },
        { 1000, "1e9bc38cbf860b9ec31918b065f9b52476c549a782e0e7990bed8ce3868d2371" },
    };
    uint8_t data[1000];
    (void)state;
    for (size_t i = 0; i < sizeof data; i++)
        data[i] = (uint8_t)((i * 7 + 3) & 255);
    for (size_t k = 0; k < sizeof v / sizeof v[0]; k++) {
        char h[65];
        ef_vec_sha256 s;
        uint8_t d[32];
        sha_hex(data, v[k].n, h);
        assert_string_equal(h, v[k].hex);
        ef_vec_sha256_init(&s);
        for (size_t i = 0; i < v[k].n; i++)
            ef_vec_sha256_update(&s, data + i, 1);
        ef_vec_sha256_final(&s, d);
        ef_vec_sha256_hex(d, h);
        assert_string_equal(h, v[k].hex);
    }
}

/* ------------------------------------------------------------ hex words */

static void test_hex_digits(void **state)
{
    /* ceil((48 + P) / 4) for P = 100, 97, 181, 36, 36, 75, 68 */
    static const unsigned want[EF_IF_COUNT] = { 37, 37, 58, 21, 21, 31, 29 };
    (void)state;
    for (int i = 0; i < EF_IF_COUNT; i++)
        assert_int_equal(ef_vec_hex_digits(i), want[i]);
    assert_int_equal(ef_vec_hex_digits(EF_IF_COUNT), 0);
}

static void test_hex_word(void **state)
{
    char w[EF_VEC_HEX_MAX_DIGITS + 1];
    (void)state;
    /* Expected words computed independently (Python big integers). */
    ef_txn span = txn(EF_IF_SPAN, UINT64_C(0x123456789abc), (const int64_t[]){ 0x1234, 0xabc, 0x7fff, 0xdeadbeef });
    assert_int_equal(ef_vec_hex_word(&span, w), 31);
    assert_string_equal(w, "091a2b3c4d5e246855e7fffdeadbeef");
    /* et_wr: 181 bits, fields across both 64-bit boundaries, negative x and qs,
     * the largest cycle. */
    ef_txn et = txn(EF_IF_ET_WR, UINT64_C(0xffffffffffff),
                    (const int64_t[]){ 0, 16383, 0x7ffff, 5, -3, 0xabcdef, -(INT64_C(1) << 29), 1, 0xffffff, 1 });
    assert_int_equal(ef_vec_hex_word(&et, w), 58);
    assert_string_equal(w, "1fffffffffffeffffffff80005fffffed5e6f7c0000000000003ffffff");
    ef_txn cmd = txn(EF_IF_CMD, 0, (const int64_t[]){ 3, -1, 0x7fffff, -0x800000, 0 });
    assert_int_equal(ef_vec_hex_word(&cmd, w), 37);
    assert_string_equal(w, "0000000000003ffffff7fffff800000000000");
    ef_txn plot = txn(EF_IF_PLOT, 7, (const int64_t[]){ 1, 2, 3, 4, 1 });
    assert_int_equal(ef_vec_hex_word(&plot, w), 21);
    assert_string_equal(w, "000000000007800430009");
}

/* ------------------------------------------------------------ collector, merge */

static void test_collect_refuses(void **state)
{
    ef_vec_collect c;
    ef_txn t;
    (void)state;

    ef_vec_collect_create(&c, EF_IF_ALL);
    t = txn(EF_IF_PLOT, 5, (const int64_t[]){ 0, 1, 2, 3, 0 });
    assert_int_equal(ef_vec_collect_add(&c, &t), EF_OK);
    t.cycle = 5; /* second transfer in one cycle */
    assert_int_equal(ef_vec_collect_add(&c, &t), EF_ERR_ARG);
    assert_non_null(strstr(c.why, "plot transaction at cycle 5"));
    t.cycle = 9; /* dropped after the first failure */
    assert_int_equal(ef_vec_collect_add(&c, &t), EF_ERR_ARG);
    assert_int_equal(ef_vec_collect_count(&c, EF_IF_PLOT), 1);
    ef_vec_collect_destroy(&c);

    ef_vec_collect_create(&c, EF_IF_ALL);
    t.cycle = UINT64_C(1) << 48;
    assert_int_equal(ef_vec_collect_add(&c, &t), EF_ERR_ARG);
    ef_vec_collect_destroy(&c);

    ef_vec_collect_create(&c, EF_IF_ALL);
    t.cycle = 1;
    t.w[0] |= UINT64_C(1) << 36; /* above plot's 36 bits */
    assert_int_equal(ef_vec_collect_add(&c, &t), EF_ERR_ARG);
    ef_vec_collect_destroy(&c);

    ef_vec_collect_create(&c, 1u << EF_IF_PIX); /* plot not enabled */
    t = txn(EF_IF_PLOT, 5, (const int64_t[]){ 0, 1, 2, 3, 0 });
    assert_int_equal(ef_vec_collect_add(&c, &t), EF_ERR_ARG);
    ef_vec_collect_destroy(&c);
}

static void test_merge_order(void **state)
{
    /* Arrival interleaves interfaces; each interface is in cycle order. */
    static const struct {
        int iface;
        uint64_t cycle;
    } in[] = {
        { EF_IF_PIX, 5 }, { EF_IF_CMD, 0 }, { EF_IF_SPAN, 5 },  { EF_IF_PIX, 6 },  { EF_IF_PLOT, 3 },
        { EF_IF_CMD, 5 }, { EF_IF_CMD, 6 }, { EF_IF_ET_RD, 2 }, { EF_IF_PLOT, 4 },
    };
    static const struct {
        int iface;
        uint64_t cycle;
    } want[] = {
        { EF_IF_CMD, 0 },  { EF_IF_ET_RD, 2 }, { EF_IF_PLOT, 3 }, { EF_IF_PLOT, 4 }, { EF_IF_CMD, 5 },
        { EF_IF_SPAN, 5 }, { EF_IF_PIX, 5 },   { EF_IF_CMD, 6 },  { EF_IF_PIX, 6 },
    };
    static const int64_t zero[EF_IF_MAX_FIELDS] = { 0 };
    ef_vec_collect c;
    ef_vec_merge m;
    ef_txn t;
    size_t k = 0;
    (void)state;

    ef_vec_collect_create(&c, EF_IF_ALL);
    for (size_t i = 0; i < sizeof in / sizeof in[0]; i++) {
        t = txn(in[i].iface, in[i].cycle, zero);
        t.w[0] = i; /* tag: which arrival */
        assert_int_equal(ef_vec_collect_add(&c, &t), EF_OK);
    }
    ef_vec_merge_init(&m, &c, EF_IF_ALL);
    while (ef_vec_merge_next(&m, &t)) {
        assert_true(k < sizeof want / sizeof want[0]);
        assert_int_equal(t.iface, want[k].iface);
        assert_true(t.cycle == want[k].cycle);
        k++;
    }
    assert_int_equal(k, sizeof want / sizeof want[0]);
    /* A mask leaves interfaces out of the merge. */
    ef_vec_merge_init(&m, &c, 1u << EF_IF_PIX | 1u << EF_IF_CMD);
    k = 0;
    while (ef_vec_merge_next(&m, &t))
        k++;
    assert_int_equal(k, 5);
    assert_true(ef_vec_collect_total(&c, EF_IF_ALL) == 9);
    assert_true(ef_vec_collect_end(&c, EF_IF_ALL) == 7);
    assert_true(ef_vec_collect_end(&c, 1u << EF_IF_PLOT) == 5);
    ef_vec_collect_destroy(&c);
}

/* ------------------------------------------------------------ files */

typedef struct run {
    ef_vec_info info;
    ef_vec_collect c;
} run;

static void small_run(run *r, uint32_t mask)
{
    static const int64_t rd[][2] = { { 1, 2 }, { 1, 3 }, { 5, 3 } };
    static const uint64_t cyc[] = { 0, 1, 3 };
    memset(r, 0, sizeof *r);
    r->info.input = "a$b.scene";
    r->info.width = 7;
    r->info.height = 5;
    r->info.samples = 8;
    r->info.rule = EF_RULE_EVENODD;
    r->info.seed = 42;
    r->info.cycles = 4;
    r->info.mask = mask;
    ef_vec_collect_create(&r->c, mask);
    for (int i = 0; i < 3; i++) {
        ef_txn t = txn(EF_IF_ET_RD, cyc[i], rd[i]);
        assert_int_equal(ef_vec_collect_add(&r->c, &t), EF_OK);
    }
}

static void write_vcd(ef_vec_out *o, const void *arg)
{
    const run *r = arg;
    ef_vec_vcd_write(o, &r->info, &r->c);
}

static void test_vcd_small(void **state)
{
    run r;
    size_t n;
    char *got;
    (void)state;
    small_run(&r, 1u << EF_IF_ET_RD);
    got = capture(write_vcd, &r, &n, NULL);
    assert_string_equal(got, "$comment\n"
                             "  edgeflag vectors format 1\n"
                             "  generator edgeflag " EF_VERSION_STRING "; input a\\x24b.scene; size 7x5; samples 8; "
                             "rule evenodd; seed 42\n"
                             "  cycles 4; cycle c: clk falls at 10c ns, rises (transfers) at 10c+5 ns\n"
                             "$end\n"
                             "$version\n  edgeflag " EF_VERSION_STRING "\n$end\n"
                             "$timescale 1ns $end\n"
                             "$scope module edgeflag $end\n"
                             "$var wire 1 ! clk $end\n"
                             "$scope module et_rd $end\n"
                             "$var wire 1 \" valid $end\n"
                             "$var wire 1 # ready $end\n"
                             "$var wire 14 % row [13:0] $end\n"
                             "$var wire 22 & eid [21:0] $end\n"
                             "$upscope $end\n"
                             "$upscope $end\n"
                             "$enddefinitions $end\n"
                             "#0\n$dumpvars\n0!\n1\"\n1#\nb1 %\nb10 &\n$end\n#5\n1!\n"
                             "#10\n0!\nb11 &\n#15\n1!\n" /* same row: only eid changes */
                             "#20\n0!\n0\"\n#25\n1!\n"   /* idle: valid drops, fields hold */
                             "#30\n0!\n1\"\nb101 %\n#35\n1!\n"
                             "#40\n0!\n0\"\n"); /* the end: 10 * cycles */
    free(got);
    ef_vec_collect_destroy(&r.c);
}

static void write_hex(ef_vec_out *o, const void *arg)
{
    const run *r = arg;
    ef_vec_hex_write(o, &r->info, &r->c, EF_IF_ET_RD);
}

static void test_hex_file(void **state)
{
    run r;
    size_t n;
    char *got, name[32];
    (void)state;
    small_run(&r, 1u << EF_IF_ET_RD);
    got = capture(write_hex, &r, &n, NULL);
    assert_string_equal(got, "// edgeflag vectors format 1: interface et_rd (ETM -> AET), role expected\n"
                             "// generator edgeflag " EF_VERSION_STRING "; input a\\x24b.scene; size 7x5; "
                             "samples 8; rule evenodd; seed 42\n"
                             "// word 84 bits: cycle[83:36] row[35:22] eid[21:0]\n"
                             "// count 3\n"
                             "000000000000000400002\n"
                             "000000000001000400003\n"
                             "000000000003001400003\n");
    free(got);
    assert_string_equal(ef_vec_hex_name(EF_IF_CMD, name, sizeof name), "cmd.stim.hex");
    assert_string_equal(ef_vec_hex_name(EF_IF_PIX, name, sizeof name), "pix.expected.hex");
    ef_vec_collect_destroy(&r.c);
}

static void write_bin(ef_vec_out *o, const void *arg)
{
    const run *r = arg;
    ef_vec_bin_write(o, &r->info, &r->c);
}

static uint64_t le(const unsigned char *p, int n)
{
    uint64_t v = 0;
    for (int i = n - 1; i >= 0; i--)
        v = v << 8 | p[i];
    return v;
}

static void test_bin(void **state)
{
    static const unsigned char magic[8] = { 0x89, 0x45, 0x46, 0x56, 0x0d, 0x0a, 0x1a, 0x0a };
    run r;
    size_t n;
    unsigned char *b;
    (void)state;
    small_run(&r, 1u << EF_IF_ET_RD | 1u << EF_IF_PIX); /* pix recorded, but empty */
    b = (unsigned char *)capture(write_bin, &r, &n, NULL);
    assert_int_equal(n, 104 + 3 * (10 + 5)); /* et_rd: 36 bits, 5 bytes */
    assert_memory_equal(b, magic, 8);
    assert_true(le(b + 8, 2) == 1 && le(b + 10, 2) == 104);
    assert_true(b[12] == 8 && b[13] == 1 && le(b + 14, 2) == 0);
    assert_true(le(b + 16, 4) == 7 && le(b + 20, 4) == 5 && le(b + 24, 8) == 42);
    assert_true(le(b + 32, 4) == (1u << EF_IF_ET_RD | 1u << EF_IF_PIX) && le(b + 36, 4) == 0);
    for (int i = 0; i < EF_IF_COUNT; i++)
        assert_true(le(b + 40 + 8 * i, 8) == (i == EF_IF_ET_RD ? 3u : 0u));
    assert_true(le(b + 96, 4) == ef_vec_crc32(0, b + 104, n - 104));
    assert_true(le(b + 100, 4) == ef_vec_crc32(0, b, 100));
    /* The third record: et_rd at cycle 3, row 5, eid 3 = payload 5 << 22 | 3. */
    const unsigned char *rec = b + 104 + 2 * 15;
    assert_true(rec[0] == EF_IF_ET_RD && rec[1] == 5 && le(rec + 2, 8) == 3);
    assert_true(le(rec + 10, 5) == (UINT64_C(5) << 22 | 3));
    free(b);
    ef_vec_collect_destroy(&r.c);
}

typedef struct mrun {
    run r;
    ef_vec_file f[1];
} mrun;

static void write_manifest(ef_vec_out *o, const void *arg)
{
    const mrun *m = arg;
    ef_vec_manifest_write(o, &m->r.info, &m->r.c, m->f, 1);
}

static void test_manifest(void **state)
{
    mrun m;
    size_t n;
    char *got;
    (void)state;
    small_run(&m.r, 1u << EF_IF_ET_RD);
    /* quote, backslash, control characters, DEL, U+00E9 in UTF-8, a stray
     * byte; the largest seed (json-c prints it exactly) */
    m.r.info.input = "q\"b\\s\x01\t\x7f\xc3\xa9\xff.svg";
    m.r.info.seed = UINT64_MAX;
    memset(m.f, 0, sizeof m.f);
    strcpy(m.f[0].name, "et_rd.expected.hex");
    m.f[0].format = "hex";
    m.f[0].iface = EF_IF_ET_RD;
    m.f[0].role = "expected";
    m.f[0].count = 3;
    m.f[0].bytes = 99;
    strcpy(m.f[0].sha256, "00");
    got = capture(write_manifest, &m, &n, NULL);
    assert_string_equal(got, "{\n"
                             "  \"format\": \"edgeflag-vectors\",\n"
                             "  \"version\": 1,\n"
                             "  \"generator\": \"edgeflag " EF_VERSION_STRING "\",\n"
                             "  \"input\": \"q\\\"b\\\\s\\u0001\\t\x7f\xc3\xa9\xef\xbf\xbd.svg\",\n"
                             "  \"width\": 7,\n"
                             "  \"height\": 5,\n"
                             "  \"samples\": 8,\n"
                             "  \"rule\": \"evenodd\",\n"
                             "  \"seed\": 18446744073709551615,\n"
                             "  \"cycles\": 4,\n"
                             "  \"transactions\": 3,\n"
                             "  \"interfaces\": [\n"
                             "    { \"name\": \"et_rd\", \"bits\": 36, \"count\": 3 }\n"
                             "  ],\n"
                             "  \"files\": [\n"
                             "    { \"name\": \"et_rd.expected.hex\", \"format\": \"hex\", \"interface\": \"et_rd\", "
                             "\"role\": \"expected\", \"count\": 3, \"bytes\": 99, \"sha256\": \"00\" }\n"
                             "  ]\n"
                             "}\n");
    free(got);
    ef_vec_collect_destroy(&m.r.c);
}

/* The out's hash and byte count are those of the bytes produced. */
static void test_out_hash(void **state)
{
    run r;
    size_t n;
    char *got, h1[65], h2[65];
    ef_vec_out o;
    uint8_t d[32];
    (void)state;
    small_run(&r, 1u << EF_IF_ET_RD);
    got = capture(write_vcd, &r, &n, &o);
    sha_hex(got, n, h1);
    ef_vec_sha256_final(&o.sha, d);
    ef_vec_sha256_hex(d, h2);
    assert_string_equal(h1, h2);
    assert_true(o.crc == ef_vec_crc32(0, got, n));
    free(got);
    ef_vec_collect_destroy(&r.c);
}

/* The sink's bytes, SHA-256 and CRC are those of what reached the file, over
 * many buffers: lines of every length (buffers end mid-line), room-and-advance
 * writes and blocks larger than a buffer (hashed and written without a copy);
 * the hash is checked against one SHA-256 of the whole file (sha_hex), the CRC
 * against ef_vec_crc32 over the whole file at once. */
static void test_out_buffers(void **state)
{
    char *bytes;
    size_t len;
    uint8_t digest[32];
    char *big = malloc(3 * EF_VEC_OUT_BUF + 17);
    FILE *fp = open_memstream(&bytes, &len);
    ef_vec_out *o = malloc(sizeof *o);
    (void)state;
    assert_non_null(big);
    assert_non_null(fp);
    assert_non_null(o);
    for (size_t i = 0; i < 3 * EF_VEC_OUT_BUF + 17; i++)
        big[i] = (char)('a' + i % 23);
    ef_vec_out_init(o, fp, EF_VEC_OUT_SHA | EF_VEC_OUT_CRC);
    for (unsigned k = 0; k < 40000; k++) {
        if (k % 1000 == 999) {
            ef_vec_out_write(o, big, EF_VEC_OUT_BUF + k % 7);
        } else if (k % 2) {
            unsigned char *p = ef_vec_out_room(o, 64);
            unsigned n = k % 61;
            memset(p, '0' + (int)(k % 10), n);
            p[n] = '\n';
            ef_vec_out_advance(o, n + 1u);
        } else {
            ef_vec_out_u64(o, (uint64_t)k * 2654435761u);
            ef_vec_out_puts(o, "\n");
        }
    }
    assert_int_equal(ef_vec_out_finish(o, digest), 0);
    assert_int_equal(fclose(fp), 0);
    assert_true(o->bytes == len && len > 10u * EF_VEC_OUT_BUF);
    assert_true(o->crc == ef_vec_crc32(0, bytes, len));
    char h1[65], h2[65];
    sha_hex(bytes, len, h1);
    ef_vec_sha256_hex(digest, h2);
    assert_string_equal(h1, h2);
    free(o);
    free(bytes);
    free(big);
}

/* ------------------------------------------------------------ seed */

static void test_seed(void **state)
{
    uint64_t s = 7;
    const char *gen = "# edgeflag gen: generator 1, edgeflag 0.1.0 (docs/gen.md)\n"
                      "# seed 20070101, level 1, case 0 of 261\nscene 8 8\n";
    (void)state;
    assert_int_equal(ef_vec_scene_seed(gen, strlen(gen), &s), 1);
    assert_true(s == 20070101);
    assert_int_equal(ef_vec_scene_seed("# seed 18446744073709551615\r\n", 29, &s), 1);
    assert_true(s == UINT64_MAX);
    assert_int_equal(ef_vec_scene_seed("\n   \n# x\n# seed 5", 17, &s), 1); /* blank lines, no newline */
    assert_true(s == 5);
    s = 7;
    assert_int_equal(ef_vec_scene_seed("# seed 18446744073709551616\n", 28, &s), 0); /* 2^64 */
    assert_int_equal(ef_vec_scene_seed("# seed 12x\n", 11, &s), 0);
    assert_int_equal(ef_vec_scene_seed("# seed \n", 8, &s), 0);
    assert_int_equal(ef_vec_scene_seed("#seed 3\n", 8, &s), 0);
    assert_int_equal(ef_vec_scene_seed("scene 1 1\n# seed 3\n", 19, &s), 0); /* after the drawing started */
    assert_int_equal(ef_vec_scene_seed("<svg># seed 3\n", 14, &s), 0);
    assert_int_equal(ef_vec_scene_seed("", 0, &s), 0);
    assert_true(s == 7);
}

/* The format table: names, bits and extensions distinct; lookups by name and by
 * file name find the row; the bits are the --formats bits. */
static void test_format_table(void **state)
{
    (void)state;
    unsigned all = 0;
    for (int k = 0; k < EF_VEC_NFORMATS; k++) {
        const ef_vec_format *f = &ef_vec_formats[k];
        assert_ptr_equal(ef_vec_format_named(f->name), f);
        char name[64];
        snprintf(name, sizeof name, "dir.x/pix.expected%s", f->ext);
        assert_ptr_equal(ef_vec_format_of_path(name), f);
        assert_int_equal(all & f->bit, 0);
        all |= f->bit;
        assert_non_null(f->write);
    }
    assert_int_equal(all, EF_VEC_F_ALL);
    assert_int_equal(ef_vec_format_named("hex")->reader, EF_VEC_FMT_HEX);
    assert_int_equal(ef_vec_format_named("bin")->reader, EF_VEC_FMT_BIN);
    assert_int_equal(ef_vec_format_named("vcd")->reader, 0);
    assert_null(ef_vec_format_named("fst"));
    assert_null(ef_vec_format_of_path("frame.png"));
    assert_null(ef_vec_format_of_path("hex"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crc32),
        cmocka_unit_test(test_sha256_fips),
        cmocka_unit_test(test_sha256_million_a),
        cmocka_unit_test(test_sha256_boundaries),
        cmocka_unit_test(test_hex_digits),
        cmocka_unit_test(test_hex_word),
        cmocka_unit_test(test_collect_refuses),
        cmocka_unit_test(test_merge_order),
        cmocka_unit_test(test_vcd_small),
        cmocka_unit_test(test_hex_file),
        cmocka_unit_test(test_bin),
        cmocka_unit_test(test_manifest),
        cmocka_unit_test(test_out_hash),
        cmocka_unit_test(test_out_buffers),
        cmocka_unit_test(test_seed),
        cmocka_unit_test(test_format_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
