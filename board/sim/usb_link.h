// usb_link.h - the simulated board's USB host controller (usb_link.cpp):
// transfers from tests/host/usb_emu.c (a unix socket, usb_wire.h) turned into
// full-speed transactions on the UTMI side of the SoC's USB core.
#ifndef EF_USB_LINK_H
#define EF_USB_LINK_H

#include <cstdint>

// The UTMI signals of the Verilated SoC (Vsim's members).
struct UtmiPins {
    uint8_t *rx_data, *rx_valid, *rx_active, *rx_error, *tx_ready, *line_state;
    const uint8_t *tx_data, *tx_valid, *term_select;
};

struct UsbLink;
// Listens on the unix socket path; nullptr (with a message) on failure.
UsbLink *usb_link_new(const char *path, UtmiPins pins);
// Once every 256 sys cycles or so: the socket (new emulator, messages both ways).
void usb_link_poll(UsbLink *u);
// Once per usb clock cycle (12 MHz): drive() before the rising edge's
// evaluation settles the inputs, sample() after it reads what the core drove.
void usb_link_drive(UsbLink *u);
void usb_link_sample(UsbLink *u);
// The board's CPU and ef_raster clocks are held (USBW_FREEZE).
bool usb_link_frozen(const UsbLink *u);
// Figures for the end-of-run line: transactions, bytes, frames.
void usb_link_report(const UsbLink *u, double sim_seconds, double wall_seconds);
void usb_link_free(UsbLink *u);

#endif
