/*
 * ef_board.c - the board's protocol engine (docs/board.md sections 2-4).
 *
 * Receive side: bytes accumulate in rx[] until a whole frame parses.  Host
 * frames are numbered from 0 (START) and taken strictly in order (go-back-N):
 * the expected one is processed and acknowledged, an earlier one (a
 * retransmission of a frame already taken) is only re-acknowledged, a later
 * one or a damaged one is answered with one NAK naming the expected sequence
 * number, after which the host resends from there.  So a frame is never lost
 * and never taken twice.
 *
 * Transmit side: ACK/NAK are small and unnumbered.  RESULT, DONE and ERROR
 * are numbered in their own sequence from 0 and kept until the host's ACKR
 * acknowledges them, at most `window` of them unacknowledged on the wire; an
 * ACKR with the RESEND flag rewinds transmission to the host's next expected
 * result frame.
 */
#include "ef_board.h"

#include <stdlib.h>
#include <string.h>

#include "ef_frame.h"

/* RESULT frames are cut at this payload size; a board with little RAM builds
 * with a smaller one (-DEF_BOARD_RESULT_PAYLOAD=1024: its frames kept for the
 * window then take window x 1 KiB). */
#ifndef EF_BOARD_RESULT_PAYLOAD
#define EF_BOARD_RESULT_PAYLOAD 32768u
#endif
#define RESULT_PAYLOAD ((uint32_t)EF_BOARD_RESULT_PAYLOAD)
/* The result queue's bound (docs/board.md 4.2): at most this many result
 * frames made and not yet acknowledged, plus the one being filled.  While it
 * is full the engine gives the DUT no command (the rest of a DATA frame waits)
 * and the DUT holds its records (ef_board_results_full()): on a slow link the
 * DUT is back-pressured instead of its results piling up in RAM.  0: no bound. */
#ifndef EF_BOARD_RESULT_QUEUE
#define EF_BOARD_RESULT_QUEUE 32u
#endif
#if EF_BOARD_RESULT_QUEUE > 0 && EF_BOARD_RESULT_QUEUE < 4
#error "EF_BOARD_RESULT_QUEUE: at least 4 (the host acknowledges results after every 4 it has written)"
#endif

typedef struct rframe { /* a numbered board -> host frame */
    uint8_t *bytes;
    size_t size;
} rframe;

typedef struct hframe { /* a host frame received in order, not yet taken whole */
    uint8_t type;
    uint32_t len, off; /* payload bytes, and those already given to the DUT */
    uint32_t crc;      /* the payload's CRC-32 */
    uint8_t *payload;
} hframe;

struct ef_board {
    ef_proto_info info;
    ef_board_dut dut;
    int dut_started;

    uint8_t *rx; /* received bytes not yet parsed */
    size_t rx_len, rx_cap;
    ef_frame_part rx_part; /* the payload CRC so far of the frame begun at rx[0] */
    int nak_pending;       /* a NAK was sent for rx_seq; no more until progress */
    /* frames received in order (rx_seq counts them) and not yet taken whole,
     * because the result queue was full or the DUT busy: ack_seq .. rx_seq-1 */
    hframe *held;
    uint32_t nheld, held_cap, ack_seq, queue_max, res_peak;

    uint8_t *tx; /* bytes for the host, from tx_head */
    size_t tx_head, tx_len, tx_cap;

    rframe *res; /* numbered frames res_acked .. res_next-1 */
    size_t res_cap;
    uint32_t res_acked, res_sent, res_next;
    uint8_t *cur; /* RESULT payload being filled */
    size_t cur_len;

    uint32_t mode, iface_mask, samples;
    uint64_t source_left;
    int source_end; /* source mode: 1 END taken, 2 its DONE made */
    uint64_t cmd_count;
    uint64_t result_bytes;
    uint32_t results_crc;
    uint64_t records_sent; /* records in RESULT frames (DONE's count outside digest runs) */
    /* digest and select runs (docs/board.md 4.5): per interface, transactions
     * so far and the current window's CRC-32 and count */
    uint32_t run_flags, dg_n;
    uint64_t dg_total[EF_PROTO_IFACES];
    /* the window of each interface's last transaction, (dg_total - 1) / dg_n, and
     * its place in it, counted (no division per transaction) */
    uint64_t dg_win[EF_PROTO_IFACES];
    uint32_t dg_pos[EF_PROTO_IFACES];
    uint32_t dg_crc[EF_PROTO_IFACES], dg_cnt[EF_PROTO_IFACES];
    uint32_t *sel, nsel; /* select: interface << 24 | window, ascending */
    ef_board_stats st;
};

/* ------------------------------------------------------------ output queue */
static int tx_append(ef_board *b, const uint8_t *p, size_t n)
{
    if (b->tx_head && b->tx_head == b->tx_len)
        b->tx_head = b->tx_len = 0;
    if (b->tx_len + n > b->tx_cap) {
        if (b->tx_head) { /* compact first */
            memmove(b->tx, b->tx + b->tx_head, b->tx_len - b->tx_head);
            b->tx_len -= b->tx_head;
            b->tx_head = 0;
        }
        if (b->tx_len + n > b->tx_cap) {
            size_t cap = b->tx_cap ? b->tx_cap : 65536;
            while (cap < b->tx_len + n)
                cap *= 2;
            uint8_t *t = realloc(b->tx, cap);
            if (!t)
                return -1;
            b->tx = t, b->tx_cap = cap;
        }
    }
    memcpy(b->tx + b->tx_len, p, n);
    b->tx_len += n;
    return 0;
}

static void send_small(ef_board *b, uint8_t type, uint32_t seq, const uint8_t *payload, uint32_t len)
{
    uint8_t f[EF_PROTO_HEADER + 64 + EF_PROTO_TRAILER];
    (void)tx_append(b, f, ef_frame_put(f, type, 0, seq, payload, len));
}

static void send_ack(ef_board *b)
{
    uint8_t p[12];
    ef_put32(p, b->ack_seq);         /* all below are taken (rx_seq less those held) */
    ef_put32(p + 4, b->info.window); /* credits */
    ef_put32(p + 8, b->res_next);    /* result frames made so far */
    send_small(b, EF_FT_ACK, 0, p, sizeof p);
}

static void send_nak(ef_board *b, uint32_t reason)
{
    if (b->nak_pending)
        return;
    uint8_t p[8];
    ef_put32(p, b->st.rx_seq);
    ef_put32(p + 4, reason);
    send_small(b, EF_FT_NAK, 0, p, sizeof p);
    b->nak_pending = 1;
    b->st.naks++;
}

/* ------------------------------------------------------- numbered frames */
static int res_push(ef_board *b, uint8_t type, const uint8_t *payload, uint32_t len)
{
    const uint32_t k = b->res_next - b->res_acked;
    if (k >= b->res_cap) {
        size_t cap = b->res_cap ? 2 * b->res_cap : 64;
        rframe *r = realloc(b->res, cap * sizeof *r);
        if (!r)
            return -1;
        b->res = r, b->res_cap = cap;
    }
    uint8_t *f = malloc(EF_PROTO_HEADER + (size_t)len + EF_PROTO_TRAILER);
    if (!f)
        return -1;
    b->res[k].bytes = f;
    uint32_t cp;
    b->res[k].size = ef_frame_put_crc(f, type, 0, b->res_next, payload, len, &cp);
    if (type == EF_FT_RESULT) { /* the results' CRC for DONE, from the same pass */
        b->results_crc = ef_frame_crc32_combine(b->results_crc, cp, len);
        b->result_bytes += len;
    }
    b->res_next++;
    if (b->res_next - b->res_acked > b->res_peak)
        b->res_peak = b->res_next - b->res_acked;
    return 0;
}

/* Puts numbered frames on the wire while the window allows. */
static void res_pump(ef_board *b)
{
    for (;;) {
        if (b->mode == EF_MODE_SOURCE && b->res_next - b->res_acked < b->info.window) {
            /* the source test makes its frames only as the window opens; its
             * DONE follows both END and the last RESULT (docs/board.md 8) */
            if (b->source_left) {
                const uint32_t n = b->source_left < RESULT_PAYLOAD ? (uint32_t)b->source_left : RESULT_PAYLOAD;
                memset(b->cur, (int)(b->res_next & 0xff), n);
                b->source_left -= n;
                (void)res_push(b, EF_FT_RESULT, b->cur, n); /* counts its bytes and CRC */
            } else if (b->source_end == 1) {
                uint8_t d[EF_PROTO_DONE_LEN] = { 0 };
                ef_put64(d + 8, b->result_bytes);
                ef_put32(d + 28, b->results_crc);
                b->st.state = EF_BS_DONE;
                b->source_end = 2;
                (void)res_push(b, EF_FT_DONE, d, sizeof d);
            }
        }
        if (b->res_sent >= b->res_next || b->res_sent - b->res_acked >= b->info.window)
            return;
        const rframe *r = &b->res[b->res_sent - b->res_acked];
        if (tx_append(b, r->bytes, r->size) != 0)
            return;
        b->res_sent++;
    }
}

static int flush_results(ef_board *b)
{
    if (!b->cur_len)
        return 0;
    const int r = res_push(b, EF_FT_RESULT, b->cur, (uint32_t)b->cur_len);
    b->cur_len = 0;
    return r;
}

/* Appends bytes (whole records) to the RESULT payload being filled. */
static int append(ef_board *b, const uint8_t *p, size_t len)
{
    if (b->cur_len + len > RESULT_PAYLOAD && flush_results(b) != 0)
        return -1;
    memcpy(b->cur + b->cur_len, p, len);
    b->cur_len += len;
    return 0;
}

/* A digest run's record for interface i's current window (docs/board.md 4.5). */
static int digest_out(ef_board *b, unsigned i)
{
    uint8_t d[EF_PROTO_DIGEST_LEN];
    d[0] = (uint8_t)i;
    d[1] = EF_PROTO_DIGEST_MARK;
    ef_put32(d + 2, (uint32_t)b->dg_win[i]);
    ef_put32(d + 6, b->dg_cnt[i]);
    ef_put32(d + 10, b->dg_crc[i]);
    b->dg_cnt[i] = b->dg_crc[i] = 0;
    return append(b, d, sizeof d);
}

/* Whether a select run returns interface i's window w (binary search). */
static int selected(const ef_board *b, unsigned i, uint64_t w)
{
    const uint32_t key = (uint32_t)i << 24 | (uint32_t)w;
    uint32_t lo = 0, hi = b->nsel;
    if (w >= 1u << 24)
        return 0;
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        if (b->sel[mid] == key)
            return 1;
        if (b->sel[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return 0;
}

int ef_board_emit(ef_board *b, const uint8_t *record, size_t len)
{
    b->st.records++;
    if (b->run_flags) {
        const unsigned i = record[0] % EF_PROTO_IFACES;
        if (b->dg_total[i]++ && ++b->dg_pos[i] == b->dg_n) /* this one's window: dg_total / dg_n before */
            b->dg_pos[i] = 0, b->dg_win[i]++;
        if (b->run_flags & EF_START_SELECT) {
            if (!selected(b, i, b->dg_win[i]))
                return 0;
        } else {
            b->dg_crc[i] = ef_frame_crc32(b->dg_crc[i], record, len);
            return ++b->dg_cnt[i] == b->dg_n ? digest_out(b, i) : 0;
        }
    }
    b->records_sent++;
    return append(b, record, len);
}

void ef_board_fail(ef_board *b, uint32_t code, const char *why)
{
    if (b->st.state == EF_BS_ERROR)
        return;
    (void)flush_results(b);
    uint8_t p[4 + 200];
    size_t n = strlen(why);
    if (n > 200)
        n = 200;
    ef_put32(p, code);
    memcpy(p + 4, why, n);
    b->st.state = EF_BS_ERROR;
    (void)res_push(b, EF_FT_ERROR, p, (uint32_t)(4 + n));
}

/* ------------------------------------------------------- frame handling */
/* A digest or select run's extra START fields.  0, or -1 after failing the run. */
static int take_run_flags(ef_board *b, const ef_frame *f)
{
    b->run_flags = f->flags;
    if (!f->flags)
        return 0;
    if (f->flags != EF_START_DIGEST && f->flags != EF_START_SELECT) {
        ef_board_fail(b, 1, "START has unknown flags");
        return -1;
    }
    b->dg_n = ef_get32(f->payload + 24);
    if (b->dg_n == 0) {
        ef_board_fail(b, 1, "START asks for digest windows of 0 transactions");
        return -1;
    }
    if (f->flags == EF_START_DIGEST)
        return 0;
    b->nsel = ef_get32(f->payload + 28);
    if (b->nsel > EF_PROTO_SELECT_MAX || f->len != 32 + 4 * b->nsel) {
        ef_board_fail(b, 1, "START's window selection is malformed");
        return -1;
    }
    b->sel = malloc(4 * (size_t)b->nsel + 4);
    if (!b->sel) {
        ef_board_fail(b, 2, "no memory for the window selection");
        return -1;
    }
    for (uint32_t k = 0; k < b->nsel; k++) {
        b->sel[k] = ef_get32(f->payload + 32 + 4 * k);
        if (k && b->sel[k] <= b->sel[k - 1]) {
            ef_board_fail(b, 1, "START's window selection is not in ascending order");
            return -1;
        }
    }
    return 0;
}

static void take_start(ef_board *b, const ef_frame *f)
{
    const uint32_t want = f->flags == 0                 ? EF_PROTO_START_LEN
                          : f->flags == EF_START_DIGEST ? EF_PROTO_START_DIGEST_LEN
                                                        : (f->len < 32 ? 32 : f->len);
    if (f->len != want || (f->flags == EF_START_SELECT && f->len < 32)) {
        ef_board_fail(b, 1, "START payload has the wrong length for its flags");
        return;
    }
    b->iface_mask = ef_get32(f->payload);
    b->samples = ef_get32(f->payload + 4);
    b->mode = ef_get32(f->payload + 8);
    b->source_left = (uint64_t)ef_get32(f->payload + 12) * 1024u;
    b->cmd_count = ef_get64(f->payload + 16);
    b->st.state = EF_BS_RUNNING;
    if (b->mode > EF_MODE_SOURCE) {
        ef_board_fail(b, 1, "START names an unknown mode");
        return;
    }
    if (b->mode != EF_MODE_DUT)
        return;
    if ((b->iface_mask & ~b->info.iface_mask) != 0) {
        ef_board_fail(b, 2, "START asks for interfaces this board cannot return");
        return;
    }
    if (!(b->info.samples_mask >> ef_proto_samples_bit(b->samples) & 1u)) {
        ef_board_fail(b, 2, "START asks for a sample count this board does not have");
        return;
    }
    if (take_run_flags(b, f) != 0)
        return;
    if (b->dut.start && b->dut.start(b->dut.self, b, b->iface_mask, (int)b->samples) != 0)
        return;
    b->dut_started = 1;
}

int ef_board_results_full(const ef_board *b)
{
    return b->queue_max && b->mode == EF_MODE_DUT && b->res_next - b->res_acked >= b->queue_max;
}

/* (at least 4: the host acknowledges results after every 4 it has written) */
void ef_board_set_result_queue(ef_board *b, uint32_t frames) { b->queue_max = frames && frames < 4 ? 4 : frames; }

/* A DATA frame's commands from *off on to the DUT.  Returns 1 when the frame
 * is taken whole, 0 when it stopped (the result queue full, or the DUT busy:
 * the rest waits, *off says where). */
static int run_data(ef_board *b, const uint8_t *payload, uint32_t len, uint32_t crc, uint32_t *off)
{
    switch (b->mode) {
    case EF_MODE_SINK:
    case EF_MODE_SOURCE: break;
    case EF_MODE_LOOPBACK: (void)res_push(b, EF_FT_RESULT, payload, len); break;
    default:
        if (len % EF_PROTO_CMD_BYTES) {
            ef_board_fail(b, 3, "DATA payload is not a whole number of 13-byte commands");
            break;
        }
        for (; *off < len && b->st.state == EF_BS_RUNNING; *off += EF_PROTO_CMD_BYTES) {
            if (ef_board_results_full(b))
                return 0;
            const int r = b->dut.push ? b->dut.push(b->dut.self, payload + *off) : 0;
            if (r > 0) /* busy: the command was not taken */
                return 0;
            b->st.cmds++;
            if (r < 0)
                break;
        }
    }
    b->st.input_crc = ef_frame_crc32_combine(b->st.input_crc, crc, len); /* (the parse read the payload) */
    return 1;
}

/* END: 1 when taken, 0 when the DUT is not finished yet (call again). */
static int take_end(ef_board *b)
{
    if (b->mode == EF_MODE_SOURCE) {
        b->source_end = 1; /* its DONE follows the last RESULT it makes */
        return 1;
    }
    if (b->mode == EF_MODE_DUT && b->dut.finish) {
        const int r = b->dut.finish(b->dut.self);
        if (r > 0)
            return 0;
        if (r < 0)
            return 1;
    }
    if (b->st.state != EF_BS_RUNNING)
        return 1;
    if (b->mode == EF_MODE_DUT && b->st.cmds != b->cmd_count) {
        ef_board_fail(b, 4, "END after a different number of commands than START announced");
        return 1;
    }
    if (b->run_flags & EF_START_DIGEST) /* every interface's last, partial window */
        for (unsigned i = 0; i < EF_PROTO_IFACES; i++)
            if (b->dg_cnt[i] && digest_out(b, i) != 0)
                return 1;
    if (flush_results(b) != 0)
        return 1;
    uint8_t d[EF_PROTO_DONE_LEN];
    ef_put64(d, b->run_flags & EF_START_DIGEST ? b->st.records : b->records_sent);
    ef_put64(d + 8, b->result_bytes);
    ef_put64(d + 16, b->st.cmds);
    ef_put32(d + 24, b->st.input_crc);
    ef_put32(d + 28, b->results_crc);
    b->st.state = EF_BS_DONE;
    (void)res_push(b, EF_FT_DONE, d, sizeof d);
    return 1;
}

static void take_ackr(ef_board *b, const ef_frame *f)
{
    if (f->len != 4)
        return;
    uint32_t next = ef_get32(f->payload);
    if (next > b->res_sent) /* cannot acknowledge what was never sent */
        next = b->res_sent;
    while (b->res_acked < next) {
        free(b->res[0].bytes);
        memmove(b->res, b->res + 1, (size_t)(b->res_next - b->res_acked - 1) * sizeof *b->res);
        b->res_acked++;
    }
    if (f->flags & EF_ACKR_RESEND)
        b->res_sent = b->res_acked;
}

static void clear_run(ef_board *b, int keep_rx);

/* A control request in the byte stream (docs/board.md 5.5): answered in
 * stream order, outside both numbered sequences (no ACK, no NAK, E and the
 * NAK suppression unchanged).  Returns 0 when f is not one. */
static int take_control(ef_board *b, const ef_frame *f, int *ack)
{
    if (f->type < EF_FT_IDENTIFY || f->type > EF_FT_RESET || f->len != 0)
        return 0;
    uint8_t p[EF_PROTO_IDENTIFY_LEN];
    if (*ack) /* the frames before it are acknowledged before its reply */
        send_ack(b), *ack = 0;
    if (f->type == EF_FT_IDENTIFY) {
        ef_board_identify(b, p);
        send_small(b, EF_FT_IDENTIFY | EF_FT_REPLY, f->seq, p, EF_PROTO_IDENTIFY_LEN);
    } else if (f->type == EF_FT_STATUS) {
        ef_board_status(b, p);
        send_small(b, EF_FT_STATUS | EF_FT_REPLY, f->seq, p, EF_PROTO_STATUS_LEN);
    } else {
        clear_run(b, 1); /* the bytes after it in rx[] belong to the new state */
        send_small(b, EF_FT_RESET | EF_FT_REPLY, f->seq, NULL, 0);
    }
    return 1;
}

/* Keeps a frame received in order that cannot be taken whole now (its commands
 * from off on wait): at most `window` of them, the frames the host may have
 * unacknowledged (the acknowledgement names ack_seq, the frames taken). */
static int hold(ef_board *b, const ef_frame *f, uint32_t off)
{
    if (b->nheld >= b->info.window)
        return -1;
    if (b->nheld == b->held_cap) {
        const uint32_t cap = b->held_cap ? 2 * b->held_cap : 4;
        hframe *h = realloc(b->held, cap * sizeof *h);
        if (!h)
            return -1;
        b->held = h, b->held_cap = cap;
    }
    hframe *h = &b->held[b->nheld];
    h->payload = malloc(f->len ? f->len : 1);
    if (!h->payload)
        return -1;
    memcpy(h->payload, f->payload, f->len);
    h->type = f->type, h->len = f->len, h->off = off, h->crc = f->payload_crc;
    b->nheld++;
    return 0;
}

static void drop_held(ef_board *b)
{
    for (uint32_t k = 0; k < b->nheld; k++)
        free(b->held[k].payload);
    b->nheld = 0;
}

/* Takes held frames in order while the result queue and the DUT allow. */
static void service(ef_board *b)
{
    int acked = 0;
    while (b->nheld) {
        hframe *h = &b->held[0];
        if (b->st.state == EF_BS_RUNNING &&
            !(h->type == EF_FT_DATA ? run_data(b, h->payload, h->len, h->crc, &h->off) : take_end(b)))
            break;
        free(h->payload);
        memmove(b->held, b->held + 1, (size_t)(b->nheld - 1) * sizeof *b->held);
        b->nheld--;
        b->ack_seq++; /* (a run that failed takes no more: its held frames are acknowledged) */
        acked = 1;
    }
    if (acked)
        send_ack(b);
}

/* One good frame from the host. */
static void take(ef_board *b, const ef_frame *f, int *ack)
{
    if (take_control(b, f, ack))
        return;
    if (f->type == EF_FT_ACKR) { /* unnumbered */
        take_ackr(b, f);
        return;
    }
    if (f->type != EF_FT_START && f->type != EF_FT_DATA && f->type != EF_FT_END) {
        send_nak(b, 2);
        return;
    }
    if (f->seq < b->st.rx_seq) { /* already taken: say so again */
        b->st.frames_dup++;
        *ack = 1;
        return;
    }
    if (f->seq > b->st.rx_seq) { /* one before it is missing */
        b->st.frames_gap++;
        send_nak(b, 1);
        return;
    }
    if ((f->seq == 0) != (f->type == EF_FT_START) || (b->st.state != EF_BS_RUNNING && f->type != EF_FT_START)) {
        send_nak(b, 3); /* out of place: START first, DATA/END only while running */
        return;
    }
    uint32_t off = 0;
    int whole = 1;
    if (f->type == EF_FT_START)
        take_start(b, f);
    else if (!b->nheld)
        whole = f->type == EF_FT_DATA ? run_data(b, f->payload, f->len, f->payload_crc, &off) : take_end(b);
    else
        whole = 0;
    if (!whole && hold(b, f, off) != 0)
        return; /* a host over its window (or no memory): as if lost, it is sent again */
    b->st.rx_seq++;
    b->st.frames_ok++;
    b->nak_pending = 0;
    *ack = 1;
    if (whole)
        b->ack_seq = b->st.rx_seq;
}

int ef_board_rx(ef_board *b, const uint8_t *buf, size_t len)
{
    if (len == 0) {
        service(b);
        res_pump(b);
        return 0;
    }
    if (b->rx_len + len > b->rx_cap) {
        size_t cap = b->rx_cap ? b->rx_cap : 2 * EF_PROTO_FRAME_MAX;
        while (cap < b->rx_len + len)
            cap *= 2;
        uint8_t *r = realloc(b->rx, cap);
        if (!r)
            return -1;
        b->rx = r, b->rx_cap = cap;
    }
    memcpy(b->rx + b->rx_len, buf, len);
    b->rx_len += len;

    /* Each byte is read once by the parse (its CRC) however many calls bring a
     * frame: the frame at rx[0] keeps its payload CRC so far in rx_part, and
     * the bytes left move only when frames before them were consumed. */
    size_t pos = 0;
    int ack = 0;
    ef_frame_part part = b->rx_part;
    while (pos < b->rx_len) {
        ef_frame f;
        size_t used;
        const int r = ef_frame_parse_part(b->rx + pos, b->rx_len - pos, &f, &used, &part);
        if (r == EF_FRAME_MORE)
            break;
        part.crc = part.done = 0; /* the next frame's */
        if (r == EF_FRAME_BAD) {
            b->st.frames_bad++;
            send_nak(b, 0);
            pos += ef_frame_resync(b->rx + pos, b->rx_len - pos);
            continue;
        }
        take(b, &f, &ack);
        pos += used;
    }
    if (pos) {
        memmove(b->rx, b->rx + pos, b->rx_len - pos);
        b->rx_len -= pos;
    }
    b->rx_part = part;
    if (ack)
        send_ack(b);
    service(b);
    res_pump(b);
    return 0;
}

size_t ef_board_tx_pending(const ef_board *b) { return b->tx_len - b->tx_head; }

size_t ef_board_tx(ef_board *b, uint8_t *buf, size_t cap)
{
    service(b);
    res_pump(b);
    size_t n = b->tx_len - b->tx_head;
    if (n == 0)
        return 0;
    if (n > cap)
        n = cap;
    memcpy(buf, b->tx + b->tx_head, n);
    b->tx_head += n;
    return n;
}

/* --------------------------------------------------------------- control */
void ef_board_identify(const ef_board *b, uint8_t out[EF_PROTO_IDENTIFY_LEN])
{
    memset(out, 0, EF_PROTO_IDENTIFY_LEN);
    memcpy(out, EF_PROTO_MAGIC, 4);
    out[4] = EF_PROTO_PROTOCOL;
    out[6] = (uint8_t)b->info.window, out[7] = (uint8_t)(b->info.window >> 8);
    ef_put32(out + 8, b->info.capabilities | EF_PROTO_CAP_DIGEST);
    ef_put32(out + 12, b->info.iface_mask);
    ef_put32(out + 16, b->info.samples_mask);
    ef_put32(out + 20, b->info.width_max);
    ef_put32(out + 24, b->info.height_max);
    ef_put32(out + 28, b->info.edges_max);
    memcpy(out + 32, b->info.serial, strnlen(b->info.serial, 16));
}

void ef_board_status(const ef_board *b, uint8_t out[EF_PROTO_STATUS_LEN])
{
    memset(out, 0, EF_PROTO_STATUS_LEN);
    memcpy(out, EF_PROTO_MAGIC, 4);
    out[4] = EF_PROTO_PROTOCOL;
    out[6] = (uint8_t)b->st.state;
    ef_put32(out + 8, b->ack_seq);
    ef_put32(out + 12, b->res_next);
    ef_put32(out + 16, b->res_acked);
    ef_put32(out + 20, b->st.input_crc);
    ef_put64(out + 24, b->st.cmds);
    ef_put64(out + 32, b->st.records);
}

static void clear_run(ef_board *b, int keep_rx)
{
    if (b->dut_started && b->dut.stop)
        b->dut.stop(b->dut.self);
    b->dut_started = 0;
    drop_held(b);
    b->ack_seq = b->res_peak = 0;
    for (uint32_t k = 0; k < b->res_next - b->res_acked; k++)
        free(b->res[k].bytes);
    b->res_acked = b->res_sent = b->res_next = 0;
    if (!keep_rx)
        b->rx_len = 0, b->rx_part.crc = b->rx_part.done = 0;
    b->tx_head = b->tx_len = b->cur_len = 0;
    b->nak_pending = 0;
    b->mode = b->iface_mask = b->samples = 0;
    b->source_left = 0;
    b->source_end = 0;
    b->cmd_count = b->result_bytes = b->records_sent = 0;
    b->results_crc = 0;
    free(b->sel);
    b->sel = NULL;
    b->nsel = b->run_flags = b->dg_n = 0;
    memset(b->dg_total, 0, sizeof b->dg_total);
    memset(b->dg_crc, 0, sizeof b->dg_crc);
    memset(b->dg_cnt, 0, sizeof b->dg_cnt);
    memset(b->dg_win, 0, sizeof b->dg_win);
    memset(b->dg_pos, 0, sizeof b->dg_pos);
    memset(&b->st, 0, sizeof b->st);
}

void ef_board_reset(ef_board *b) { clear_run(b, 0); }

void ef_board_link_lost(ef_board *b)
{
    b->rx_len = 0; /* a frame only partly received */
    b->rx_part.crc = b->rx_part.done = 0;
    b->tx_head = b->tx_len = 0; /* bytes queued and not sent */
    b->res_sent = b->res_acked; /* unacknowledged results go out again on the next link */
}

void ef_board_rx_idle(ef_board *b)
{
    b->rx_len = 0;
    b->rx_part.crc = b->rx_part.done = 0;
}

void ef_board_get_stats(const ef_board *b, ef_board_stats *s)
{
    *s = b->st;
    s->res_next = b->res_next;
    s->res_acked = b->res_acked;
    s->res_peak = b->res_peak;
    s->held = b->nheld;
}

ef_board *ef_board_new(const ef_proto_info *info, ef_board_dut dut)
{
    ef_board *b = calloc(1, sizeof *b);
    if (!b)
        return NULL;
    b->info = *info;
    if (!b->info.window)
        b->info.window = 16;
    b->dut = dut;
    b->queue_max = EF_BOARD_RESULT_QUEUE;
    /* the buffers at their first sizes now, not in the first calls (a board's
     * allocator may clear what it gives: its time is spent before any link talks) */
    b->cur = malloc(RESULT_PAYLOAD);
    b->rx_cap = 2 * EF_PROTO_FRAME_MAX;
    b->rx = malloc(b->rx_cap);
    b->tx_cap = 65536;
    b->tx = malloc(b->tx_cap);
    if (!b->cur || !b->rx || !b->tx) {
        free(b->cur);
        free(b->rx);
        free(b->tx);
        free(b);
        return NULL;
    }
    return b;
}

void ef_board_free(ef_board *b)
{
    if (!b)
        return;
    clear_run(b, 0);
    if (b->dut.destroy)
        b->dut.destroy(b->dut.self);
    free(b->res);
    free(b->held);
    free(b->rx);
    free(b->tx);
    free(b->cur);
    free(b);
}
