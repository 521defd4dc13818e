/*
 * link_usb.c (board firmware) - the USB link (docs/board-usb.md): the SoC's
 * USB device (board/soc/ef_usb.py, LUNA's core) on the ULX3S's US2 port.
 * Bulk OUT 0x01 and bulk IN 0x81 are the byte stream, through the device's
 * FIFOs; the vendor requests come out of band: the core answers IDENTIFY
 * from its mailbox by itself (filled here before the board appears on the
 * bus), and hands STATUS and RESET to the engine (their data and status
 * stages are NAKed until the reply is in: status bytes in the mailbox, or
 * the reset done).  A USB bus reset (a replug, a re-enumeration) ends the
 * connection: the engine drops half frames and unsent bytes
 * (ef_board_link_lost), the core empties its IN path meanwhile.
 *
 * IN bursts end with a short packet or a zero-length packet (section 4): the
 * last byte of what the engine offers is held back until the next call, and
 * sent marked "last" when the engine has nothing more; a burst also ends
 * after BURST_MAX bytes, so the host gets the ACKs among streaming results.
 */
#include "link.h"

#ifdef CSR_USB_BASE

#define ST_OUT 1u
#define ST_IN_ROOM 2u
#define ST_REQ_SHIFT 2 /* bits 4:2: the request toggles */
#define REQ_STATUS 1u
#define REQ_RESET 2u
#define REQ_LOST 4u
#define IN_LAST 0x100u
#define MB_STATUS 64u
/* A burst ends after this many bytes even when the engine has more: while results stream, the
 * host's IN transfers (64 KiB) would otherwise complete only when full, holding back the ACKs
 * among the results; 1 KiB at full speed is under 1 ms of the bus. */
#define BURST_MAX 1024u

static int identified;   /* the mailbox holds identify and the board is on the bus */
static uint32_t acked;   /* the request toggles as last served (ctl_ack) */
static uint32_t serving; /* the kind of request being served (REQ_*) */
static int held = -1;    /* the byte held back, or -1 */
static unsigned burst;   /* IN bytes since the last burst ended */

static void usb_mailbox(unsigned at, const uint8_t *buf, size_t len)
{
    for (size_t i = 0; i < len; i++)
        usb_mb_write((uint32_t)(at + i) << 8 | buf[i]);
}

static size_t usb_rx(uint8_t *buf, size_t cap)
{
    size_t n = 0;
    while (n < cap && (usb_status_read() & ST_OUT)) {
        buf[n++] = (uint8_t)usb_out_data_read();
        usb_out_pop_write(1);
    }
    return n;
}

/* One IN byte; "last" ends the burst (a short packet, or a ZLP after a full one). */
static void put(uint32_t b, int last)
{
    last |= burst + 1 >= BURST_MAX;
    usb_in_data_write(b | (last ? IN_LAST : 0u));
    burst = last ? 0 : burst + 1;
}

static size_t usb_tx(const uint8_t *buf, size_t len)
{
    size_t n = 0;
    if (held >= 0) {
        if (!(usb_status_read() & ST_IN_ROOM))
            return 0;
        put((uint32_t)held, len == 0); /* nothing more: the burst ends */
        held = -1;
    }
    while (n + 1 < len && (usb_status_read() & ST_IN_ROOM))
        put(buf[n++], 0);
    if (n + 1 == len) /* the last byte offered: held until we know whether more follows */
        held = buf[n++];
    return n;
}

static int usb_control(void)
{
    if (!identified)
        return FW_REQ_IDENTIFY; /* once, at start: the mailbox first, then the pull-up */
    /* one toggle per kind: a kind is pending while its toggle differs from ours */
    const uint32_t pending = ((usb_status_read() >> ST_REQ_SHIFT) & 7u) ^ acked;
    serving = pending & REQ_LOST ? REQ_LOST : pending & REQ_RESET ? REQ_RESET : pending & REQ_STATUS;
    return serving == REQ_LOST    ? FW_REQ_LINK_LOST
           : serving == REQ_RESET ? FW_REQ_RESET
           : serving              ? FW_REQ_STATUS
                                  : FW_REQ_NONE;
}

static void usb_reply(int req, const uint8_t *buf, size_t len)
{
    if (req == FW_REQ_IDENTIFY && !identified) {
        usb_mailbox(0, buf, len);
        identified = 1;
        acked = (usb_status_read() >> ST_REQ_SHIFT) & 7u; /* a bus reset before this is no news */
        usb_ctl_ack_write(acked);
        usb_ctrl_write(1); /* connect */
        return;
    }
    if (req == FW_REQ_STATUS)
        usb_mailbox(MB_STATUS, buf, len);
    if (req == FW_REQ_RESET || req == FW_REQ_LINK_LOST)
        held = -1;           /* the IN bytes: the core drops those it has until the ack below */
    if (req == FW_REQ_RESET) /* the OUT bytes (a bus reset keeps them: the host saw them ACKed) */
        while (usb_status_read() & ST_OUT)
            usb_out_pop_write(1);
    acked ^= serving;
    usb_ctl_ack_write(acked);
}

const fw_link fw_link_usb = { "usb", NULL, usb_rx, usb_tx, usb_control, usb_reply, NULL };

#endif /* CSR_USB_BASE */
