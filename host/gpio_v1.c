/*
 * gpio_v1.c - gpio_lib.h on libgpiod 1.x (Debian 12's 1.6.3, kernel uAPI v1):
 * two line bulks, one of outputs and one of inputs, each one kernel request,
 * so a bus step is one GPIOHANDLE ioctl.
 */
#include "gpio_lib.h"

#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct ef_gpiol {
    struct gpiod_chip *chip;
    struct gpiod_line_bulk out, in;
    int requested_out, requested_in;
};

int ef_gpiol_open(ef_gpiol **out, const char *path, char *err, size_t errlen)
{
    ef_gpiol *c = calloc(1, sizeof *c);
    if (!c)
        return EF_HOST_ENOMEM;
    c->chip = gpiod_chip_open(path);
    if (!c->chip) {
        int e = errno;
        snprintf(err, errlen, "%s: cannot open GPIO chip: %s%s", path, strerror(e),
                 e == EACCES || e == EPERM ? " (give your user access to it: docs/board-gpio.md section 7)" : "");
        free(c);
        return ef_gpiol_errno(e);
    }
    *out = c;
    return 0;
}

void ef_gpiol_close(ef_gpiol *c)
{
    if (!c)
        return;
    if (c->requested_out)
        gpiod_line_release_bulk(&c->out);
    if (c->requested_in)
        gpiod_line_release_bulk(&c->in);
    gpiod_chip_close(c->chip);
    free(c);
}

int ef_gpiol_info(ef_gpiol *c, char *label, size_t labellen, unsigned *nlines)
{
    snprintf(label, labellen, "%s", gpiod_chip_label(c->chip));
    *nlines = gpiod_chip_num_lines(c->chip);
    return 0;
}

int ef_gpiol_line(ef_gpiol *c, unsigned offset, char *name, size_t namelen, char *consumer, size_t conslen)
{
    struct gpiod_line *line = gpiod_chip_get_line(c->chip, offset);
    if (!line)
        return ef_gpiol_errno(errno);
    const char *n = gpiod_line_name(line), *u = gpiod_line_consumer(line);
    snprintf(name, namelen, "%s", n ? n : "");
    snprintf(consumer, conslen, "%s", u ? u : "");
    return 0;
}

static int request_bulk(ef_gpiol *c, struct gpiod_line_bulk *bulk, const unsigned *offsets, unsigned n, int output,
                        const char *consumer, char *err, size_t errlen)
{
    int zeros[GPIOD_LINE_BULK_MAX_LINES] = { 0 };
    if (gpiod_chip_get_lines(c->chip, (unsigned *)offsets, n, bulk) != 0) {
        int e = errno;
        snprintf(err, errlen, "%s: cannot get lines: %s", gpiod_chip_name(c->chip), strerror(e));
        return ef_gpiol_errno(e);
    }
    int rc =
        output ? gpiod_line_request_bulk_output(bulk, consumer, zeros) : gpiod_line_request_bulk_input(bulk, consumer);
    if (rc != 0) {
        int e = errno;
        snprintf(err, errlen, "%s: cannot request %u %s lines: %s", gpiod_chip_name(c->chip), n,
                 output ? "output" : "input", strerror(e));
        return ef_gpiol_errno(e);
    }
    return 0;
}

int ef_gpiol_request(ef_gpiol *c, const unsigned *out_offsets, unsigned n_out, const unsigned *in_offsets,
                     unsigned n_in, const char *consumer, char *err, size_t errlen)
{
    int rc = request_bulk(c, &c->out, out_offsets, n_out, 1, consumer, err, errlen);
    if (rc)
        return rc;
    c->requested_out = 1;
    rc = request_bulk(c, &c->in, in_offsets, n_in, 0, consumer, err, errlen);
    if (rc) {
        gpiod_line_release_bulk(&c->out);
        c->requested_out = 0;
        return rc;
    }
    c->requested_in = 1;
    return 0;
}

int ef_gpiol_set(ef_gpiol *c, uint32_t values)
{
    int v[GPIOD_LINE_BULK_MAX_LINES];
    for (unsigned i = 0; i < c->out.num_lines; i++)
        v[i] = (int)(values >> i & 1);
    return gpiod_line_set_value_bulk(&c->out, v) == 0 ? 0 : ef_gpiol_errno(errno);
}

int ef_gpiol_get(ef_gpiol *c, uint32_t *values)
{
    int v[GPIOD_LINE_BULK_MAX_LINES];
    if (gpiod_line_get_value_bulk(&c->in, v) != 0)
        return ef_gpiol_errno(errno);
    uint32_t r = 0;
    for (unsigned i = 0; i < c->in.num_lines; i++)
        r |= (uint32_t)(v[i] != 0) << i;
    *values = r;
    return 0;
}

const char *ef_gpiol_version(void)
{
    static char buf[64];
    snprintf(buf, sizeof buf, "libgpiod %s (v1 API)", gpiod_version_string());
    return buf;
}

int ef_gpiol_available(void) { return 1; }
