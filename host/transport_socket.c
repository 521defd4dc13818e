/*
 * transport_socket.c - a board at the other end of one byte stream (docs/board.md
 * section 5.5): a unix socket or a TCP connection, e.g. a TCP bridge to a lab
 * machine's board or a Verilator simulation that exposes the board on a socket.
 *
 * The stream carries the frames of docs/board.md section 2 unchanged; identify,
 * status and reset travel in the same stream as control frames (0x10-0x12,
 * replies 0x90-0x92, the seq field a tag echoed by the board).  Everything the
 * board sends goes through a small streaming scanner that takes the control
 * replies out and passes every other byte to host_link in order, so the
 * protocol above sees exactly what it would see on USB.
 *
 * POSIX sockets, non-blocking, every wait bounded by poll() and the timeout.
 * The end of the stream, ECONNRESET and EPIPE are EF_HOST_ENODEV (the board
 * went away: the run is resumable); nobody listening (ECONNREFUSED, no such
 * socket file, unknown host) is EF_HOST_ENOTFOUND naming the address.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

#include "ef_board.h"
#include "ef_frame.h"
#include "transport.h"

enum {
    CTL_IDENTIFY = 0x10,
    CTL_STATUS = 0x11,
    CTL_RESET = 0x12,
    CTL_REPLY = 0x80,
    CTL_TRIES = 4,
    CTL_PAYLOAD_MAX = 64,
    DEFAULT_TIMEOUT_MS = 2000
};

typedef struct sock_link {
    int fd, timeout_ms, gone;
    char addr[300];
    char err[400];
    uint8_t *in; /* bytes from the board: [0, pass) for host_link, [pass, len) not yet scanned */
    size_t pass, len, cap;
    size_t skip;   /* bytes of a non-control frame still to pass through unscanned */
    uint32_t tag;  /* the last control request's tag */
    int want_type; /* reply type awaited (0: none) */
    int got;       /* the awaited reply arrived */
    uint8_t reply[CTL_PAYLOAD_MAX];
    uint32_t reply_len;
} sock_link;

static long long now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

static int gone(sock_link *s, const char *what, int e)
{
    s->gone = 1;
    if (e)
        snprintf(s->err, sizeof s->err, "%s: %s: %s", s->addr, what, strerror(e));
    else
        snprintf(s->err, sizeof s->err, "%s: %s", s->addr, what);
    return EF_HOST_ENODEV;
}

/* Takes out the control reply at in[p], size bytes; a reset's reply also drops
 * every board byte before it (the old run's, docs/board.md 5.5).  Returns
 * where scanning goes on. */
static size_t take_reply(sock_link *s, size_t p, size_t size)
{
    const uint8_t type = s->in[p + 4];
    const uint32_t tag = ef_get32(s->in + p + 8), n = ef_get32(s->in + p + 12);
    const int ours = s->want_type && type == s->want_type && tag == s->tag && !s->got;
    if (ours) {
        memcpy(s->reply, s->in + p + EF_PROTO_HEADER, n);
        s->reply_len = n;
        s->got = 1;
    }
    const size_t from = ours && type == (CTL_RESET | CTL_REPLY) ? 0 : p;
    memmove(s->in + from, s->in + p + size, s->len - p - size);
    s->len -= p + size - from;
    if (from == 0)
        s->pass = 0, s->skip = 0;
    return from;
}

/* Scans the bytes after pass: whole non-control frames (and bytes that are no
 * frame) become deliverable, control replies are taken out; a frame start whose
 * kind cannot be told yet is held until more bytes arrive. */
static void scan(sock_link *s)
{
    size_t p = s->pass;
    while (p < s->len) {
        if (s->skip) {
            const size_t n = s->len - p < s->skip ? s->len - p : s->skip;
            p += n, s->skip -= n;
            continue;
        }
        const size_t avail = s->len - p;
        if (memcmp(s->in + p, EF_PROTO_MAGIC, avail < 4 ? avail : 4) != 0) {
            const uint8_t *e = memchr(s->in + p + 1, 'E', avail - 1);
            p = e ? (size_t)(e - s->in) : s->len; /* no frame here: host_link resyncs */
            continue;
        }
        if (avail < EF_PROTO_HEADER)
            break;
        const uint8_t type = s->in[p + 4];
        const uint32_t n = ef_get32(s->in + p + 12);
        if (s->in[p + 6] || s->in[p + 7] || n > EF_PROTO_PAYLOAD_MAX) {
            p++;
            continue;
        }
        if ((type & 0xf0) != 0x90) {
            s->skip = EF_PROTO_HEADER + n + EF_PROTO_TRAILER;
            continue;
        }
        const size_t size = EF_PROTO_HEADER + n + EF_PROTO_TRAILER;
        if (n > CTL_PAYLOAD_MAX) {
            p++;
            continue;
        }
        if (avail < size)
            break;
        if (ef_frame_crc32(0, s->in + p, EF_PROTO_HEADER + n) != ef_get32(s->in + p + EF_PROTO_HEADER + n)) {
            p++; /* damaged: never seen, the request is retried */
            continue;
        }
        p = take_reply(s, p, size); /* 0 after a reset's reply */
    }
    s->pass = p < s->len ? p : s->len;
}

/* Waits up to ms for bytes from the board and scans them.  0 when some came. */
static int receive(sock_link *s, int ms)
{
    if (s->gone)
        return EF_HOST_ENODEV;
    if (s->cap - s->len < 65536) {
        const size_t cap = s->cap ? s->cap * 2 : 1 << 18;
        uint8_t *p = realloc(s->in, cap);
        if (!p)
            return EF_HOST_ENOMEM;
        s->in = p, s->cap = cap;
    }
    struct pollfd pfd = { s->fd, POLLIN, 0 };
    const int r = poll(&pfd, 1, ms < 0 ? 0 : ms);
    if (r < 0)
        return errno == EINTR ? EF_HOST_ETIMEDOUT : gone(s, "poll", errno);
    if (r == 0)
        return EF_HOST_ETIMEDOUT;
    const ssize_t n = recv(s->fd, s->in + s->len, s->cap - s->len, 0);
    if (n == 0)
        return gone(s, "the board closed the connection", 0);
    if (n < 0) {
        if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)
            return EF_HOST_ETIMEDOUT;
        return gone(s, "receive", errno);
    }
    s->len += (size_t)n;
    scan(s);
    return 0;
}

static int send_all(sock_link *s, const uint8_t *buf, size_t len, int timeout_ms)
{
    if (s->gone)
        return EF_HOST_ENODEV;
    long long deadline = now_ms() + timeout_ms;
    while (len) {
        const ssize_t n = send(s->fd, buf, len, MSG_NOSIGNAL);
        if (n > 0) {
            buf += n, len -= (size_t)n;
            deadline = now_ms() + timeout_ms; /* the timeout bounds a wait with no progress */
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
            return gone(s, "send", errno);
        /* No room: wait for it, and keep reading meanwhile so that a board
         * blocked on sending to us can never deadlock the pair. */
        const long long left = deadline - now_ms();
        if (left <= 0) {
            snprintf(s->err, sizeof s->err, "%s: no room to send for %d ms", s->addr, timeout_ms);
            return EF_HOST_ETIMEDOUT;
        }
        struct pollfd pfd = { s->fd, POLLOUT | POLLIN, 0 };
        const int r = poll(&pfd, 1, (int)left);
        if (r < 0 && errno != EINTR)
            return gone(s, "poll", errno);
        if (r > 0 && (pfd.revents & (POLLIN | POLLHUP | POLLERR)) && !(pfd.revents & POLLOUT)) {
            const int e = receive(s, 0);
            if (e && e != EF_HOST_ETIMEDOUT)
                return e;
        }
    }
    return 0;
}

/* One non-blocking connect bounded by the timeout: 0 with s->fd connected, or an errno. */
static int connect_one(sock_link *s, int family, const struct sockaddr *sa, socklen_t salen, int timeout_ms)
{
    s->fd = socket(family, SOCK_STREAM | SOCK_CLOEXEC, 0);
    int e = 0;
    if (s->fd < 0 || fcntl(s->fd, F_SETFL, O_NONBLOCK) < 0) {
        e = errno;
    } else if (connect(s->fd, sa, salen) < 0) {
        e = errno;
        if (e == EINPROGRESS) {
            struct pollfd pfd = { s->fd, POLLOUT, 0 };
            socklen_t el = sizeof e;
            const int p = poll(&pfd, 1, timeout_ms);
            if (p == 0)
                e = ETIMEDOUT;
            else if (p < 0 || getsockopt(s->fd, SOL_SOCKET, SO_ERROR, &e, &el) < 0)
                e = errno;
        }
    }
    if (e && s->fd >= 0) {
        close(s->fd);
        s->fd = -1;
    }
    return e;
}

/* "unix:PATH" or "tcp:HOST:PORT" ("tcp:[v6]:PORT"): a connected, non-blocking socket.  addr is
 * never NULL (sock_open refuses a missing --connect before it dials). */
static int dial(sock_link *s, const char *addr, int timeout_ms, char *err, size_t errlen)
{
    struct addrinfo *ai = NULL, hints = { 0 };
    struct sockaddr_un un = { 0 };
    const struct sockaddr *sa;
    socklen_t salen;
    int family;
    if (strncmp(addr, "unix:", 5) == 0 && addr[5] && strlen(addr + 5) < sizeof un.sun_path) {
        un.sun_family = AF_UNIX;
        strcpy(un.sun_path, addr + 5);
        sa = (const struct sockaddr *)&un, salen = sizeof un, family = AF_UNIX;
    } else if (strncmp(addr, "tcp:", 4) == 0 && strrchr(addr + 4, ':')) {
        char host[256];
        const char *colon = strrchr(addr + 4, ':'), *h = addr + 4;
        size_t hl = (size_t)(colon - h);
        if (hl >= 2 && h[0] == '[' && h[hl - 1] == ']')
            h++, hl -= 2;
        if (hl == 0 || hl >= sizeof host || !colon[1]) {
            snprintf(err, errlen, "--connect '%s': expected unix:PATH or tcp:HOST:PORT", addr);
            return EF_HOST_EINVAL;
        }
        memcpy(host, h, hl);
        host[hl] = 0;
        hints.ai_socktype = SOCK_STREAM;
        const int g = getaddrinfo(host, colon + 1, &hints, &ai);
        if (g) {
            snprintf(err, errlen, "%s: %s", addr, gai_strerror(g));
            return g == EAI_SERVICE ? EF_HOST_EINVAL : EF_HOST_ENOTFOUND;
        }
        sa = ai->ai_addr, salen = ai->ai_addrlen, family = ai->ai_family;
    } else {
        snprintf(err, errlen, "--connect '%s': expected unix:PATH or tcp:HOST:PORT", addr);
        return EF_HOST_EINVAL;
    }
    /* every address the name has (a name may give ::1 and 127.0.0.1), the first that answers */
    int e = 0;
    for (struct addrinfo *i = ai; !ai || i; i = i ? i->ai_next : NULL) {
        if (i)
            sa = i->ai_addr, salen = i->ai_addrlen, family = i->ai_family;
        e = connect_one(s, family, sa, salen, timeout_ms);
        if (!e || !ai)
            break;
    }
    if (ai)
        freeaddrinfo(ai);
    if (e) {
        snprintf(err, errlen, "%s: %s (is the board, bridge or simulation listening?)", addr, strerror(e));
        return e == EACCES || e == EPERM ? EF_HOST_EACCESS
               : e == ECONNREFUSED || e == ENOENT || e == ETIMEDOUT || e == EHOSTUNREACH || e == ENETUNREACH
                   ? EF_HOST_ENOTFOUND
                   : EF_HOST_EIO;
    }
    if (family != AF_UNIX) {
        const int one = 1;
        setsockopt(s->fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    }
    return 0;
}

static int sock_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)
{
    if (!o->connect) {
        snprintf(err, errlen, "--transport socket needs --connect unix:PATH or tcp:HOST:PORT");
        return EF_HOST_EINVAL;
    }
    sock_link *s = calloc(1, sizeof *s);
    if (!s)
        return EF_HOST_ENOMEM;
    s->fd = -1;
    s->timeout_ms = o->timeout_ms > 0 ? o->timeout_ms : DEFAULT_TIMEOUT_MS;
    snprintf(s->addr, sizeof s->addr, "%s", o->connect);
    const int r = dial(s, o->connect, s->timeout_ms, err, errlen);
    if (r) {
        if (s->fd >= 0)
            close(s->fd);
        free(s);
        return r;
    }
    *out = (ef_link *)s;
    return 0;
}

/* One control request (docs/board.md 5.5): up to CTL_TRIES tries with a new tag each. */
static int control(sock_link *s, int type, uint8_t *out, uint32_t want_len)
{
    static const char *const NAME[] = { "identify", "status", "reset" };
    for (int t = 0; t < CTL_TRIES; t++) {
        uint8_t req[EF_PROTO_HEADER + EF_PROTO_TRAILER];
        s->tag++;
        s->want_type = type | CTL_REPLY;
        s->got = 0;
        ef_frame_put(req, (uint8_t)type, 0, s->tag, NULL, 0);
        int r = send_all(s, req, sizeof req, s->timeout_ms);
        const long long deadline = now_ms() + s->timeout_ms;
        while (!r && !s->got) {
            const long long left = deadline - now_ms();
            if (left <= 0)
                break;
            r = receive(s, (int)left);
            if (r == EF_HOST_ETIMEDOUT)
                r = 0;
        }
        s->want_type = 0;
        if (r && r != EF_HOST_ETIMEDOUT)
            return r;
        if (s->got) {
            if (s->reply_len != want_len) {
                snprintf(s->err, sizeof s->err, "%s: %s reply of %u bytes, not %u", s->addr, NAME[type - CTL_IDENTIFY],
                         s->reply_len, want_len);
                return EF_HOST_EPROTO;
            }
            if (want_len)
                memcpy(out, s->reply, want_len);
            return 0;
        }
    }
    snprintf(s->err, sizeof s->err, "%s: no %s reply in %d tries of %d ms", s->addr, NAME[type - CTL_IDENTIFY],
             CTL_TRIES, s->timeout_ms);
    return EF_HOST_ETIMEDOUT;
}

static int sock_identify(ef_link *l, uint8_t out[48])
{
    return control((sock_link *)l, CTL_IDENTIFY, out, EF_PROTO_IDENTIFY_LEN);
}

static int sock_status(ef_link *l, uint8_t out[40])
{
    return control((sock_link *)l, CTL_STATUS, out, EF_PROTO_STATUS_LEN);
}

static int sock_reset(ef_link *l) { return control((sock_link *)l, CTL_RESET, NULL, 0); }

static int sock_write(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms)
{
    sock_link *s = (sock_link *)l;
    return send_all(s, buf, len, timeout_ms > 0 ? timeout_ms : s->timeout_ms);
}

static int sock_flush(ef_link *l, int timeout_ms)
{
    (void)timeout_ms; /* write() hands every byte to the kernel before it returns */
    return ((sock_link *)l)->gone ? EF_HOST_ENODEV : 0;
}

static int sock_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    sock_link *s = (sock_link *)l;
    *got = 0;
    const long long deadline = now_ms() + (timeout_ms > 0 ? timeout_ms : 0);
    while (s->pass == 0) {
        const long long left = deadline - now_ms();
        const int r = receive(s, left > 0 ? (int)left : 0);
        if (r && r != EF_HOST_ETIMEDOUT)
            return r;
        if (r == EF_HOST_ETIMEDOUT && now_ms() >= deadline && s->pass == 0)
            return EF_HOST_ETIMEDOUT;
    }
    const size_t n = s->pass < cap ? s->pass : cap;
    memcpy(buf, s->in, n);
    memmove(s->in, s->in + n, s->len - n);
    s->len -= n, s->pass -= n;
    *got = n;
    return 0;
}

static void sock_close(ef_link *l)
{
    sock_link *s = (sock_link *)l;
    if (!s)
        return;
    if (s->fd >= 0)
        close(s->fd);
    free(s->in);
    free(s);
}

static int sock_probe(const ef_host_opts *o, ef_found *found, int max)
{
    (void)o, (void)found, (void)max;
    return 0; /* sockets are not probed: the address is always named */
}

static const char *sock_version(void) { return "built in (POSIX sockets: --connect unix:PATH or tcp:HOST:PORT)"; }

static const char *sock_detail(ef_link *l) { return l ? ((sock_link *)l)->err : ""; }

const ef_transport_ops ef_transport_socket = { "socket",    sock_probe, sock_open,    sock_identify,
                                               sock_status, sock_reset, sock_write,   sock_flush,
                                               sock_read,   sock_close, sock_version, sock_detail };
