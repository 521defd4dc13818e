/*
 * link_uart.c (board firmware) - the UART link (LiteX's UART on the FT231X,
 * docs/board-serial.md): a byte stream both ways through the UART core's
 * FIFOs; control requests travel in the stream (docs/board.md 5.5).
 */
#include <string.h>

#include "link.h"

#define UART_EV_RX 2u

/* The receive ring: the UART core's FIFO holds 64 bytes, 6,400 sys cycles of a
 * 3 Mbaud line at 30 MHz, less than some of the engine's calls take (a frame
 * taken whole by the DUT, a 32 KiB result frame made).  fw_link_poll(), called
 * by the loop and, inside those calls, by the work that takes long (crc32.c's
 * CRC and mem.c's copies every KiB, dut_soc.c's waits for the peripheral),
 * moves the FIFO's bytes here, so the FIFO never fills.  Its size: what the
 * host may send unacknowledged (the window of 16 frames of at most 65,556
 * bytes) and more, so it never fills either (docs/board-ulx3s.md, "The UART
 * at 3 Mbaud").  In main RAM, not cleared at boot (linker.ld's .noinit). */
#define RING_SIZE (16u * 65556u + 65536u)
static uint8_t ring[RING_SIZE] __attribute__((section(".noinit")));
/* the oldest byte, and the count: volatile, as the polls inside memcpy (mem.c)
 * change them, which the compiler, knowing memcpy, would not expect */
static volatile uint32_t ring_head, ring_len;

#ifdef EF_FW_POLLSTAT /* a debug build: the times between two polls, as text after 50 ms idle */
static void say(const char *t, uint32_t v)
{
    for (; *t; t++) {
        while (uart_txfull_read())
            ;
        uart_rxtx_write((uint8_t)*t);
    }
    for (int k = 28; k >= 0; k -= 4) {
        while (uart_txfull_read())
            ;
        uart_rxtx_write((uint8_t) "0123456789abcdef"[v >> k & 15]);
    }
}
static uint32_t last_poll, hist[16], worst[3];
static void *last_ra;
void fw_pollstat_dump(void);
void fw_pollstat_dump(void)
{
    for (int i = 0; i < 16; i++)
        say(i ? " " : "\npollstat hist (1024-cycle bins, since boot) ", hist[i]);
    say("\nworst ", worst[0]);
    say(" from ", worst[1]);
    say(" to ", worst[2]);

    worst[0] = 0;
    say("\n", 0);
    last_poll = 0;
}
#endif

void fw_link_poll(void)
{
#ifdef EF_FW_POLLSTAT
    timer0_update_value_write(1);
    const uint32_t now = timer0_value_read(), gap = last_poll - now;
    if (last_poll && !uart_rxempty_read()) { /* (only gaps that bytes arrived in) */
        hist[gap >> 10 < 15 ? gap >> 10 : 15]++;
        if (gap > worst[0])
            worst[0] = gap, worst[1] = (uint32_t)last_ra, worst[2] = (uint32_t)__builtin_return_address(0);
    }
    last_poll = now;
    last_ra = __builtin_return_address(0);
#endif
    while (!uart_rxempty_read()) {
        const uint8_t c = (uint8_t)uart_rxtx_read();
        uart_ev_pending_write(UART_EV_RX);
        if (ring_len < RING_SIZE) { /* (else lost, as a full FIFO loses it: the host sends it again) */
            const uint32_t at = ring_head + ring_len;
            ring_len = ring_len + 1;
            ring[at < RING_SIZE ? at : at - RING_SIZE] = c;
        }
    }
}

static size_t uart_rx(uint8_t *buf, size_t cap)
{
    fw_link_poll();
    const uint32_t n = ring_len < cap ? ring_len : (uint32_t)cap;
    const uint32_t first = RING_SIZE - ring_head < n ? RING_SIZE - ring_head : n; /* to the ring's end */
    memcpy(buf, ring + ring_head, first);
    memcpy(buf + first, ring, n - first);
    const uint32_t h = ring_head + n;
    ring_head = h < RING_SIZE ? h : h - RING_SIZE;
    ring_len = ring_len - n;
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
