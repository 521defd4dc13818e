/*
 * link.h (board firmware) - a link between the host and the board engine
 * (docs/board-ulx3s.md, "One engine, several links"): the engine of main.c
 * serves every link the SoC has through this table of functions.  A link
 * moves the protocol's byte stream both ways (docs/board.md section 2); a
 * link with out-of-band control (the GPIO bus's control view, USB's control
 * transfers) also hands the engine identify, status and reset requests and
 * carries their replies.  A link that is only a byte stream (the UART)
 * carries them as control frames inside the stream (docs/board.md 5.5),
 * which the engine answers itself: its control function is NULL.
 *
 * No function may block: each does what its hardware allows now and returns.
 */
#ifndef EF_FW_LINK_H
#define EF_FW_LINK_H

#include <stddef.h>
#include <stdint.h>

#include <generated/csr.h>

/* Out-of-band control requests (docs/board.md 3.1). */
enum { FW_REQ_NONE = 0, FW_REQ_IDENTIFY = 1, FW_REQ_STATUS = 2, FW_REQ_RESET = 3, FW_REQ_LINK_LOST = 4 };

typedef struct fw_link {
    const char *name;
    /* Called once before the loop starts; may be NULL. */
    void (*init)(void);
    /* Copies up to cap bytes the host sent into buf; returns the count. */
    size_t (*rx)(uint8_t *buf, size_t cap);
    /* Offers len bytes for the host; returns how many the link took. */
    size_t (*tx)(const uint8_t *buf, size_t len);
    /* Out-of-band control: returns a pending FW_REQ_* (FW_REQ_NONE: none).
     * NULL for a link whose requests travel in the byte stream. */
    int (*control)(void);
    /* The answer to the request control() returned: the reply's bytes
     * (identify, status), or len 0 for reset, which the engine has done
     * (the link then drops the stream bytes it holds both ways), or len 0
     * for link lost (the link's connection ended, e.g. a USB bus reset: the
     * engine dropped a half frame and its unsent bytes, ef_board_link_lost;
     * the run is kept). */
    void (*reply)(int req, const uint8_t *buf, size_t len);
    /* The engine's state for a link that shows it on lines (the GPIO bus's
     * done and err); may be NULL.  Called on every turn of the loop. */
    void (*state)(int done, int failed);
} fw_link;

extern const fw_link fw_link_uart;
/* Moves the bytes the UART received into its ring (link_uart.c): called by
 * the loop and by work inside the engine's calls that may take long. */
void fw_link_poll(void);
#ifdef CSR_GPIOBUS_BASE
extern const fw_link fw_link_gpio;
#endif
#ifdef CSR_USB_BASE
extern const fw_link fw_link_usb;
#endif

#endif /* EF_FW_LINK_H */
