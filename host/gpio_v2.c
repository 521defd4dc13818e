/*
 * gpio_v2.c - gpio_lib.h on libgpiod 2.x (kernel uAPI v2), using only what
 * 2.1 has (Debian 13 and Ubuntu 24.04 ship 2.1): two line requests, one of
 * outputs and one of inputs, so a bus step is one GPIO_V2_LINE ioctl.
 */
#include "gpio_lib.h"

#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EF_GPIOL_MAX 32

struct ef_gpiol {
    struct gpiod_chip *chip;
    struct gpiod_line_request *out, *in;
    unsigned n_out, n_in;
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
    if (c->out)
        gpiod_line_request_release(c->out);
    if (c->in)
        gpiod_line_request_release(c->in);
    gpiod_chip_close(c->chip);
    free(c);
}

int ef_gpiol_info(ef_gpiol *c, char *label, size_t labellen, unsigned *nlines)
{
    struct gpiod_chip_info *info = gpiod_chip_get_info(c->chip);
    if (!info)
        return ef_gpiol_errno(errno);
    snprintf(label, labellen, "%s", gpiod_chip_info_get_label(info));
    *nlines = (unsigned)gpiod_chip_info_get_num_lines(info);
    gpiod_chip_info_free(info);
    return 0;
}

int ef_gpiol_line(ef_gpiol *c, unsigned offset, char *name, size_t namelen, char *consumer, size_t conslen)
{
    struct gpiod_line_info *info = gpiod_chip_get_line_info(c->chip, offset);
    if (!info)
        return ef_gpiol_errno(errno);
    const char *n = gpiod_line_info_get_name(info), *u = gpiod_line_info_get_consumer(info);
    snprintf(name, namelen, "%s", n ? n : "");
    snprintf(consumer, conslen, "%s", u ? u : "");
    gpiod_line_info_free(info);
    return 0;
}

static int request_one(ef_gpiol *c, struct gpiod_line_request **req, const unsigned *offsets, unsigned n, int output,
                       const char *consumer, char *err, size_t errlen)
{
    int rc = EF_HOST_ENOMEM;
    struct gpiod_line_settings *s = gpiod_line_settings_new();
    struct gpiod_line_config *lc = gpiod_line_config_new();
    struct gpiod_request_config *rc_cfg = gpiod_request_config_new();
    if (!s || !lc || !rc_cfg)
        goto out;
    gpiod_line_settings_set_direction(s, output ? GPIOD_LINE_DIRECTION_OUTPUT : GPIOD_LINE_DIRECTION_INPUT);
    if (output)
        gpiod_line_settings_set_output_value(s, GPIOD_LINE_VALUE_INACTIVE);
    gpiod_request_config_set_consumer(rc_cfg, consumer);
    if (gpiod_line_config_add_line_settings(lc, offsets, n, s) != 0)
        goto fail;
    *req = gpiod_chip_request_lines(c->chip, rc_cfg, lc);
    if (!*req)
        goto fail;
    rc = 0;
    goto out;
fail:;
    int e = errno;
    snprintf(err, errlen, "cannot request %u %s lines: %s", n, output ? "output" : "input", strerror(e));
    rc = ef_gpiol_errno(e);
out:
    gpiod_request_config_free(rc_cfg);
    gpiod_line_config_free(lc);
    gpiod_line_settings_free(s);
    return rc;
}

int ef_gpiol_request(ef_gpiol *c, const unsigned *out_offsets, unsigned n_out, const unsigned *in_offsets,
                     unsigned n_in, const char *consumer, char *err, size_t errlen)
{
    if (n_out > EF_GPIOL_MAX || n_in > EF_GPIOL_MAX)
        return EF_HOST_EINVAL;
    int rc = request_one(c, &c->out, out_offsets, n_out, 1, consumer, err, errlen);
    if (rc)
        return rc;
    rc = request_one(c, &c->in, in_offsets, n_in, 0, consumer, err, errlen);
    if (rc) {
        gpiod_line_request_release(c->out);
        c->out = NULL;
        return rc;
    }
    c->n_out = n_out, c->n_in = n_in;
    return 0;
}

int ef_gpiol_set(ef_gpiol *c, uint32_t values)
{
    enum gpiod_line_value v[EF_GPIOL_MAX];
    for (unsigned i = 0; i < c->n_out; i++)
        v[i] = (values >> i & 1) ? GPIOD_LINE_VALUE_ACTIVE : GPIOD_LINE_VALUE_INACTIVE;
    return gpiod_line_request_set_values(c->out, v) == 0 ? 0 : ef_gpiol_errno(errno);
}

int ef_gpiol_get(ef_gpiol *c, uint32_t *values)
{
    enum gpiod_line_value v[EF_GPIOL_MAX];
    if (gpiod_line_request_get_values(c->in, v) != 0)
        return ef_gpiol_errno(errno);
    uint32_t r = 0;
    for (unsigned i = 0; i < c->n_in; i++)
        r |= (uint32_t)(v[i] == GPIOD_LINE_VALUE_ACTIVE) << i;
    *values = r;
    return 0;
}

const char *ef_gpiol_version(void)
{
    static char buf[64];
    /* The package version comes from pkg-config at build time (host/gpio.mk):
     * gpiod_api_version() is the API's own number (2.2.1 in libgpiod 2.3). */
#ifdef EF_GPIOD_VERSION
    snprintf(buf, sizeof buf, "libgpiod %s (v2 API %s)", EF_GPIOD_VERSION, gpiod_api_version());
#else
    snprintf(buf, sizeof buf, "libgpiod (v2 API %s)", gpiod_api_version());
#endif
    return buf;
}

int ef_gpiol_available(void) { return 1; }
