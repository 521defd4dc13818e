/*
 * vec_bin_check.c - an independent reader of vectors.bin for
 * tests/vectors/run.sh, written from docs/vectors.md section 4 alone (it
 * shares no code with rtl_vectors/: its own bitwise CRC-32, its own copy of
 * the payload widths, its own hex formatting).  It checks everything the
 * document promises of a stream: magic, version, header size, samples, rule,
 * reserved bytes, both CRCs, record framing (interface number, payload
 * length ceil(P/8), bits above P zero), counts per interface against the
 * header and the interface mask, the global order (cycle, then interface)
 * and one transfer per interface per cycle.
 *
 *   vec_bin_check FILE           check; print the header as key=value
 *   vec_bin_check --hex I FILE   check; print interface I's records as the
 *                                hex words of docs/vectors.md section 3
 *   vec_bin_check --hex all FILE check; print every record as "NAME WORD",
 *                                grouped by interface in interface order
 *   exit 0 valid, 1 invalid (reason on stderr), 2 usage or unreadable
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* docs/microarch.md section 3: payload bits of cmd, seg, et_wr, et_rd, plot, span, pix. */
static const unsigned WIDTH[7] = { 100, 97, 181, 36, 36, 75, 68 };
static const char *const NAME[7] = { "cmd", "seg", "et_wr", "et_rd", "plot", "span", "pix" };

static uint64_t le(const unsigned char *p, int n)
{
    uint64_t v = 0;
    while (n--)
        v = v << 8 | p[n];
    return v;
}

/* Bit by bit, straight from the definition: reflected 0xEDB88320. */
static uint32_t crc32(const unsigned char *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

static int invalid(const char *path, const char *fmt, unsigned long long a, unsigned long long b)
{
    fprintf(stderr, "vec_bin_check: %s: ", path);
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    return 1;
}

/* The word { cycle[47:0], payload } of a record as ceil((48 + P) / 4) hex
 * digits: payload bytes are least significant first. */
static void print_word(const char *prefix, uint64_t cycle, const unsigned char *pay, unsigned p)
{
    static const char hex[] = "0123456789abcdef";
    unsigned nd = (48 + p + 3) / 4;
    char out[128];
    for (unsigned d = 0; d < nd; d++) {
        unsigned v = 0;
        for (unsigned b = 0; b < 4; b++) {
            unsigned bit = 4 * d + b, x;
            if (bit < p)
                x = pay[bit / 8] >> (bit % 8) & 1u;
            else if (bit - p < 48)
                x = (unsigned)(cycle >> (bit - p) & 1u);
            else
                x = 0;
            v |= x << b;
        }
        out[nd - 1 - d] = hex[v];
    }
    out[nd] = '\0';
    printf("%s%s%s\n", prefix ? prefix : "", prefix ? " " : "", out);
}

int main(int argc, char **argv)
{
    static const unsigned char magic[8] = { 0x89, 'E', 'F', 'V', '\r', '\n', 0x1a, '\n' };
    const char *path;
    int want = -1;
    FILE *f;
    unsigned char *buf = NULL;
    size_t len = 0, cap = 0, got;

    if (argc == 4 && strcmp(argv[1], "--hex") == 0 && argv[2][0] >= '0' && argv[2][0] <= '6' && !argv[2][1]) {
        want = argv[2][0] - '0';
        path = argv[3];
    } else if (argc == 4 && strcmp(argv[1], "--hex") == 0 && strcmp(argv[2], "all") == 0) {
        want = 7;
        path = argv[3];
    } else if (argc == 2) {
        path = argv[1];
    } else {
        fputs("usage: vec_bin_check [--hex 0..6|all] FILE\n", stderr);
        return 2;
    }
    if (!(f = fopen(path, "rb"))) {
        perror(path);
        return 2;
    }
    do {
        if (cap - len < 65536) {
            cap = cap ? 2 * cap : 1 << 20;
            if (!(buf = realloc(buf, cap)))
                return 2;
        }
        len += got = fread(buf + len, 1, cap - len, f);
    } while (got);
    fclose(f);

    if (len < 104)
        return invalid(path, "%llu bytes: shorter than the header (%llu)", len, 104);
    if (memcmp(buf, magic, 8) != 0)
        return invalid(path, "bad magic%.0llu%.0llu", 0, 0);
    if (le(buf + 8, 2) != 1 || le(buf + 10, 2) != 104)
        return invalid(path, "version %llu, header size %llu (want 1, 104)", le(buf + 8, 2), le(buf + 10, 2));
    if (!(buf[12] == 8 || buf[12] == 16 || buf[12] == 32) || buf[13] > 2)
        return invalid(path, "samples %llu, rule %llu", buf[12], buf[13]);
    if (le(buf + 14, 2) != 0 || le(buf + 36, 4) != 0)
        return invalid(path, "reserved bytes not zero%.0llu%.0llu", 0, 0);
    if (le(buf + 100, 4) != crc32(buf, 100))
        return invalid(path, "header CRC %llx, computed %llx", le(buf + 100, 4), crc32(buf, 100));
    if (le(buf + 96, 4) != crc32(buf + 104, len - 104))
        return invalid(path, "records CRC %llx, computed %llx", le(buf + 96, 4), crc32(buf + 104, len - 104));
    const uint64_t mask = le(buf + 32, 4);
    if (mask & ~0x7Full)
        return invalid(path, "interface mask %llx%.0llu", mask, 0);

    uint64_t count[7] = { 0 }, last_cycle[7] = { 0 }, prev_cycle = 0, records = 0;
    int prev_iface = -1;
    size_t pos = 104;
    while (pos < len) {
        if (len - pos < 10)
            return invalid(path, "record %llu cut short at byte %llu", records, pos);
        const unsigned i = buf[pos], l = buf[pos + 1];
        if (i > 6 || !(mask >> i & 1u))
            return invalid(path, "record %llu: interface %llu not recorded", records, i);
        if (l != (WIDTH[i] + 7) / 8)
            return invalid(path, "record %llu: payload length %llu", records, l);
        if (len - pos < 10u + l)
            return invalid(path, "record %llu cut short at byte %llu", records, pos);
        const uint64_t cyc = le(buf + pos + 2, 8);
        const unsigned char *pay = buf + pos + 10;
        if (cyc >> 48)
            return invalid(path, "record %llu: cycle %llu needs more than 48 bits", records, cyc);
        if (WIDTH[i] % 8 && (pay[l - 1] >> (WIDTH[i] % 8)))
            return invalid(path, "record %llu: bits above the payload width set (interface %llu)", records, i);
        if (prev_iface >= 0 && (cyc < prev_cycle || (cyc == prev_cycle && (int)i <= prev_iface)))
            return invalid(path, "record %llu out of order (cycle %llu)", records, cyc);
        if (count[i] && cyc <= last_cycle[i])
            return invalid(path, "record %llu: second transfer of interface %llu in a cycle", records, i);
        count[i]++;
        last_cycle[i] = cyc;
        prev_cycle = cyc;
        prev_iface = (int)i;
        records++;
        pos += 10u + l;
    }
    for (int i = 0; i < 7; i++)
        if (le(buf + 40 + 8 * i, 8) != count[i])
            return invalid(path, "interface %llu: header count differs from the %llu records", (unsigned)i, count[i]);
    /* Printed only once the whole stream is known to be valid. */
    for (int i = 0; i < 7 && want >= 0; i++) {
        if (want != 7 && want != i)
            continue;
        for (pos = 104; pos < len; pos += 10u + buf[pos + 1])
            if (buf[pos] == i)
                print_word(want == 7 ? NAME[i] : NULL, le(buf + pos + 2, 8), buf + pos + 10, WIDTH[i]);
    }
    if (want < 0)
        printf("version=1 header=104 samples=%u rule=%u width=%llu height=%llu seed=%llu mask=%llu "
               "counts=%llu,%llu,%llu,%llu,%llu,%llu,%llu records=%llu bytes=%llu\n",
               buf[12], buf[13], (unsigned long long)le(buf + 16, 4), (unsigned long long)le(buf + 20, 4),
               (unsigned long long)le(buf + 24, 8), (unsigned long long)mask, (unsigned long long)count[0],
               (unsigned long long)count[1], (unsigned long long)count[2], (unsigned long long)count[3],
               (unsigned long long)count[4], (unsigned long long)count[5], (unsigned long long)count[6],
               (unsigned long long)records, (unsigned long long)len);
    free(buf);
    return 0;
}
