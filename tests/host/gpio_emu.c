/*
 * gpio_emu.c - the GPIO transport (host/transport_gpio.c) against an
 * emulated chip with the real board engine on its lines (gpio_chip.c),
 * through the real libgpiod: 1.6 (Debian 12) or 2.x, whichever this program
 * was linked with (docs/board-gpio.md section 8).  Runs under umockdev-wrapper.
 *
 *   gpio_emu VECTORS.bin RESULTS_DIR     (tests/host/gpio.sh gives both)
 *
 * Checks: the board's side of the bus alone (board/gpio_bus.c: underrun,
 * control errors, RESET, a control request between stream bytes), listing, line maps (names and offsets, and bad ones), identify and
 * status byte for byte against the engine, a vectors stream end to end
 * through host_link.c (results written for `edgeflag check`), and the faults:
 * the board's error line (engine failure and a bus overrun), a stall past the
 * timeout, a device that answers identify wrongly or not at all, lines in use.
 * Each fault checks what the board received and what the user is told.
 * Prints GPIO words/s (bus cycles through the emulator).  Exit 0 only when
 * every check passed.
 *
 * Timeouts: the stall and the mute device test a timeout and get short ones
 * (150 and 300 ms); every other wait is one a run that goes well never reaches,
 * generous so that a busy machine cannot end it: 10 s times
 * EF_TEST_TIMEOUT_SCALE (docs/testing.md; a whole number 1..100, default 1),
 * which also scales the bounds on how long a timed-out operation may take.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "ef_board.h"
#include "gpio_bus.h"
#include "ef_frame.h"
#include "ef_trace.h"
#include "emu_check.h"
#include "gpio_chip.h"
#include "host_link.h"
#include "transport.h"
#include "transport_gpio.h"
#include "emu_wiring.h"

static int scale = 1; /* EF_TEST_TIMEOUT_SCALE */
#define LONG_MS (10000 * scale)

static ef_board *new_board(void)
{
    ef_proto_info info = { .serial = "EMU-GPIO-1",
                           .capabilities = EF_PROTO_CAP_RESULTS | EF_PROTO_CAP_RESUME | EF_PROTO_CAP_INTERNAL,
                           .samples_mask = 1u << ef_proto_samples_bit(8) | 1u << ef_proto_samples_bit(16) |
                                           1u << ef_proto_samples_bit(32),
                           .width_max = 4096,
                           .height_max = 4096,
                           .edges_max = 1u << 20,
                           .window = 8,
                           .iface_mask = (1u << EF_IF_COUNT) - 1 };
    return ef_board_new(&info, ef_board_dut_model());
}

/* timeout_ms: control replies (identify, status, reset) and err queries */
static ef_link *open_link(const char *lines, int timeout_ms, int *rc, char *err, size_t errlen)
{
    ef_host_opts o = { .chip = "gpiochip0", .lines = lines, .timeout_ms = timeout_ms };
    ef_link *l = NULL;
    err[0] = '\0';
    *rc = ef_transport_gpio.open(&l, &o, err, errlen);
    return l;
}

static void test_list(void)
{
    ef_found f[4];
    ef_host_opts o = { .chip = "gpiochip0", .lines = LINES };
    int n = ef_transport_gpio.probe(&o, f, 4);
    check(n == 1, "list: %d chips, expected 1", n);
    if (n < 1)
        return;
    check(strcmp(f[0].where, "/dev/gpiochip0") == 0, "list: where '%s'", f[0].where);
    check(strstr(f[0].desc, "edgeflag-emu") && strstr(f[0].desc, "32 lines") && strstr(f[0].desc, "0=EF_CLK"),
          "list: desc '%s' lacks the label, line count or line names", f[0].desc);
    check(f[0].ok == 1, "list: the board on --chip/--lines did not answer identify");
    ef_host_opts bare = { 0 };
    n = ef_transport_gpio.probe(&bare, f, 4);
    check(n == 1 && f[0].ok == 0, "list: without --lines a chip must be listed but not driven (n %d ok %d)", n,
          n > 0 ? f[0].ok : -1);
}

static void test_bad_maps(void)
{
    static const struct {
        const char *spec;
        int rc;
        const char *says;
    } bad[] = {
        { "clk=99", EF_HOST_EINVAL, "clk=99" },         /* past the chip's 32 lines */
        { "clk=NOPE", EF_HOST_ENOTFOUND, "NOPE" },      /* no such line name */
        { "clk=4", EF_HOST_EINVAL, "both d4 and clk" }, /* 4 is d4 in the default map */
        { "clk=EF_CLK", EF_HOST_EINVAL, "line 0 of /dev/gpiochip0 is mapped to both d0 and clk" }, /* by name */
        { "bogus=3", EF_HOST_EINVAL, "bogus" },
        { "d=1-5", EF_HOST_EINVAL, "8 lines" },
        { "q=1:2:3", EF_HOST_EINVAL, "8 lines" },
        { "setup=0", EF_HOST_EINVAL, "steps" },
        { "clk", EF_HOST_EINVAL, "SIGNAL=LINE" },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char err[256];
        int rc;
        ef_link *l = open_link(bad[i].spec, LONG_MS, &rc, err, sizeof err);
        check(!l && rc == bad[i].rc && strstr(err, bad[i].says), "--lines %s: rc %d, message '%s'", bad[i].spec, rc,
              err);
        if (l)
            ef_transport_gpio.close(l);
    }
}

static void test_identify(ef_link *l, ef_board *b)
{
    uint8_t got[EF_PROTO_IDENTIFY_LEN], want[EF_PROTO_IDENTIFY_LEN];
    uint8_t sgot[EF_PROTO_STATUS_LEN], swant[EF_PROTO_STATUS_LEN];
    int rc = ef_transport_gpio.identify(l, got);
    ef_board_identify(b, want);
    check(rc == 0 && memcmp(got, want, sizeof got) == 0, "identify: rc %d (%s) or bytes differ from the engine's", rc,
          ef_gpio_link_detail(l));
    ef_host_ident id;
    check(ef_host_ident_parse(got, &id) == 0 && strcmp(id.serial, "EMU-GPIO-1") == 0,
          "identify: not parsed as an edgeflag board");
    rc = ef_transport_gpio.status(l, sgot);
    ef_board_status(b, swant);
    check(rc == 0 && memcmp(sgot, swant, sizeof sgot) == 0, "status: rc %d or bytes differ", rc);
}

/* What edgeflag-host's protocol layer tells the user goes to stderr: keep a
 * copy of it for the checks (and still show it in the log). */
static FILE *capture;
static int saved_fd = -1;

static void capture_begin(void)
{
    fflush(stderr);
    capture = tmpfile();
    saved_fd = dup(2);
    if (capture)
        dup2(fileno(capture), 2);
}

static void capture_end(char *buf, size_t size)
{
    fflush(stderr);
    dup2(saved_fd, 2);
    close(saved_fd);
    buf[0] = '\0';
    if (!capture)
        return;
    rewind(capture);
    size_t n = fread(buf, 1, size - 1, capture);
    buf[n] = '\0';
    fclose(capture);
    fputs(buf, stderr);
}

static int stream_opts(ef_link *l, const char *vectors, const char *results, int timeout_ms, int resume,
                       ef_host_stream_report *rep, char *told, size_t toldlen)
{
    ef_host_stream_opts so = { .vectors = vectors,
                               .results = results,
                               .iface_mask = 1u << EF_IF_PIX,
                               .timeout_ms = timeout_ms,
                               .resume = resume,
                               .quiet = 1 };
    memset(rep, 0, sizeof *rep);
    capture_begin();
    int code = ef_host_stream(&ef_transport_gpio, l, &so, rep);
    capture_end(told, toldlen);
    return code;
}

static int stream(ef_link *l, const char *vectors, const char *results, int timeout_ms, ef_host_stream_report *rep,
                  char *told, size_t toldlen)
{
    return stream_opts(l, vectors, results, timeout_ms, 0, rep, told, toldlen);
}

/* The board starts each test fresh: a new engine behind the bus, and the
 * transport's own reset so the host's state matches. */
static ef_board *fresh_board(emu_chip *e, ef_link *l, ef_board *old)
{
    ef_board *b = new_board();
    emu_chip_set_faults(e, EMU_FAULT_NONE);
    emu_chip_set_byte_faults(e, 0, 0, 0);
    emu_chip_set_board(e, b);
    if (old)
        ef_board_free(old);
    int rc = ef_transport_gpio.reset(l);
    check(rc == 0, "reset: rc %d (%s)", rc, ef_gpio_link_detail(l));
    return b;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The vectors stream end to end; the results are checked against the
 * expected records by `edgeflag check` in tests/host/gpio.sh. */
static void test_stream(emu_chip *e, ef_link *l, const char *vectors, const char *results)
{
    ef_host_stream_report rep;
    char told[4096];
    uint64_t c0 = ef_gpio_link_cycles(l);
    double t0 = now_s();
    int code = stream(l, vectors, results, LONG_MS, &rep, told, sizeof told);
    double dt = now_s() - t0;
    uint64_t cycles = ef_gpio_link_cycles(l) - c0;
    check(code == EF_HX_OK, "stream: exit %d: %s", code, told);
    check(rep.records > 0 && rep.retransmits == 0 && rep.naks == 0, "stream: %llu records, %llu retransmits, %llu NAKs",
          (unsigned long long)rep.records, (unsigned long long)rep.retransmits, (unsigned long long)rep.naks);
    ef_board_stats st;
    ef_board_get_stats(e->board, &st);
    check(st.state == EF_BS_DONE && st.cmds == rep.cmds && st.frames_bad == 0,
          "stream: board state %d, %llu of %llu commands, %llu bad frames", st.state, (unsigned long long)st.cmds,
          (unsigned long long)rep.cmds, (unsigned long long)st.frames_bad);
    /* The run is over: the done line is high, and a read says so. */
    uint8_t buf[16];
    size_t got = 0;
    int rc = ef_transport_gpio.read(l, buf, sizeof buf, &got, 50);
    check(rc == EF_HOST_ETIMEDOUT && got == 0 && strstr(ef_gpio_link_detail(l), "done is high"),
          "after the stream: read rc %d got %zu detail '%s'", rc, got, ef_gpio_link_detail(l));
    printf("gpio-emu: stream: %llu commands, %llu result records in %.2f s; %llu bus cycles (GPIO words) = "
           "%.0f words/s through the emulator, %llu emulated ioctls\n",
           (unsigned long long)rep.cmds, (unsigned long long)rep.records, dt, (unsigned long long)cycles,
           dt > 0 ? (double)cycles / dt : 0.0, (unsigned long long)e->ioctls);
}

/* Both directions at once, byte for byte: the engine's loopback mode returns
 * every DATA payload as a RESULT while the host is still writing, so the
 * write path's take-in-the-same-cycle is exercised.  Every frame that comes
 * back must parse (no resync, no CRC error) and the payloads must be the
 * ones sent. */
static void test_duplex(emu_chip *e, ef_link *l)
{
    enum { NDATA = 6, CHUNK = 250 }; /* 6 RESULT + DONE fit the board's window of 8 */
    static uint8_t f[EF_PROTO_HEADER + CHUNK + EF_PROTO_TRAILER], sent[NDATA * CHUNK], back[NDATA * CHUNK + 1];
    static uint8_t rx[16384];
    uint8_t start[EF_PROTO_START_LEN] = { 0 };
    size_t nback = 0, rlen = 0, pos = 0;
    int bad = 0, done = 0, rc;
    uint32_t x = 12345;
    fresh_board(e, l, e->board);
    ef_put32(start + 8, EF_MODE_LOOPBACK);
    uint64_t c0 = ef_gpio_link_cycles(l);
    double t0 = now_s();
    rc = ef_transport_gpio.write(l, f, ef_frame_put(f, EF_FT_START, 0, 0, start, sizeof start), LONG_MS);
    for (uint32_t seq = 1; rc == 0 && seq <= NDATA + 1; seq++) {
        uint8_t *p = f + EF_PROTO_HEADER;
        uint32_t len = seq <= NDATA ? CHUNK : 0;
        for (uint32_t i = 0; i < len; i++)
            x = x * 1103515245u + 12345u, p[i] = sent[(seq - 1) * CHUNK + i] = (uint8_t)(x >> 16);
        rc = ef_transport_gpio.write(l, f, ef_frame_seal(f, seq <= NDATA ? EF_FT_DATA : EF_FT_END, 0, seq, len),
                                     LONG_MS);
    }
    check(rc == 0, "duplex: write rc %d (%s)", rc, ef_gpio_link_detail(l));
    while (rc == 0 && !done) {
        size_t got = 0;
        rc = ef_transport_gpio.read(l, rx + rlen, sizeof rx - rlen, &got, LONG_MS);
        rlen += got;
        ef_frame fr;
        size_t used;
        for (;;) {
            int pr = ef_frame_parse(rx + pos, rlen - pos, &fr, &used);
            if (pr == EF_FRAME_MORE)
                break;
            if (pr == EF_FRAME_BAD) {
                bad++, pos++;
                continue;
            }
            if (fr.type == EF_FT_RESULT && nback + fr.len <= sizeof back - 1) {
                memcpy(back + nback, fr.payload, fr.len);
                nback += fr.len;
            }
            done |= fr.type == EF_FT_DONE;
            pos += used;
        }
    }
    double dt = now_s() - t0;
    uint64_t cycles = ef_gpio_link_cycles(l) - c0;
    check(done && bad == 0 && nback == sizeof sent && memcmp(back, sent, sizeof sent) == 0,
          "duplex: done %d, %d bad bytes, %zu of %zu payload bytes back%s", done, bad, nback, sizeof sent,
          nback == sizeof sent ? " but different" : "");
    printf("gpio-emu: duplex: %zu payload bytes each way, %llu bus cycles in %.2f s = %.0f GPIO words/s "
           "through the emulator\n",
           sizeof sent, (unsigned long long)cycles, dt, dt > 0 ? (double)cycles / dt : 0.0);
}

static int same_file(const char *x, const char *y)
{
    FILE *a = fopen(x, "rb"), *b = fopen(y, "rb");
    int same = a && b;
    while (same) {
        int ca = getc(a), cb = getc(b);
        same = ca == cb;
        if (ca == EOF)
            break;
    }
    if (a)
        fclose(a);
    if (b)
        fclose(b);
    return same;
}

static void test_faults(emu_chip *e, ef_link *l, const char *vectors, const char *results)
{
    ef_host_stream_report rep;
    char told[4096], dir[4200];
    ef_board *b = e->board;
    int code;

    /* 1. The engine fails mid-stream: err rises, the ERROR frame still reaches the host. */
    b = fresh_board(e, l, b);
    emu_chip_set_byte_faults(e, 0, 60, 0);
    snprintf(dir, sizeof dir, "%s.enginefail", results);
    code = stream(l, vectors, dir, LONG_MS, &rep, told, sizeof told);
    check(code == EF_HX_BOARD && strstr(told, "injected by the GPIO emulator"), "engine failure: exit %d, told '%s'",
          code, told);
    uint8_t st[EF_PROTO_STATUS_LEN];
    check(ef_transport_gpio.status(l, st) == 0, "engine failure: status unreadable");
    ef_board_stats bs;
    ef_board_get_stats(b, &bs);
    check(bs.state == EF_BS_ERROR && emu_chip_received(e) >= 60, "engine failure: board state %d, %u bytes", bs.state,
          emu_chip_received(e));
    uint8_t buf[64];
    size_t got = 0;
    int rc;
    /* reset clears err: the board answers and takes bytes again */
    check(ef_transport_gpio.reset(l) == 0, "reset after failure");
    rc = ef_transport_gpio.read(l, buf, sizeof buf, &got, 50);
    check(rc == EF_HOST_ETIMEDOUT && got == 0, "after reset: read rc %d got %zu (err must be clear, nothing sent)", rc,
          got);

    /* 2. A data line stuck high at the board: the reset request 0x03 arrives as
     * 0x07, an unknown code; err rises and the bus status says why. */
    b = fresh_board(e, l, b);
    emu_chip_set_byte_faults(e, 0, 0, 0x04);
    rc = ef_transport_gpio.reset(l);
    emu_chip_set_byte_faults(e, 0, 0, 0);
    rc = ef_transport_gpio.write(l, (const uint8_t *)"E", 1, LONG_MS);
    check(rc == EF_HOST_EIO && strstr(ef_gpio_link_detail(l), "bad control cycle") &&
              strstr(ef_gpio_link_detail(l), "accepted 0 bytes"),
          "stuck d2: rc %d, detail '%s'", rc, ef_gpio_link_detail(l));
    check(emu_chip_received(e) == 0, "stuck d2: the board took %u bytes while err was high", emu_chip_received(e));

    /* 3. The board stops taking bytes after 100: a stall past the timeout is a
     * lost link (exit 5, --resume continues), and the board has exactly 100. */
    b = fresh_board(e, l, b);
    emu_chip_set_byte_faults(e, 100, 0, 0);
    snprintf(dir, sizeof dir, "%s.stall", results);
    double t0 = now_s();
    code = stream(l, vectors, dir, 150, &rep, told, sizeof told);
    double dt = now_s() - t0;
    check(code == EF_HX_LOST && emu_chip_received(e) == 100, "stall: exit %d, board received %u bytes, told '%s'", code,
          emu_chip_received(e), told);
    check(strstr(ef_gpio_link_detail(l), "held ready low") != NULL, "stall: detail '%s'", ef_gpio_link_detail(l));
    check(dt < 0.6 + LONG_MS / 1000.0, "stall: took %.1f s to give up", dt);
    /* The board takes bytes again: --resume finishes the run, and the results
     * are byte for byte those of the uninterrupted run. */
    emu_chip_set_byte_faults(e, 0, 0, 0);
    code = stream_opts(l, vectors, dir, LONG_MS, 1, &rep, told, sizeof told);
    char a[4300], c[4300];
    snprintf(a, sizeof a, "%s/vectors.actual.bin", results);
    snprintf(c, sizeof c, "%s/vectors.actual.bin", dir);
    check(code == EF_HX_OK && same_file(a, c), "stall, then --resume: exit %d, results %s the clean run's; told '%s'",
          code, same_file(a, c) ? "equal to" : "differ from", told);

    /* 4. Another device on the lines answers identify with other bytes. */
    b = fresh_board(e, l, b);
    emu_chip_set_faults(e, EMU_FAULT_FOREIGN);
    snprintf(dir, sizeof dir, "%s.foreign", results);
    code = stream(l, vectors, dir, LONG_MS, &rep, told, sizeof told);
    check(code == EF_HX_BOARD && strstr(told, "did not answer identify as an edgeflag board") &&
              emu_chip_received(e) == 0,
          "foreign device: exit %d, %u bytes sent to it, told '%s'", code, emu_chip_received(e), told);
    b = fresh_board(e, l, b);
}

/* Nothing answers on the lines: identify times out after the link's timeout
 * (300 ms here, what this checks), not before, and not much later. */
static void test_mute(emu_chip *e)
{
    char err[256];
    int rc;
    ef_link *l = open_link(LINES, 300, &rc, err, sizeof err);
    check(l != NULL, "open for the mute device: rc %d: %s", rc, err);
    if (!l)
        return;
    emu_chip_set_faults(e, EMU_FAULT_MUTE);
    uint8_t id[EF_PROTO_IDENTIFY_LEN];
    double t0 = now_s();
    rc = ef_transport_gpio.identify(l, id);
    double dt = now_s() - t0;
    check(rc == EF_HOST_ETIMEDOUT && strstr(ef_gpio_link_detail(l), "no identify reply") && dt >= 0.29 &&
              dt < 0.3 + LONG_MS / 1000.0,
          "mute device: rc %d after %.2f s (timeout 0.3 s), detail '%s'", rc, dt, ef_gpio_link_detail(l));
    emu_chip_set_faults(e, EMU_FAULT_NONE);
    ef_transport_gpio.close(l);
}

/* The host paused past its deadline while the board raised avail: the read
 * that returns after the pause still shows avail low, the board's reply is
 * there by then, and the host must sample once more before calling it a
 * timeout (host/transport_gpio.c, wait_line). */
static void test_late_sample(emu_chip *e)
{
    char err[256];
    int rc;
    ef_link *l = open_link(LINES, 300, &rc, err, sizeof err);
    check(l != NULL, "open for the late sample: rc %d: %s", rc, err);
    if (!l)
        return;
    /* read 1 ends the request's cycle, read 2 is the wait's first, paused 400 ms past the 300 */
    emu_chip_set_pause(e, 2, 400);
    uint8_t id[EF_PROTO_IDENTIFY_LEN];
    double t0 = now_s();
    rc = ef_transport_gpio.identify(l, id);
    double dt = now_s() - t0;
    emu_chip_set_pause(e, 0, 0);
    check(rc == 0 && dt >= 0.39, "a host paused past its deadline: identify rc %d after %.2f s (%s)", rc, dt,
          ef_gpio_link_detail(l));
    ef_transport_gpio.close(l);
}

/* ---- the board's side alone (board/gpio_bus.c against docs/board-gpio.md 4-5) ---- */

static void bus_edge(ef_gpio_bus *g, uint8_t d, unsigned ctrl, ef_gpio_bus_lines *o)
{
    ef_gpio_bus_edge(g, d, ctrl);
    ef_gpio_bus_outputs(g, o);
}

/* A control request as the host makes it; returns the reply's length. */
static size_t bus_request(ef_gpio_bus *g, uint8_t code, uint8_t *reply, size_t cap)
{
    ef_gpio_bus_lines o;
    size_t n = 0;
    bus_edge(g, code, EF_GB_CTL | EF_GB_VALID, &o);
    while (o.avail && n < cap) {
        reply[n++] = o.q;
        bus_edge(g, 0, EF_GB_CTL | EF_GB_TAKE, &o);
    }
    bus_edge(g, 0, 0, &o);
    return n;
}

static void test_bus_side(void)
{
    ef_board *b = new_board();
    ef_gpio_bus *g = ef_gpio_bus_new(b);
    ef_gpio_bus_lines o;
    uint8_t r[64], want[EF_PROTO_IDENTIFY_LEN];
    ef_gpio_bus_outputs(g, &o);
    check(o.ready && !o.avail && !o.err && !o.done, "bus: idle lines ready %d avail %d err %d done %d", o.ready,
          o.avail, o.err, o.done);

    /* take with nothing to take: UNDERRUN, sticky, in BUS_STATUS; RESET clears it */
    bus_edge(g, 0, EF_GB_TAKE, &o);
    check(o.err, "bus: take while avail was low did not raise err");
    size_t n = bus_request(g, EF_GB_REQ_BUS_STATUS, r, sizeof r);
    ef_gpio_bus_outputs(g, &o);
    check(n == EF_GB_BUS_STATUS_LEN && r[0] == EF_GB_ERR_UNDERRUN && o.err,
          "bus: BUS_STATUS after an underrun: %zu bytes, cause %d, err %d", n, n ? r[0] : -1, o.err);
    n = bus_request(g, EF_GB_REQ_RESET, r, sizeof r);
    ef_gpio_bus_outputs(g, &o);
    check(n == 0 && !o.err && o.ready, "bus: RESET: %zu reply bytes, err %d, ready %d", n, o.err, o.ready);

    /* a START frame goes in; its ACK waits on q while IDENTIFY runs in the
     * control view, and is still whole afterwards */
    uint8_t f[EF_PROTO_HEADER + EF_PROTO_START_LEN + EF_PROTO_TRAILER], start[EF_PROTO_START_LEN] = { 0 };
    ef_put32(start + 8, EF_MODE_SINK);
    size_t flen = ef_frame_put(f, EF_FT_START, 0, 0, start, sizeof start);
    for (size_t i = 0; i < flen; i++)
        bus_edge(g, f[i], EF_GB_VALID, &o);
    check(o.avail && o.q == 'E' && ef_gpio_bus_rx_count(g) == flen, "bus: no ACK on q after START (%u bytes in)",
          ef_gpio_bus_rx_count(g));
    n = bus_request(g, EF_GB_REQ_IDENTIFY, r, sizeof r);
    ef_board_identify(b, want);
    check(n == sizeof want && memcmp(r, want, n) == 0, "bus: IDENTIFY between stream bytes: %zu bytes", n);
    uint8_t ack[64];
    size_t k = 0;
    ef_gpio_bus_outputs(g, &o);
    while (o.avail && k < sizeof ack) {
        ack[k++] = o.q;
        bus_edge(g, 0, EF_GB_TAKE, &o);
    }
    ef_frame fr;
    size_t used;
    check(ef_frame_parse(ack, k, &fr, &used) == EF_FRAME_OK && fr.type == EF_FT_ACK && used == k &&
              ef_gpio_bus_tx_count(g) == k,
          "bus: the stream after a control request is not the ACK frame (%zu bytes)", k);

    /* take on the edge that enters the control view, and an unknown code: CONTROL */
    bus_edge(g, 0, EF_GB_CTL | EF_GB_TAKE, &o);
    check(o.err, "bus: take on a ctl-changing edge did not raise err");
    bus_edge(g, 0, 0, &o);
    n = bus_request(g, EF_GB_REQ_BUS_STATUS, r, sizeof r);
    check(n == EF_GB_BUS_STATUS_LEN && r[0] == EF_GB_ERR_CONTROL && ef_get32(r + 4) == flen && ef_get32(r + 8) == k,
          "bus: BUS_STATUS: cause %d, %u in, %u out", n ? r[0] : -1, ef_get32(r + 4), ef_get32(r + 8));
    bus_request(g, EF_GB_REQ_RESET, r, sizeof r);
    n = bus_request(g, 0x55, r, sizeof r);
    ef_gpio_bus_outputs(g, &o);
    check(n == 0 && o.err, "bus: unknown request 0x55: %zu reply bytes, err %d", n, o.err);
    ef_gpio_bus_free(g);
    ef_board_free(b);
}

/* The host keeps the documented timing (docs/board-gpio.md section 3), as the
 * emulated board sees it: S setup and H hold steps exactly, S + H writes and
 * one read per cycle, one rising edge per cycle. */
static void check_timing(emu_chip *e, ef_link *l, unsigned S, unsigned H)
{
    uint64_t su, ho, sets, gets, edges;
    uint8_t id[EF_PROTO_IDENTIFY_LEN];
    emu_chip_timing(e, &su, &ho, &sets, &gets, &edges);
    unsigned long long c0 = ef_gpio_link_cycles(l);
    int rc = ef_transport_gpio.identify(l, id);
    unsigned long long cycles = ef_gpio_link_cycles(l) - c0;
    emu_chip_timing(e, &su, &ho, &sets, &gets, &edges);
    check(rc == 0 && su == S && ho == H && edges == cycles && sets == (S + H) * cycles && gets == cycles,
          "timing setup=%u hold=%u: rc %d, board saw setup %llu hold %llu, %llu edges for %llu cycles, %llu writes, "
          "%llu reads",
          S, H, rc, (unsigned long long)su, (unsigned long long)ho, (unsigned long long)edges, cycles,
          (unsigned long long)sets, (unsigned long long)gets);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: gpio_emu VECTORS.bin RESULTS_DIR (under umockdev-wrapper)\n");
        return 2;
    }
    const char *sc = getenv("EF_TEST_TIMEOUT_SCALE");
    if (sc && *sc) {
        char *end;
        long v = strtol(sc, &end, 10);
        if (*end || v < 1 || v > 100) {
            fprintf(stderr, "gpio_emu: EF_TEST_TIMEOUT_SCALE='%s': want a whole number 1..100\n", sc);
            return 2;
        }
        scale = (int)v;
    }
    ef_board *b = new_board();
    emu_chip *e = emu_chip_new(b, WIRING);
    if (!e)
        return 2;
    printf("gpio-emu: %s\n", ef_transport_gpio.version());
    test_bus_side();
    test_list();
    test_bad_maps();

    char err[256];
    int rc;
    ef_link *l = open_link(LINES, LONG_MS, &rc, err, sizeof err);
    check(l != NULL, "open: rc %d: %s", rc, err);
    if (!l)
        goto out;
    test_identify(l, b);
    check_timing(e, l, 1, 1);

    /* A second program on the same lines is told who holds them. */
    ef_link *l2 = open_link(LINES, LONG_MS, &rc, err, sizeof err);
    check(!l2 && rc == EF_HOST_EBUSY && strstr(err, "edgeflag-host"), "busy: rc %d, message '%s'", rc, err);
    if (l2)
        ef_transport_gpio.close(l2);

    test_stream(e, l, argv[1], argv[2]);
    test_duplex(e, l);
    test_faults(e, l, argv[1], argv[2]);

    /* Slower timing for a slower board: the same bus, more steps. */
    ef_transport_gpio.close(l);
    char slow[512];
    snprintf(slow, sizeof slow, "%s,setup=3,hold=2", LINES);
    l = open_link(slow, LONG_MS, &rc, err, sizeof err);
    check(l != NULL, "open with setup=3,hold=2: rc %d: %s", rc, err);
    if (!l)
        goto out;
    check_timing(e, l, 3, 2);

    ef_transport_gpio.close(l);
    test_mute(e);
    test_late_sample(e);
out:
    printf("gpio-emu: %d checks, %d failed\n", checks, failed);
    return failed ? 1 : 0;
}
