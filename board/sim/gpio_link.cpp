// gpio_link.cpp - the simulated board's GPIO header (gpio_link.h; docs/board-gpio.md section 8,
// "Co-simulation with the gateware").
//
// The channel: a unix stream socket.  Every GPIO call the host makes (a write of its 12 lines or a
// read of the board's 12) is one step: the client sends 2 bytes (little-endian: bits 7:0 d0..d7,
// 8 clk, 9 valid, 10 take, 11 ctl: the levels the host drives after this call), the board applies
// them to the SoC's pins, lets at least step_cycles sys cycles pass, samples its own pins and
// answers 2 bytes (bits 7:0 q0..q7, 8 ready, 9 avail, 10 done, 11 err).  So each host step lasts
// at least step_cycles of the board's time (default 60: 1 us at the simulation's 60 MHz, a fast
// single-board computer's GPIO call), whatever the wall-clock speed of either side; the board's
// clock runs on between steps as a real board's does (with lockstep it does not: the board's time
// then advances only by steps, so throughput in board time is that of a host stepping every
// step_cycles).  A client that goes away leaves the host's lines low, as the header's pull-downs
// do on an unplugged board.
#include "gpio_link.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include "Vsim.h"

struct GpioLink {
    int lfd = -1, fd = -1;
    unsigned step_cycles = 60;
    bool lockstep = false;
    bool serving = false;   // a step is under way: reply at reply_at
    uint64_t reply_at = 0;
    uint64_t last_msg = 0;   // the cycle of the last step (fast polling while the host is busy)
    unsigned host = 0;       // the host's lines now
    unsigned shown = 0;      // the board's lines in the last reply
    // what moved, counted at the host's rising clk edges from the lines the host had seen
    uint64_t steps = 0, edges = 0, bytes_in = 0, bytes_out = 0, ctl_edges = 0, clients = 0;
    uint64_t first_cyc = 0, last_cyc = 0;
};

enum { H_CLK = 1u << 8, H_VALID = 1u << 9, H_TAKE = 1u << 10, H_CTL = 1u << 11 };
enum { B_READY = 1u << 8, B_AVAIL = 1u << 9 };

GpioLink *gpio_link_open(const char *path, unsigned step_cycles, bool lockstep)
{
    GpioLink *g = new GpioLink;
    g->step_cycles = step_cycles ? step_cycles : 1;
    g->lockstep = lockstep;
    sockaddr_un sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sun_family = AF_UNIX;
    g->lfd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0);
    if (g->lfd < 0 || std::strlen(path) >= sizeof sa.sun_path) {
        std::perror("board_sim: --gpio-listen");
        delete g;
        return nullptr;
    }
    std::strcpy(sa.sun_path, path);
    unlink(path);
    if (bind(g->lfd, (sockaddr *)&sa, sizeof sa) != 0 || listen(g->lfd, 1) != 0) {
        std::perror("board_sim: --gpio-listen bind/listen");
        close(g->lfd);
        delete g;
        return nullptr;
    }
    std::printf("board_sim: GPIO header on %s (a host step >= %u sys cycles%s)\n", path, g->step_cycles,
                lockstep ? ", lockstep" : "");
    return g;
}

static void drive(Vsim &top, unsigned host)
{
    top.ef_gpio_d = host & 0xFF;
    top.ef_gpio_clk = (host & H_CLK) != 0;
    top.ef_gpio_valid = (host & H_VALID) != 0;
    top.ef_gpio_take = (host & H_TAKE) != 0;
    top.ef_gpio_ctl = (host & H_CTL) != 0;
}

static unsigned sample(const Vsim &top)
{
    return (unsigned)(top.ef_gpio_q & 0xFF) | (top.ef_gpio_ready ? 1u << 8 : 0) | (top.ef_gpio_avail ? 1u << 9 : 0) |
           (top.ef_gpio_done ? 1u << 10 : 0) | (top.ef_gpio_err ? 1u << 11 : 0);
}

static void drop_client(GpioLink *g, Vsim &top)
{
    close(g->fd);
    g->fd = -1;
    g->serving = false;
    g->host = 0;   // the pull-downs
    drive(top, 0);
}

// Reads one step if one is there (2 bytes; a stream socket may split them: wait for the second).
static bool next_step(GpioLink *g, Vsim &top, uint64_t cyc, int wait_ms)
{
    uint8_t m[2];
    if (wait_ms > 0) {
        pollfd p = { g->fd, POLLIN, 0 };
        if (poll(&p, 1, wait_ms) <= 0)
            return false;
    }
    ssize_t n = recv(g->fd, m, 2, MSG_DONTWAIT);
    if (n == 1) {
        pollfd p = { g->fd, POLLIN, 0 };
        if (poll(&p, 1, 1000) == 1 && recv(g->fd, m + 1, 1, 0) == 1)
            n = 2;
    }
    if (n != 2) {
        if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) || n == 1)
            drop_client(g, top);
        return false;
    }
    const unsigned host = (unsigned)m[0] | (unsigned)m[1] << 8;
    if (!(g->host & H_CLK) && (host & H_CLK)) {   // a bus edge, judged by what the host had seen
        g->edges++;
        if (host & H_CTL)
            g->ctl_edges++;
        else if (!(g->host & H_CTL)) {
            g->bytes_in += (host & H_VALID) && (g->shown & B_READY);
            g->bytes_out += (host & H_TAKE) && (g->shown & B_AVAIL);
        }
    }
    g->host = host;
    drive(top, host);
    g->serving = true;
    g->reply_at = cyc + g->step_cycles;
    if (!g->steps++)
        g->first_cyc = cyc;
    g->last_msg = cyc;
    return true;
}

void gpio_link_cycle(GpioLink *g, Vsim &top, uint64_t cyc)
{
    if (g->fd < 0) {
        if ((cyc & 255) == 0) {
            g->fd = accept4(g->lfd, nullptr, nullptr, SOCK_NONBLOCK);
            if (g->fd >= 0)
                g->clients++, g->shown = sample(top);
        }
        return;
    }
    if (g->serving) {
        if (cyc < g->reply_at)
            return;
        g->shown = sample(top);
        uint8_t r[2] = { (uint8_t)g->shown, (uint8_t)(g->shown >> 8) };
        g->serving = false;
        g->last_cyc = cyc;
        if (send(g->fd, r, 2, MSG_NOSIGNAL) != 2) {
            drop_client(g, top);
            return;
        }
    }
    // the next step: in lockstep the board waits for it (its time stands still meanwhile, but
    // for one cycle every 20 ms so that a client that went away is noticed); otherwise it looks
    // often while the host is busy, now and then while it is not
    if (g->lockstep)
        next_step(g, top, cyc, 20);
    else if (cyc - g->last_msg < 4096 ? (cyc & 3) == 0 : (cyc & 63) == 0)
        next_step(g, top, cyc, 0);
}

void gpio_link_close(GpioLink *g, double sys_hz)
{
    if (!g)
        return;
    const double t = (double)(g->last_cyc - g->first_cyc) / sys_hz;
    std::fprintf(stderr,
                 "board_sim: GPIO: %llu host steps, %llu bus cycles (%llu in the control view), %llu bytes to the "
                 "board, %llu to the host, in %.6f s of board time (first to last step): %.0f bus cycles/s, "
                 "%.0f stream bytes/s; %llu client(s)\n",
                 (unsigned long long)g->steps, (unsigned long long)g->edges, (unsigned long long)g->ctl_edges,
                 (unsigned long long)g->bytes_in, (unsigned long long)g->bytes_out, t, t > 0 ? g->edges / t : 0.0,
                 t > 0 ? (g->bytes_in + g->bytes_out) / t : 0.0, (unsigned long long)g->clients);
    if (g->fd >= 0)
        close(g->fd);
    close(g->lfd);
    delete g;
}
