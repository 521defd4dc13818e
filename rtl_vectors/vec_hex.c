/*
 * vec_hex.c - `$readmemh` files, one per interface (docs/vectors.md section
 * 3): comment lines naming the interface, the run, the word layout and the
 * count, then one word { cycle[47:0], payload[P-1:0] } per line as exactly
 * ceil((48 + P) / 4) lower-case hex digits.  A fixed digit count keeps the
 * columns aligned for a human and makes every line's length predictable for
 * a reader; `$readmemh` itself needs neither.
 */
#include "ef_vec.h"

#include <string.h>

unsigned ef_vec_hex_digits(int iface)
{
    const ef_iface_desc *d = ef_iface_get(iface);
    return d ? (EF_CYCLE_BITS + d->width + 3u) / 4u : 0;
}

unsigned ef_vec_hex_word(const ef_txn *t, char *out)
{
    static const char hex[] = "0123456789abcdef";
    const ef_iface_desc *d = ef_iface_get(t->iface);
    uint64_t word[EF_TXN_WORDS + 1] = { 0 };
    unsigned p, nd;

    if (!d) {
        out[0] = '\0';
        return 0;
    }
    p = d->width;
    nd = ef_vec_hex_digits(t->iface);
    memcpy(word, t->w, sizeof t->w);
    /* The cycle goes above the payload, possibly straddling two words. */
    word[p / 64] |= t->cycle << (p % 64);
    if (p % 64 && p % 64 + EF_CYCLE_BITS > 64)
        word[p / 64 + 1] |= t->cycle >> (64 - p % 64);
    /* Digit i from the right is bits 4i+3..4i; a nibble never straddles a
     * 64-bit word because 64 is a multiple of 4. */
    for (unsigned i = 0; i < nd; i++) {
        unsigned b = 4u * i;
        out[nd - 1 - i] = hex[(word[b / 64] >> (b % 64)) & 15u];
    }
    out[nd] = '\0';
    return nd;
}

/* "name[hi:lo]", or "name[b]" for a one-bit field. */
static void out_range(ef_vec_out *o, const char *name, unsigned hi, unsigned lo)
{
    ef_vec_out_puts(o, " ");
    ef_vec_out_puts(o, name);
    ef_vec_out_puts(o, "[");
    ef_vec_out_u64(o, hi);
    if (hi != lo) {
        ef_vec_out_puts(o, ":");
        ef_vec_out_u64(o, lo);
    }
    ef_vec_out_puts(o, "]");
}

void ef_vec_hex_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c, int iface)
{
    const ef_iface_desc *d = ef_iface_get(iface);
    const size_t n = ef_vec_collect_count(c, iface);
    char line[EF_VEC_HEX_MAX_DIGITS + 2];
    unsigned top;

    if (!d)
        return;
    ef_vec_out_puts(o, "// edgeflag vectors format 1: interface ");
    ef_vec_out_puts(o, d->name);
    ef_vec_out_puts(o, " (");
    ef_vec_out_puts(o, d->from);
    ef_vec_out_puts(o, " -> ");
    ef_vec_out_puts(o, d->to);
    ef_vec_out_puts(o, "), role ");
    ef_vec_out_puts(o, info->dump ? "actual" : ef_vec_role(iface));
    ef_vec_out_puts(o, "\n// ");
    ef_vec_out_run_line(o, info);
    ef_vec_out_puts(o, "\n// word ");
    ef_vec_out_u64(o, EF_CYCLE_BITS + (unsigned)d->width);
    ef_vec_out_puts(o, " bits:");
    top = EF_CYCLE_BITS + d->width;
    out_range(o, "cycle", top - 1, d->width);
    top = d->width;
    for (unsigned k = 0; k < d->nfields; k++) {
        out_range(o, d->field[k].name, top - 1, top - d->field[k].width);
        top -= d->field[k].width;
    }
    ef_vec_out_puts(o, "\n// count ");
    ef_vec_out_u64(o, n);
    ef_vec_out_puts(o, "\n");
    for (size_t k = 0; k < n; k++) {
        ef_txn t;
        unsigned nd;
        ef_vec_collect_get(c, iface, k, &t);
        nd = ef_vec_hex_word(&t, line);
        line[nd] = '\n';
        ef_vec_out_write(o, line, nd + 1u);
    }
}
