// gpio_link.h - the simulated board's GPIO header (docs/board-gpio.md, "Co-simulation"): a unix
// socket that carries the host's line changes to the SoC's GPIO bus pins and their samples back,
// so the emulated gpiochip of the tests (tests/host/gpio_chip.c) drives the gateware slave of
// board/soc/ef_gpio.py through the real libgpiod.  board_sim.cpp calls these three.
#ifndef EF_SIM_GPIO_LINK_H
#define EF_SIM_GPIO_LINK_H

#include <cstdint>

class Vsim;
struct GpioLink;

// Listens on the unix socket path (one client at a time).  A host step lasts at least
// step_cycles sys cycles; with lockstep the board's time runs only while a step is served.
// Returns nullptr after printing why.
GpioLink *gpio_link_open(const char *path, unsigned step_cycles, bool lockstep);
// Once per sys cycle, before the cycle's evaluation: applies the host's lines, answers a step.
void gpio_link_cycle(GpioLink *g, Vsim &top, uint64_t cyc);
// What moved over the bus (stderr), in simulated time at sys_hz; closes the socket.
void gpio_link_close(GpioLink *g, double sys_hz);

#endif   // EF_SIM_GPIO_LINK_H
