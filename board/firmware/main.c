/*
 * main.c (board firmware) - the ULX3S board: the board engine
 * (board/ef_board.c, compiled unchanged) between the UART and the ef_raster
 * peripheral (dut_soc.c).  One loop: bytes the UART received go to
 * ef_board_rx(), the records the peripheral made to the engine, the engine's
 * bytes for the host to the UART.  Control requests travel in the byte
 * stream (docs/board.md 5.5); a line idle for 50 ms with a frame half received
 * drops that half (ef_board_rx_idle, docs/board-serial.md 3: a host killed
 * mid-frame), timed by LiteX's timer0 counting down at the sys clock.
 */
#include <stdint.h>
#include <string.h>

#include <generated/csr.h>
#include <generated/mem.h>
#include <generated/soc.h>

#include "dut_soc.h"
#include "ef_board.h"

#ifndef EF_BOARD_SERIAL
#define EF_BOARD_SERIAL "EFULX3S-0001"
#endif

#define UART_EV_RX 2u

#ifdef CSR_SDRAM_BASE
#include <generated/sdram_phy.h>

/* LiteDRAM's SDR start-up: the mode register through the DFII, then the
 * controller takes the memory. */
static void sdram_start(void)
{
    sdram_dfii_control_write(DFII_CONTROL_CKE | DFII_CONTROL_ODT | DFII_CONTROL_RESET_N);
    init_sequence();
    sdram_dfii_control_write(DFII_CONTROL_SEL);
}
#else
static void sdram_start(void) {}
#endif

static uint8_t rxb[256], txb[256];

static uint32_t now_ticks(void) /* sys clock ticks, counting down */
{
    timer0_update_value_write(1);
    return timer0_value_read();
}

int main(void)
{
    sdram_start();
    ef_proto_info info;
    memset(&info, 0, sizeof info);
    strncpy(info.serial, EF_BOARD_SERIAL, sizeof info.serial - 1);
    info.capabilities = EF_PROTO_CAP_RESULTS | EF_PROTO_CAP_RESUME | EF_PROTO_CAP_INTERNAL;
    info.samples_mask = 1u << ef_proto_samples_bit(EF_NS);
    info.width_max = EF_W_MAX, info.height_max = EF_H_MAX, info.edges_max = EF_E_MAX;
    info.window = 16;
    info.iface_mask = 0x7Fu;
    ef_board *b = ef_board_new(&info, ef_board_dut_soc());
    if (!b)
        for (;;)
            ;
    timer0_en_write(0);
    timer0_load_write(0);
    timer0_reload_write(0xFFFFFFFFu);
    timer0_en_write(1);
    const uint32_t idle_ticks = CONFIG_CLOCK_FREQUENCY / 20; /* 50 ms */
    uint32_t last_rx = now_ticks();
    int rx_pending = 0; /* bytes went in since the last idle call */
    size_t tx_len = 0, tx_pos = 0;
    for (;;) {
        size_t n = 0;
        while (n < sizeof rxb && !uart_rxempty_read()) {
            rxb[n++] = (uint8_t)uart_rxtx_read();
            uart_ev_pending_write(UART_EV_RX);
        }
        if (n) {
            (void)ef_board_rx(b, rxb, n); /* a full buffer: the host broke the window; it resends */
            last_rx = now_ticks();
            rx_pending = 1;
        } else if (rx_pending && last_rx - now_ticks() > idle_ticks) {
            ef_board_rx_idle(b);
            rx_pending = 0;
        }
        dut_soc_poll();
        if (tx_pos == tx_len) {
            tx_pos = 0;
            tx_len = ef_board_tx(b, txb, sizeof txb);
        }
        while (tx_pos < tx_len && !uart_txfull_read())
            uart_rxtx_write(txb[tx_pos++]);
    }
}
