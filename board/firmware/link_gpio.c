/*
 * link_gpio.c (board firmware) - the GPIO bus link (docs/board-gpio.md): the
 * gateware slave of board/soc/ef_gpio.py does the bus cycles, the stream
 * FIFOs and the error causes; this moves the stream's bytes between its FIFOs
 * and the engine, answers its control requests (IDENTIFY and STATUS from the
 * engine, BUS_STATUS here from the slave's counters), acknowledges RESET once
 * the engine has reset, and shows the engine's state on `done` and `err`.
 * Compiles to nothing when the SoC has no GPIO bus.
 */
#include "link.h"

#ifdef CSR_GPIOBUS_BASE

#define ST_TX_ROOM 2u
#define ST_REQ 4u
#define ST_RST 8u
#define RX_THERE 0x100u
#define REQ_IDENTIFY 1u
#define REQ_STATUS 2u
#define REQ_BUS_STATUS 4u
#define CAUSE_ENGINE 4u
#define BUS_STATUS_LEN 12

static uint32_t req_tag;      /* the tag of the request being answered */
static int shown = -1;        /* the engine state last written to the slave (-1: none since reset) */
static int engine_failed_now; /* the engine's ERROR state, for BUS_STATUS's cause */

static size_t gpio_rx(uint8_t *buf, size_t cap)
{
    size_t n = 0;
    while (n < cap) {
        const uint32_t v = gpiobus_rx_read();
        if (!(v & RX_THERE))
            break;
        buf[n++] = (uint8_t)v;
        gpiobus_rx_pop_write(1);
    }
    return n;
}

static size_t gpio_tx(const uint8_t *buf, size_t len)
{
    size_t n = 0;
    while (n < len && (gpiobus_status_read() & ST_TX_ROOM))
        gpiobus_tx_write(buf[n++]);
    return n;
}

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}

static void send_reply(const uint8_t *buf, size_t len)
{
    gpiobus_reply_begin_write(1);
    for (size_t i = 0; i < len; i++)
        gpiobus_reply_write(buf[i]);
    gpiobus_reply_end_write(req_tag);
}

static int gpio_control(void)
{
    const uint32_t st = gpiobus_status_read();
    if (st & ST_RST)
        return FW_REQ_RESET;
    if (!(st & ST_REQ))
        return FW_REQ_NONE;
    const uint32_t code = st >> 8 & 0xFFu;
    req_tag = st >> 16 & 0xFu;
    if (code == REQ_BUS_STATUS) { /* docs/board-gpio.md section 5: the bus's own */
        uint8_t r[BUS_STATUS_LEN] = { 0 };
        const uint32_t cause = gpiobus_cause_read();
        r[0] = (uint8_t)(cause ? cause : engine_failed_now ? CAUSE_ENGINE : 0);
        put32(r + 4, gpiobus_rx_count_read());
        put32(r + 8, gpiobus_tx_count_read());
        send_reply(r, sizeof r);
        return FW_REQ_NONE;
    }
    return code == REQ_IDENTIFY ? FW_REQ_IDENTIFY : code == REQ_STATUS ? FW_REQ_STATUS : FW_REQ_NONE;
}

static void gpio_reply(int req, const uint8_t *buf, size_t len)
{
    if (req == FW_REQ_RESET) {
        shown = -1, engine_failed_now = 0;
        gpiobus_reset_ack_write(1);
        return;
    }
    send_reply(buf, len);
}

static void gpio_state(int done, int failed)
{
    const int v = (done ? 1 : 0) | (failed ? 2 : 0);
    engine_failed_now = failed;
    if (v != shown) {
        gpiobus_engine_write((uint32_t)v);
        shown = v;
    }
}

const fw_link fw_link_gpio = { "gpio", NULL, gpio_rx, gpio_tx, gpio_control, gpio_reply, gpio_state };

#endif /* CSR_GPIOBUS_BASE */
