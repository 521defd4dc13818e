// board_sim.cpp - the whole ULX3S board in Verilator (docs/board-ulx3s.md,
// "The board simulated"): the SoC's Verilog as LiteX writes it for the
// simulation target of board/soc/soc.py (VexRiscv, the firmware in its ROM,
// ef_raster and its frame memory, the UART), ef at 15 MHz and sys at 60 MHz
// (four sys cycles per ef cycle, the USB device's 12 MHz a fifth of sys);
// --sys-clk 30e6 clocks it as the board is clocked (two sys cycles per ef
// cycle) for a SoC built by soc.py --sys-clk 30e6; its UART connected to a
// pseudo-terminal -- or a unix socket -- so that edgeflag-host drives it
// through the same code a real board gets.
//
// The UART is joined at the UART core's PHY stream (LiteX's "sim" PHY: a
// byte with valid/ready each way), not at the pins: the harness paces that
// stream at the line rate (--baud, default 3,000,000: one byte every 10 bit
// times of simulated time, 200 sys cycles at 3 Mbaud and 60 MHz), so the firmware sees
// bytes arrive and leave as fast as the FT231X would bring them.
//
//   board_sim --dir GATEWARE_DIR [--pty-link FILE] [--link PATH] [--listen PATH] [--baud N]
//             [--sys-clk HZ] [--ef-clk HZ] [--faults LIST] [--probe-status CYCLES]
//             [--max-seconds S] [--quiet] [--gpio-listen PATH [--gpio-step-cycles N] [--gpio-lockstep]]
//             [--usb PATH]
//
// --dir: where the memory images (sim_rom.init, ...) are.  The board is
// published only once it is up (but with --gpio-listen or --usb, whose hosts
// wait for their own sockets): the harness itself sends the firmware an
// identify control frame (docs/board.md 5.5) and waits for its reply (a
// readiness handshake, however slow the machine), then makes the host's end.
// With a pty (the default) its name (/dev/pts/N) is the first line of the
// standard output, written into FILE with --pty-link, and --link makes PATH a
// symlink to it (kept across an unplug).  With --listen the board listens on
// the unix socket PATH instead (one host at a time; a host's disconnection
// keeps the board's run, as a powered board keeps it).
//
// --faults KIND=N,... (docs/board.md section 6, on the board itself): after
// the host's N-th whole frame (counted by their headers, as
// tests/host/ptyboard counts them)
//   stall    the whole board stops (no clock, no byte either way) until
//            SIGUSR1;
//   reset    the SoC is reset (sys_rst: the CPU boots the firmware again, the
//            peripheral and ef_raster reset, the bytes the board had not sent
//            lost): a power cycle.  Its N counts the board's frames written
//            to the host instead, so that the host has acknowledgements of
//            frames the board then forgets;
//   unplug   the host's pty is closed (the host sees the line hang up) and a
//            new one made at --link; the board runs on, its run kept.
// --probe-status CYCLES: every CYCLES sys cycles, between two of the host's
// frames, the harness sends the board a status request of its own (a tag the
// host never uses: the host drops its reply) and keeps the most result
// frames the board held unacknowledged (made less acknowledged); a probe waits
// for the last one's reply.
// On SIGTERM or SIGINT, or after --max-seconds of wall time, it prints the
// cycles simulated, the bytes moved, the faults played, the simulated time
// from the host's first byte to the board's last, the most result
// frames kept and, on a paced line, the UART receive FIFO's overruns (bytes
// due while its 64 bytes were full: lost on a real UART), and exits 0.  --gpio-listen: the SoC's GPIO bus pins behind a
// unix socket for the emulated gpiochip of the tests (gpio_link.cpp), served
// once the board is up.  --usb PATH: the SoC's USB device on a unix socket for
// tests/host/usb_emu.c (--soc), through the host controller of usb_link.cpp
// (the usb clock is 12 MHz: one every 5 sys cycles, so sys must be 60 MHz).
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <string>
#include <sys/stat.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <termios.h>
#include <unistd.h>

#include "Vsim.h"
#include "gpio_link.h"
#include "usb_link.h"
#include "verilated.h"
#include <zlib.h>

static volatile sig_atomic_t stop_now, unstall;
static void on_signal(int) { stop_now = 1; }
static void on_usr1(int) { unstall = 1; }

enum { F_STALL, F_RESET, F_UNPLUG, F_KINDS };
static const char *const KIND[F_KINDS] = { "stall", "reset", "unplug" };
static unsigned long long fault_at[F_KINDS];

// The board's result queue as its own status requests say it (docs/board.md 3.1: result frames
// made less those acknowledged), asked by the harness itself (--probe-status): the most at once.
static const uint32_t PROBE_TAG = 0x51515151u;   // the host drops replies with tags it did not use
struct Kept {
    uint32_t most = 0;
    unsigned long long probes = 0;
    bool asked = false;   // a probe is out: the next waits for its reply (a slow line is not flooded)
};

// Counts whole frames of one direction by their headers (magic, len), as tests/host/ptyboard does.
struct FrameCount {
    unsigned long long frames = 0;
    uint8_t hdr[16], pay[20];
    size_t hdr_len = 0, body_left = 0, body_len = 0;
    Kept *kept = nullptr;   // the board's side: status replies to the harness's probes
    static uint32_t le32(const uint8_t *b)
    {
        return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
    }
    void done()
    {
        frames++;
        if (kept && hdr[4] == 0x91 && le32(hdr + 8) == PROBE_TAG && body_len == 44) {
            const uint32_t made = le32(pay + 12), acked = le32(pay + 16);
            if (made - acked > kept->most && made >= acked)
                kept->most = made - acked;
            kept->probes++;
            kept->asked = false;
        }
    }
    void add(const uint8_t *p, size_t n)
    {
        static const uint8_t magic[4] = { 'E', 'F', 'B', '1' };
        for (size_t i = 0; i < n; i++) {
            if (body_left) {
                if (body_len - body_left < sizeof pay)
                    pay[body_len - body_left] = p[i];
                if (--body_left == 0)
                    done();
                continue;
            }
            if (hdr_len < 4 && p[i] != magic[hdr_len]) {
                hdr_len = p[i] == 'E';
                hdr[0] = p[i];
                continue;
            }
            hdr[hdr_len++] = p[i];
            if (hdr_len == 16) {
                const uint32_t len =
                    (uint32_t)hdr[12] | (uint32_t)hdr[13] << 8 | (uint32_t)hdr[14] << 16 | (uint32_t)hdr[15] << 24;
                body_left = body_len = len <= 65536 ? len + 4 : 0;
                hdr_len = 0;
            }
        }
    }
};

// A new pty for the host (raw until the host sets its own mode), its name in name; the
// symlink link (if any) made to point at it.
static int new_pty(std::string &name, const char *link)
{
    const int fd = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd < 0 || grantpt(fd) != 0 || unlockpt(fd) != 0)
        return -1;
    name = ptsname(fd);
    int sfd = open(name.c_str(), O_RDWR | O_NOCTTY);
    if (sfd >= 0) {
        termios t;
        if (tcgetattr(sfd, &t) == 0) {
            cfmakeraw(&t);
            tcsetattr(sfd, TCSANOW, &t);
        }
        close(sfd);
    }
    if (link) {
        const std::string tmp = std::string(link) + ".new";
        unlink(tmp.c_str());
        if (symlink(name.c_str(), tmp.c_str()) != 0 || rename(tmp.c_str(), link) != 0)
            return -1;
    }
    return fd;
}

static double now_s()
{
    timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec * 1e-9;
}

static void usage()
{
    std::fprintf(stderr,
                 "usage: board_sim --dir GATEWARE_DIR [--pty-link FILE] [--link PATH] [--listen PATH] "
                 "[--baud N] [--sys-clk HZ] [--ef-clk HZ] [--faults stall=N,reset=N,unplug=N] [--probe-status CYCLES] "
                 "[--max-seconds S] "
                 "[--quiet] [--gpio-listen PATH [--gpio-step-cycles N] [--gpio-lockstep]]\n");
    std::exit(2);
}

// The simulated SoC, clocked as on the board, its UART's PHY streams paced at the line rate.
struct Board {
    VerilatedContext ctx;
    Vsim top{ &ctx };
    uint64_t cyc = 0, byte_cycles = 0, next_rx = 0, next_tx = 0, ef_div = 2;
    // A paced line cannot wait: a byte due while the UART's receive FIFO is full is one a real
    // UART loses (LiteX's PHY has no flow control).  The harness holds it back instead and counts
    // it here (once per byte); 0 on a paced run is the firmware keeping up with the line.
    uint64_t overruns = 0;
    bool refused = false;
    GpioLink *gpio = nullptr;   // the GPIO header's socket (gpio_link.cpp), served once the board is up
    UsbLink *usb = nullptr;     // the USB device's socket (usb_link.cpp)
    void reset_pins()
    {
        top.sys_rst = 1;
        top.serial_sink_valid = 0;
        top.serial_source_ready = 0;
        top.sim_trace = 0;
        top.utmi_line_state = 2;   // J: an idle bus, no reset
    }
    // One sys cycle.  in: a byte for the board (or none); sets *took when the board took it, and
    // returns 1 with *out set when the board sent a byte (room: the caller can take one).
    int step(const uint8_t *in, bool *took, bool room, uint8_t *out)
    {
        // usb rises with every fifth sys rise (12 MHz): its inputs before, its outputs between
        const unsigned um = (unsigned)(cyc % 5);
        const bool frozen = usb && usb_link_frozen(usb);
        if (usb && um == 0)
            usb_link_drive(usb);
        top.serial_sink_valid = in && cyc >= next_rx;
        top.serial_sink_data = in ? *in : 0;
        top.serial_source_ready = room && cyc >= next_tx;
        if (gpio)
            gpio_link_cycle(gpio, top, cyc);
        // sys falls, then rises; ef is high for the first half of every ef_div sys cycles, so it
        // rises with every ef_div-th sys rise and falls ef_div/2 sys cycles later
        top.sys_clk = 0;
        top.ef_clk = frozen ? 0 : (cyc - 1) % ef_div < ef_div / 2;
        top.usb_clk = um == 1 || um == 2;
        top.eval();
        if (usb && um == 0)
            usb_link_sample(usb);
        const bool rx_take = top.serial_sink_valid && top.serial_sink_ready;
        if (byte_cycles && top.serial_sink_valid && !top.serial_sink_ready && !refused && !top.sys_rst)
            overruns++, refused = true;
        const bool tx_take = top.serial_source_valid && top.serial_source_ready;
        const uint8_t tx_byte = top.serial_source_data;
        top.sys_clk = !frozen;   // a frozen board: its CPU and ef_raster stand still (usb_wire.h)
        top.ef_clk = frozen ? 0 : cyc % ef_div < ef_div / 2;
        top.usb_clk = um <= 2;
        top.eval();
        if (rx_take)
            next_rx = cyc + byte_cycles, refused = false;
        if (tx_take)
            next_tx = cyc + byte_cycles, *out = tx_byte;
        *took = rx_take;
        cyc++;
        return tx_take;
    }
};

int main(int argc, char **argv)
{
    const char *dir = nullptr, *pty_link = nullptr, *link = nullptr, *listen_path = nullptr;
    double baud = 3e6, max_seconds = 0, sys_clk = 60e6, ef_clk = 15e6;
    const char *usb_path = nullptr;
    uint64_t probe = 0;
    int quiet = 0;
    const char *gpio_path = nullptr;
    unsigned gpio_step = 60;
    bool gpio_lockstep = false;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--dir" && i + 1 < argc)
            dir = argv[++i];
        else if (a == "--pty-link" && i + 1 < argc)
            pty_link = argv[++i];
        else if (a == "--link" && i + 1 < argc)
            link = argv[++i];
        else if (a == "--listen" && i + 1 < argc)
            listen_path = argv[++i];
        else if (a == "--baud" && i + 1 < argc)
            baud = std::atof(argv[++i]);
        else if (a == "--probe-status" && i + 1 < argc)
            probe = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--sys-clk" && i + 1 < argc)
            sys_clk = std::atof(argv[++i]);
        else if (a == "--ef-clk" && i + 1 < argc)
            ef_clk = std::atof(argv[++i]);
        else if (a == "--max-seconds" && i + 1 < argc)
            max_seconds = std::atof(argv[++i]);
        else if (a == "--faults" && i + 1 < argc) {
            std::string list = argv[++i];
            for (size_t p = 0; p <= list.size();) {
                size_t e = list.find(',', p);
                if (e == std::string::npos)
                    e = list.size();
                const std::string item = list.substr(p, e - p);
                const size_t eq = item.find('=');
                int k = 0;
                while (k < F_KINDS && (eq == std::string::npos || item.substr(0, eq) != KIND[k]))
                    k++;
                if (k == F_KINDS || (fault_at[k] = std::strtoull(item.c_str() + eq + 1, nullptr, 10)) == 0) {
                    std::fprintf(stderr, "board_sim: bad fault '%s'\n", item.c_str());
                    return 2;
                }
                p = e + 1;
            }
        } else if (a == "--quiet")
            quiet = 1;
        else if (a == "--gpio-listen" && i + 1 < argc)
            gpio_path = argv[++i];
        else if (a == "--gpio-step-cycles" && i + 1 < argc)
            gpio_step = (unsigned)std::atoi(argv[++i]);
        else if (a == "--gpio-lockstep")
            gpio_lockstep = true;
        else if (a == "--usb" && i + 1 < argc)
            usb_path = argv[++i];
        else
            usage();
    }
    if (!dir || (listen_path && (pty_link || link)))
        usage();
    GpioLink *gpio = gpio_path ? gpio_link_open(gpio_path, gpio_step, gpio_lockstep) : nullptr;
    if (gpio_path && !gpio)
        return 1;
    if (chdir(dir) != 0) {   // the $readmemh images are named relative to the gateware folder
        std::perror("board_sim: --dir");
        return 1;
    }
    std::signal(SIGTERM, on_signal);
    std::signal(SIGINT, on_signal);
    std::signal(SIGUSR1, on_usr1);
    std::signal(SIGPIPE, SIG_IGN);

    Board bd;
    const uint64_t sys_hz = (uint64_t)sys_clk;
    bd.ef_div = (uint64_t)(sys_clk / ef_clk + 0.5);
    if (bd.ef_div < 2 || bd.ef_div % 2 || std::fabs(sys_clk - ef_clk * (double)bd.ef_div) > 1) {
        std::fprintf(stderr, "board_sim: --sys-clk must be an even multiple of --ef-clk\n");
        return 2;
    }
    if (usb_path && sys_clk != 60e6) {
        std::fprintf(stderr, "board_sim: --usb needs --sys-clk 60000000 (the usb clock is a fifth of it)\n");
        return 2;
    }
    bd.byte_cycles = baud > 0 ? (uint64_t)(sys_hz * 10 / baud) : 0;   // 10 bits a byte (8N1)
    const double t0 = now_s();
    bd.reset_pins();
    if (usb_path) {   // served from the start: the device enumerates once its firmware is up
        bd.usb =
            usb_link_new(usb_path, UtmiPins{ &bd.top.utmi_rx_data, &bd.top.utmi_rx_valid, &bd.top.utmi_rx_active,
                                             &bd.top.utmi_rx_error, &bd.top.utmi_tx_ready, &bd.top.utmi_line_state,
                                             &bd.top.utmi_tx_data, &bd.top.utmi_tx_valid, &bd.top.utmi_term_select });
        if (!bd.usb)
            return 1;
        std::printf("board_sim: usb on %s\n", usb_path);
        std::fflush(stdout);
    }

    // Readiness: the firmware answers an identify control frame (docs/board.md 5.5) before
    // the host's end exists, so a host never talks to a board still booting (a UART host).
    uint8_t in[4096], out[4096];
    size_t in_len = 0, in_pos = 0, out_len = 0;
    {
        uint8_t f[20] = { 'E', 'F', 'B', '1', 0x10, 0, 0, 0, 0x5a, 0x5a, 0x5a, 0x5a, 0, 0, 0, 0 };
        const uint32_t c = (uint32_t)crc32(0, f, 16);
        for (int i = 0; i < 4; i++)
            f[16 + i] = (uint8_t)(c >> (8 * i));
        std::memcpy(in, f, sizeof f);
        in_len = sizeof f;
        static const uint8_t want[9] = { 'E', 'F', 'B', '1', 0x90, 0, 0, 0, 0x5a };
        // (not with a GPIO or USB host: the UART's identify would make the UART the engine's owner
        // for 50 ms, and the other link's first bytes would be dropped, docs/board-ulx3s.md)
        size_t got = 0, reply_left = gpio_path || usb_path ? 0 : 68;   // 16 + 48 + 4 bytes: the reply
        uint64_t sent_at = 64;   // (out of reset first) asked again every 2^22 cycles
        for (; !stop_now && reply_left;) {
            if (bd.cyc == 16)
                bd.top.sys_rst = 0;
            if (bd.cyc == sent_at + (1u << 22))
                in_pos = 0, sent_at = bd.cyc;
            bool took = false;
            uint8_t b = 0;
            if (bd.step(bd.cyc >= sent_at && in_pos < in_len ? &in[in_pos] : nullptr, &took, true, &b)) {
                if (got < sizeof want)
                    got = b == want[got] ? got + 1 : (b == 'E');
                else
                    reply_left--;
                if (got == sizeof want && reply_left == 68)
                    reply_left -= sizeof want;
            }
            if (took)
                in_pos++;
            if ((bd.cyc & ((1u << 22) - 1)) == 0 && max_seconds > 0 && now_s() - t0 > max_seconds) {
                std::fprintf(stderr, "board_sim: the firmware did not answer identify in %.0f s\n", max_seconds);
                return 1;
            }
        }
        in_len = in_pos = 0;
    }
    const double t_ready = now_s();
    bd.gpio = gpio;   // (not while the harness's own identify runs: a lockstep GPIO host would hold it)

    const uint64_t cyc_ready = bd.cyc;

    // the host's end: a pseudo-terminal (default) or a unix socket
    int fd = -1, lfd = -1;
    std::string name;
    if (listen_path) {
        lfd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0);
        sockaddr_un sa;
        std::memset(&sa, 0, sizeof sa);
        sa.sun_family = AF_UNIX;
        if (lfd < 0 || std::strlen(listen_path) >= sizeof sa.sun_path) {
            std::perror("board_sim: socket");
            return 1;
        }
        std::strcpy(sa.sun_path, listen_path);
        unlink(listen_path);
        if (bind(lfd, (sockaddr *)&sa, sizeof sa) != 0 || listen(lfd, 1) != 0) {
            std::perror("board_sim: bind/listen");
            return 1;
        }
        std::printf("board_sim: listening on %s\n", listen_path);
    } else {
        if ((fd = new_pty(name, link)) < 0) {
            std::perror("board_sim: the pty");
            return 1;
        }
        std::printf("%s\n", link ? link : name.c_str());   // alone on the first line (tests/host/serial.sh)
        if (pty_link) {
            std::string tmp = std::string(pty_link) + ".tmp";
            FILE *f = std::fopen(tmp.c_str(), "w");
            if (!f || std::fprintf(f, "%s\n", name.c_str()) < 0 || std::fclose(f) != 0 ||
                std::rename(tmp.c_str(), pty_link) != 0) {
                std::perror("board_sim: --pty-link");
                return 1;
            }
        }
    }
    std::fflush(stdout);

    uint64_t bytes_in = 0, bytes_out = 0, rst_until = bd.cyc < 16 ? 16 : 0;   // (no handshake: the reset here)
    FrameCount up, down;   // the host's frames the board took, the board's frames written to the host
    Kept kept;
    uint64_t first_in = 0, last_out = 0;   // the host's first byte taken, the board's last byte sent
    uint64_t next_probe = 0;
    size_t inj_left = 0;   // bytes of the harness's own status request still in in[]
    down.kept = &kept;
    int played[F_KINDS] = { 0, 0, 0 };
    while (!stop_now) {
        if (bd.cyc == rst_until)
            bd.top.sys_rst = 0;
        // host bytes in, board bytes out: every 256 cycles (a 3 Mbaud byte is 200 at 60 MHz)
        if ((bd.cyc & 255) == 0) {
            if (listen_path && fd < 0) {
                fd = accept4(lfd, nullptr, nullptr, SOCK_NONBLOCK);
                in_len = in_pos = out_len = 0;
            }
            if (probe && fd >= 0 && in_pos == in_len && !up.hdr_len && !up.body_left && bd.cyc >= next_probe &&
                !kept.asked) {
                // (between two of the host's frames) the harness asks the board's status itself
                uint8_t f[20] = { 'E', 'F', 'B', '1', 0x11, 0, 0, 0, 0x51, 0x51, 0x51, 0x51, 0, 0, 0, 0 };
                const uint32_t c = (uint32_t)crc32(0, f, 16);
                for (int i = 0; i < 4; i++)
                    f[16 + i] = (uint8_t)(c >> (8 * i));
                std::memcpy(in, f, sizeof f);
                in_len = inj_left = sizeof f, in_pos = 0;
                next_probe = bd.cyc + probe;
                kept.asked = true;
            }
            if (fd >= 0 && in_pos == in_len) {
                ssize_t n = read(fd, in, sizeof in);
                if (n > 0) {
                    in_len = (size_t)n, in_pos = 0;
                } else if (listen_path && (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK))) {
                    close(fd);   // the host went away: the board keeps its run
                    fd = -1;
                }
            }
            if (fd >= 0 && out_len) {
                ssize_t n = write(fd, out, out_len);
                if (n > 0) {
                    down.add(out, (size_t)n);
                    std::memmove(out, out + n, out_len - (size_t)n);
                    out_len -= (size_t)n;
                } else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
                    out_len = 0;   // nobody reads (no host on the pty): the bytes are lost, as on a wire
                }
            }
            // the board's faults, after the host's N-th frame
            const unsigned long long frames = up.frames;
            if (fault_at[F_STALL] && !played[F_STALL] && frames >= fault_at[F_STALL]) {
                played[F_STALL] = 1;
                unstall = 0;
                std::fprintf(stderr, "board_sim: stalled after the host's frame %llu (until SIGUSR1)\n", frames);
                while (!unstall && !stop_now)
                    usleep(10000);   // nothing moves: no clock, no byte
                std::fprintf(stderr, "board_sim: the stall ends\n");
            }
            if (fault_at[F_RESET] && !played[F_RESET] && down.frames >= fault_at[F_RESET]) {
                played[F_RESET] = 1;
                bd.top.sys_rst = 1;
                rst_until = bd.cyc + 16;
                out_len = 0;   // the bytes the board had not sent die with it
                std::fprintf(stderr, "board_sim: reset after the board's frame %llu to the host\n", down.frames);
            }
            if (fault_at[F_UNPLUG] && !played[F_UNPLUG] && frames >= fault_at[F_UNPLUG] && !listen_path) {
                played[F_UNPLUG] = 1;
                // (said before the hang-up: a test reads it once the host has seen it)
                std::fprintf(stderr, "board_sim: unplugged after the host's frame %llu\n", frames);
                close(fd);   // the host's side hangs up
                in_len = in_pos = out_len = 0;
                if ((fd = new_pty(name, link)) < 0) {
                    std::perror("board_sim: the new pty");
                    return 1;
                }
                std::fprintf(stderr, "board_sim: the line is back at %s\n", name.c_str());
            }
            if ((bd.cyc & ((1u << 22) - 1)) == 0 && max_seconds > 0 && now_s() - t0 > max_seconds)
                break;
            if (bd.usb)
                usb_link_poll(bd.usb);
        }
        bool took = false;
        uint8_t b = 0;
        if (bd.step(in_pos < in_len ? &in[in_pos] : nullptr, &took, out_len < sizeof out, &b))
            out[out_len++] = b, bytes_out++, last_out = bd.cyc;
        if (took && inj_left) {
            in_pos++, inj_left--;
        } else if (took) {   // the host's frames are counted as the board takes their bytes
            if (!bytes_in)
                first_in = bd.cyc;
            up.add(&in[in_pos++], 1), bytes_in++;
        }
    }
    const double dt = now_s() - t0;
    char ov[64] = "";   // (a paced line only: unpaced, the harness feeds the FIFO as fast as it takes)
    if (bd.byte_cycles)
        std::snprintf(ov, sizeof ov, ", UART receive FIFO overruns %llu", (unsigned long long)bd.overruns);
    if (!quiet)
        std::fprintf(stderr,
                     "board_sim: %llu sys cycles (%.3f s simulated) in %.1f s (%.0f cycles/s), ready after %llu "
                     "cycles (%.1f s), %llu bytes in, %llu bytes out, the host's first byte to the board's last %.6f s "
                     "simulated, result frames kept at most %u (%llu status probes)%s%s%s%s\n",
                     (unsigned long long)bd.cyc, bd.cyc / (double)sys_hz, dt, bd.cyc / dt,
                     (unsigned long long)cyc_ready, t_ready - t0, (unsigned long long)bytes_in,
                     (unsigned long long)bytes_out, last_out > first_in ? (last_out - first_in) / (double)sys_hz : 0.0,
                     (unsigned)kept.most, kept.probes, played[F_STALL] ? ", stalled" : "",
                     played[F_RESET] ? ", reset" : "", played[F_UNPLUG] ? ", unplugged" : "", ov);
    if (gpio)
        gpio_link_close(gpio, (double)sys_hz);
    if (bd.usb) {
        if (!quiet)
            usb_link_report(bd.usb, bd.cyc / (double)sys_hz, dt);
        usb_link_free(bd.usb);
    }
    bd.top.final();
    if (link)
        unlink(link);
    return 0;
}
