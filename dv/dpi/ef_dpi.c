/*
 * ef_dpi.c - SystemVerilog DPI-C (IEEE 1800-2017 section 35, svdpi.h) binding
 * of ef_model_stream.h: the functions ef_model_pkg.sv imports.  Vectors cross
 * as svBitVecVal arrays (32-bit chunks, chunk i = bits 32i+31..32i), cycles as
 * longint, the handle as a chandle.  Nothing here keeps state of its own: the
 * handle is the ef_mstream, so a simulation can hold as many models as it
 * likes.  docs/dpi.md lists every function with its SystemVerilog prototype.
 */
#include <stdint.h>
#include <string.h>

#include "svdpi.h"

#include "ef_model_stream.h"

/* Widest payload (et_wr, 181 bits) in 32-bit chunks: the package's EF_PAYLOAD_BITS. */
#define EF_DPI_PAYLOAD_BITS 181
#define EF_DPI_CHUNKS ((EF_DPI_PAYLOAD_BITS + 31) / 32)
#define EF_DPI_CMD_CHUNKS 4 /* bit [99:0] */

/* The prototypes Verilator generates (its __Dpi.h), here so that a
 * mismatch between this file and the package's imports fails to compile
 * in C too: ef_model_pkg.sv must say the same. */
void *ef_dpi_create(int samples, int width_max, int height_max, int edges_max, int rule, int ifaces, int *status);
void ef_dpi_destroy(void *h);
int ef_dpi_cmd(void *h, const svBitVecVal *word);
int ef_dpi_pop(void *h, int iface, long long *cycle, svBitVecVal *payload);
int ef_dpi_peek(void *h, int iface, long long *cycle, svBitVecVal *payload);
int ef_dpi_pending(void *h, int iface);
int ef_dpi_expect(void *h, int iface, long long cycle, const svBitVecVal *payload, int check_cycle);
int ef_dpi_expect_done(void *h, int iface);
const char *ef_dpi_message(void *h);
const char *ef_dpi_strerror(int status);
const char *ef_dpi_iface_name(int iface);
int ef_dpi_iface_width(int iface);
long long ef_dpi_frame_cycles(void *h);
long long ef_dpi_commands(void *h);
int ef_dpi_field_is(int iface, const char *name, const svBitVecVal *ones);

/* ifaces: the interfaces to keep (bit i = interface i), 0 for all. */
void *ef_dpi_create(int samples, int width_max, int height_max, int edges_max, int rule, int ifaces, int *status)
{
    ef_mstream_params p;
    ef_mstream_params_default(&p);
    p.samples = samples;
    p.width_max = width_max;
    p.height_max = height_max;
    p.edges_max = edges_max > 0 ? (uint32_t)edges_max : 0;
    p.rule = rule;
    p.ifaces = ifaces == 0 ? EF_IF_ALL : (uint32_t)ifaces;
    ef_mstream *m = NULL;
    *status = ef_mstream_create(&m, &p);
    return m;
}

void ef_dpi_destroy(void *h) { ef_mstream_destroy(h); }

int ef_dpi_cmd(void *h, const svBitVecVal *word)
{
    uint64_t w[2] = { 0, 0 };
    for (int i = 0; i < EF_DPI_CMD_CHUNKS; i++)
        w[i / 2] |= (uint64_t)word[i] << (32 * (i % 2));
    w[1] &= (UINT64_C(1) << 36) - 1; /* bit [99:0]: the chunk's upper bits are not the vector's */
    return ef_mstream_cmd(h, w);
}

static void to_sv(const ef_txn *t, svBitVecVal *payload)
{
    for (int i = 0; i < EF_DPI_CHUNKS; i++)
        payload[i] = (svBitVecVal)(t->w[i / 2] >> (32 * (i % 2)));
}

/* The payload's P bits of iface (bits above P dropped: they are not the interface's). */
static void from_sv(int iface, const svBitVecVal *payload, ef_txn *t)
{
    const ef_iface_desc *d = ef_iface_get(iface);
    memset(t, 0, sizeof *t);
    t->iface = (uint8_t)iface;
    for (int i = 0; i < EF_DPI_CHUNKS; i++)
        t->w[i / 2] |= (uint64_t)payload[i] << (32 * (i % 2));
    for (unsigned b = d->width; b < 64 * EF_TXN_WORDS; b++)
        t->w[b / 64] &= ~(UINT64_C(1) << (b % 64));
}

static int take(void *h, int iface, long long *cycle, svBitVecVal *payload, int pop)
{
    ef_txn t;
    const int st = pop ? ef_mstream_pop(h, iface, &t) : ef_mstream_peek(h, iface, &t);
    if (st != EF_MS_OK)
        memset(&t, 0, sizeof t);
    *cycle = (long long)t.cycle; /* < 2^48 */
    to_sv(&t, payload);
    return st;
}

int ef_dpi_pop(void *h, int iface, long long *cycle, svBitVecVal *payload) { return take(h, iface, cycle, payload, 1); }

int ef_dpi_peek(void *h, int iface, long long *cycle, svBitVecVal *payload)
{
    return take(h, iface, cycle, payload, 0);
}

int ef_dpi_pending(void *h, int iface)
{
    const size_t n = ef_mstream_pending(h, iface);
    return n > INT32_MAX ? INT32_MAX : (int)n;
}

int ef_dpi_expect(void *h, int iface, long long cycle, const svBitVecVal *payload, int check_cycle)
{
    if (!ef_iface_get(iface) || cycle < 0)
        return EF_MS_ERR_ARG;
    ef_txn t;
    from_sv(iface, payload, &t);
    t.cycle = (uint64_t)cycle;
    return ef_mstream_expect(h, &t, check_cycle);
}

int ef_dpi_expect_done(void *h, int iface) { return ef_mstream_expect_done(h, iface); }
const char *ef_dpi_message(void *h) { return ef_mstream_message(h); }
const char *ef_dpi_strerror(int status) { return ef_mstream_strerror(status); }

const char *ef_dpi_iface_name(int iface)
{
    const ef_iface_desc *d = ef_iface_get(iface);
    return d ? d->name : "";
}

int ef_dpi_iface_width(int iface)
{
    const ef_iface_desc *d = ef_iface_get(iface);
    return d ? d->width : 0;
}

long long ef_dpi_frame_cycles(void *h)
{
    uint64_t c;
    return ef_mstream_frame_cycles(h, &c) ? (long long)c : -1;
}

long long ef_dpi_commands(void *h) { return (long long)ef_mstream_commands(h); }

/* The package's layout check: 1 when `ones` is field `name` of iface set to
 * all ones and nothing else, per the interface table (ef_txn_set_field). */
int ef_dpi_field_is(int iface, const char *name, const svBitVecVal *ones)
{
    const ef_iface_desc *d = ef_iface_get(iface);
    if (!d || !name)
        return 0;
    for (unsigned k = 0; k < d->nfields; k++) {
        if (strcmp(d->field[k].name, name) != 0)
            continue;
        ef_txn want = { .iface = (uint8_t)iface }, got;
        ef_txn_set_field(&want, k, ~UINT64_C(0));
        memset(&got, 0, sizeof got);
        for (int i = 0; i < EF_DPI_CHUNKS; i++) /* all bits, above P too: a wide field would show */
            got.w[i / 2] |= (uint64_t)ones[i] << (32 * (i % 2));
        return memcmp(want.w, got.w, sizeof want.w) == 0;
    }
    return 0;
}
