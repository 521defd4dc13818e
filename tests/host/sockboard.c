/*
 * sockboard.c - the board engine of board/ with the C model as its DUT,
 * behind a unix socket (docs/board.md section 5.5): what a Verilator
 * simulation or a TCP bridge in front of a board does, so that the engine's
 * own answers to the control frames (identify, status, reset in the byte
 * stream) are tested end to end through edgeflag-host's socket transport.
 *
 * usage: sockboard [--hang-dut] PATH [CUT]   (serves one connection at a time
 * until killed; the run outlives a connection, as a board's does).  CUT > 0
 * closes the first connection once CUT bytes have come from the host, in the
 * middle of a frame when CUT falls there: a board that went away mid-stream,
 * for --resume.  --hang-dut: the DUT never returns from its first command (a
 * CPU loop inside the engine, as a mutant of board/ef_board.c that spins has;
 * tests/mutants/c-mutants.sh runs those), for the test of the signals.
 *
 * SIGTERM and SIGINT end it at once, whatever it is doing (idle in poll or
 * spinning in the engine): the handler removes the socket file, so no stale
 * one is left for the next board, and the process dies of the signal (exit
 * status 143 or 130 in a shell, as docs/cli.md says the project's programs
 * do).  It holds nothing else that outlives it: the board's run is in memory
 * only, as a board's is across a power cycle.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include "ef_board.h"

static unsigned long long cut; /* bytes from the host until the connection is cut (0: never) */
static char sock_path[sizeof((struct sockaddr_un *)0)->sun_path];

/* SIGTERM, SIGINT: async-signal-safe calls only.  The handler was installed
 * with SA_RESETHAND, so the signal raised here (blocked until the handler
 * returns) takes the default action: the process dies of it. */
static void on_term(int sig)
{
    if (sock_path[0])
        unlink(sock_path);
    raise(sig);
}

/* --hang-dut: the C model's DUT with a push that never returns. */
static int hang_push(void *self, const uint8_t cmd[EF_PROTO_CMD_BYTES])
{
    volatile int spin = 1;
    (void)self;
    (void)cmd;
    while (spin)
        ;
    return 0;
}

/* Moves bytes both ways until the connection ends. */
static void serve(ef_board *b, int fd)
{
    static uint8_t in[1 << 16], out[1 << 16];
    size_t out_len = 0, out_pos = 0;
    for (;;) {
        if (out_pos == out_len) {
            out_pos = 0;
            out_len = ef_board_tx(b, out, sizeof out);
        }
        struct pollfd p = { fd, POLLIN | (out_pos < out_len ? POLLOUT : 0), 0 };
        if (poll(&p, 1, 1000) < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        if (p.revents & POLLOUT) {
            const ssize_t n = send(fd, out + out_pos, out_len - out_pos, MSG_NOSIGNAL);
            if (n < 0 && errno != EAGAIN && errno != EINTR)
                break;
            if (n > 0)
                out_pos += (size_t)n;
        }
        if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
            const ssize_t n = recv(fd, in, cut && cut < sizeof in ? (size_t)cut : sizeof in, 0);
            if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR))
                break;
            if (cut && n > 0 && (cut -= (unsigned long long)n) == 0) {
                ef_board_rx(b, in, (size_t)n); /* the last bytes arrive, then the link is gone */
                break;
            }
            if (n > 0 && ef_board_rx(b, in, (size_t)n) != 0) {
                fprintf(stderr, "sockboard: the receive buffer is full (the host broke the window)\n");
                break;
            }
        }
    }
    close(fd);
    ef_board_link_lost(b); /* a half-sent frame of ours is gone with the connection */
}

int main(int argc, char **argv)
{
    struct sockaddr_un a = { .sun_family = AF_UNIX };
    const int hang = argc > 1 && strcmp(argv[1], "--hang-dut") == 0;
    argc -= hang, argv += hang;
    if (argc < 2 || argc > 3 || strlen(argv[1]) >= sizeof a.sun_path) {
        fprintf(stderr, "usage: sockboard [--hang-dut] PATH [CUT]\n");
        return 2;
    }
    if (argc == 3)
        cut = strtoull(argv[2], NULL, 10);
    strcpy(a.sun_path, argv[1]);
    struct sigaction sa = { .sa_handler = on_term, .sa_flags = SA_RESETHAND };
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGTERM); /* one handler at a time: the first signal wins */
    sigaddset(&sa.sa_mask, SIGINT);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGINT, &sa, NULL);
    const ef_proto_info info = { "EFSOCK0001",
                                 EF_PROTO_CAP_RESULTS | EF_PROTO_CAP_RESUME | EF_PROTO_CAP_INTERNAL,
                                 1u << 3 | 1u << 4 | 1u << 5,
                                 16384,
                                 16384,
                                 1u << 22,
                                 16,
                                 (1u << 7) - 1 };
    ef_board_dut dut = ef_board_dut_model();
    if (hang)
        dut.push = hang_push;
    ef_board *b = ef_board_new(&info, dut);
    const int ls = socket(AF_UNIX, SOCK_STREAM, 0);
    unlink(a.sun_path);
    if (!b || ls < 0 || bind(ls, (struct sockaddr *)&a, sizeof a) < 0 || listen(ls, 4) < 0) {
        fprintf(stderr, "sockboard: %s: %s\n", a.sun_path, strerror(errno));
        return 1;
    }
    memcpy(sock_path, a.sun_path, sizeof sock_path); /* ours now: the handler removes it */
    for (;;) {
        const int fd = accept(ls, NULL, NULL);
        if (fd >= 0)
            serve(b, fd);
    }
}
