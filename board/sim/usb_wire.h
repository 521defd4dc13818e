/*
 * usb_wire.h - the messages between the emulated USB host side
 * (tests/host/usb_emu.c, its --soc back end) and the simulated board's USB
 * host controller (board/sim/usb_link.cpp) over a unix socket: one
 * transfer (a usbfs URB) per message, both ways.  Little-endian.
 *
 * emulator -> board: a header, then len bytes
 *   USBW_SUBMIT    id, a = type (USBW_CONTROL, USBW_BULK) | endpoint << 8,
 *                  b = the IN length (bulk IN: the buffer; control: wLength),
 *                  payload: control: the 8 setup bytes and the OUT data stage;
 *                  bulk OUT: the bytes; bulk IN: none
 *   USBW_CANCEL    id: complete it now with what it has (status USBW_ECANCELED)
 *   USBW_BUS_RESET id: wait for the device's pull-up, drive a bus reset,
 *                  address 0 again; answered with a USBW_BUS_RESET of that id
 *   USBW_FREEZE    a = 1: the board's CPU and ef_raster stop (their clocks
 *                  held; the USB core runs on: a board that stops answering),
 *                  a = 0: they run again
 * board -> emulator
 *   USBW_COMPLETE  id, a = status (0, or a negative errno value: USBW_*),
 *                  b = bytes done (OUT: sent, IN: received), payload: the IN
 *                  bytes received
 *   USBW_BUS_RESET id: the reset is over
 */
#ifndef EF_USB_WIRE_H
#define EF_USB_WIRE_H

#include <stdint.h>

enum { USBW_SUBMIT = 1, USBW_CANCEL = 2, USBW_BUS_RESET = 3, USBW_FREEZE = 4, USBW_COMPLETE = 5 };
enum { USBW_CONTROL = 0, USBW_BULK = 1 };
/* completion statuses, as usbfs reports them (Linux errno values) */
enum { USBW_OK = 0, USBW_EPIPE = -32, USBW_ECANCELED = -2, USBW_EPROTO = -71 };

typedef struct usbw_hdr {
    uint32_t op, id, a, b, len;
} usbw_hdr;

#endif /* EF_USB_WIRE_H */
