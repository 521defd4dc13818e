/*
 * gpio_chip.h - an emulated GPIO chip with an edgeflag board wired to it, for
 * the GPIO transport's tests (docs/board-gpio.md section 8).  umockdev
 * presents /dev/gpiochip0; the ioctl handler answers libgpiod's uAPI v1 and v2
 * calls and plays the board's side of the bus: the real board engine
 * (board) behind the real bus logic (board/gpio_bus.c), at the
 * line offsets of `wiring`.  In-process only (docs/board-gpio.md explains).
 */
#ifndef EF_TEST_GPIO_CHIP_H
#define EF_TEST_GPIO_CHIP_H

#include <stdint.h>

#include "ef_board.h"
#include "gpio_bus.h"

#define EMU_LINES 32
#define EMU_SIGNALS 24

/* Faults the emulated board can show (set between transport calls). */
enum {
    EMU_FAULT_NONE = 0,
    EMU_FAULT_STALL = 1,     /* ready stays low: the board stopped taking bytes */
    EMU_FAULT_LIE_READY = 2, /* ready shown high while the bus holds a byte: the host overruns */
    EMU_FAULT_FOREIGN = 4,   /* control replies scrambled: another device on the lines */
    EMU_FAULT_MUTE = 8,      /* avail never rises: nothing on the lines */
    EMU_FAULT_LIE_AVAIL = 16 /* avail shown high while the board has nothing: the host underruns */
};

typedef struct emu_chip {
    ef_board *board;
    ef_gpio_bus *bus;
    unsigned wiring[EMU_SIGNALS]; /* line offset of each signal, transport_gpio.c's order */
    int faults;
    uint32_t stall_after;      /* > 0: ready stays low once the bus accepted this many bytes */
    uint32_t fail_after;       /* > 0: the engine fails (ef_board_fail) after this many bytes */
    uint8_t stuck_d;           /* d lines stuck high at the board (a wiring fault) */
    uint32_t unplug_after;     /* > 0, the simulated board: its lines go dead once it took this many bytes */
    unsigned hide_avail_reads; /* the next this many reads show avail low; the last one takes pause_ms */
    unsigned pause_ms;         /* (the host paused in a GPIO call, as a busy scheduler does) */
    uint64_t edges, ioctls, sets, gets;
    /* The timing the host kept (docs/board-gpio.md section 3), in steps (line
     * ioctls): the fewest from a change of d/valid/take/ctl to the rising
     * edge, and from the edge to the next change (exclusive). */
    uint64_t min_setup, min_hold;
} emu_chip;

/* Creates the testbed, /dev/gpiochip0 and its handler; returns NULL and
 * prints why on failure.  The board engine and DUT are the caller's. */
emu_chip *emu_chip_new(ef_board *board, const unsigned wiring[EMU_SIGNALS]);
/* The second back end: the lines lead to the simulated board's GPIO header
 * (board/sim/gpio_link.cpp) at socket_path; no engine here (board and bus
 * NULL; fail_after does nothing). */
emu_chip *emu_chip_new_sim(const char *socket_path, const unsigned wiring[EMU_SIGNALS]);
void emu_chip_set_faults(emu_chip *e, int faults);
void emu_chip_set_byte_faults(emu_chip *e, uint32_t stall_after, uint32_t fail_after, uint8_t stuck_d);
/* A host paused past its deadline: the next `reads` reads show avail low, the
 * last of them returns only after ms milliseconds. */
void emu_chip_set_pause(emu_chip *e, unsigned reads, unsigned ms);
/* Stream bytes the board's bus accepted from the host since its last reset. */
uint32_t emu_chip_received(emu_chip *e);
/* Swaps in a new board (after a test made the old one fail). */
void emu_chip_set_board(emu_chip *e, ef_board *board);
/* Reads and restarts the timing and step counters. */
void emu_chip_timing(emu_chip *e, uint64_t *min_setup, uint64_t *min_hold, uint64_t *sets, uint64_t *gets,
                     uint64_t *edges);

#endif /* EF_TEST_GPIO_CHIP_H */
