/*
 * bench.c (board firmware, debug builds only) - the engine's costs on the
 * SoC's CPU, measured with timer0 (sys cycles): built with
 * FW_EXTRA=-DEF_FW_BENCH, the firmware runs these before its loop and writes
 * one text line per measurement to the UART (docs/board-ulx3s.md, "The
 * engine's cost per call").  A second engine with no DUT takes a sink-mode
 * run's frames as a host sends them.  Compiles to nothing in a normal build.
 */
#ifdef EF_FW_BENCH
#include <generated/csr.h>
#include <stdlib.h>
#include <string.h>

#include "ef_board.h"
#include "ef_frame.h"

void fw_bench(void);

static uint32_t ticks(void) /* timer0 counts down */
{
    timer0_update_value_write(1);
    return timer0_value_read();
}

static void put(const char *s)
{
    for (; *s; s++) {
        while (uart_txfull_read())
            ;
        uart_rxtx_write((uint8_t)*s);
    }
}

static void put_num(uint32_t v)
{
    char d[11];
    int i = 10;
    d[i] = 0;
    do
        d[--i] = (char)('0' + v % 10);
    while (v /= 10);
    put(d + i);
}

static void line(const char *what, uint32_t cycles)
{
    put("bench: ");
    put(what);
    put(": ");
    put_num(cycles);
    put(" cycles\r\n");
}

static uint8_t out[512];

/* The engine's answer to one call: its bytes for the host taken (as the loop does). */
static uint32_t drain(ef_board *b)
{
    uint32_t n = 0, k;
    while ((k = (uint32_t)ef_board_tx(b, out, sizeof out)) != 0)
        n += k;
    return n;
}

/* ef_board_rx of len bytes in pieces of piece bytes: the cycles of the call that completed it. */
static uint32_t feed(ef_board *b, const uint8_t *f, size_t len, size_t piece, uint32_t *all)
{
    uint32_t last = 0, sum = 0;
    for (size_t o = 0; o < len; o += piece) {
        const size_t n = len - o < piece ? len - o : piece;
        const uint32_t t0 = ticks();
        (void)ef_board_rx(b, f + o, n);
        last = t0 - ticks();
        sum += last;
    }
    if (all)
        *all = sum;
    return last;
}

void fw_bench(void)
{
    uint8_t *f = malloc(16 + 4096 + 4), *p = malloc(4096);
    ef_proto_info info;
    memset(&info, 0, sizeof info);
    info.window = 16;
    ef_board_dut none = { 0 };
    uint32_t t0 = ticks();
    ef_board *b = ef_board_new(&info, none);
    line("ef_board_new", t0 - ticks());
    if (!b || !f || !p) {
        put("bench: no memory\r\n");
        return;
    }
    for (size_t i = 0; i < 4096; i++)
        p[i] = (uint8_t)(i * 7 + 1);
    t0 = ticks();
    for (int i = 0; i < 100; i++)
        (void)uart_rxempty_read();
    line("100 reads of the UART's rxempty", t0 - ticks());
    t0 = ticks();
    for (int i = 0; i < 100; i++)
        uart_ev_pending_write(0);
    line("100 writes of the UART's ev_pending", t0 - ticks());
    t0 = ticks();
    for (int i = 0; i < 100; i++)
        (void)ticks();
    line("100 timer0 reads", t0 - ticks());
    t0 = ticks();
    (void)ef_frame_crc32(0, p, 256);
    line("crc32 of 256 bytes (the first call)", t0 - ticks());
    t0 = ticks();
    (void)ef_frame_crc32(0, p, 256);
    line("crc32 of 256 bytes", t0 - ticks());
    t0 = ticks();
    (void)ef_frame_crc32_combine(0x12345678u, 0x9abcdef0u, 256);
    line("crc32_combine over 256 bytes", t0 - ticks());
    t0 = ticks();
    (void)ef_frame_crc32_combine(0x12345678u, 0x9abcdef0u, 65536);
    line("crc32_combine over 65536 bytes", t0 - ticks());
    size_t n = ef_frame_put(f, EF_FT_DATA, 0, 1, p, 256);
    ef_frame fr;
    size_t used;
    t0 = ticks();
    (void)ef_frame_parse(f, n, &fr, &used);
    line("ef_frame_parse of a 256-byte DATA frame", t0 - ticks());
    t0 = ticks();
    n = ef_frame_put(f, EF_FT_DATA, 0, 1, p, 256);
    line("ef_frame_put of a 256-byte frame", t0 - ticks());

    for (int run = 0; run < 2; run++) {
        const size_t piece = run ? 64 : 4096; /* whole frames, then as the UART's FIFO brings them */
        const char *how = run ? " (in 64-byte pieces; the last)" : " (whole)";
        uint8_t s[EF_PROTO_START_LEN] = { 0 };
        s[8] = EF_MODE_SINK;
        ef_board_reset(b);
        uint32_t sum;
        n = ef_frame_put(f, EF_FT_START, 0, 0, s, sizeof s);
        put("bench: sink START");
        put(how);
        line("", feed(b, f, n, piece, &sum));
        line("  its bytes for the host", drain(b));
        for (uint32_t k = 1; k <= 3; k++) {
            n = ef_frame_put(f, EF_FT_DATA, 0, k, p, 256);
            put("bench: 256-byte DATA");
            put(how);
            line("", feed(b, f, n, piece, &sum));
            t0 = ticks();
            (void)drain(b);
            line("  ef_board_tx after it", t0 - ticks());
        }
        n = ef_frame_put(f, EF_FT_DATA, 0, 4, p, 4096);
        put("bench: 4096-byte DATA");
        put(how);
        line("", feed(b, f, n, piece, &sum));
        line("  all its calls", sum);
        (void)drain(b);
    }
    ef_board_free(b);
    free(f);
    free(p);
    put("bench: end\r\n");
}
#endif /* EF_FW_BENCH */
