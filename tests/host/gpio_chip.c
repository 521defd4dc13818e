/*
 * gpio_chip.c - the emulated GPIO chip of gpio_chip.h.
 *
 * How it works (docs/board-gpio.md section 8, ../shared/docs/HOST.md):
 * umockdev's preload routes every open/ioctl on /dev/gpiochip0 to the
 * handler below, which runs on umockdev's own thread.  A line request must
 * return a new file descriptor, so the handler opens /dev/gpiochip0 itself
 * (a new umockdev connection) and marks the next client that connects as that
 * request.  umockdev never says when a client goes away, so lines stay owned
 * until their owner's `connected` turns false.
 *
 * The board side: every set-values call updates the line levels; a rising
 * level on the clk line is an edge for ef_gpio_bus_edge(); every get-values
 * call reads ef_gpio_bus_outputs().  Both uAPI versions are answered, so one
 * emulator serves libgpiod 1.6 and 2.x.
 *
 * The second back end (emu_chip_new_sim): the lines lead to the simulated
 * board's GPIO header instead (board/sim/gpio_link.cpp: the SoC's gateware
 * slave, board/soc/ef_gpio.py, and its firmware), one socket round trip per
 * set-values or get-values call: the levels the host drives go out, the
 * board's lines come back after at least one host step of its time.
 */
#include "gpio_chip.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/gpio.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <umockdev.h>
#include <unistd.h>

/* transport_gpio.c's signal order: d0..d7 clk valid take ctl q0..q7 ready avail done err */
enum { S_D0 = 0, S_CLK = 8, S_VALID, S_TAKE, S_CTL, S_Q0 = 12, S_READY = 20, S_AVAIL, S_DONE, S_ERR };

typedef struct emu_req {
    UMockdevIoctlClient *client; /* a reference: its `connected` tells when it is gone */
    unsigned n, offsets[GPIO_V2_LINES_MAX];
    int output;
    char consumer[GPIO_MAX_NAME_SIZE];
} emu_req;

typedef struct emu_state {
    emu_chip pub;
    GMutex lock;
    UMockdevTestbed *tb;
    UMockdevIoctlBase *handler;
    uint8_t level[EMU_LINES]; /* what the host drives on its outputs */
    emu_req *owner[EMU_LINES];
    emu_req *pending[8]; /* requests waiting for their connection */
    int npending;
    emu_req *reqs[64]; /* every request made (freed at exit) */
    int nreqs;
    uint64_t step, change_step, edge_step; /* line ioctls, and when data changed / clk rose */
    int edge_since_change;
    uint32_t data;     /* d | valid << 8 | take << 9 | ctl << 10 as last written */
    int sim_fd;        /* >= 0: the simulated board's GPIO header (gpio_link.cpp) */
    unsigned sim_out;  /* its lines as last answered: q | ready << 8 | avail << 9 | done << 10 | err << 11 */
    uint32_t sim_rx;   /* stream bytes the host clocked in while ready was shown, since the last RESET */
    int data_prev_ctl; /* ctl at the last edge */
} emu_state;

static const char *line_name(const emu_state *s, unsigned off)
{
    /* The control lines carry names (a board's device tree would give them),
     * the data lines none, so tests map both by name and by offset. */
    static const char *const named[] = {
        [S_CLK] = "EF_CLK",     [S_VALID] = "EF_VALID", [S_TAKE] = "EF_TAKE", [S_CTL] = "EF_CTL",
        [S_READY] = "EF_READY", [S_AVAIL] = "EF_AVAIL", [S_DONE] = "EF_DONE", [S_ERR] = "EF_ERR"
    };
    for (unsigned sig = 0; sig < EMU_SIGNALS; sig++)
        if (s->pub.wiring[sig] == off && sig < sizeof named / sizeof named[0] && named[sig])
            return named[sig];
    return "";
}

static int req_alive(const emu_req *r) { return r && r->client && umockdev_ioctl_client_get_connected(r->client); }

/* The board's outputs onto the line levels. */
/* The simulated board: one host step (the levels the host drives now), its lines back. */
static void sim_step(emu_state *s)
{
    const unsigned *w = s->pub.wiring;
    unsigned host = s->pub.stuck_d;
    for (int i = 0; i < 12; i++)
        host |= (unsigned)s->level[w[i]] << i;
    uint8_t m[2] = { (uint8_t)host, (uint8_t)(host >> 8) }, r[2];
    if (s->sim_fd < 0 || send(s->sim_fd, m, 2, MSG_NOSIGNAL) != 2 || recv(s->sim_fd, r, 2, MSG_WAITALL) != 2) {
        if (s->sim_fd >= 0) {
            fprintf(stderr, "gpio_chip: the simulated board went away\n");
            close(s->sim_fd);
        }
        s->sim_fd = -1;
        s->sim_out = 0; /* nothing on the lines */
        return;
    }
    s->sim_out = (unsigned)r[0] | (unsigned)r[1] << 8;
}

static uint32_t bus_received(const emu_state *s) { return s->pub.bus ? ef_gpio_bus_rx_count(s->pub.bus) : s->sim_rx; }

static void board_drive(emu_state *s)
{
    ef_gpio_bus_lines o;
    if (s->pub.bus) {
        ef_gpio_bus_outputs(s->pub.bus, &o);
    } else {
        if (s->pub.unplug_after && s->sim_rx >= s->pub.unplug_after && s->sim_fd >= 0) {
            fprintf(stderr, "gpio_chip: unplugged after %u bytes\n", (unsigned)s->sim_rx);
            close(s->sim_fd); /* the board's header sees its pull-downs, the host nothing */
            s->sim_fd = -1, s->sim_out = 0;
        }
        sim_step(s);
        o.q = (uint8_t)s->sim_out, o.ready = s->sim_out >> 8 & 1, o.avail = s->sim_out >> 9 & 1;
        o.done = s->sim_out >> 10 & 1, o.err = s->sim_out >> 11 & 1;
    }
    int f = s->pub.faults;
    if ((f & EMU_FAULT_STALL) || (s->pub.stall_after && bus_received(s) >= s->pub.stall_after))
        o.ready = 0;
    if (f & EMU_FAULT_LIE_READY)
        o.ready = 1;
    if (f & EMU_FAULT_MUTE)
        o.avail = 0;
    if (f & EMU_FAULT_LIE_AVAIL)
        o.avail = 1;
    if (s->pub.hide_avail_reads) {
        o.avail = 0;
        if (--s->pub.hide_avail_reads == 0 && s->pub.pause_ms) {
            g_usleep((gulong)s->pub.pause_ms * 1000);
            s->pub.pause_ms = 0;
        }
    }
    if ((f & EMU_FAULT_FOREIGN) && s->level[s->pub.wiring[S_CTL]])
        o.q ^= 0x5a;
    for (int i = 0; i < 8; i++)
        s->level[s->pub.wiring[S_Q0 + i]] = (uint8_t)(o.q >> i & 1);
    s->level[s->pub.wiring[S_READY]] = o.ready;
    s->level[s->pub.wiring[S_AVAIL]] = o.avail;
    s->level[s->pub.wiring[S_DONE]] = o.done;
    s->level[s->pub.wiring[S_ERR]] = o.err;
}

/* The host changed its outputs: a rising clk is a bus edge. */
static void host_drive(emu_state *s, const emu_req *r, uint64_t bits, uint64_t mask)
{
    const unsigned *w = s->pub.wiring;
    int clk_before = s->level[w[S_CLK]];
    for (unsigned i = 0; i < r->n; i++)
        if (mask >> i & 1)
            s->level[r->offsets[i]] = (uint8_t)(bits >> i & 1);
    uint32_t data = 0;
    for (int i = 0; i < 12; i++)
        if (i != S_CLK)
            data |= (uint32_t)s->level[w[i]] << i;
    if (data != s->data) {
        if (s->edge_since_change && s->step - s->edge_step - 1 < s->pub.min_hold)
            s->pub.min_hold = s->step - s->edge_step - 1;
        s->data = data, s->change_step = s->step, s->edge_since_change = 0;
    }
    if (!clk_before && s->level[w[S_CLK]]) {
        if (s->step - s->change_step < s->pub.min_setup)
            s->pub.min_setup = s->step - s->change_step;
        s->edge_step = s->step, s->edge_since_change = 1;
    }
    if (!s->pub.bus) { /* the simulated board samples the lines itself */
        if (!clk_before && s->level[w[S_CLK]]) {
            s->pub.edges++;
            const int ctl = s->level[w[S_CTL]], valid = s->level[w[S_VALID]];
            if (!ctl && valid && (s->sim_out >> 8 & 1) && !(s->data_prev_ctl))
                s->sim_rx++;
            if (ctl && valid && (((data | s->pub.stuck_d) & 0xFF) == EF_GB_REQ_RESET))
                s->sim_rx = 0;
            s->data_prev_ctl = ctl;
        }
        sim_step(s);
        return;
    }
    if (!clk_before && s->level[w[S_CLK]]) {
        uint8_t d = s->pub.stuck_d;
        for (int i = 0; i < 8; i++)
            d |= (uint8_t)(s->level[w[S_D0 + i]] << i);
        unsigned ctrl = (s->level[w[S_VALID]] ? EF_GB_VALID : 0) | (s->level[w[S_TAKE]] ? EF_GB_TAKE : 0) |
                        (s->level[w[S_CTL]] ? EF_GB_CTL : 0);
        ef_gpio_bus_edge(s->pub.bus, d, ctrl);
        s->pub.edges++;
        if (s->pub.fail_after && ef_gpio_bus_rx_count(s->pub.bus) >= s->pub.fail_after) {
            ef_board_fail(s->pub.board, 0x7e, "injected by the GPIO emulator");
            s->pub.fail_after = 0;
        }
    }
}

static gboolean finish(UMockdevIoctlClient *client, UMockdevIoctlData *d, long rc, int err)
{
    if (d)
        umockdev_ioctl_data_unref(d);
    umockdev_ioctl_client_complete(client, rc, err);
    return TRUE;
}

static UMockdevIoctlData *arg_of(UMockdevIoctlClient *client, size_t len)
{
    GError *error = NULL;
    UMockdevIoctlData *d = umockdev_ioctl_data_resolve(umockdev_ioctl_client_get_arg(client), 0, len, &error);
    if (!d) {
        fprintf(stderr, "gpio_chip: cannot read an ioctl argument: %s\n", error ? error->message : "?");
        g_clear_error(&error);
    }
    return d;
}

/* A new line request: check and own the lines, open the connection that
 * becomes its file descriptor. */
static int new_request(emu_state *s, const uint32_t *offsets, unsigned n, int output, const char *consumer, int *fd)
{
    if (n == 0 || n > GPIO_V2_LINES_MAX)
        return EINVAL;
    for (unsigned i = 0; i < n; i++) {
        if (offsets[i] >= EMU_LINES)
            return EINVAL;
        emu_req *o = s->owner[offsets[i]];
        if (o && req_alive(o))
            return EBUSY;
        if (o && o->client) /* a closed request's lines are free again */
            for (unsigned k = 0; k < EMU_LINES; k++)
                if (s->owner[k] == o)
                    s->owner[k] = NULL;
        if (o && !o->client)
            return EBUSY; /* still waiting for its connection */
    }
    if (s->npending == 8 || s->nreqs == 64)
        return ENOMEM;
    emu_req *r = calloc(1, sizeof *r);
    if (!r)
        return ENOMEM;
    r->n = n, r->output = output;
    memcpy(r->offsets, offsets, n * sizeof *offsets);
    snprintf(r->consumer, sizeof r->consumer, "%s", consumer);
    *fd = open("/dev/gpiochip0", O_RDWR | O_CLOEXEC);
    if (*fd < 0) {
        free(r);
        return EIO;
    }
    for (unsigned i = 0; i < n; i++)
        s->owner[offsets[i]] = r;
    s->pending[s->npending++] = r;
    s->reqs[s->nreqs++] = r;
    return 0;
}

static gboolean on_connected(UMockdevIoctlBase *base, UMockdevIoctlClient *client, gpointer user)
{
    emu_state *s = user;
    (void)base;
    g_mutex_lock(&s->lock);
    if (s->npending) {
        emu_req *r = s->pending[0];
        memmove(s->pending, s->pending + 1, (size_t)--s->npending * sizeof s->pending[0]);
        r->client = g_object_ref(client);
        g_object_set_data(G_OBJECT(client), "emu-req", r);
    }
    g_mutex_unlock(&s->lock);
    return TRUE;
}

static gboolean chip_ioctl(emu_state *s, UMockdevIoctlClient *client, unsigned long req)
{
    UMockdevIoctlData *d;
    switch (req) {
    case GPIO_GET_CHIPINFO_IOCTL: {
        if (!(d = arg_of(client, sizeof(struct gpiochip_info))))
            return finish(client, NULL, -1, EFAULT);
        struct gpiochip_info *ci = (void *)d->data;
        memset(ci, 0, sizeof *ci);
        snprintf(ci->name, sizeof ci->name, "gpiochip0");
        snprintf(ci->label, sizeof ci->label, "edgeflag-emu");
        ci->lines = EMU_LINES;
        return finish(client, d, 0, 0);
    }
    case GPIO_GET_LINEINFO_IOCTL: {
        if (!(d = arg_of(client, sizeof(struct gpioline_info))))
            return finish(client, NULL, -1, EFAULT);
        struct gpioline_info *li = (void *)d->data;
        unsigned off = li->line_offset;
        if (off >= EMU_LINES)
            return finish(client, d, -1, EINVAL);
        emu_req *o = req_alive(s->owner[off]) ? s->owner[off] : NULL;
        memset(li, 0, sizeof *li);
        li->line_offset = off;
        snprintf(li->name, sizeof li->name, "%s", line_name(s, off));
        if (o) {
            li->flags = GPIOLINE_FLAG_KERNEL | (o->output ? GPIOLINE_FLAG_IS_OUT : 0);
            snprintf(li->consumer, sizeof li->consumer, "%s", o->consumer);
        }
        return finish(client, d, 0, 0);
    }
    case GPIO_V2_GET_LINEINFO_IOCTL: {
        if (!(d = arg_of(client, sizeof(struct gpio_v2_line_info))))
            return finish(client, NULL, -1, EFAULT);
        struct gpio_v2_line_info *li = (void *)d->data;
        unsigned off = li->offset;
        if (off >= EMU_LINES)
            return finish(client, d, -1, EINVAL);
        emu_req *o = req_alive(s->owner[off]) ? s->owner[off] : NULL;
        memset(li, 0, sizeof *li);
        li->offset = off;
        snprintf(li->name, sizeof li->name, "%s", line_name(s, off));
        li->flags = GPIO_V2_LINE_FLAG_INPUT;
        if (o) {
            li->flags = GPIO_V2_LINE_FLAG_USED | (o->output ? GPIO_V2_LINE_FLAG_OUTPUT : GPIO_V2_LINE_FLAG_INPUT);
            snprintf(li->consumer, sizeof li->consumer, "%s", o->consumer);
        }
        return finish(client, d, 0, 0);
    }
    case GPIO_GET_LINEHANDLE_IOCTL: {
        if (!(d = arg_of(client, sizeof(struct gpiohandle_request))))
            return finish(client, NULL, -1, EFAULT);
        struct gpiohandle_request *hr = (void *)d->data;
        int output = (hr->flags & GPIOHANDLE_REQUEST_OUTPUT) != 0, fd = -1;
        int e = new_request(s, hr->lineoffsets, hr->lines, output, hr->consumer_label, &fd);
        if (e)
            return finish(client, d, -1, e);
        if (output)
            for (unsigned i = 0; i < hr->lines; i++)
                s->level[hr->lineoffsets[i]] = hr->default_values[i] ? 1 : 0;
        hr->fd = fd;
        return finish(client, d, 0, 0);
    }
    case GPIO_V2_GET_LINE_IOCTL: {
        if (!(d = arg_of(client, sizeof(struct gpio_v2_line_request))))
            return finish(client, NULL, -1, EFAULT);
        struct gpio_v2_line_request *lr = (void *)d->data;
        int output = (lr->config.flags & GPIO_V2_LINE_FLAG_OUTPUT) != 0, fd = -1;
        int e = new_request(s, lr->offsets, lr->num_lines, output, lr->consumer, &fd);
        if (e)
            return finish(client, d, -1, e);
        if (output) {
            for (unsigned i = 0; i < lr->num_lines; i++)
                s->level[lr->offsets[i]] = 0;
            for (unsigned a = 0; a < lr->config.num_attrs && a < GPIO_V2_LINE_NUM_ATTRS_MAX; a++)
                if (lr->config.attrs[a].attr.id == GPIO_V2_LINE_ATTR_ID_OUTPUT_VALUES)
                    for (unsigned i = 0; i < lr->num_lines; i++)
                        if (lr->config.attrs[a].mask >> i & 1)
                            s->level[lr->offsets[i]] = (uint8_t)(lr->config.attrs[a].attr.values >> i & 1);
        }
        lr->fd = fd;
        return finish(client, d, 0, 0);
    }
    default: return finish(client, NULL, -1, ENOTTY);
    }
}

static gboolean line_ioctl(emu_state *s, emu_req *r, UMockdevIoctlClient *client, unsigned long req)
{
    UMockdevIoctlData *d;
    switch (req) {
    case GPIOHANDLE_SET_LINE_VALUES_IOCTL:
    case GPIOHANDLE_GET_LINE_VALUES_IOCTL: {
        if (!(d = arg_of(client, sizeof(struct gpiohandle_data))))
            return finish(client, NULL, -1, EFAULT);
        struct gpiohandle_data *hd = (void *)d->data;
        if (req == GPIOHANDLE_SET_LINE_VALUES_IOCTL) {
            if (!r->output)
                return finish(client, d, -1, EPERM);
            uint64_t bits = 0;
            for (unsigned i = 0; i < r->n; i++)
                bits |= (uint64_t)(hd->values[i] != 0) << i;
            host_drive(s, r, bits, ~(uint64_t)0);
            s->pub.sets++, s->step++;
        } else {
            board_drive(s);
            for (unsigned i = 0; i < r->n; i++)
                hd->values[i] = s->level[r->offsets[i]];
            s->pub.gets++, s->step++;
        }
        return finish(client, d, 0, 0);
    }
    case GPIO_V2_LINE_SET_VALUES_IOCTL:
    case GPIO_V2_LINE_GET_VALUES_IOCTL: {
        if (!(d = arg_of(client, sizeof(struct gpio_v2_line_values))))
            return finish(client, NULL, -1, EFAULT);
        struct gpio_v2_line_values *lv = (void *)d->data;
        if (req == GPIO_V2_LINE_SET_VALUES_IOCTL) {
            if (!r->output)
                return finish(client, d, -1, EPERM);
            host_drive(s, r, lv->bits, lv->mask);
            s->pub.sets++, s->step++;
        } else {
            board_drive(s);
            uint64_t bits = 0;
            for (unsigned i = 0; i < r->n; i++)
                if (lv->mask >> i & 1)
                    bits |= (uint64_t)s->level[r->offsets[i]] << i;
            lv->bits = bits;
            s->pub.gets++, s->step++;
        }
        return finish(client, d, 0, 0);
    }
    default: return finish(client, NULL, -1, ENOTTY);
    }
}

static gboolean on_ioctl(UMockdevIoctlBase *base, UMockdevIoctlClient *client, gpointer user)
{
    emu_state *s = user;
    (void)base;
    g_mutex_lock(&s->lock);
    s->pub.ioctls++;
    unsigned long req = umockdev_ioctl_client_get_request(client);
    emu_req *r = g_object_get_data(G_OBJECT(client), "emu-req");
    gboolean ok = r ? line_ioctl(s, r, client, req) : chip_ioctl(s, client, req);
    g_mutex_unlock(&s->lock);
    return ok;
}

emu_chip *emu_chip_new(ef_board *board, const unsigned wiring[EMU_SIGNALS])
{
    emu_state *s = calloc(1, sizeof *s);
    GError *error = NULL;
    if (!s)
        return NULL;
    g_mutex_init(&s->lock);
    s->pub.board = board;
    s->pub.bus = board ? ef_gpio_bus_new(board) : NULL;
    s->sim_fd = -1;
    memcpy(s->pub.wiring, wiring, sizeof s->pub.wiring);
    s->pub.min_setup = s->pub.min_hold = UINT64_MAX;
    s->tb = umockdev_testbed_new();
    if (!umockdev_in_mock_environment()) {
        fprintf(stderr, "gpio_chip: not in a umockdev environment: run under umockdev-wrapper\n");
        return NULL;
    }
    s->handler = umockdev_ioctl_base_new();
    g_signal_connect(s->handler, "handle-ioctl", G_CALLBACK(on_ioctl), s);
    g_signal_connect(s->handler, "client-connected", G_CALLBACK(on_connected), s);
    /* The handler first, then the device with its node (HOST.md's order);
     * libgpiod 1.6 compares the sysfs dev attribute byte for byte, newline
     * included. */
    if (!umockdev_testbed_attach_ioctl(s->tb, "/dev/gpiochip0", s->handler, &error) ||
        !umockdev_testbed_add_from_string(s->tb,
                                          "P: /devices/platform/edgeflag-emu/gpiochip0\n"
                                          "N: gpiochip0=00\n"
                                          "E: DEVNAME=/dev/gpiochip0\n"
                                          "E: SUBSYSTEM=gpio\n"
                                          "A: dev=254:0\\n\n",
                                          &error)) {
        fprintf(stderr, "gpio_chip: cannot create /dev/gpiochip0: %s\n", error ? error->message : "?");
        return NULL;
    }
    return &s->pub;
}

emu_chip *emu_chip_new_sim(const char *socket_path, const unsigned wiring[EMU_SIGNALS])
{
    struct sockaddr_un sa;
    memset(&sa, 0, sizeof sa);
    sa.sun_family = AF_UNIX;
    if (strlen(socket_path) >= sizeof sa.sun_path) {
        fprintf(stderr, "gpio_chip: socket path too long: %s\n", socket_path);
        return NULL;
    }
    strcpy(sa.sun_path, socket_path);
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0 || connect(fd, (struct sockaddr *)&sa, sizeof sa) != 0) {
        fprintf(stderr, "gpio_chip: cannot reach the simulated board at %s\n", socket_path);
        if (fd >= 0)
            close(fd);
        return NULL;
    }
    emu_chip *e = emu_chip_new(NULL, wiring);
    if (!e) {
        close(fd);
        return NULL;
    }
    emu_state *s = (emu_state *)e;
    s->sim_fd = fd;
    sim_step(s); /* the board's lines as they are */
    return e;
}

void emu_chip_set_faults(emu_chip *e, int faults)
{
    emu_state *s = (emu_state *)e;
    g_mutex_lock(&s->lock);
    e->faults = faults;
    g_mutex_unlock(&s->lock);
}

void emu_chip_set_byte_faults(emu_chip *e, uint32_t stall_after, uint32_t fail_after, uint8_t stuck_d)
{
    emu_state *s = (emu_state *)e;
    g_mutex_lock(&s->lock);
    e->stall_after = stall_after, e->fail_after = fail_after, e->stuck_d = stuck_d;
    g_mutex_unlock(&s->lock);
}

void emu_chip_set_pause(emu_chip *e, unsigned reads, unsigned ms)
{
    emu_state *s = (emu_state *)e;
    g_mutex_lock(&s->lock);
    e->hide_avail_reads = reads, e->pause_ms = ms;
    g_mutex_unlock(&s->lock);
}

uint32_t emu_chip_received(emu_chip *e)
{
    emu_state *s = (emu_state *)e;
    g_mutex_lock(&s->lock);
    uint32_t n = bus_received(s);
    g_mutex_unlock(&s->lock);
    return n;
}

void emu_chip_set_board(emu_chip *e, ef_board *board)
{
    emu_state *s = (emu_state *)e;
    g_mutex_lock(&s->lock);
    ef_gpio_bus_free(e->bus);
    e->board = board;
    e->bus = ef_gpio_bus_new(board);
    g_mutex_unlock(&s->lock);
}

void emu_chip_timing(emu_chip *e, uint64_t *min_setup, uint64_t *min_hold, uint64_t *sets, uint64_t *gets,
                     uint64_t *edges)
{
    emu_state *s = (emu_state *)e;
    g_mutex_lock(&s->lock);
    *min_setup = e->min_setup, *min_hold = e->min_hold, *sets = e->sets, *gets = e->gets, *edges = e->edges;
    e->min_setup = e->min_hold = UINT64_MAX;
    e->sets = e->gets = e->edges = 0;
    g_mutex_unlock(&s->lock);
}
