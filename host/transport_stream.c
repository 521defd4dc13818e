/*
 * transport_stream.c - the byte-stream layer of the socket and serial
 * transports (transport_stream.h, docs/board.md section 5.5).
 *
 * The stream carries the frames of docs/board.md section 2 unchanged; identify,
 * status and reset travel in the same stream as control frames (0x10-0x12,
 * replies 0x90-0x92, the seq field a tag echoed by the board).  Everything the
 * board sends goes through a small streaming scanner that takes the control
 * replies out and passes every other byte to host_link in order, so the
 * protocol above sees exactly what it would see on USB.
 */
#define _POSIX_C_SOURCE 200809L
#include "transport_stream.h"

#include <errno.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "ef_frame.h"
#include "transport.h"

enum { CTL_REPLY = 0x80, CTL_TRIES = 4, CTL_IDENTIFY = 0x10 };

long long ef_stream_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

void ef_stream_init(ef_stream *s, const char *addr, int timeout_ms, int socket)
{
    memset(s, 0, sizeof *s);
    s->fd = -1;
    s->timeout_ms = timeout_ms;
    s->socket = socket;
    snprintf(s->addr, sizeof s->addr, "%s", addr);
}

static int gone(ef_stream *s, const char *what, int e)
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
static size_t take_reply(ef_stream *s, size_t p, size_t size)
{
    const uint8_t type = s->in[p + 4];
    const uint32_t tag = ef_get32(s->in + p + 8), n = ef_get32(s->in + p + 12);
    const int ours = s->want_type && type == s->want_type && tag == s->tag && !s->got;
    if (ours) {
        memcpy(s->reply, s->in + p + EF_PROTO_HEADER, n);
        s->reply_len = n;
        s->got = 1;
    }
    const size_t from = ours && type == (EF_FT_RESET | CTL_REPLY) ? 0 : p;
    memmove(s->in + from, s->in + p + size, s->len - p - size);
    s->len -= p + size - from;
    if (from == 0)
        s->pass = 0, s->skip = 0;
    return from;
}

/* Scans the bytes after pass: whole non-control frames (and bytes that are no
 * frame) become deliverable, control replies are taken out; a frame start whose
 * kind cannot be told yet is held until more bytes arrive. */
static void scan(ef_stream *s)
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
        if (n > EF_STREAM_CTL_PAYLOAD_MAX) {
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
static int receive(ef_stream *s, int ms)
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
    const ssize_t n =
        s->socket ? recv(s->fd, s->in + s->len, s->cap - s->len, 0) : read(s->fd, s->in + s->len, s->cap - s->len);
    if (n == 0 && !s->socket && !(pfd.revents & (POLLHUP | POLLERR)))
        return EF_HOST_ETIMEDOUT; /* a raw tty's read with nothing to give (VMIN 0) */
    if (n == 0)
        return gone(s, s->socket ? "the board closed the connection" : "the line hung up", 0);
    if (n < 0) {
        if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)
            return EF_HOST_ETIMEDOUT;
        return gone(s, "receive", errno);
    }
    s->len += (size_t)n;
    scan(s);
    return 0;
}

int ef_stream_write(ef_stream *s, const uint8_t *buf, size_t len, int timeout_ms)
{
    if (s->gone)
        return EF_HOST_ENODEV;
    if (timeout_ms <= 0)
        timeout_ms = s->timeout_ms;
    long long deadline = ef_stream_now_ms() + timeout_ms;
    while (len) {
        const ssize_t n = s->socket ? send(s->fd, buf, len, MSG_NOSIGNAL) : write(s->fd, buf, len);
        if (n > 0) {
            buf += n, len -= (size_t)n;
            deadline = ef_stream_now_ms() + timeout_ms; /* the timeout bounds a wait with no progress */
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
            return gone(s, "send", errno);
        /* No room: wait for it, and keep reading meanwhile so that a board
         * blocked on sending to us can never deadlock the pair. */
        const long long left = deadline - ef_stream_now_ms();
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

int ef_stream_flush(ef_stream *s)
{
    return s->gone ? EF_HOST_ENODEV : 0; /* write() hands every byte to the kernel before it returns */
}

int ef_stream_control(ef_stream *s, int type, uint8_t *out, uint32_t want_len)
{
    static const char *const NAME[] = { "identify", "status", "reset" };
    for (int t = 0; t < CTL_TRIES; t++) {
        uint8_t req[EF_PROTO_HEADER + EF_PROTO_TRAILER];
        s->tag++;
        s->want_type = type | CTL_REPLY;
        s->got = 0;
        ef_frame_put(req, (uint8_t)type, 0, s->tag, NULL, 0);
        int r = ef_stream_write(s, req, sizeof req, s->timeout_ms);
        const long long deadline = ef_stream_now_ms() + s->timeout_ms;
        while (!r && !s->got) {
            const long long left = deadline - ef_stream_now_ms();
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

int ef_stream_read(ef_stream *s, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    *got = 0;
    const long long deadline = ef_stream_now_ms() + (timeout_ms > 0 ? timeout_ms : 0);
    while (s->pass == 0) {
        const long long left = deadline - ef_stream_now_ms();
        const int r = receive(s, left > 0 ? (int)left : 0);
        if (r && r != EF_HOST_ETIMEDOUT)
            return r;
        if (r == EF_HOST_ETIMEDOUT && ef_stream_now_ms() >= deadline && s->pass == 0)
            return EF_HOST_ETIMEDOUT;
    }
    const size_t n = s->pass < cap ? s->pass : cap;
    memcpy(buf, s->in, n);
    memmove(s->in, s->in + n, s->len - n);
    s->len -= n, s->pass -= n;
    *got = n;
    return 0;
}

void ef_stream_close(ef_stream *s)
{
    if (s->fd >= 0)
        close(s->fd);
    s->fd = -1;
    free(s->in);
    s->in = NULL;
}

/* ------------------------------------------------- the transport operations */
int ef_stream_op_identify(ef_link *l, uint8_t out[48])
{
    return ef_stream_control((ef_stream *)l, EF_FT_IDENTIFY, out, EF_PROTO_IDENTIFY_LEN);
}

int ef_stream_op_status(ef_link *l, uint8_t out[40])
{
    return ef_stream_control((ef_stream *)l, EF_FT_STATUS, out, EF_PROTO_STATUS_LEN);
}

int ef_stream_op_reset(ef_link *l) { return ef_stream_control((ef_stream *)l, EF_FT_RESET, NULL, 0); }

int ef_stream_op_write(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms)
{
    return ef_stream_write((ef_stream *)l, buf, len, timeout_ms);
}

int ef_stream_op_flush(ef_link *l, int timeout_ms)
{
    (void)timeout_ms;
    return ef_stream_flush((ef_stream *)l);
}

int ef_stream_op_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    return ef_stream_read((ef_stream *)l, buf, cap, got, timeout_ms);
}

const char *ef_stream_op_detail(ef_link *l) { return l ? ((ef_stream *)l)->err : ""; }
