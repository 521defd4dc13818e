/*
 * transport.h - how edgeflag-host reaches a board: one table of operations
 * per transport (usb, gpio, sim, null, socket, serial), as libusb keeps its OS backends behind
 * one table.  A transport moves bytes and the three control requests; the
 * protocol (frames, sequence numbers, CRC, windows, resume) lives above it in
 * host_link.c and is the same for every transport (docs/board.md).
 *
 * Errors: every operation returns 0 (or a count) on success and a negative
 * EF_HOST_E* on failure; the transport translates errno / libusb / libgpiod
 * errors at its boundary and may leave a human-readable detail in link->err.
 */
#ifndef EF_TRANSPORT_H
#define EF_TRANSPORT_H

#include <stddef.h>
#include <stdint.h>

enum {
    EF_HOST_OK = 0,
    EF_HOST_ENODEV = -1,     /* the board went away (unplug): the run can be resumed */
    EF_HOST_ETIMEDOUT = -2,  /* no answer within the timeout */
    EF_HOST_EACCESS = -3,    /* permission denied (udev rule, docs/board.md section 7) */
    EF_HOST_EIO = -4,        /* any other I/O failure */
    EF_HOST_EPROTO = -5,     /* not an edgeflag board, or another protocol version */
    EF_HOST_ENOTFOUND = -6,  /* no board matches the selectors */
    EF_HOST_EAMBIGUOUS = -7, /* several boards match: say which */
    EF_HOST_EBUSY = -8,      /* claimed by another program */
    EF_HOST_ENOMEM = -9,
    EF_HOST_EINVAL = -10,      /* bad option value */
    EF_HOST_EUNSUPPORTED = -11 /* transport not built in (library absent at build time) */
};
const char *ef_host_strerror(int err);

/* Options every transport may read (unset: 0 / NULL). */
typedef struct ef_host_opts {
    const char *device;     /* usb: SERIAL, BUS:DEV, or #INDEX (docs/board.md 5.1) */
    uint16_t vid, pid;      /* usb: 0 = the defaults (1209:0001) */
    unsigned transfer_size; /* usb: bytes per bulk transfer (0 = default) */
    unsigned in_flight;     /* usb: transfers in flight each way (0 = default, >= 4) */
    int timeout_ms;         /* every transfer / bus wait; 0 = default */
    const char *chip;       /* gpio: chip name or path (gpiochip0, /dev/gpiochip0) */
    const char *lines;      /* gpio: line map (docs/board.md 5.2) */
    const char *sim_state;  /* sim: directory holding the board's state across runs */
    const char *sim_faults; /* sim: fault injection (docs/board.md 6) */
    const char *connect;    /* socket: unix:PATH or tcp:HOST:PORT (docs/board.md 5.5) */
    const char *port;       /* serial: the tty (/dev/ttyUSB0, docs/board-serial.md) */
    unsigned baud;          /* serial: 0 = the default (3,000,000) */
} ef_host_opts;

typedef struct ef_link ef_link;

/* One board found by list / auto. */
typedef struct ef_found {
    char transport[8];
    char where[64]; /* usb "BUS:DEV", gpio chip path */
    char desc[160]; /* VID:PID, serial, protocol, DUT parameters / lines */
    int ok;         /* answered identify with our protocol */
    int err;        /* why not (EF_HOST_E*: EACCESS, EPROTO, ...), 0 when ok */
} ef_found;

typedef struct ef_transport_ops {
    const char *name;
    /* Finds candidate boards; fills up to max entries, returns the count (all
     * found, may exceed max) or a negative error. */
    int (*probe)(const ef_host_opts *o, ef_found *found, int max);
    int (*open)(ef_link **out, const ef_host_opts *o, char *err, size_t errlen);
    int (*identify)(ef_link *l, uint8_t out[48]);
    int (*status)(ef_link *l, uint8_t out[40]);
    int (*reset)(ef_link *l);
    /* Queues len bytes for the board; may return before they are on the wire
     * (asynchronous transfers) but never holds more than the transport's own
     * in-flight limit; timeout bounds the wait for room. */
    int (*write)(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms);
    /* Waits until every queued byte is delivered (or fails). */
    int (*flush)(ef_link *l, int timeout_ms);
    /* Reads what the board has sent: waits up to timeout_ms for at least one
     * byte, stores up to cap, sets *got (0 on timeout, with EF_HOST_ETIMEDOUT). */
    int (*read)(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms);
    void (*close)(ef_link *l);
    /* Build-time note for --version ("libusb 1.0.26", "absent: built without libusb"). */
    const char *(*version)(void);
    /* The last failure in the transport's own words (which transfer, which
     * line, the library's error name), or "" / NULL op when there is none. */
    const char *(*detail)(ef_link *l);
} ef_transport_ops;

extern const ef_transport_ops ef_transport_usb;
extern const ef_transport_ops ef_transport_gpio;
extern const ef_transport_ops ef_transport_sim;
extern const ef_transport_ops ef_transport_null;
extern const ef_transport_ops ef_transport_socket;
extern const ef_transport_ops ef_transport_serial;

#endif /* EF_TRANSPORT_H */
