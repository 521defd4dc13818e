/*
 * link_uart.c (board firmware) - the UART link (LiteX's UART on the FT231X,
 * docs/board-serial.md): a byte stream both ways through the UART core's
 * FIFOs; control requests travel in the stream (docs/board.md 5.5).
 */
#include "link.h"

#define UART_EV_RX 2u

static size_t uart_rx(uint8_t *buf, size_t cap)
{
    size_t n = 0;
    while (n < cap && !uart_rxempty_read()) {
        buf[n++] = (uint8_t)uart_rxtx_read();
        uart_ev_pending_write(UART_EV_RX);
    }
    return n;
}

static size_t uart_tx(const uint8_t *buf, size_t len)
{
    size_t n = 0;
    while (n < len && !uart_txfull_read())
        uart_rxtx_write(buf[n++]);
    return n;
}

const fw_link fw_link_uart = { "uart", NULL, uart_rx, uart_tx, NULL, NULL, NULL };
