/*
 * trace_iface.c - the interfaces of the reference microarchitecture as data
 * (docs/microarch.md section 3): names, blocks, field names and widths.  The
 * vector writers, the checker and the docs' tables all follow this one table.
 */
#include <string.h>

#include "ef_trace.h"

#define F(n, w) \
    { \
        n, w, 0 \
    }
#define S(n, w) \
    { \
        n, w, 1 \
    }

/* clang-format off */
static const ef_iface_desc ifaces[EF_IF_COUNT] = {
    { "cmd", "host", "DEC", 100, 5, { F("op", 4), S("a", 24), S("b", 24), S("c", 24), S("d", 24) } },
    { "seg", "DEC", "SETUP", 97, 5, { F("eos", 1), S("xa", 24), S("ya", 24), S("xb", 24), S("yb", 24) } },
    { "et_wr", "SETUP", "ETM", 181, 10,
      { F("eos", 1), F("slot", 14), F("r0", 19), F("r1", 19), S("x", 25), F("e", 24), S("qs", 30), F("rs", 24),
        F("dy", 24), F("dir", 1) } },
    { "et_rd", "ETM", "AET", 36, 2, { F("row", 14), F("eid", 22) } },
    { "plot", "PLOT", "SLB", 36, 5, { F("last", 1), F("row", 14), F("s", 5), F("q", 15), F("dir", 1) } },
    { "span", "FILL", "COV", 75, 4, { F("y", 14), F("x", 14), F("len", 15), F("mask", 32) } },
    { "pix", "COV", "memory", 68, 4, { F("y", 14), F("x", 14), F("alpha", 8), F("rgba", 32) } },
};
/* clang-format on */

static const char *const op_names[] = { NULL, "FRAME", "SHAPE", "EDGE", "SHAPE_END", "FRAME_END" };

const char *ef_op_name(int op) { return op >= EF_OP_FRAME && op <= EF_OP_FRAME_END ? op_names[op] : NULL; }

const ef_iface_desc *ef_iface_get(int iface) { return iface >= 0 && iface < EF_IF_COUNT ? &ifaces[iface] : NULL; }

/* `edge` was the name of `seg` until the RTL needed a wire of that name
 * (`edge` is a Verilog keyword): names a user or an older vector set gives are
 * still read under it; nothing is written under it. */
int ef_iface_find(const char *name)
{
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (strcmp(ifaces[i].name, name) == 0)
            return i;
    if (strcmp(name, "edge") == 0)
        return EF_IF_SEG;
    return -1;
}

/* Bit position of field k's least significant bit in the payload. */
static unsigned field_lsb(const ef_iface_desc *d, unsigned k)
{
    unsigned lsb = 0;
    for (unsigned i = d->nfields; i-- > k + 1;)
        lsb += d->field[i].width;
    return lsb;
}

uint64_t ef_txn_field(const ef_txn *t, unsigned k)
{
    const ef_iface_desc *d = ef_iface_get(t->iface);
    if (!d || k >= d->nfields)
        return 0;
    const unsigned lsb = field_lsb(d, k), width = d->field[k].width;
    uint64_t v = 0;
    for (unsigned b = 0; b < width; b++) { /* bit by bit: fields straddle words */
        const unsigned p = lsb + b;
        v |= ((t->w[p >> 6] >> (p & 63)) & 1u) << b;
    }
    return v;
}

int64_t ef_txn_field_value(const ef_txn *t, unsigned k)
{
    const ef_iface_desc *d = ef_iface_get(t->iface);
    uint64_t v = ef_txn_field(t, k);
    if (!d || k >= d->nfields || !d->field[k].is_signed)
        return (int64_t)v;
    const uint64_t sign = UINT64_C(1) << (d->field[k].width - 1);
    return (int64_t)(v ^ sign) - (int64_t)sign; /* sign extension without shifting a negative */
}

void ef_txn_set_field(ef_txn *t, unsigned k, uint64_t v)
{
    const ef_iface_desc *d = ef_iface_get(t->iface);
    if (!d || k >= d->nfields)
        return;
    const unsigned lsb = field_lsb(d, k), width = d->field[k].width;
    for (unsigned b = 0; b < width; b++) {
        const unsigned p = lsb + b;
        const uint64_t bit = UINT64_C(1) << (p & 63);
        t->w[p >> 6] = ((v >> b) & 1u) ? t->w[p >> 6] | bit : t->w[p >> 6] & ~bit;
    }
}
