/*
 * gpio_bus.c - the board's side of the GPIO bus (docs/board-gpio.md
 * sections 3-5): a byte register each way between the host's bit-banged lines
 * and the board engine, plus the control view that carries identify, status,
 * reset and the bus's own status.
 *
 * The engine is fed one byte per edge (ef_board_rx takes any split) and
 * drained in chunks into tx[], which is what a FIFO between the engine and
 * the pins would hold on an FPGA.  ready and avail only fall in response to
 * an edge, so the host may act on the last values it sampled (section 4).
 */
#include "gpio_bus.h"

#include <stdlib.h>
#include <string.h>

struct ef_gpio_bus {
    ef_board *b;
    int ctl_mode;      /* ctl as sampled at the last edge */
    uint8_t reply[64]; /* control view: the last request's reply */
    size_t reply_len, reply_pos;
    uint8_t tx[4096]; /* stream view: engine bytes not yet taken */
    size_t tx_len, tx_pos;
    int rx_hold; /* a byte the engine refused waits in rx_byte */
    uint8_t rx_byte;
    int err; /* latched EF_GB_ERR_* (bus causes) */
    uint32_t rx_count, tx_count;
};

ef_gpio_bus *ef_gpio_bus_new(ef_board *b)
{
    ef_gpio_bus *g = calloc(1, sizeof *g);
    if (g)
        g->b = b;
    return g;
}

void ef_gpio_bus_free(ef_gpio_bus *g) { free(g); }

static void refill(ef_gpio_bus *g)
{
    if (g->tx_pos == g->tx_len) {
        g->tx_len = ef_board_tx(g->b, g->tx, sizeof g->tx);
        g->tx_pos = 0;
    }
    /* A byte the engine refused (its receive buffer was full) is offered
     * again before ready may rise. */
    if (g->rx_hold && ef_board_rx(g->b, &g->rx_byte, 1) == 0)
        g->rx_hold = 0;
}

static int engine_failed(const ef_gpio_bus *g)
{
    ef_board_stats s;
    ef_board_get_stats(g->b, &s);
    return s.state == EF_BS_ERROR;
}

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}

static void request(ef_gpio_bus *g, uint8_t code)
{
    g->reply_len = g->reply_pos = 0;
    switch (code) {
    case EF_GB_REQ_IDENTIFY:
        ef_board_identify(g->b, g->reply);
        g->reply_len = EF_PROTO_IDENTIFY_LEN;
        break;
    case EF_GB_REQ_STATUS:
        ef_board_status(g->b, g->reply);
        g->reply_len = EF_PROTO_STATUS_LEN;
        break;
    case EF_GB_REQ_RESET:
        ef_board_reset(g->b);
        g->tx_len = g->tx_pos = 0;
        g->rx_hold = 0;
        g->err = EF_GB_ERR_NONE;
        g->rx_count = g->tx_count = 0;
        break;
    case EF_GB_REQ_BUS_STATUS:
        memset(g->reply, 0, EF_GB_BUS_STATUS_LEN);
        g->reply[0] = (uint8_t)ef_gpio_bus_error(g);
        put32(g->reply + 4, g->rx_count);
        put32(g->reply + 8, g->tx_count);
        g->reply_len = EF_GB_BUS_STATUS_LEN;
        break;
    default: g->err = g->err ? g->err : EF_GB_ERR_CONTROL; break;
    }
}

static void fail(ef_gpio_bus *g, int cause)
{
    if (!g->err) /* the first cause is the one worth reporting */
        g->err = cause;
}

void ef_gpio_bus_edge(ef_gpio_bus *g, uint8_t d, unsigned ctrl)
{
    int ctl = (ctrl & EF_GB_CTL) != 0, valid = (ctrl & EF_GB_VALID) != 0, take = (ctrl & EF_GB_TAKE) != 0;
    refill(g);
    if (ctl != g->ctl_mode) {
        /* The host sampled the other view before this edge, so it cannot
         * have meant to take from this one; only a request may ride on the
         * edge that enters the control view (section 5). */
        if (take || (valid && !ctl))
            fail(g, EF_GB_ERR_CONTROL);
        g->ctl_mode = ctl;
        g->reply_len = g->reply_pos = 0;
        if (ctl && valid)
            request(g, d);
        return;
    }
    if (ctl) {
        if (take) {
            if (g->reply_pos < g->reply_len)
                g->reply_pos++;
            else
                fail(g, EF_GB_ERR_UNDERRUN);
        }
        if (valid)
            request(g, d);
        return;
    }
    if (take) {
        if (g->tx_pos < g->tx_len)
            g->tx_pos++, g->tx_count++;
        else
            fail(g, EF_GB_ERR_UNDERRUN);
    }
    if (valid) {
        if (g->rx_hold) {
            fail(g, EF_GB_ERR_OVERRUN); /* the byte is dropped: ready was low */
        } else {
            g->rx_count++;
            if (ef_board_rx(g->b, &d, 1) != 0)
                g->rx_hold = 1, g->rx_byte = d;
        }
    }
}

void ef_gpio_bus_outputs(ef_gpio_bus *g, ef_gpio_bus_lines *out)
{
    ef_board_stats s;
    ef_board_get_stats(g->b, &s);
    if (g->ctl_mode) {
        out->ready = 1;
        out->avail = g->reply_pos < g->reply_len;
        out->q = out->avail ? g->reply[g->reply_pos] : 0;
    } else {
        refill(g);
        out->ready = !g->rx_hold;
        out->avail = g->tx_pos < g->tx_len;
        out->q = out->avail ? g->tx[g->tx_pos] : 0;
    }
    out->done = s.state == EF_BS_DONE;
    out->err = g->err != EF_GB_ERR_NONE || s.state == EF_BS_ERROR;
}

uint32_t ef_gpio_bus_rx_count(const ef_gpio_bus *g) { return g->rx_count; }

uint32_t ef_gpio_bus_tx_count(const ef_gpio_bus *g) { return g->tx_count; }

int ef_gpio_bus_error(const ef_gpio_bus *g)
{
    if (g->err)
        return g->err;
    return engine_failed(g) ? EF_GB_ERR_ENGINE : EF_GB_ERR_NONE;
}
