/*
 * transport_gpio.h - what the GPIO transport tells beyond transport.h: the
 * sentence behind its last error (which line, what the board's bus status
 * said), for edgeflag-host's messages and the tests (docs/board-gpio.md).
 */
#ifndef EF_TRANSPORT_GPIO_H
#define EF_TRANSPORT_GPIO_H

#include "transport.h"

const char *ef_gpio_link_detail(const ef_link *l);
/* Bus cycles clocked on this link so far. */
unsigned long long ef_gpio_link_cycles(const ef_link *l);

#endif /* EF_TRANSPORT_GPIO_H */
