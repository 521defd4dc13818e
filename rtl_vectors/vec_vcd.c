/*
 * vec_vcd.c - vectors.vcd (docs/vectors.md section 5): IEEE 1364-2005
 * section 18 four-state VCD of every recorded interface, one clock.  Cycle c
 * is the interval [10c, 10c + 10) ns: clk falls at 10c, when the signals of
 * cycle c are driven, and rises at 10c + 5, when a valid transfer happens.
 * `valid` is 1 exactly in the cycles the interface transfers, `ready` is a
 * constant 1 (the reference schedule never holds valid against a low
 * ready) and payload fields keep their last value between transfers, as a
 * register would, so only real changes are dumped.
 *
 * Nothing depends on the time of day: there is no $date section.
 */
#include "ef_vec.h"

#include <string.h>

/* Identifier codes are printable ASCII; '$' is left out so that no code can
 * read like a keyword ("$end") to a careless tokenizer. */
static unsigned make_id(unsigned n, char *id)
{
    char tmp[8];
    unsigned k = 0;
    do {
        unsigned d = n % 93u;
        tmp[k++] = (char)(d + 33u >= '$' ? d + 34u : d + 33u);
        n /= 93u;
    } while (n);
    memset(id, 0, 8);
    for (unsigned i = 0; i < k; i++)
        id[i] = tmp[k - 1 - i];
    return k;
}

typedef struct sig {
    char id[8]; /* NUL-padded: copied 8 bytes at a time, idlen of them kept */
    unsigned idlen;
    unsigned width;
} sig;

/* Signals of one interface: valid, ready, then the fields, with where each
 * field's bits are in a collected record (ef_vec_list: the cycle, then the
 * payload words) and its cursor into the interface's transactions. */
typedef struct iface_sigs {
    sig valid, ready, field[EF_IF_MAX_FIELDS];
    unsigned nfields;
    unsigned word[EF_IF_MAX_FIELDS], shift[EF_IF_MAX_FIELDS];
    uint64_t mask[EF_IF_MAX_FIELDS];
    uint64_t last[EF_IF_MAX_FIELDS];
    int on;              /* valid in the previous cycle */
    const uint64_t *rec; /* the next transaction */
    size_t left;         /* transactions from rec on */
    unsigned stride;     /* words per record */
} iface_sigs;

/* Eight binary digits of each byte value; one row more, so that copying 8
 * bytes from inside the last row stays in the table. */
static const char BIN8[257][8] = {
#define B8(b) \
    { \
        '0' + ((b) >> 7 & 1), '0' + ((b) >> 6 & 1), '0' + ((b) >> 5 & 1), '0' + ((b) >> 4 & 1), '0' + ((b) >> 3 & 1), \
            '0' + ((b) >> 2 & 1), '0' + ((b) >> 1 & 1), '0' + ((b)&1) \
    }
#define B16(r) \
    B8(r + 0), B8(r + 1), B8(r + 2), B8(r + 3), B8(r + 4), B8(r + 5), B8(r + 6), B8(r + 7), B8(r + 8), B8(r + 9), \
        B8(r + 10), B8(r + 11), B8(r + 12), B8(r + 13), B8(r + 14), B8(r + 15)
    B16(0x00), B16(0x10), B16(0x20), B16(0x30), B16(0x40), B16(0x50), B16(0x60), B16(0x70),
    B16(0x80), B16(0x90), B16(0xa0), B16(0xb0), B16(0xc0), B16(0xd0), B16(0xe0), B16(0xf0),
#undef B16
#undef B8
};

/* Bytes one value change may take: 'b', 64 digits, ' ', an id copied 8
 * bytes wide, '\n'. */
#define VALUE_MAX (1 + 64 + 1 + 8 + 1)

/* A scalar change: "0!" or "1!" and a newline. */
static inline unsigned char *put_bit(unsigned char *p, unsigned bit, const sig *s)
{
    *p++ = (unsigned char)('0' + bit);
    memcpy(p, s->id, 8);
    p += s->idlen;
    *p++ = '\n';
    return p;
}

/* Binary digits of v without leading zeros, 1 for zero. */
static inline unsigned bit_length(uint64_t v)
{
#if defined(__GNUC__)
    return v ? 64u - (unsigned)__builtin_clzll(v) : 1u;
#else
    unsigned nb = 1;
    for (uint64_t x = v >> 1; x; x >>= 1)
        nb++;
    return nb;
#endif
}

/* A change of s to v: a one-bit signal as a scalar, a vector as 'b' and its
 * binary digits without leading zeros (VCD left-extends a vector with 0),
 * "b0" for zero, eight digits at a time from the table. */
static inline unsigned char *put_value(unsigned char *p, const sig *s, uint64_t v)
{
    if (s->width == 1)
        return put_bit(p, (unsigned)(v & 1u), s);
    const unsigned nb = bit_length(v);
    unsigned g = (nb - 1) / 8, top = nb - 8 * g; /* g whole bytes below a top group of 1..8 digits */
    *p++ = 'b';
    memcpy(p, BIN8[v >> (8 * g) & 0xFFu] + (8 - top), 8);
    p += top;
    for (; g > 0; g--) {
        memcpy(p, BIN8[v >> (8 * (g - 1)) & 0xFFu], 8);
        p += 8;
    }
    *p++ = ' ';
    memcpy(p, s->id, 8);
    p += s->idlen;
    *p++ = '\n';
    return p;
}

/* The decimal digits of the cycle number c, kept by counting up, so that the
 * two timestamps of a cycle, 10c and 10c + 5, are its digits and a '0' or a
 * '5' (c = 0 is the empty string: "#0", "#5").  The digits are kept at the
 * start of the buffer so that a timestamp copies a fixed 16 bytes (one
 * vector move, no call) and keeps n of them: a cycle < 2^48 has at most 15. */
typedef struct counter {
    char d[24];
    unsigned n; /* the digits are d[0..n) */
} counter;

static void counter_next(counter *k)
{
    unsigned i = k->n;
    while (i > 0 && k->d[i - 1] == '9')
        k->d[--i] = '0';
    if (i > 0) {
        k->d[i - 1]++;
    } else if (k->n == 0) { /* 0 (no digits) + 1 */
        k->d[0] = '1';
        k->n = 1;
    } else { /* 9..9 + 1: the loop left 0..0; 10..0, one digit more */
        k->d[0] = '1';
        k->d[k->n++] = '0';
    }
}

static inline unsigned char *put_time(unsigned char *p, const counter *k, char last)
{
    *p++ = '#';
    memcpy(p, k->d, 16);
    p += k->n;
    *p++ = (unsigned char)last;
    *p++ = '\n';
    return p;
}

static void out_var(ef_vec_out *o, const sig *s, const char *name)
{
    ef_vec_out_puts(o, "$var wire ");
    ef_vec_out_u64(o, s->width);
    ef_vec_out_puts(o, " ");
    ef_vec_out_puts(o, s->id);
    ef_vec_out_puts(o, " ");
    ef_vec_out_puts(o, name);
    if (s->width > 1) {
        ef_vec_out_puts(o, " [");
        ef_vec_out_u64(o, s->width - 1u);
        ef_vec_out_puts(o, ":0]");
    }
    ef_vec_out_puts(o, " $end\n");
}

static void header(ef_vec_out *o, const ef_vec_info *info, const iface_sigs *s, const sig *clk)
{
    ef_vec_out_puts(o, "$comment\n  edgeflag vectors format 1\n  ");
    ef_vec_out_run_line(o, info);
    ef_vec_out_puts(o, "\n  cycles ");
    ef_vec_out_u64(o, info->cycles);
    ef_vec_out_puts(o, "; cycle c: clk falls at 10c ns, rises (transfers) at 10c+5 ns\n$end\n"
                       "$version\n  edgeflag " EF_VERSION_STRING "\n$end\n"
                       "$timescale 1ns $end\n"
                       "$scope module edgeflag $end\n");
    out_var(o, clk, "clk");
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        if (!(info->mask >> i & 1u))
            continue;
        ef_vec_out_puts(o, "$scope module ");
        ef_vec_out_puts(o, d->name);
        ef_vec_out_puts(o, " $end\n");
        out_var(o, &s[i].valid, "valid");
        out_var(o, &s[i].ready, "ready");
        for (unsigned k = 0; k < d->nfields; k++)
            out_var(o, &s[i].field[k], d->field[k].name);
        ef_vec_out_puts(o, "$upscope $end\n");
    }
    ef_vec_out_puts(o, "$upscope $end\n$enddefinitions $end\n");
}

/* The changes at the falling edge that starts cycle cyc: each interface's
 * valid, and its fields when it transfers (a field keeps its value between
 * transfers, so only a transfer can change it).  With all set, everything
 * is dumped (the $dumpvars of time 0). */
static unsigned char *changes(unsigned char *p, iface_sigs *const *on, unsigned n, uint64_t cyc, int all)
{
    for (unsigned j = 0; j < n; j++) {
        iface_sigs *s = on[j];
        const int got = s->left && s->rec[0] == cyc; /* at most one per cycle (collector) */
        if (all || got != s->on)
            p = put_bit(p, (unsigned)got, &s->valid);
        if (all)
            p = put_bit(p, 1, &s->ready);
        s->on = got;
        if (!got && !all)
            continue;
        for (unsigned k = 0; k < s->nfields; k++) {
            uint64_t v = s->last[k];
            if (got) {
                const uint64_t *w = s->rec + 1 + s->word[k];
                v = w[0] >> s->shift[k];
                if (s->shift[k] && s->shift[k] + s->field[k].width > 64) /* masked: no bit shifted out */
                    v |= (w[1] & (UINT64_MAX >> (64 - s->shift[k]))) << (64 - s->shift[k]);
                v &= s->mask[k];
            }
            if (all || v != s->last[k])
                p = put_value(p, &s->field[k], v);
            s->last[k] = v;
        }
        if (got) {
            s->rec += s->stride;
            s->left--;
        }
    }
    return p;
}

void ef_vec_vcd_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c)
{
    iface_sigs s[EF_IF_COUNT], *on[EF_IF_COUNT];
    sig clk;
    unsigned nid = 0, non = 0;
    size_t room = 2 * (1 + sizeof((counter *)0)->d + 2) + 2 * (1 + 8 + 1) + sizeof "$dumpvars\n$end\n";
    counter k;
    uint64_t cycles = info->cycles, end = ef_vec_collect_end(c, info->mask);

    if (end > cycles) /* the caller checks; never cut a transfer off */
        cycles = end;
    memset(s, 0, sizeof s);
    memset(&clk, 0, sizeof clk);
    clk.idlen = make_id(nid++, clk.id);
    clk.width = 1;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        const ef_vec_list *l = &c->list[i];
        unsigned lsb = d->width;
        if (!(info->mask >> i & 1u))
            continue;
        on[non++] = &s[i];
        s[i].valid.idlen = make_id(nid++, s[i].valid.id);
        s[i].valid.width = 1;
        s[i].ready.idlen = make_id(nid++, s[i].ready.id);
        s[i].ready.width = 1;
        s[i].nfields = d->nfields;
        room += 2 * VALUE_MAX;
        for (unsigned f = 0; f < d->nfields; f++) {
            const unsigned w = d->field[f].width;
            s[i].field[f].idlen = make_id(nid++, s[i].field[f].id);
            s[i].field[f].width = w;
            lsb -= w; /* fields are most significant first */
            s[i].word[f] = lsb / 64;
            s[i].shift[f] = lsb % 64;
            s[i].mask[f] = w >= 64 ? ~UINT64_C(0) : (UINT64_C(1) << w) - 1u;
            room += VALUE_MAX;
        }
        s[i].stride = 1u + l->nw;
        s[i].rec = l->rec;
        s[i].left = l->count;
    }
    header(o, info, s, &clk);

    memset(&k, 0, sizeof k);
    for (uint64_t cyc = 0; cyc < cycles; cyc++, counter_next(&k)) {
        unsigned char *const p0 = ef_vec_out_room(o, room);
        unsigned char *p = put_time(p0, &k, '0');
        if (cyc == 0) {
            memcpy(p, "$dumpvars\n", 10);
            p = changes(put_bit(p + 10, 0, &clk), on, non, cyc, 1);
            memcpy(p, "$end\n", 5);
            p += 5;
        } else {
            p = changes(put_bit(p, 0, &clk), on, non, cyc, 0);
        }
        p = put_bit(put_time(p, &k, '5'), 1, &clk);
        ef_vec_out_advance(o, (size_t)(p - p0));
    }
    /* The end of the last cycle: the clock falls and every valid drops (no
     * list has a transaction left, so nothing transfers). */
    unsigned char *const p0 = ef_vec_out_room(o, room);
    unsigned char *p = put_time(p0, &k, '0');
    if (cycles == 0) {
        memcpy(p, "$dumpvars\n", 10);
        p = changes(put_bit(p + 10, 0, &clk), on, non, cycles, 1);
        memcpy(p, "$end\n", 5);
        p += 5;
    } else {
        p = changes(put_bit(p, 0, &clk), on, non, cycles, 0);
    }
    ef_vec_out_advance(o, (size_t)(p - p0));
}
