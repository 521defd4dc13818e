/*
 * transport_socket.c - a board at the other end of one byte stream (docs/board.md
 * section 5.5): a unix socket or a TCP connection, e.g. a TCP bridge to a lab
 * machine's board or a Verilator simulation that exposes the board on a socket.
 *
 * The stream and its control frames are transport_stream.c's (shared with
 * the serial transport); this file dials the address.
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
#include <unistd.h>

#include "ef_frame.h"
#include "transport.h"
#include "transport_stream.h"

enum { DEFAULT_TIMEOUT_MS = 2000 };

typedef ef_stream sock_link;

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
    ef_stream_init(s, o->connect, o->timeout_ms > 0 ? o->timeout_ms : DEFAULT_TIMEOUT_MS, 1);
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

static void sock_close(ef_link *l)
{
    sock_link *s = (sock_link *)l;
    if (!s)
        return;
    ef_stream_close(s);
    free(s);
}

static int sock_probe(const ef_host_opts *o, ef_found *found, int max)
{
    (void)o, (void)found, (void)max;
    return 0; /* sockets are not probed: the address is always named */
}

static const char *sock_version(void) { return "built in (POSIX sockets: --connect unix:PATH or tcp:HOST:PORT)"; }

const ef_transport_ops ef_transport_socket = {
    "socket",           sock_probe,         sock_open,          ef_stream_op_identify, ef_stream_op_status,
    ef_stream_op_reset, ef_stream_op_write, ef_stream_op_flush, ef_stream_op_read,     sock_close,
    sock_version,       ef_stream_op_detail
};
