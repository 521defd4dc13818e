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

/* The 16 lower-case hex digits of v, most significant first, into out.
 * SWAR: each nibble is spread into a byte of its own (halves, then
 * quarters, then bytes), and '0' or 'a' - 10 added to every byte at once;
 * the bytes are stored by shifts, so the host's byte order does not matter. */
static inline void hex16(uint64_t v, unsigned char *out)
{
    const uint64_t ones = UINT64_C(0x0101010101010101);
    for (unsigned half = 0; half < 2; half++) {
        /* Digits 8*half .. 8*half+7 from the left: bits 32*(1-half) and up. */
        uint64_t y = v >> (32 * (1 - half)) & 0xFFFFFFFFu;
        /* Nibble k from the left goes to byte k (byte 0 the lowest): the
         * left 16 bits to the low lane, their left byte to the lane's low
         * byte, and each byte's left nibble to the lower byte. */
        y = ((y & 0xFFFF0000u) >> 16) | ((y & 0x0000FFFFu) << 32);
        y = ((y & UINT64_C(0x0000FF000000FF00)) >> 8) | ((y & UINT64_C(0x000000FF000000FF)) << 16);
        y = ((y & UINT64_C(0x00F000F000F000F0)) >> 4) | ((y & UINT64_C(0x000F000F000F000F)) << 8);
        /* Now byte k holds digit k; >= 10 gets 'a' - 10 - '0' more. */
        const uint64_t ge10 = ((y + ones * 6u) >> 4) & ones;
        y += ones * '0' + ge10 * ('a' - 10 - '0');
        unsigned char *o = out + 8 * half; /* eight stores that compilers merge */
        o[0] = (unsigned char)y;
        o[1] = (unsigned char)(y >> 8);
        o[2] = (unsigned char)(y >> 16);
        o[3] = (unsigned char)(y >> 24);
        o[4] = (unsigned char)(y >> 32);
        o[5] = (unsigned char)(y >> 40);
        o[6] = (unsigned char)(y >> 48);
        o[7] = (unsigned char)(y >> 56);
    }
}

/* Every transaction of iface, one word a line: the same digits as
 * ef_vec_hex_word, made a byte (two digits) at a time from the right
 * straight into the output buffer - the file is most of what `vectors`
 * writes, so this loop is its speed. */
static void hex_lines(ef_vec_out *o, const ef_vec_collect *c, int iface)
{
    const ef_vec_list *l = &c->list[iface];
    const unsigned p = ef_iface_get(iface)->width, nd = ef_vec_hex_digits(iface), nw = l->nw;
    const unsigned pw = p / 64, ps = p % 64;
    const uint64_t *r = l->rec;

    for (size_t k = 0; k < l->count; k++, r += 1u + nw) {
        uint64_t word[EF_TXN_WORDS + 1] = { 0 };
        unsigned char *out = ef_vec_out_room(o, nd + 1u);
        unsigned i = nd, b = 0;
        for (unsigned w = 0; w < nw; w++)
            word[w] = r[1 + w];
        word[pw] |= (r[0] & (UINT64_MAX >> ps)) << ps; /* the bits that fit; the rest go above */
        if (ps && ps + EF_CYCLE_BITS > 64)
            word[pw + 1] |= r[0] >> (64 - ps);
        /* Whole 64-bit words (16 digits) from the right, then the rest. */
        for (; i >= 16; i -= 16, b += 64)
            hex16(word[b / 64], out + i - 16);
        if (i) {
            unsigned char tmp[16];
            hex16(word[b / 64], tmp);
            memcpy(out, tmp + 16 - i, i);
        }
        out[nd] = '\n';
        ef_vec_out_advance(o, nd + 1u);
    }
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
    hex_lines(o, c, iface);
}
