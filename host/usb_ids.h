/*
 * usb_ids.h - the USB mapping of the board protocol (docs/board-usb.md): the
 * numbers firmware and edgeflag-host must agree on, in one place for the
 * transport (transport_usb.c) and the emulated board (tests/host/usb_emu.c).
 */
#ifndef EF_USB_IDS_H
#define EF_USB_IDS_H

#include <stddef.h>
#include <stdint.h>

/* pid.codes' test VID:PID; a product overrides it (--vid/--pid). */
#define EF_USB_VID 0x1209
#define EF_USB_PID 0x0001

#define EF_USB_INTERFACE 0 /* vendor class 0xff, subclass 0, protocol 0 */
#define EF_USB_EP_OUT 0x01 /* bulk, frames to the board */
#define EF_USB_EP_IN 0x81  /* bulk, frames from the board */
#define EF_USB_MPS_HS 512  /* bulk wMaxPacketSize at High-Speed */
#define EF_USB_MPS_FS 64   /* ... at Full-Speed */

/* Vendor control requests to the device (recipient device, wValue = wIndex = 0). */
#define EF_USB_RT_IN 0xC0        /* device-to-host | vendor | device */
#define EF_USB_RT_OUT 0x40       /* host-to-device | vendor | device */
#define EF_USB_REQ_IDENTIFY 0x01 /* IN, 48 bytes: ef_board_identify() */
#define EF_USB_REQ_RESET 0x02    /* OUT, no data: ef_board_reset() */
#define EF_USB_REQ_STATUS 0x03   /* IN, 40 bytes: ef_board_status() */
#define EF_USB_IDENTIFY_LEN 48
#define EF_USB_STATUS_LEN 40

#define EF_USB_MAGIC "EFB1"
#define EF_USB_PROTOCOL 1

#endif /* EF_USB_IDS_H */
