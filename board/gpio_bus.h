/*
 * gpio_bus.h - the board's side of the edgeflag GPIO bus (docs/board-gpio.md):
 * what an FPGA's bus interface does between the header pins and the board
 * engine (ef_board.h), written once in C so the emulated GPIO chip in the
 * tests runs the same logic a board implements.
 *
 * The host is the bus master and owns the clock.  At every rising edge of clk
 * the board samples the host's lines (d0..d7, valid, take, ctl) and calls
 * ef_gpio_bus_edge(); between edges the board drives q0..q7, ready, avail,
 * done and err from ef_gpio_bus_outputs().  Like the engine, it never blocks,
 * never prints and holds no globals.
 */
#ifndef EF_GPIO_BUS_H
#define EF_GPIO_BUS_H

#include <stdint.h>

#include "ef_board.h"

/* Host-driven control lines sampled at an edge (bit set = line high). */
enum { EF_GB_VALID = 1, EF_GB_TAKE = 2, EF_GB_CTL = 4 };

/* Control request codes, sent on d0..d7 with ctl and valid high. */
enum {
    EF_GB_REQ_IDENTIFY = 0x01,  /* reply: EF_PROTO_IDENTIFY_LEN bytes */
    EF_GB_REQ_STATUS = 0x02,    /* reply: EF_PROTO_STATUS_LEN bytes */
    EF_GB_REQ_RESET = 0x03,     /* no reply: engine and bus reset */
    EF_GB_REQ_BUS_STATUS = 0x04 /* reply: EF_GB_BUS_STATUS_LEN bytes */
};
#define EF_GB_BUS_STATUS_LEN 12

/* Latched error causes (BUS_STATUS byte 0; err high while non-zero). */
enum {
    EF_GB_ERR_NONE = 0,
    EF_GB_ERR_OVERRUN = 1,  /* valid at an edge while ready was low */
    EF_GB_ERR_UNDERRUN = 2, /* take at an edge while avail was low */
    EF_GB_ERR_CONTROL = 3,  /* unknown request code, or valid/take on a ctl-changing edge */
    EF_GB_ERR_ENGINE = 4    /* the engine failed (its state is ERROR) */
};

/* What the board drives between edges. */
typedef struct ef_gpio_bus_lines {
    uint8_t q; /* q0..q7 */
    uint8_t ready, avail, done, err;
} ef_gpio_bus_lines;

typedef struct ef_gpio_bus ef_gpio_bus;

/* The bus owns neither the engine nor its DUT: b must outlive it. */
ef_gpio_bus *ef_gpio_bus_new(ef_board *b);
void ef_gpio_bus_free(ef_gpio_bus *g);
/* One rising edge of clk with d0..d7 = d and the EF_GB_* lines in ctrl. */
void ef_gpio_bus_edge(ef_gpio_bus *g, uint8_t d, unsigned ctrl);
/* The lines the board drives now. */
void ef_gpio_bus_outputs(ef_gpio_bus *g, ef_gpio_bus_lines *out);
/* Counters: stream bytes accepted from the host and sent to it since reset. */
uint32_t ef_gpio_bus_rx_count(const ef_gpio_bus *g);
uint32_t ef_gpio_bus_tx_count(const ef_gpio_bus *g);
int ef_gpio_bus_error(const ef_gpio_bus *g);

#endif /* EF_GPIO_BUS_H */
