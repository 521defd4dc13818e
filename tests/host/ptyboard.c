/*
 * ptyboard.c - a board behind a pseudo-terminal, for edgeflag-host's serial
 * transport (docs/board-serial.md): what a USB UART in front of a board looks
 * like to the host, with the wire's speed and faults under the test's control.
 *
 *   ptyboard [OPTIONS]             the board engine of board/ with the C model
 *                                  as its DUT behind a new pty
 *   ptyboard --to TTY [OPTIONS]    a relay: a new pty for the host, TTY (another
 *                                  board's pty, e.g. a Verilated SoC's UART) behind it
 *
 * It prints the path the host opens (the --link symlink, else the pty's own
 * name) on its first line of standard output, then moves bytes until SIGTERM.
 *
 *   --link PATH       a symlink to the pty, kept across an unplug (a new pty)
 *   --rate B          bytes per second each way (a 3 Mbaud 8N1 line: 300000)
 *   --faults LIST     KIND=N,...: on the bytes from the host (N counts them from 1)
 *                     flip (one bit of byte N inverted), drop, dup (sent twice);
 *                     on the board's bytes flip-down, drop-down, dup-down; and
 *                     after the host's N-th frame (whole frames counted by their
 *                     headers) stall (nothing moves for --stall-ms), unplug (the
 *                     host's pty closed and a new one made at --link; the board
 *                     keeps its run) and reset (the board resets: a reset control
 *                     frame sent to it, docs/board.md 5.5)
 *   --stall-ms MS     how long a stall lasts (default 3000)
 *   --serial NAME     the engine's identify serial (default EFPTY0001)
 *   --result-queue N  the engine's result queue bound in frames (docs/board.md
 *                     4.2; 0: none); at exit the most frames it kept at once
 *                     is printed on standard error
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "ef_board.h"
#include "ef_frame.h"

enum { F_FLIP, F_DROP, F_DUP, F_FLIP_DOWN, F_DROP_DOWN, F_DUP_DOWN, F_STALL, F_UNPLUG, F_RESET, F_KINDS };
static const char *const KIND[F_KINDS] = { "flip",     "drop",  "dup",    "flip-down", "drop-down",
                                           "dup-down", "stall", "unplug", "reset" };
static unsigned long long fault_at[F_KINDS];

static volatile sig_atomic_t stop;
static void on_term(int sig)
{
    (void)sig;
    stop = 1;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void raw(int fd)
{
    struct termios t;
    if (tcgetattr(fd, &t) == 0) {
        cfmakeraw(&t);
        t.c_cflag |= CLOCAL | CREAD;
        t.c_cc[VMIN] = 0, t.c_cc[VTIME] = 0;
        tcsetattr(fd, TCSANOW, &t);
    }
}

/* A new pty for the host: the master (returned), the slave held open by us
 * too (so the master never sees a hang-up between two host processes) and
 * set raw, and the symlink. */
static int slave_keep = -1;
static int new_pty(const char *link, char *name, size_t size)
{
    const int m = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0 || ptsname_r(m, name, size) != 0)
        return -1;
    if (slave_keep >= 0)
        close(slave_keep);
    slave_keep = open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (slave_keep < 0)
        return -1;
    raw(slave_keep);
    if (link) {
        char tmp[4200];
        snprintf(tmp, sizeof tmp, "%s.new", link);
        unlink(tmp);
        if (symlink(name, tmp) != 0 || rename(tmp, link) != 0)
            return -1;
    }
    return m;
}

/* A byte queue. */
typedef struct q {
    uint8_t b[1 << 18];
    size_t head, len;
} q;
static size_t q_room(const q *x) { return sizeof x->b - x->len; }
static void q_put(q *x, const uint8_t *p, size_t n)
{
    if (x->head + x->len + n > sizeof x->b) {
        memmove(x->b, x->b + x->head, x->len);
        x->head = 0;
    }
    memcpy(x->b + x->head + x->len, p, n);
    x->len += n;
}
static void q_drop(q *x, size_t n)
{
    x->head += n, x->len -= n;
    if (!x->len)
        x->head = 0;
}

/* Faults on one direction's bytes (pos counts them from 1). */
static size_t mangle(const uint8_t *in, size_t n, uint8_t *out, unsigned long long *pos, int flip, int drop, int dup)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        const unsigned long long p = ++*pos;
        uint8_t c = in[i];
        if (p == fault_at[drop])
            continue;
        if (p == fault_at[flip])
            c ^= 0x10;
        out[k++] = c;
        if (p == fault_at[dup])
            out[k++] = c;
    }
    return k;
}

/* Counts whole frames of the host's stream by their headers. */
static unsigned long long frames;
static uint8_t hdr[16];
static size_t hdr_len, body_left;
static void count_frames(const uint8_t *p, size_t n, unsigned long long *first_done)
{
    for (size_t i = 0; i < n; i++) {
        if (body_left) {
            if (--body_left == 0)
                frames++;
            continue;
        }
        if (hdr_len < 4 && p[i] != (uint8_t)EF_PROTO_MAGIC[hdr_len]) {
            hdr_len = p[i] == 'E';
            hdr[0] = p[i];
            continue;
        }
        hdr[hdr_len++] = p[i];
        if (hdr_len == 16) {
            const uint32_t len = ef_get32(hdr + 12);
            body_left = len <= EF_PROTO_PAYLOAD_MAX ? len + 4 : 0;
            hdr_len = 0;
        }
    }
    *first_done = frames;
}

int main(int argc, char **argv)
{
    const char *link = NULL, *to = NULL, *serial = "EFPTY0001";
    double rate = 0;
    int stall_ms = 3000;
    long queue = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!v) {
            fprintf(stderr, "ptyboard: %s needs a value\n", a);
            return 2;
        }
        i++;
        if (strcmp(a, "--link") == 0)
            link = v;
        else if (strcmp(a, "--to") == 0)
            to = v;
        else if (strcmp(a, "--serial") == 0)
            serial = v;
        else if (strcmp(a, "--rate") == 0)
            rate = strtod(v, NULL);
        else if (strcmp(a, "--stall-ms") == 0)
            stall_ms = atoi(v);
        else if (strcmp(a, "--result-queue") == 0)
            queue = atol(v);
        else if (strcmp(a, "--faults") == 0) {
            char buf[512];
            snprintf(buf, sizeof buf, "%s", v);
            for (char *sv, *t = strtok_r(buf, ",", &sv); t; t = strtok_r(NULL, ",", &sv)) {
                char *eq = strchr(t, '=');
                int k = 0;
                if (eq)
                    *eq = 0;
                while (k < F_KINDS && strcmp(KIND[k], t) != 0)
                    k++;
                if (!eq || k == F_KINDS || (fault_at[k] = strtoull(eq + 1, NULL, 10)) == 0) {
                    fprintf(stderr, "ptyboard: bad fault '%s'\n", t);
                    return 2;
                }
            }
        } else {
            fprintf(stderr, "usage: ptyboard [--to TTY] [--link PATH] [--rate B] [--faults LIST] [--stall-ms MS] "
                            "[--serial NAME] [--result-queue N]\n");
            return 2;
        }
    }
    const struct sigaction sa = { .sa_handler = on_term };
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGINT, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);

    ef_board *b = NULL;
    int bfd = -1;
    if (to) {
        bfd = open(to, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
        if (bfd < 0) {
            fprintf(stderr, "ptyboard: %s: %s\n", to, strerror(errno));
            return 1;
        }
        raw(bfd);
        tcflush(bfd, TCIOFLUSH);
    } else {
        ef_proto_info info = { .capabilities = EF_PROTO_CAP_RESULTS | EF_PROTO_CAP_RESUME | EF_PROTO_CAP_INTERNAL,
                               .samples_mask = 7u << 3, /* 8, 16 and 32 */
                               .width_max = 1u << 14,
                               .height_max = 1u << 14,
                               .edges_max = 1u << 22,
                               .window = 16,
                               .iface_mask = 0x7f }; /* every interface */
        snprintf(info.serial, sizeof info.serial, "%s", serial);
        b = ef_board_new(&info, ef_board_dut_model());
        if (!b)
            return 1;
        if (queue >= 0)
            ef_board_set_result_queue(b, (uint32_t)queue);
    }
    char name[256];
    int m = new_pty(link, name, sizeof name);
    if (m < 0) {
        fprintf(stderr, "ptyboard: cannot make a pty: %s\n", strerror(errno));
        return 1;
    }
    printf("%s\n", link ? link : name);
    fflush(stdout);

    static q up, down; /* host -> board, board -> host */
    static uint8_t buf[1 << 16], mb[1 << 17];
    unsigned long long up_pos = 0, down_pos = 0, done_frames = 0;
    int stalled = 0, unplugged = 0, reset_done = 0;
    double stall_end = 0, t_last = now(), tok_up = 0, tok_down = 0, last_rx = now();
    /* the bucket holds 50 ms of the line: a relay the scheduler left waiting catches up, as a
     * UART's buffers do, and the average never exceeds the rate */
    const double burst = rate > 0 ? (rate / 20 > 64 ? rate / 20 : 64) : 0;
    while (!stop) {
        const double t = now();
        if (rate > 0) {
            tok_up += (t - t_last) * rate, tok_down += (t - t_last) * rate;
            if (tok_up > burst)
                tok_up = burst;
            if (tok_down > burst)
                tok_down = burst;
        }
        t_last = t;
        if (stalled && t >= stall_end)
            stalled = 0;
        /* frame-counted faults */
        if (!stalled && fault_at[F_STALL] && done_frames >= fault_at[F_STALL]) {
            fault_at[F_STALL] = 0, stalled = 1, stall_end = t + stall_ms / 1000.0;
        }
        if (fault_at[F_UNPLUG] && !unplugged && done_frames >= fault_at[F_UNPLUG]) {
            unplugged = 1;
            close(m);
            up.len = down.len = 0, up.head = down.head = 0;
            if (b)
                ef_board_link_lost(b);
            if ((m = new_pty(link, name, sizeof name)) < 0)
                return 1;
            /* the host's open copy of the old slave sees the hang-up once ours is gone too */
        }
        if (fault_at[F_RESET] && !reset_done && done_frames >= fault_at[F_RESET]) {
            reset_done = 1;
            uint8_t f[EF_PROTO_HEADER + EF_PROTO_TRAILER];
            ef_frame_put(f, EF_FT_RESET, 0, 0x7e7e7e7e, NULL, 0); /* a tag the host never uses first */
            if (b)
                ef_board_reset(b);
            else
                q_put(&up, f, sizeof f);
        }
        if (stalled) {
            usleep(1000);
            continue;
        }
        /* the board side */
        if (b) {
            if (up.len) {
                ef_board_rx(b, up.b + up.head, up.len);
                q_drop(&up, up.len);
                last_rx = t;
            } else if (t - last_rx > 1.0) { /* a line idle for 1 s: no frame is still coming */
                ef_board_rx_idle(b);
                last_rx = t;
            }
            if (q_room(&down) > 2 * sizeof buf) {
                const size_t n = ef_board_tx(b, buf, sizeof buf);
                if (n)
                    q_put(&down, mb, mangle(buf, n, mb, &down_pos, F_FLIP_DOWN, F_DROP_DOWN, F_DUP_DOWN));
            }
        } else {
            if (up.len) {
                const ssize_t n = write(bfd, up.b + up.head, up.len);
                if (n > 0)
                    q_drop(&up, (size_t)n);
            }
            if (q_room(&down) > 2 * sizeof buf) {
                const ssize_t n = read(bfd, buf, sizeof buf);
                if (n > 0)
                    q_put(&down, mb, mangle(buf, (size_t)n, mb, &down_pos, F_FLIP_DOWN, F_DROP_DOWN, F_DUP_DOWN));
                else if (n < 0 && errno != EAGAIN && errno != EINTR) {
                    fprintf(stderr, "ptyboard: the board's tty %s went away\n", to);
                    break;
                }
            }
        }
        /* the host side: what the rate allows */
        int moved = 0;
        if (down.len) {
            size_t n = down.len;
            if (rate > 0 && n > (size_t)tok_down)
                n = (size_t)tok_down;
            const ssize_t w = n ? write(m, down.b + down.head, n) : 0; /* what the pty has room for */
            if (w > 0) {
                q_drop(&down, (size_t)w);
                tok_down -= (double)w, moved = 1;
            }
        }
        size_t room = q_room(&up) / 2;
        if (rate > 0 && room > (size_t)tok_up)
            room = (size_t)tok_up;
        if (room > sizeof buf)
            room = sizeof buf;
        if (room) {
            const ssize_t n = read(m, buf, room);
            if (n > 0) {
                count_frames(buf, (size_t)n, &done_frames);
                q_put(&up, mb, mangle(buf, (size_t)n, mb, &up_pos, F_FLIP, F_DROP, F_DUP));
                tok_up -= (double)n, moved = 1;
            }
        }
        if (!moved) {
            /* (room to write to the host wakes it too, unless the rate is what holds the bytes) */
            const short out = down.len && (rate <= 0 || tok_down >= 1) ? POLLOUT : 0;
            struct pollfd p[2] = { { m, (short)(POLLIN | out), 0 }, { bfd, POLLIN, 0 } };
            poll(p, bfd >= 0 ? 2 : 1, rate > 0 ? 1 : 5);
        }
    }
    if (link)
        unlink(link);
    if (b) {
        ef_board_stats st;
        ef_board_get_stats(b, &st);
        fprintf(stderr, "ptyboard: result frames kept at most %u at once (the last run)\n", (unsigned)st.res_peak);
        ef_board_free(b);
    }
    return 0;
}
