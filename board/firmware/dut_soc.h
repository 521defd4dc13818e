/*
 * dut_soc.h (board firmware) - the SoC's ef_raster peripheral as the board
 * engine's DUT (dut_soc.c).
 */
#ifndef EF_DUT_SOC_H
#define EF_DUT_SOC_H

#include "ef_board.h"

/* The one peripheral as a DUT table (one engine per board). */
ef_board_dut ef_board_dut_soc(void);
/* Moves the records the peripheral made into the engine: the main loop
 * calls it on every turn. */
void dut_soc_poll(void);

#endif /* EF_DUT_SOC_H */
