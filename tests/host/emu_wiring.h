/*
 * emu_wiring.h - how the emulated GPIO board is wired, for the programs that
 * drive the GPIO transport against it (gpio_emu.c, and gpio_cosim.c, whose
 * chip leads to the simulated SoC's GPIO header): control lines first, data
 * bytes in the middle (line offsets of EMU_SIGNALS in emu_chip's order), and
 * the --lines map a user would write for it (some lines by name, some by
 * offset; docs/board-gpio.md).  Static definitions: included by one file of
 * a program, after gpio_chip.h.
 */
#ifndef EF_TEST_EMU_WIRING_H
#define EF_TEST_EMU_WIRING_H

#include "gpio_chip.h"

static const unsigned WIRING[EMU_SIGNALS] = {
    4,  5,  6,  7,  8,  9,  10, 11, /* d0..d7 */
    0,  1,  2,  3,                  /* clk valid take ctl */
    20, 21, 22, 23, 24, 25, 26, 27, /* q0..q7 */
    12, 13, 14, 15                  /* ready avail done err */
};
static const char *LINES = "clk=EF_CLK,valid=EF_VALID,take=EF_TAKE,ctl=EF_CTL,d=4-11,q=20:21:22:23:24:25:26:27,"
                           "ready=EF_READY,avail=13,done=EF_DONE,err=15";

#endif /* EF_TEST_EMU_WIRING_H */
