/*
 * transport_serial.c - a board behind a serial line (docs/board-serial.md): a
 * USB UART such as the ULX3S's FT231X (/dev/ttyUSB0), or a pseudo-terminal in
 * front of a simulation.  The line is one byte stream each way carrying the
 * frames and control frames of docs/board.md section 5.5: transport_stream.c
 * does all of that; this file opens the tty, sets it raw at the baud asked
 * for and finds FTDI boards in sysfs for `list` and `auto`.
 *
 * The speed goes through termios2 (TCSETS2 with BOTHER, <asm/termbits.h>),
 * which takes any baud the driver can make (the FTDI driver computes its own
 * divisor); a kernel or driver that refuses it gets the classic Bnnn codes for
 * the standard speeds.  <termios.h> is not included: its struct termios
 * clashes with the kernel's, so raw mode is set field by field here.
 */
#define _DEFAULT_SOURCE
#include <asm/termbits.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "ef_proto.h"
#include "host_link.h"
#include "transport.h"
#include "transport_stream.h"

enum { DEFAULT_BAUD = 3000000, DEFAULT_TIMEOUT_MS = 2000, PROBE_TIMEOUT_MS = 250 };

/* FTDI's UARTs on edgeflag boards: the ULX3S's FT231X, the FT2232H of
 * ECPIX-5-like boards (docs/board-serial.md section 1). */
static const struct {
    uint16_t vid, pid;
    const char *chip;
} KNOWN[] = { { 0x0403, 0x6015, "FT231X" }, { 0x0403, 0x6010, "FT2232" } };

typedef struct serial_link {
    ef_stream s;
    unsigned baud, actual;
} serial_link;

/* The classic codes, for a driver without termios2. */
static const struct {
    unsigned baud;
    unsigned code;
} STD[] = { { 9600, B9600 },       { 19200, B19200 },     { 38400, B38400 },     { 57600, B57600 },
            { 115200, B115200 },   { 230400, B230400 },   { 460800, B460800 },   { 500000, B500000 },
            { 921600, B921600 },   { 1000000, B1000000 }, { 1500000, B1500000 }, { 2000000, B2000000 },
            { 3000000, B3000000 }, { 4000000, B4000000 } };

/* Raw 8N1, no flow control, reads that never wait (poll() does the waiting). */
static void make_raw(struct termios2 *t)
{
    t->c_iflag &= ~(tcflag_t)(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON | IXOFF | IXANY);
    t->c_oflag &= ~(tcflag_t)OPOST;
    t->c_lflag &= ~(tcflag_t)(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
    t->c_cflag &= ~(tcflag_t)(CSIZE | PARENB | CSTOPB | CRTSCTS);
    t->c_cflag |= CS8 | CREAD | CLOCAL;
    t->c_cc[VMIN] = 0;
    t->c_cc[VTIME] = 0;
}

/* Sets raw mode at baud; *actual = what the driver reports back.  0 or an errno. */
static int set_line(int fd, unsigned baud, unsigned *actual)
{
    struct termios2 t;
    if (ioctl(fd, TCGETS2, &t) == 0) {
        make_raw(&t);
        t.c_cflag &= ~(tcflag_t)(CBAUD | (CBAUD << IBSHIFT));
        t.c_cflag |= BOTHER | (BOTHER << IBSHIFT);
        t.c_ispeed = t.c_ospeed = baud;
        if (ioctl(fd, TCSETS2, &t) == 0 && ioctl(fd, TCGETS2, &t) == 0) {
            *actual = t.c_ospeed;
            return 0;
        }
    }
    /* no termios2: the standard speeds only */
    struct termios o;
    if (ioctl(fd, TCGETS, &o) != 0)
        return errno;
    for (size_t i = 0; i < sizeof STD / sizeof STD[0]; i++) {
        if (STD[i].baud != baud)
            continue;
        struct termios2 t2 = { 0 };
        t2.c_iflag = o.c_iflag, t2.c_oflag = o.c_oflag, t2.c_cflag = o.c_cflag, t2.c_lflag = o.c_lflag;
        make_raw(&t2);
        o.c_iflag = t2.c_iflag, o.c_oflag = t2.c_oflag, o.c_lflag = t2.c_lflag;
        o.c_cflag = (t2.c_cflag & ~(tcflag_t)CBAUD) | STD[i].code;
        o.c_cc[VMIN] = 0, o.c_cc[VTIME] = 0;
        if (ioctl(fd, TCSETS, &o) != 0)
            return errno;
        *actual = baud;
        return 0;
    }
    return EINVAL;
}

static int open_port(serial_link **out, const char *port, unsigned baud, int timeout_ms, char *err, size_t errlen)
{
    const int fd = open(port, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int e = errno;
        if (e == EACCES || e == EPERM) {
            snprintf(
                err, errlen,
                "%s: %s: install the udev rule host/60-edgeflag-serial.rules as /etc/udev/rules.d/60-edgeflag-serial.rules "
                "and run `udevadm control --reload && udevadm trigger` as root, then replug the board "
                "(docs/board-serial.md section 4)",
                port, strerror(e));
            return EF_HOST_EACCESS;
        }
        snprintf(err, errlen, "%s: %s", port, strerror(e));
        return e == ENOENT || e == ENXIO || e == ENODEV ? EF_HOST_ENOTFOUND : EF_HOST_EIO;
    }
    if (!isatty(fd)) {
        snprintf(err, errlen, "%s: not a terminal (a serial port or a pseudo-terminal)", port);
        close(fd);
        return EF_HOST_EINVAL;
    }
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        snprintf(err, errlen, "%s: in use by another program (it holds the port's lock)", port);
        close(fd);
        return EF_HOST_EBUSY;
    }
    unsigned actual = 0;
    const int e = set_line(fd, baud, &actual);
    if (e) {
        snprintf(err, errlen, "%s: the driver does not take %u baud: %s", port, baud, strerror(e));
        close(fd);
        return EF_HOST_EINVAL;
    }
    ioctl(fd, TCFLSH, TCIOFLUSH); /* what an earlier program left in the queues is not ours */
    serial_link *l = calloc(1, sizeof *l);
    if (!l) {
        close(fd);
        return EF_HOST_ENOMEM;
    }
    ef_stream_init(&l->s, port, timeout_ms, 0);
    l->s.fd = fd;
    l->baud = baud, l->actual = actual;
    *out = l;
    return 0;
}

static int ser_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)
{
    if (!o->port) {
        snprintf(err, errlen, "--transport serial needs --port /dev/ttyUSB0 (edgeflag-host list shows the boards)");
        return EF_HOST_EINVAL;
    }
    serial_link *l;
    const int r = open_port(&l, o->port, o->baud ? o->baud : DEFAULT_BAUD,
                            o->timeout_ms > 0 ? o->timeout_ms : DEFAULT_TIMEOUT_MS, err, errlen);
    if (r == 0)
        *out = (ef_link *)l;
    return r;
}

static void ser_close(ef_link *l)
{
    if (!l)
        return;
    ef_stream_close((ef_stream *)l);
    free(l);
}

/* ------------------------------------------------------------------ list */
/* sysfs and /dev, or the folders named by EF_SERIAL_SYSFS and EF_SERIAL_DEV
 * (the test's stand-ins for a machine with FTDI boards plugged in). */
static const char *root(const char *env, const char *dflt)
{
    const char *v = getenv(env);
    return v && *v ? v : dflt;
}

static int read_attr(const char *dir, const char *name, char *buf, size_t size)
{
    char p[PATH_MAX + 64];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    FILE *f = fopen(p, "r");
    if (!f)
        return -1;
    const int ok = fgets(buf, (int)size, f) != NULL;
    fclose(f);
    if (!ok)
        return -1;
    buf[strcspn(buf, "\r\n")] = 0;
    return 0;
}

/* The USB device above a tty's sysfs device (the folder with idVendor): 0, or -1. */
static int usb_parent(const char *sys, const char *tty, char *dev, size_t size, char *ifnum, size_t ifsize)
{
    char p[PATH_MAX], real[PATH_MAX];
    if (snprintf(p, sizeof p, "%s/class/tty/%s/device", sys, tty) >= (int)sizeof p || !realpath(p, real))
        return -1;
    ifnum[0] = 0;
    for (int up = 0; up < 4; up++) {
        char v[16];
        if (!ifnum[0])
            read_attr(real, "bInterfaceNumber", ifnum, ifsize);
        if (read_attr(real, "idVendor", v, sizeof v) == 0) {
            snprintf(dev, size, "%s", real);
            return 0;
        }
        char *slash = strrchr(real, '/');
        if (!slash || slash == real)
            return -1;
        *slash = 0;
    }
    return -1;
}

static int ser_probe(const ef_host_opts *o, ef_found *found, int max)
{
    const char *sys = root("EF_SERIAL_SYSFS", "/sys"), *devdir = root("EF_SERIAL_DEV", "/dev");
    char cls[PATH_MAX];
    snprintf(cls, sizeof cls, "%s/class/tty", sys);
    DIR *d = opendir(cls);
    if (!d)
        return 0;
    struct dirent *e;
    int n = 0;
    char names[64][64];
    int k = 0;
    while ((e = readdir(d)) && k < 64)
        if (e->d_name[0] != '.' && strlen(e->d_name) < sizeof names[0])
            snprintf(names[k++], sizeof names[0], "%s", e->d_name);
    closedir(d);
    qsort(names, (size_t)k, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    for (int i = 0; i < k; i++) {
        char dev[PATH_MAX], ifnum[16], v[16] = "", p[16] = "", serial[64] = "";
        if (usb_parent(sys, names[i], dev, sizeof dev, ifnum, sizeof ifnum) != 0)
            continue;
        read_attr(dev, "idVendor", v, sizeof v);
        read_attr(dev, "idProduct", p, sizeof p);
        read_attr(dev, "serial", serial, sizeof serial);
        const unsigned vid = (unsigned)strtoul(v, NULL, 16), pid = (unsigned)strtoul(p, NULL, 16);
        const char *chip = NULL;
        if (o->vid && o->pid)
            chip = vid == o->vid && pid == o->pid ? "UART" : NULL;
        else
            for (size_t j = 0; j < sizeof KNOWN / sizeof KNOWN[0]; j++)
                if (KNOWN[j].vid == vid && KNOWN[j].pid == pid)
                    chip = KNOWN[j].chip;
        if (!chip)
            continue;
        if (n < max) {
            ef_found *f = &found[n];
            memset(f, 0, sizeof *f);
            snprintf(f->transport, sizeof f->transport, "serial");
            if (snprintf(f->where, sizeof f->where, "%s/%s", devdir, names[i]) >= (int)sizeof f->where)
                continue; /* a path too long to name: not listed */
            char head[96];
            snprintf(head, sizeof head, "%04x:%04x %s%s%s, USB serial %s", vid, pid, chip,
                     ifnum[0] ? " interface " : "", ifnum, serial[0] ? serial : "(none)");
            serial_link *l;
            char err[300] = "";
            int r = open_port(&l, f->where, o->baud ? o->baud : DEFAULT_BAUD, PROBE_TIMEOUT_MS, err, sizeof err);
            uint8_t raw[EF_PROTO_IDENTIFY_LEN];
            ef_host_ident id;
            if (r == 0) {
                r = ef_stream_op_identify((ef_link *)l, raw);
                ser_close((ef_link *)l);
                if (r == 0)
                    r = ef_host_ident_parse(raw, &id);
            }
            f->ok = r == 0;
            f->err = r;
            if (r == 0) {
                char desc[120];
                ef_host_ident_describe(&id, desc, sizeof desc);
                if (snprintf(f->desc, sizeof f->desc, "%s; %s", head, desc) >= (int)sizeof f->desc)
                    f->desc[sizeof f->desc - 1] = 0;
            } else {
                snprintf(f->desc, sizeof f->desc, "%s; %s", head,
                         r == EF_HOST_EACCESS ? "permission denied: install host/60-edgeflag-serial.rules"
                         : r == EF_HOST_EBUSY ? "in use by another program"
                                              : "does not answer identify");
            }
        }
        n++;
    }
    return n;
}

static const char *ser_version(void)
{
    return "built in (termios2: --port /dev/ttyUSB0 [--baud N], any baud the driver takes)";
}

const ef_transport_ops ef_transport_serial = {
    "serial",           ser_probe,          ser_open,           ef_stream_op_identify, ef_stream_op_status,
    ef_stream_op_reset, ef_stream_op_write, ef_stream_op_flush, ef_stream_op_read,     ser_close,
    ser_version,        ef_stream_op_detail
};
