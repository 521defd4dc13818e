/*
 * transport_null.c - a link to nowhere, for `edgeflag-host bench --transport
 * null`: frames are built, CRC'd and handed over exactly as for a real link,
 * then dropped; the "board" answers each numbered frame with an ACK at once.
 * What the bench measures through it is the host's own cost per byte, which
 * must stay far below any real link's (docs/board.md section 8).
 */
#include <stdlib.h>
#include <string.h>

#include "ef_board.h"
#include "ef_frame.h"
#include "transport.h"

typedef struct null_link {
    uint32_t next; /* one past the highest numbered frame seen */
    int ack_due;
    uint8_t ack[EF_PROTO_HEADER + 12 + EF_PROTO_TRAILER];
} null_link;

static int null_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)
{
    (void)o, (void)err, (void)errlen;
    null_link *n = calloc(1, sizeof *n);
    if (!n)
        return EF_HOST_ENOMEM;
    *out = (ef_link *)n;
    return 0;
}

static int null_identify(ef_link *l, uint8_t out[48])
{
    (void)l;
    memset(out, 0, 48);
    memcpy(out, EF_PROTO_MAGIC, 4);
    out[4] = EF_PROTO_PROTOCOL;
    out[6] = 64; /* window */
    ef_put32(out + 16, 1u << 3 | 1u << 4 | 1u << 5);
    ef_put32(out + 20, 16384);
    ef_put32(out + 24, 16384);
    ef_put32(out + 28, 1u << 22);
    memcpy(out + 32, "NULL", 4);
    return 0;
}

static int null_status(ef_link *l, uint8_t out[40])
{
    memset(out, 0, 40);
    memcpy(out, EF_PROTO_MAGIC, 4);
    out[4] = EF_PROTO_PROTOCOL;
    ef_put32(out + 8, ((null_link *)l)->next);
    return 0;
}

static int null_reset(ef_link *l)
{
    ((null_link *)l)->next = 0;
    return 0;
}

static int null_write(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms)
{
    null_link *n = (null_link *)l;
    (void)timeout_ms;
    if (len >= EF_PROTO_HEADER && buf[4] != EF_FT_ACKR) {
        n->next = ef_get32(buf + 8) + 1;
        n->ack_due = 1;
    }
    return 0;
}

static int null_flush(ef_link *l, int timeout_ms)
{
    (void)l, (void)timeout_ms;
    return 0;
}

static int null_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    null_link *n = (null_link *)l;
    (void)timeout_ms;
    *got = 0;
    if (!n->ack_due || cap < sizeof n->ack)
        return EF_HOST_ETIMEDOUT;
    uint8_t p[12];
    ef_put32(p, n->next);
    ef_put32(p + 4, 64);
    ef_put32(p + 8, 0);
    *got = ef_frame_put(buf, EF_FT_ACK, 0, 0, p, sizeof p);
    n->ack_due = 0;
    return 0;
}

static void null_close(ef_link *l) { free(l); }

static int null_probe(const ef_host_opts *o, ef_found *found, int max)
{
    (void)o, (void)found, (void)max;
    return 0;
}

static const char *null_version(void) { return "built in (no link: measures the host's own cost)"; }

const ef_transport_ops ef_transport_null = { "null",     null_probe, null_open, null_identify, null_status,  null_reset,
                                             null_write, null_flush, null_read, null_close,    null_version, NULL };
