// board_sim.cpp - the whole ULX3S board in Verilator (docs/board-ulx3s.md,
// "The board simulated"): the SoC's Verilog as LiteX writes it for the
// simulation target of board/soc/soc.py (VexRiscv, the firmware in its ROM,
// ef_raster and its frame memory, the UART), clocked as on the board (sys 60
// MHz, ef 15 MHz: four sys cycles per ef cycle), its UART connected to a
// pseudo-terminal -- or a unix socket -- so that edgeflag-host drives it
// through the same code a real board gets.
//
// The UART is joined at the UART core's PHY stream (LiteX's "sim" PHY: a
// byte with valid/ready each way), not at the pins: the harness paces that
// stream at the line rate (--baud, default 3,000,000: one byte every 10 bit
// times of simulated time, 200 sys cycles at 3 Mbaud), so the firmware sees
// bytes arrive and leave as fast as the FT231X would bring them.
//
//   board_sim --dir GATEWARE_DIR [--pty-link FILE] [--listen PATH] [--baud N]
//             [--max-seconds S] [--quiet] [--gpio-listen PATH [--gpio-step-cycles N] [--gpio-lockstep]]
//             [--usb PATH]
//
// --dir: where the memory images (sim_rom.init, ...) are.  With --pty-link
// the pseudo-terminal's name (/dev/pts/N) is written into FILE; it is always
// the first line of the standard output; with --listen the board listens on the unix socket PATH instead
// (one host at a time; a host's disconnection keeps the board's run, as a
// powered board keeps it).  On SIGTERM or SIGINT, or after --max-seconds of
// wall time, it prints the cycles simulated and the bytes moved, and exits 0.  --gpio-listen: the
// SoC's GPIO bus pins behind a unix socket for the emulated gpiochip of the tests (gpio_link.cpp).
// --usb PATH: the SoC's USB device on a unix socket for tests/host/usb_emu.c
// (--soc), through the host controller of usb_link.cpp (the usb clock is 12
// MHz: one every 5 sys cycles).
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <string>
#include <sys/socket.h>
#include <sys/un.h>
#include <termios.h>
#include <unistd.h>

#include "Vsim.h"
#include "gpio_link.h"
#include "usb_link.h"
#include "verilated.h"

static volatile sig_atomic_t stop_now;
static void on_signal(int) { stop_now = 1; }

static double now_s()
{
    timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec * 1e-9;
}

static void usage()
{
    std::fprintf(stderr, "usage: board_sim --dir GATEWARE_DIR [--pty-link FILE | --listen PATH] [--baud N] "
                         "[--max-seconds S] [--quiet] [--gpio-listen PATH [--gpio-step-cycles N] "
                         "[--gpio-lockstep]]\n");
    std::exit(2);
}

int main(int argc, char **argv)
{
    const char *dir = nullptr, *pty_link = nullptr, *listen_path = nullptr, *usb_path = nullptr;
    double baud = 3e6, max_seconds = 0;
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
        else if (a == "--listen" && i + 1 < argc)
            listen_path = argv[++i];
        else if (a == "--baud" && i + 1 < argc)
            baud = std::atof(argv[++i]);
        else if (a == "--max-seconds" && i + 1 < argc)
            max_seconds = std::atof(argv[++i]);
        else if (a == "--usb" && i + 1 < argc)
            usb_path = argv[++i];
        else if (a == "--quiet")
            quiet = 1;
        else if (a == "--gpio-listen" && i + 1 < argc)
            gpio_path = argv[++i];
        else if (a == "--gpio-step-cycles" && i + 1 < argc)
            gpio_step = (unsigned)std::atoi(argv[++i]);
        else if (a == "--gpio-lockstep")
            gpio_lockstep = true;
        else
            usage();
    }
    if (!dir || (pty_link && listen_path))
        usage();

    // the host's end: a pseudo-terminal (default) or a unix socket
    int fd = -1, lfd = -1;
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
        fd = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (fd < 0 || grantpt(fd) != 0 || unlockpt(fd) != 0) {
            std::perror("board_sim: posix_openpt");
            return 1;
        }
        const char *name = ptsname(fd);
        // raw until the host sets its own mode: no echo, no line discipline
        int sfd = open(name, O_RDWR | O_NOCTTY);
        if (sfd >= 0) {
            termios t;
            if (tcgetattr(sfd, &t) == 0) {
                cfmakeraw(&t);
                tcsetattr(sfd, TCSANOW, &t);
            }
            close(sfd);
        }
        std::printf("%s\n", name);   // the path alone on the first line (tests/host/serial.sh reads it)
        if (pty_link) {
            std::string tmp = std::string(pty_link) + ".tmp";
            FILE *f = std::fopen(tmp.c_str(), "w");
            if (!f || std::fprintf(f, "%s\n", name) < 0 || std::fclose(f) != 0 ||
                std::rename(tmp.c_str(), pty_link) != 0) {
                std::perror("board_sim: --pty-link");
                return 1;
            }
        }
    }
    GpioLink *gpio = gpio_path ? gpio_link_open(gpio_path, gpio_step, gpio_lockstep) : nullptr;
    if (gpio_path && !gpio)
        return 1;
    std::fflush(stdout);
    if (chdir(dir) != 0) {   // the $readmemh images are named relative to the gateware folder
        std::perror("board_sim: --dir");
        return 1;
    }
    std::signal(SIGTERM, on_signal);
    std::signal(SIGINT, on_signal);
    std::signal(SIGPIPE, SIG_IGN);

    VerilatedContext ctx;
    Vsim top(&ctx);
    const uint64_t sys_hz = 60000000;
    const uint64_t byte_cycles = baud > 0 ? (uint64_t)(sys_hz * 10 / baud) : 0;   // 10 bits a byte (8N1)
    uint8_t in[4096], out[4096];
    size_t in_len = 0, in_pos = 0, out_len = 0;
    uint64_t next_rx = 0, next_tx = 0, bytes_in = 0, bytes_out = 0;
    const double t0 = now_s();

    top.sys_rst = 1;
    top.serial_sink_valid = 0;
    top.serial_source_ready = 0;
    top.sim_trace = 0;
    top.utmi_line_state = 2;   // J: an idle bus, no reset
    UsbLink *usb = nullptr;
    if (usb_path) {
        usb = usb_link_new(usb_path, UtmiPins{ &top.utmi_rx_data, &top.utmi_rx_valid, &top.utmi_rx_active,
                                               &top.utmi_rx_error, &top.utmi_tx_ready, &top.utmi_line_state,
                                               &top.utmi_tx_data, &top.utmi_tx_valid, &top.utmi_term_select });
        if (!usb)
            return 1;
        std::printf("board_sim: usb on %s\n", usb_path);
        std::fflush(stdout);
    }
    uint64_t cyc = 0;
    for (; !stop_now; cyc++) {
        if (cyc == 16)
            top.sys_rst = 0;
        // host bytes in, board bytes out: every 256 cycles (a 3 Mbaud byte is 200)
        if ((cyc & 255) == 0) {
            if (listen_path && fd < 0) {
                fd = accept4(lfd, nullptr, nullptr, SOCK_NONBLOCK);
                in_len = in_pos = out_len = 0;
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
                    std::memmove(out, out + n, out_len - (size_t)n);
                    out_len -= (size_t)n;
                } else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
                    out_len = 0;   // nobody reads (no host on the pty): the bytes are lost, as on a wire
                }
            }
            if ((cyc & ((1u << 22) - 1)) == 0 && max_seconds > 0 && now_s() - t0 > max_seconds)
                break;
            if (usb)
                usb_link_poll(usb);
        }
        // usb rises with every fifth sys rise (12 MHz): its inputs before, its outputs between
        const unsigned um = (unsigned)(cyc % 5);
        const bool frozen = usb && usb_link_frozen(usb);
        if (usb && um == 0)
            usb_link_drive(usb);
        // the UART's PHY streams, at the line rate
        top.serial_sink_valid = in_pos < in_len && cyc >= next_rx;
        top.serial_sink_data = in_pos < in_len ? in[in_pos] : 0;
        top.serial_source_ready = out_len < sizeof out && cyc >= next_tx;
        if (gpio)
            gpio_link_cycle(gpio, top, cyc);
        // sys falls, then rises; ef is high for sys cycles 0 and 1 of every 4, so it rises
        // with every fourth sys rise and falls two sys cycles later
        top.sys_clk = 0;
        top.ef_clk = frozen ? 0 : ((cyc - 1) & 3) < 2;
        top.usb_clk = um == 1 || um == 2;
        top.eval();
        if (usb && um == 0)
            usb_link_sample(usb);
        const bool rx_take = top.serial_sink_valid && top.serial_sink_ready;
        const bool tx_take = top.serial_source_valid && top.serial_source_ready;
        const uint8_t tx_byte = top.serial_source_data;
        top.sys_clk = !frozen;   // a frozen board: its CPU and ef_raster stand still (usb_wire.h)
        top.ef_clk = frozen ? 0 : (cyc & 3) < 2;
        top.usb_clk = um <= 2;
        top.eval();
        if (rx_take) {
            in_pos++, bytes_in++;
            next_rx = cyc + byte_cycles;
        }
        if (tx_take) {
            out[out_len++] = tx_byte, bytes_out++;
            next_tx = cyc + byte_cycles;
        }
    }
    const double dt = now_s() - t0;
    if (!quiet)
        std::fprintf(stderr,
                     "board_sim: %llu sys cycles (%.3f s simulated) in %.1f s (%.0f cycles/s), %llu bytes in, "
                     "%llu bytes out\n",
                     (unsigned long long)cyc, cyc / (double)sys_hz, dt, cyc / dt, (unsigned long long)bytes_in,
                     (unsigned long long)bytes_out);
    if (gpio)
        gpio_link_close(gpio, (double)sys_hz);
    if (usb) {
        if (!quiet)
            usb_link_report(usb, cyc / (double)sys_hz, dt);
        usb_link_free(usb);
    }
    top.final();
    return 0;
}
