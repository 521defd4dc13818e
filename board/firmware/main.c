/*
 * main.c (board firmware) - the ULX3S board: one board engine
 * (board/ef_board.c, compiled unchanged) between the SoC's links to the host
 * (link.h: the UART, and the GPIO bus when the SoC has it) and the ef_raster
 * peripheral (dut_soc.c).  One loop: out-of-band control requests of any link
 * are answered (identify, status: at once; reset: the engine resets), the
 * bytes a link received go to ef_board_rx(), the records the peripheral made
 * to the engine, the engine's bytes for the host to the link that owns the
 * engine.
 *
 * Ownership (docs/board-ulx3s.md, "One engine, several links"): the engine
 * has one byte stream, so one link at a time owns it: the link that delivered
 * the last stream bytes.  Another link's stream bytes are dropped while the
 * owner has delivered bytes within the last 50 ms; after that, the first
 * bytes of another link take the engine over as a reconnection
 * (ef_board_link_lost: a half frame and the bytes not yet sent are dropped,
 * the run is kept, so --resume continues on the new link).  A reset leaves
 * the engine without an owner.
 *
 * A link idle for 50 ms with a frame half received drops that half
 * (ef_board_rx_idle, docs/board-serial.md 3: a host killed mid-frame), timed
 * by LiteX's timer0 counting down at the sys clock.
 */
#include <stdint.h>
#include <string.h>

#include <generated/csr.h>
#include <generated/mem.h>
#include <generated/soc.h>

#include "dut_soc.h"
#include "ef_board.h"
#include "ef_frame.h"
#include "link.h"

#ifndef EF_BOARD_SERIAL
#define EF_BOARD_SERIAL "EFULX3S-0001"
#endif

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

/* Every link of this SoC. */
static const fw_link *const links[] = {
    &fw_link_uart,
#ifdef CSR_GPIOBUS_BASE
    &fw_link_gpio,
#endif
#ifdef CSR_USB_BASE
    &fw_link_usb,
#endif
};
#define NLINKS (sizeof links / sizeof links[0])

static uint8_t rxb[256], txb[256];

#ifdef EF_FW_BENCH
void fw_bench(void);
#endif
#ifdef EF_FW_POLLSTAT
void fw_pollstat_dump(void);
#endif

static uint32_t now_ticks(void) /* sys clock ticks, counting down */
{
    timer0_update_value_write(1);
    return timer0_value_read();
}

typedef struct engine {
    ef_board *b;
    const fw_link *owner;  /* the link whose bytes the engine takes and answers; NULL: none yet */
    uint32_t last_rx;      /* when the owner last delivered bytes (now_ticks) */
    int rx_pending;        /* bytes went in since the last idle call */
    size_t tx_len, tx_pos; /* txb: engine bytes the owner has not taken yet */
} engine;

static void serve_control(engine *e, const fw_link *l, int req)
{
    uint8_t reply[EF_PROTO_IDENTIFY_LEN > EF_PROTO_STATUS_LEN ? EF_PROTO_IDENTIFY_LEN : EF_PROTO_STATUS_LEN];
    switch (req) {
    case FW_REQ_IDENTIFY:
        ef_board_identify(e->b, reply);
        l->reply(req, reply, EF_PROTO_IDENTIFY_LEN);
        break;
    case FW_REQ_STATUS:
        ef_board_status(e->b, reply);
        l->reply(req, reply, EF_PROTO_STATUS_LEN);
        break;
    case FW_REQ_RESET:
        ef_board_reset(e->b);
        e->tx_len = e->tx_pos = 0;
        e->rx_pending = 0;
        e->owner = NULL;
        l->reply(req, NULL, 0);
        break;
    case FW_REQ_LINK_LOST:
        if (e->owner == l) {
            ef_board_link_lost(e->b);
            e->tx_len = e->tx_pos = 0;
        }
        l->reply(req, NULL, 0);
        break;
    default: break;
    }
}

static void take_bytes(engine *e, const fw_link *l, size_t n, uint32_t idle_ticks)
{
    const uint32_t now = now_ticks();
    if (l != e->owner) {
        if (e->owner && e->last_rx - now <= idle_ticks)
            return; /* another link is talking to the engine: these bytes are dropped */
        if (e->owner)
            ef_board_link_lost(e->b); /* a reconnection on another link */
        e->owner = l;
        e->tx_len = e->tx_pos = 0;
    }
    (void)ef_board_rx(e->b, rxb, n); /* a full buffer: the host broke the window; it resends */
    /* (after the call: one that ran the DUT for long is no idle link, and the
     * bytes that came meanwhile are in the UART's ring, not yet delivered) */
    e->last_rx = now_ticks();
    e->rx_pending = 1;
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
    engine e;
    memset(&e, 0, sizeof e);
    e.b = ef_board_new(&info, ef_board_dut_soc());
    if (!e.b)
        for (;;)
            ;
    (void)ef_frame_crc32_combine(0, 0, 0); /* crc32.c's tables now, not in the first frame's call */
    timer0_en_write(0);
    timer0_load_write(0);
    timer0_reload_write(0xFFFFFFFFu);
    timer0_en_write(1);
#ifdef EF_FW_BENCH /* a debug build: the engine's costs on this CPU (bench.c), and no loop */
    fw_bench();
    for (;;)
        ;
#endif
    const uint32_t idle_ticks = CONFIG_CLOCK_FREQUENCY / 20; /* 50 ms */
    for (size_t i = 0; i < NLINKS; i++)
        if (links[i]->init)
            links[i]->init();
    e.last_rx = now_ticks();
    for (;;) {
        for (size_t i = 0; i < NLINKS; i++) {
            const fw_link *l = links[i];
            int req;
            if (l->control && (req = l->control()) != FW_REQ_NONE)
                serve_control(&e, l, req);
            const size_t n = l->rx(rxb, sizeof rxb);
            if (n)
                take_bytes(&e, l, n, idle_ticks);
        }
        if (e.rx_pending && e.last_rx - now_ticks() > idle_ticks) {
            ef_board_rx_idle(e.b);
            e.rx_pending = 0;
#ifdef EF_FW_POLLSTAT
            fw_pollstat_dump();
#endif
        }
        dut_soc_poll();
        if (e.tx_pos == e.tx_len) {
            e.tx_pos = 0;
            e.tx_len = e.owner ? ef_board_tx(e.b, txb, sizeof txb) : 0;
        }
        if (e.owner)
            e.tx_pos += e.owner->tx(txb + e.tx_pos, e.tx_len - e.tx_pos);
        ef_board_stats s;
        ef_board_get_stats(e.b, &s);
        for (size_t i = 0; i < NLINKS; i++)
            if (links[i]->state)
                links[i]->state(s.state == EF_BS_DONE, s.state == EF_BS_ERROR);
    }
}
