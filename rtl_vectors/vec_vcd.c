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
static void make_id(unsigned n, char *id)
{
    char tmp[8];
    unsigned k = 0;
    do {
        unsigned d = n % 93u;
        tmp[k++] = (char)(d + 33u >= '$' ? d + 34u : d + 33u);
        n /= 93u;
    } while (n);
    for (unsigned i = 0; i < k; i++)
        id[i] = tmp[k - 1 - i];
    id[k] = '\0';
}

typedef struct sig {
    char id[8];
    unsigned width;
} sig;

/* Signals of one interface: valid, ready, then the fields. */
typedef struct iface_sigs {
    sig valid, ready, field[EF_IF_MAX_FIELDS];
    uint64_t last[EF_IF_MAX_FIELDS];
    int on;                 /* valid in the previous cycle */
} iface_sigs;

static void out_value(ef_vec_out *o, const sig *s, uint64_t v)
{
    char buf[72];
    unsigned n = 0;
    if (s->width == 1) {
        buf[n++] = (char)('0' + (v & 1u));
    } else {
        /* Leading zeros are dropped (VCD left-extends a vector with 0). */
        int top = 63;
        while (top > 0 && !(v >> top & 1u))
            top--;
        buf[n++] = 'b';
        for (int b = top; b >= 0; b--)
            buf[n++] = (char)('0' + (v >> b & 1u));
        buf[n++] = ' ';
    }
    ef_vec_out_write(o, buf, n);
    ef_vec_out_puts(o, s->id);
    ef_vec_out_puts(o, "\n");
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

static void out_time(ef_vec_out *o, uint64_t t)
{
    char buf[24];
    buf[0] = '#';
    size_t n = ef_vec_u64_dec(t, buf + 1);
    buf[1 + n] = '\n';
    ef_vec_out_write(o, buf, n + 2);
}

static void header(ef_vec_out *o, const ef_vec_info *info, iface_sigs *s, const sig *clk)
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

/* The changes at the falling edge that starts cycle c; got[i] says whether
 * interface i transfers t[i] in c.  With all set, everything is dumped (the
 * $dumpvars of time 0). */
static void changes(ef_vec_out *o, uint32_t mask, iface_sigs *s, const int *got, const ef_txn *t, int all)
{
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        if (!(mask >> i & 1u))
            continue;
        if (all || got[i] != s[i].on)
            out_value(o, &s[i].valid, (uint64_t)got[i]);
        if (all)
            out_value(o, &s[i].ready, 1);
        s[i].on = got[i];
        for (unsigned k = 0; k < d->nfields; k++) {
            uint64_t v = got[i] ? ef_txn_field(&t[i], k) : s[i].last[k];
            if (all || v != s[i].last[k])
                out_value(o, &s[i].field[k], v);
            s[i].last[k] = v;
        }
    }
}

void ef_vec_vcd_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c)
{
    iface_sigs s[EF_IF_COUNT];
    sig clk = { "", 1 };
    unsigned nid = 0;
    ef_vec_merge m;
    ef_txn next, t[EF_IF_COUNT];
    int have, got[EF_IF_COUNT];
    uint64_t cycles = info->cycles, end = ef_vec_collect_end(c, info->mask);

    if (end > cycles)       /* the caller checks; never cut a transfer off */
        cycles = end;
    memset(s, 0, sizeof s);
    memset(t, 0, sizeof t);
    make_id(nid++, clk.id);
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        if (!(info->mask >> i & 1u))
            continue;
        make_id(nid++, s[i].valid.id);
        s[i].valid.width = 1;
        make_id(nid++, s[i].ready.id);
        s[i].ready.width = 1;
        for (unsigned k = 0; k < d->nfields; k++) {
            make_id(nid++, s[i].field[k].id);
            s[i].field[k].width = d->field[k].width;
        }
    }
    header(o, info, s, &clk);

    ef_vec_merge_init(&m, c, info->mask);
    have = ef_vec_merge_next(&m, &next);
    for (uint64_t cyc = 0; cyc < cycles; cyc++) {
        memset(got, 0, sizeof got);
        while (have && next.cycle == cyc) {     /* at most one per interface (collector) */
            got[next.iface] = 1;
            t[next.iface] = next;
            have = ef_vec_merge_next(&m, &next);
        }
        out_time(o, 10u * cyc);
        if (cyc == 0) {
            ef_vec_out_puts(o, "$dumpvars\n");
            out_value(o, &clk, 0);
            changes(o, info->mask, s, got, t, 1);
            ef_vec_out_puts(o, "$end\n");
        } else {
            out_value(o, &clk, 0);
            changes(o, info->mask, s, got, t, 0);
        }
        out_time(o, 10u * cyc + 5u);
        out_value(o, &clk, 1);
    }
    /* The end of the last cycle: the clock falls and every valid drops. */
    memset(got, 0, sizeof got);
    out_time(o, 10u * cycles);
    if (cycles == 0) {
        ef_vec_out_puts(o, "$dumpvars\n");
        out_value(o, &clk, 0);
        changes(o, info->mask, s, got, t, 1);
        ef_vec_out_puts(o, "$end\n");
    } else {
        out_value(o, &clk, 0);
        changes(o, info->mask, s, got, t, 0);
    }
}
