/*
 * gpio_cosim.c - edgeflag-host over GPIO into the simulated board's gateware
 * (docs/board-gpio.md section 8, "Co-simulation with the gateware"): the
 * emulated gpiochip of gpio_chip.c with its second back end, whose lines lead
 * to the Verilated SoC's GPIO header (board/sim/gpio_link.cpp: the gateware
 * slave of board/soc/ef_gpio.py, the firmware's link_gpio.c, the engine,
 * ef_raster), driven through the real libgpiod (1.6 or 2.x, whichever this
 * program was linked with).  Runs under umockdev-wrapper; one process, as the
 * emulated chip must be (docs/board-gpio.md section 8).
 *
 *   gpio_cosim SOCKET [--unplug-after N] -- ARGS...
 *       runs edgeflag-host ARGS (host/main.c compiled in unchanged, its main
 *       renamed) against the simulated board; exits with its exit status.
 *       --unplug-after N: once the board has taken N stream bytes the lines
 *       go dead (the socket closes: the board's pull-downs, nothing on the
 *       host's inputs), as if the cable were pulled.
 *   gpio_cosim SOCKET --bench KIB [sink|source]
 *       the link tests by hand: KIB x 1040 bytes in sink mode, KIB KiB in
 *       source mode; bus cycles, host steps and wall time (the board's time
 *       is in board_sim's report when it exits).
 *   gpio_cosim SOCKET --status
 *       identify and status of the board as it is (no reset).
 *   gpio_cosim SOCKET --selftest SERIAL
 *       the bus through the transport: identify (serial SERIAL) and status,
 *       the host's timing as the chip sees it, an engine failure (err with
 *       cause ENGINE, the ERROR frame still arrives), a stuck data line (the
 *       RESET code arrives as an unknown one: CONTROL), a take with nothing
 *       there (UNDERRUN), and RESET clearing each.  Prints "N checks, M failed".
 *
 * The wiring is gpio_emu.c's (control lines first, some mapped by name); the
 * --lines map for it is printed by `gpio_cosim --lines`.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ef_frame.h"
#include "emu_check.h"
#include "gpio_chip.h"
#include "host_link.h"
#include "transport.h"
#include "transport_gpio.h"
#include "emu_wiring.h"

int edgeflag_host_main(int argc, char **argv); /* host/main.c's main */

/* Reads what the board sends until a frame of type `want` is whole (or the
 * link fails); returns 1 when it came. */
static int read_frame(ef_link *l, uint8_t want, ef_frame *out, uint8_t *buf, size_t cap)
{
    size_t len = 0, pos = 0;
    for (int tries = 0; tries < 64 && len < cap; tries++) {
        size_t got = 0;
        int rc = ef_transport_gpio.read(l, buf + len, cap - len, &got, 10000);
        len += got;
        for (;;) {
            size_t used;
            int pr = ef_frame_parse(buf + pos, len - pos, out, &used);
            if (pr == EF_FRAME_MORE)
                break;
            if (pr == EF_FRAME_BAD) {
                pos++;
                continue;
            }
            if (out->type == want)
                return 1;
            pos += used;
        }
        if (rc && rc != EF_HOST_ETIMEDOUT)
            return 0;
    }
    return 0;
}

static void selftest(emu_chip *e, const char *serial)
{
    char err[256];
    int rc;
    ef_host_opts o = { .chip = "gpiochip0", .lines = LINES, .timeout_ms = 10000 };
    ef_link *l = NULL;
    rc = ef_transport_gpio.open(&l, &o, err, sizeof err);
    check(rc == 0 && l, "open: rc %d: %s", rc, err);
    if (!l)
        return;

    /* identify and status from the firmware, through the slave's control view; the timing the
     * host keeps, as the chip sees it (docs/board-gpio.md section 3) */
    uint8_t id[EF_PROTO_IDENTIFY_LEN], st[EF_PROTO_STATUS_LEN];
    uint64_t su, ho, sets, gets, edges;
    emu_chip_timing(e, &su, &ho, &sets, &gets, &edges);
    unsigned long long c0 = ef_gpio_link_cycles(l);
    rc = ef_transport_gpio.identify(l, id);
    unsigned long long cycles = ef_gpio_link_cycles(l) - c0;
    emu_chip_timing(e, &su, &ho, &sets, &gets, &edges);
    ef_host_ident ident;
    check(rc == 0 && ef_host_ident_parse(id, &ident) == 0 && strcmp(ident.serial, serial) == 0,
          "identify: rc %d (%s), serial '%s' (want '%s')", rc, ef_gpio_link_detail(l), rc == 0 ? ident.serial : "",
          serial);
    /* reads: one per cycle, and more while the firmware prepares the reply (avail low) */
    check(su == 1 && ho == 1 && edges == cycles && sets == 2 * cycles && gets >= cycles,
          "timing: setup %llu hold %llu, %llu edges for %llu cycles, %llu writes, %llu reads", (unsigned long long)su,
          (unsigned long long)ho, (unsigned long long)edges, cycles, (unsigned long long)sets,
          (unsigned long long)gets);
    rc = ef_transport_gpio.status(l, st);
    check(rc == 0 && memcmp(st, "EFB1", 4) == 0, "status: rc %d (%s)", rc, ef_gpio_link_detail(l));
    printf("gpio-cosim: identify from the gateware: %s, %ux%u, %u edges max; %llu bus cycles\n", ident.serial,
           (unsigned)ident.width_max, (unsigned)ident.height_max, (unsigned)ident.edges_max, cycles);

    /* 1. The engine fails (a START asking for 16 samples of a board built for 8: ERROR code 2):
     * err rises with cause ENGINE, the stream keeps moving and the ERROR frame arrives. */
    check(ef_transport_gpio.reset(l) == 0, "reset: %s", ef_gpio_link_detail(l));
    uint8_t f[EF_PROTO_HEADER + EF_PROTO_START_LEN + EF_PROTO_TRAILER], start[EF_PROTO_START_LEN] = { 0 };
    ef_put32(start, 1u << 6);
    ef_put32(start + 4, 16);
    rc = ef_transport_gpio.write(l, f, ef_frame_put(f, EF_FT_START, 0, 0, start, sizeof start), 10000);
    static uint8_t buf[8192];
    ef_frame fr;
    int got_error = rc == 0 && read_frame(l, EF_FT_ERROR, &fr, buf, sizeof buf);
    check(got_error && fr.len >= 4 && ef_get32(fr.payload) == 2, "engine failure: write rc %d, ERROR frame %s (%s)", rc,
          got_error ? "code differs" : "missing", ef_gpio_link_detail(l));
    check(ef_transport_gpio.status(l, st) == 0 && st[6] == 3, "engine failure: status state %d (want 3, error)", st[6]);
    check(ef_transport_gpio.reset(l) == 0, "reset after the engine failure: %s", ef_gpio_link_detail(l));
    size_t n = 0;
    rc = ef_transport_gpio.read(l, buf, 16, &n, 50);
    check(rc == EF_HOST_ETIMEDOUT && n == 0 && !strstr(ef_gpio_link_detail(l), "error line"),
          "after reset: read rc %d, %zu bytes, detail '%s' (err must be low, nothing sent)", rc, n,
          ef_gpio_link_detail(l));

    /* 2. d2 stuck high at the board: RESET (0x03) arrives as 0x07: CONTROL, and the bus status
     * the host reads says so with both sides' byte counts. */
    emu_chip_set_byte_faults(e, 0, 0, 0x04);
    (void)ef_transport_gpio.reset(l);
    emu_chip_set_byte_faults(e, 0, 0, 0);
    rc = ef_transport_gpio.write(l, (const uint8_t *)"E", 1, 10000);
    check(rc == EF_HOST_EIO && strstr(ef_gpio_link_detail(l), "bad control cycle") &&
              strstr(ef_gpio_link_detail(l), "accepted 0 bytes"),
          "stuck d2: rc %d, detail '%s'", rc, ef_gpio_link_detail(l));
    check(ef_transport_gpio.reset(l) == 0, "reset after CONTROL: %s", ef_gpio_link_detail(l));

    /* 3. avail shown high with nothing there (a wiring fault on the host's side): the host takes,
     * the slave latches UNDERRUN. */
    emu_chip_set_faults(e, EMU_FAULT_LIE_AVAIL);
    n = 0;
    rc = ef_transport_gpio.read(l, buf, 1, &n, 1000);
    emu_chip_set_faults(e, EMU_FAULT_NONE);
    check(rc == 0 && n == 1, "lied avail: the host did not take (rc %d, %zu bytes)", rc, n);
    rc = ef_transport_gpio.flush(l, 200); /* the sample after the take shows err */
    check(rc == EF_HOST_EIO && strstr(ef_gpio_link_detail(l), "underrun"), "lied avail: rc %d, detail '%s'", rc,
          ef_gpio_link_detail(l));
    check(ef_transport_gpio.reset(l) == 0, "reset after UNDERRUN: %s", ef_gpio_link_detail(l));
    rc = ef_transport_gpio.identify(l, id);
    check(rc == 0, "identify after the faults: rc %d (%s)", rc, ef_gpio_link_detail(l));
    ef_transport_gpio.close(l);
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* One link test (docs/board.md section 8) by hand: payload bytes each way, and what it cost on
 * the bus (cycles), in host steps (GPIO calls, as the chip counted them) and in wall time. */
static void bench_mode(emu_chip *e, ef_link *l, uint32_t mode, unsigned kib)
{
    static uint8_t f[EF_PROTO_HEADER + 1040 + EF_PROTO_TRAILER], buf[65536];
    uint8_t start[EF_PROTO_START_LEN] = { 0 };
    const unsigned nframes = mode == EF_MODE_SINK ? kib : 0; /* 1040-byte DATA payloads (80 commands) */
    uint64_t su, ho, sets, gets, edges;
    check(ef_transport_gpio.reset(l) == 0, "bench: reset: %s", ef_gpio_link_detail(l));
    emu_chip_timing(e, &su, &ho, &sets, &gets, &edges);
    const unsigned long long c0 = ef_gpio_link_cycles(l);
    const double t0 = now_s();
    ef_put32(start + 8, mode);
    ef_put32(start + 12, mode == EF_MODE_SOURCE ? kib : 0);
    int rc = ef_transport_gpio.write(l, f, ef_frame_put(f, EF_FT_START, 0, 0, start, sizeof start), 10000);
    for (uint32_t seq = 1; rc == 0 && seq <= nframes + 1; seq++) {
        uint32_t len = seq <= nframes ? 1040 : 0;
        memset(f + EF_PROTO_HEADER, (int)seq, len);
        rc = ef_transport_gpio.write(l, f, ef_frame_seal(f, seq <= nframes ? EF_FT_DATA : EF_FT_END, 0, seq, len),
                                     10000);
    }
    ef_frame fr;
    int done = rc == 0 && read_frame(l, EF_FT_DONE, &fr, buf, sizeof buf);
    const double dt = now_s() - t0;
    const unsigned long long cycles = ef_gpio_link_cycles(l) - c0;
    emu_chip_timing(e, &su, &ho, &sets, &gets, &edges);
    const unsigned long long steps = sets + gets,
                             payload = (unsigned long long)(nframes ? nframes * 1040u : kib * 1024u);
    check(done, "bench %s: no DONE (rc %d, %s)", mode == EF_MODE_SINK ? "sink" : "source", rc, ef_gpio_link_detail(l));
    printf("gpio-cosim: bench %s: %llu payload bytes, %llu bus cycles (%.2f payload bytes per cycle), %llu host steps "
           "(%.2f per cycle); wall %.2f s: %.0f bus cycles/s, %.0f payload B/s (board time: board_sim's report)\n",
           mode == EF_MODE_SINK ? "sink (host to board)" : "source (board to host)", payload, cycles,
           cycles ? (double)payload / (double)cycles : 0.0, steps, cycles ? (double)steps / (double)cycles : 0.0, dt,
           dt > 0 ? (double)cycles / dt : 0.0, dt > 0 ? (double)payload / dt : 0.0);
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--lines") == 0) {
        printf("%s\n", LINES);
        return 0;
    }
    if (argc < 3) {
        fprintf(stderr, "usage: gpio_cosim SOCKET [--unplug-after N] -- EDGEFLAG-HOST-ARGS...\n"
                        "       gpio_cosim SOCKET --selftest SERIAL\n       gpio_cosim --lines\n");
        return 2;
    }
    emu_chip *e = emu_chip_new_sim(argv[1], WIRING);
    if (!e)
        return 2;
    if (strcmp(argv[2], "--bench") == 0 && (argc == 4 || argc == 5)) { /* SOCKET --bench KIB [sink|source] */
        char err[256];
        ef_host_opts o = { .chip = "gpiochip0", .lines = LINES, .timeout_ms = 10000 };
        ef_link *l = NULL;
        int rc = ef_transport_gpio.open(&l, &o, err, sizeof err);
        check(rc == 0 && l, "open: rc %d: %s", rc, err);
        if (l) {
            if (argc == 4 || strcmp(argv[4], "sink") == 0)
                bench_mode(e, l, EF_MODE_SINK, (unsigned)atoi(argv[3]));
            if (argc == 4 || strcmp(argv[4], "source") == 0)
                bench_mode(e, l, EF_MODE_SOURCE, (unsigned)atoi(argv[3]));
            ef_transport_gpio.close(l);
        }
        printf("gpio-cosim: %d checks, %d failed\n", checks, failed);
        return failed ? 1 : 0;
    }
    if (strcmp(argv[2], "--status") == 0) { /* the board as it is: identify and status, no reset */
        char err[256];
        ef_host_opts o = { .chip = "gpiochip0", .lines = LINES, .timeout_ms = 3000 };
        ef_link *l = NULL;
        uint8_t id[EF_PROTO_IDENTIFY_LEN], st[EF_PROTO_STATUS_LEN];
        if (ef_transport_gpio.open(&l, &o, err, sizeof err) != 0)
            return 1;
        int r1 = ef_transport_gpio.identify(l, id), r2 = ef_transport_gpio.status(l, st);
        printf(
            "gpio-cosim: identify rc %d, status rc %d: state %u, next frame %u, result frames %u, commands %u (%s)\n",
            r1, r2, st[6], ef_get32(st + 8), ef_get32(st + 12), ef_get32(st + 24), ef_gpio_link_detail(l));
        ef_transport_gpio.close(l);
        return 0;
    }
    if (strcmp(argv[2], "--selftest") == 0 && argc == 4) {
        selftest(e, argv[3]);
        printf("gpio-cosim: %d checks, %d failed\n", checks, failed);
        return failed ? 1 : 0;
    }
    int i = 2;
    if (strcmp(argv[i], "--unplug-after") == 0 && i + 1 < argc) {
        e->unplug_after = (uint32_t)strtoul(argv[i + 1], NULL, 10);
        i += 2;
    }
    if (i >= argc || strcmp(argv[i], "--") != 0) {
        fprintf(stderr, "gpio_cosim: expected -- before edgeflag-host's arguments\n");
        return 2;
    }
    static char name[] = "edgeflag-host";
    argv[i] = name;
    return edgeflag_host_main(argc - i, argv + i);
}
