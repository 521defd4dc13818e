/*
 * vec_collect.c - the transaction collector behind the trace sink: one
 * growable array per interface.  The model delivers each interface in cycle
 * order but interleaves interfaces freely, and the VCD and the binary stream
 * merge all interfaces, so the whole trace is kept until the files are
 * written.
 * Records are packed to the interface's payload width (a `plot` takes 16
 * bytes, not sizeof(ef_txn)), which matters for millions of transfers.
 *
 * The sink cannot return an error, so the first failure is remembered and
 * the command checks it after the frame; every later transaction is dropped.
 */
#include "ef_vec.h"

#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

void ef_vec_collect_create(ef_vec_collect *c, uint32_t mask)
{
    memset(c, 0, sizeof *c);
    c->mask = mask;
    c->error = EF_OK;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const unsigned width = ef_iface_get(i)->width;
        c->list[i].nw = (width + 63u) / 64u;
        for (unsigned w = 0; w < EF_TXN_WORDS; w++) {
            const unsigned lo = 64 * w;
            c->allowed[i][w] = width >= lo + 64 ? ~UINT64_C(0) : width <= lo ? 0 : (UINT64_C(1) << (width - lo)) - 1u;
        }
    }
}

void ef_vec_collect_destroy(ef_vec_collect *c)
{
    for (int i = 0; i < EF_IF_COUNT; i++) {
        free(c->list[i].rec);
        c->list[i].rec = NULL;
        c->list[i].count = c->list[i].cap = 0;
    }
}

static ef_status broken(ef_vec_collect *c, const char *fmt, const ef_txn *t)
{
    const ef_iface_desc *d = ef_iface_get(t->iface);
    if (c->error == EF_OK) {
        c->error = EF_ERR_ARG;
        snprintf(c->why, sizeof c->why, "trace: %s transaction at cycle %" PRIu64 ": %s", d ? d->name : "unknown",
                 t->cycle, fmt);
    }
    return EF_ERR_ARG;
}

static int grow(ef_vec_list *l)
{
    const size_t stride = 1u + l->nw;
    size_t cap = l->cap ? l->cap * 2u : 1024u;
    uint64_t *p;
    if (cap < l->cap || cap > SIZE_MAX / (stride * sizeof *p))
        return -1;
    p = realloc(l->rec, cap * stride * sizeof *p);
    if (!p)
        return -1;
    l->rec = p;
    l->cap = cap;
    return 0;
}

/* Called once per transaction of the traced render (a million for the
 * tiger at 640x480): the checks are a few compares and one OR of masked
 * words, the copy a loop of at most EF_TXN_WORDS words (no memcpy call). */
ef_status ef_vec_collect_add(ef_vec_collect *c, const ef_txn *t)
{
    ef_vec_list *l;
    uint64_t *r, above = 0;
    unsigned nw;

    if (c->error != EF_OK)
        return c->error;
    if (t->iface >= EF_IF_COUNT || !(c->mask >> t->iface & 1u))
        return broken(c, "interface not enabled", t);
    l = &c->list[t->iface];
    nw = l->nw;
    if (t->cycle >> EF_CYCLE_BITS)
        return broken(c, "cycle stamp needs more than 48 bits", t);
    /* One valid/ready stream transfers at most once per cycle; the VCD and
     * the hex words could not show a second transfer in the same cycle. */
    if (l->count && t->cycle <= l->rec[(l->count - 1) * (1u + nw)])
        return broken(c, "not after the interface's previous transfer", t);
    for (unsigned w = 0; w < EF_TXN_WORDS; w++)
        above |= t->w[w] & ~c->allowed[t->iface][w];
    if (above)
        return broken(c, "payload bits set above the interface's width", t);
    if (l->count == l->cap && grow(l) != 0) {
        c->error = EF_ERR_NOMEM;
        return EF_ERR_NOMEM;
    }
    r = l->rec + l->count * (1u + nw);
    r[0] = t->cycle;
    for (unsigned w = 0; w < nw; w++)
        r[1 + w] = t->w[w];
    l->count++;
    return EF_OK;
}

void ef_vec_collect_sink(void *user, const ef_txn *t) { (void)ef_vec_collect_add(user, t); }

size_t ef_vec_collect_count(const ef_vec_collect *c, int iface)
{
    return iface >= 0 && iface < EF_IF_COUNT ? c->list[iface].count : 0;
}

void ef_vec_collect_get(const ef_vec_collect *c, int iface, size_t k, ef_txn *out)
{
    const ef_vec_list *l = &c->list[iface];
    const uint64_t *r = l->rec + k * (1u + l->nw);
    memset(out, 0, sizeof *out);
    out->iface = (uint8_t)iface;
    out->cycle = r[0];
    memcpy(out->w, r + 1, l->nw * sizeof *r);
}

uint64_t ef_vec_collect_total(const ef_vec_collect *c, uint32_t mask)
{
    uint64_t n = 0;
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (mask >> i & 1u)
            n += c->list[i].count;
    return n;
}

uint64_t ef_vec_collect_end(const ef_vec_collect *c, uint32_t mask)
{
    uint64_t end = 0;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_vec_list *l = &c->list[i];
        if ((mask >> i & 1u) && l->count && l->rec[(l->count - 1) * (1u + l->nw)] + 1u > end)
            end = l->rec[(l->count - 1) * (1u + l->nw)] + 1u;
    }
    return end;
}
