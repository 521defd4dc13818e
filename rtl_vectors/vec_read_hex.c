/*
 * vec_read_hex.c - reader of the `$readmemh` hex files of docs/vectors.md
 * section 3: one word per transaction, { cycle[47:0], payload[P-1:0] }.
 *
 * A byte-at-a-time state machine, so a file is read in chunks and never held
 * whole.  It accepts what IEEE 1364-2005 17.2.9 lets a `$readmemh` file hold
 * and a testbench's `$fwrite("%h\n", word)` produces - white space, `//` and
 * `/ * * /` comments, upper- or lower-case digits, `_` between digits - and
 * refuses, with the line and column, everything that would make a
 * simulator load something else than the words we compare: `x`/`z`/`?`
 * digits (the RTL drove an unknown value), more digits than the interface's
 * word has, a value wider than 48 + P bits, `@` addresses (the files are
 * transaction lists, not memory images), an unterminated comment, any other
 * character.
 *
 * The header lines (`// edgeflag vectors format 1: interface NAME ...`,
 * `// generator ...; size WxH; ...`, `// word N bits: ...`, `// count N`) are
 * recognised only in the comments before the first word and only after the
 * format line, so an RTL dump's own comments never look like a header.
 */
#include "vec_read_internal.h"

#include <inttypes.h>
#include <string.h>

enum { S_NORMAL, S_WORD, S_SLASH, S_LINE_COMMENT, S_BLOCK, S_BLOCK_STAR };

#define CBUF 1024 /* header comment text kept; longer lines are cut (only `size` can be lost) */

typedef struct hex_state {
    const char *name;
    int want, hint, iface; /* iface: -1 until the header or the first word */
    ef_vec_dump *out;
    ef_vec_read_error *err;
    uint64_t line, col; /* of the current character */
    int state;
    uint64_t w[4];        /* the word being read, 256 bits (the widest is 229) */
    unsigned nd, maxd;    /* digits read, digits allowed */
    uint64_t wline, wcol; /* where it started */
    uint64_t sline, scol; /* the '/' or the comment start */
    int words_seen;       /* no header lines after the first word */
    int saw_format;
    char cbuf[CBUF]; /* text of the current // comment */
    size_t clen;
    int ctrunc;
    int have_count;
    uint64_t count, count_line, count_col, nwords;
    uint64_t size;   /* of the input, when known: bounds the count's reservation */
    unsigned pwidth; /* payload bits of iface, once known */
} hex_state;

static int is_hex(int c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

static unsigned hex_val(int c)
{
    if (c <= '9')
        return (unsigned)(c - '0');
    return (unsigned)((c | 0x20) - 'a' + 10);
}

static int is_unknown_digit(int c) { return c == 'x' || c == 'X' || c == 'z' || c == 'Z' || c == '?'; }

static int is_space(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/* Bits [lsb, lsb + n) of the 256-bit w, n <= 64.  The masks keep every shift
 * from dropping bits (the integer sanitizer flags unsigned shifts that do). */
static uint64_t bits_at(const uint64_t w[4], unsigned lsb, unsigned n)
{
    unsigned q = lsb >> 6, r = lsb & 63u;
    uint64_t v = w[q] >> r;
    if (r && q + 1 < 4)
        v |= (w[q + 1] & ((UINT64_C(1) << r) - 1u)) << (64u - r);
    return n < 64 ? v & ((UINT64_C(1) << n) - 1u) : v;
}

static ef_status err_here(hex_state *h, ef_status st, uint64_t line, uint64_t col, const char *msg, int c)
{
    char q[8] = "";
    if (c >= 0)
        ef_vr_quote_byte(c, q);
    return ef_vr_err_line(h->err, st, h->name, line, col, "%s%s", msg, q);
}

/* Columns of the header text: "//" is at scol, the text starts after it. */
static uint64_t text_col(const hex_state *h, size_t i)
{
    uint64_t col = h->scol + 2;
    for (size_t k = 0; k < i; k++)
        if (((unsigned char)h->cbuf[k] & 0xC0u) != 0x80u)
            col++;
    return col;
}

/* Decimal digits at s[*i], at most 18 (no overflow); 1 and the value, or 0. */
static int dec_at(const char *s, size_t *i, uint64_t *v)
{
    size_t k = *i;
    uint64_t x = 0;
    while (s[k] >= '0' && s[k] <= '9' && k - *i < 18)
        x = x * 10u + (uint64_t)(s[k++] - '0');
    if (k == *i || (s[k] >= '0' && s[k] <= '9'))
        return 0;
    *i = k;
    *v = x;
    return 1;
}

static int starts(const char *s, size_t *i, const char *p)
{
    size_t n = strlen(p);
    if (strncmp(s + *i, p, n) != 0)
        return 0;
    *i += n;
    return 1;
}

static ef_status header_format(hex_state *h, const char *t, size_t i)
{
    uint64_t ver;
    size_t v0 = i;
    if (!dec_at(t, &i, &ver))
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, v0),
                              "malformed header: format version expected");
    if (ver != EF_VEC_HEX_VERSION)
        return ef_vr_err_line(h->err, EF_ERR_UNSUPPORTED, h->name, h->sline, text_col(h, v0),
                              "vector format %" PRIu64 " is not supported (this edgeflag reads format %u)", ver,
                              EF_VEC_HEX_VERSION);
    if (!starts(t, &i, ": interface "))
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, i),
                              "malformed header: ': interface NAME' expected");
    size_t n0 = i;
    char nm[16];
    while (((t[i] >= 'a' && t[i] <= 'z') || t[i] == '_') && i - n0 < sizeof nm - 1)
        i++;
    memcpy(nm, t + n0, i - n0);
    nm[i - n0] = '\0';
    int f = ef_iface_find(nm);
    if (f < 0)
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, n0),
                              "unknown interface '%s' in the header", nm);
    if (h->want >= 0 && f != h->want)
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, n0),
                              "the header names interface '%s', expected '%s'", nm, ef_iface_get(h->want)->name);
    if (h->saw_format && f != h->iface)
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, n0),
                              "a second header names interface '%s', the first '%s'", nm, ef_iface_get(h->iface)->name);
    h->iface = f;
    h->saw_format = 1;
    h->out->has_header = 1;
    ef_vr_dump_add_iface(h->out, f);
    return EF_OK;
}

/* "generator ...; size WxH; samples N; ...": the fields check needs. */
static ef_status header_generator(hex_state *h, const char *t)
{
    for (size_t i = 0; t[i]; i++) {
        if (i > 0 && !(t[i - 1] == ' ' && i > 1 && t[i - 2] == ';'))
            continue;
        size_t k = i, k0;
        uint64_t a, b;
        if (starts(t, &k, "size ")) {
            k0 = k;
            if (!dec_at(t, &k, &a) || t[k] != 'x' || (k++, !dec_at(t, &k, &b)) || a < 1 || b < 1 || a > EF_MAX_CANVAS ||
                b > EF_MAX_CANVAS || (t[k] != ';' && t[k] != '\0')) {
                if (h->ctrunc && !strchr(t + k0, ';'))
                    return EF_OK; /* cut by the comment buffer, not malformed */
                return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, k0),
                                      "malformed header: 'size WxH' with 1 <= W, H <= %d expected", EF_MAX_CANVAS);
            }
            h->out->width = (int32_t)a;
            h->out->height = (int32_t)b;
        } else if (starts(t, &k, "samples ")) {
            if (dec_at(t, &k, &a) && a <= EF_SAMPLES_MAX && ef_samples_valid((int)a))
                h->out->samples = (int)a;
        }
    }
    return EF_OK;
}

static ef_status header_line(hex_state *h)
{
    while (h->clen > 0 && h->cbuf[h->clen - 1] == '\r') /* CRLF files */
        h->clen--;
    h->cbuf[h->clen] = '\0';
    const char *t = h->cbuf;
    size_t i = 0;
    uint64_t v;
    while (t[i] == ' ' || t[i] == '\t')
        i++;
    if (starts(t, &i, "edgeflag vectors format "))
        return header_format(h, t, i);
    if (!h->saw_format)
        return EF_OK;
    if (starts(t, &i, "generator "))
        return header_generator(h, t + i);
    if (starts(t, &i, "word ")) {
        size_t i0 = i;
        unsigned bits = EF_CYCLE_BITS + ef_iface_get(h->iface)->width;
        if (!dec_at(t, &i, &v) || !starts(t, &i, " bits") || v != bits)
            return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, i0),
                                  "malformed header: interface %s has %u-bit words ('word %u bits')",
                                  ef_iface_get(h->iface)->name, bits, bits);
    } else if (starts(t, &i, "count ")) {
        size_t i0 = i;
        if (!dec_at(t, &i, &v) || (t[i] != '\0' && t[i] != ' '))
            return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, text_col(h, i0),
                                  "malformed header: 'count N' expected");
        h->have_count = 1;
        h->count = v;
        ef_vr_reserve(h->out, h->iface, v, h->size, 2, 0); /* a word takes a digit and a newline at least */
        h->count_line = h->sline;
        h->count_col = text_col(h, i0);
    }
    return EF_OK;
}

static ef_status word_start(hex_state *h)
{
    if (h->iface < 0) {
        if (h->hint < 0)
            return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->line, h->col,
                                  "cannot tell which interface this file holds: no header line "
                                  "'// edgeflag vectors format 1: interface NAME', and the file name does not "
                                  "start with an interface name");
        h->iface = h->hint;
        ef_vr_dump_add_iface(h->out, h->iface);
    }
    h->words_seen = 1;
    h->maxd = ef_vr_word_digits(h->iface);
    h->pwidth = ef_iface_get(h->iface)->width;
    memset(h->w, 0, sizeof h->w);
    h->nd = 0;
    h->wline = h->line;
    h->wcol = h->col;
    h->state = S_WORD;
    return EF_OK;
}

static ef_status word_digit(hex_state *h, int c)
{
    const ef_iface_desc *d = ef_iface_get(h->iface);
    /* Leading zeros do not count: a wider register dumped with %h (a 128-bit
     * word as 32 digits) holds the same value. */
    if (h->nd == 0 && c == '0')
        return EF_OK;
    if (++h->nd > h->maxd)
        return ef_vr_err_line(h->err, EF_ERR_RANGE, h->name, h->wline, h->wcol,
                              "too many digits: a %s word has at most %u significant hex digits (%u-bit cycle + "
                              "%u-bit payload)",
                              d->name, h->maxd, EF_CYCLE_BITS, (unsigned)d->width);
    const uint64_t low60 = (UINT64_C(1) << 60) - 1u;
    for (unsigned k = 3; k > 0; k--)
        h->w[k] = ((h->w[k] & low60) << 4) | (h->w[k - 1] >> 60);
    h->w[0] = ((h->w[0] & low60) << 4) | hex_val(c);
    return EF_OK;
}

static ef_status word_end(hex_state *h)
{
    const ef_iface_desc *d = ef_iface_get(h->iface);
    const unsigned p = d->width, bits = EF_CYCLE_BITS + p;
    h->state = S_NORMAL;
    for (unsigned b = bits; b < 256; b += 64)
        if (bits_at(h->w, b, b + 64 <= 256 ? 64 : 256 - b))
            return ef_vr_err_line(h->err, EF_ERR_RANGE, h->name, h->wline, h->wcol,
                                  "value too wide: a %s word has %u bits (%u-bit cycle + %u-bit payload)", d->name,
                                  bits, EF_CYCLE_BITS, p);
    uint64_t pay[EF_TXN_WORDS] = { 0 };
    for (unsigned k = 0; k * 64 < p; k++)
        pay[k] = bits_at(h->w, k * 64, p - k * 64 < 64 ? p - k * 64 : 64);
    if (ef_vr_append(h->out, h->iface, bits_at(h->w, p, EF_CYCLE_BITS), pay, h->wline, 0, 0))
        return ef_vr_err_file(h->err, EF_ERR_NOMEM, h->name, "out of memory");
    h->nwords++;
    return EF_OK;
}

/* One byte in state S_NORMAL (also after a word ended). */
static ef_status normal_byte(hex_state *h, int c, uint64_t offset)
{
    if (is_space(c))
        return EF_OK;
    if (c == '/') {
        h->state = S_SLASH;
        h->sline = h->line;
        h->scol = h->col;
        return EF_OK;
    }
    if (is_hex(c)) {
        ef_status st = word_start(h);
        return st != EF_OK ? st : word_digit(h, c);
    }
    if (is_unknown_digit(c))
        return err_here(h, EF_ERR_SYNTAX, h->line, h->col, "unknown value (the RTL drove x or z): digit ", c);
    if (c == '@')
        return err_here(h, EF_ERR_UNSUPPORTED, h->line, h->col,
                        "address specifiers are not supported (one transaction per line, in order): ", c);
    if (offset == 0 && c == ef_vec_bin_magic[0])
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->line, h->col,
                              "not a hex file: this looks like a binary vector stream (name it *.bin)");
    return err_here(h, EF_ERR_SYNTAX, h->line, h->col, "invalid character ", c);
}

static ef_status step(hex_state *h, int c, uint64_t offset)
{
    switch (h->state) {
    case S_WORD:
        if (is_hex(c))
            return word_digit(h, c);
        if (c == '_')
            return EF_OK; /* IEEE 1364: underscores separate digits */
        if (is_unknown_digit(c))
            return err_here(h, EF_ERR_SYNTAX, h->line, h->col, "unknown value (the RTL drove x or z): digit ", c);
        if (is_space(c) || c == '/') {
            ef_status st = word_end(h);
            return st != EF_OK ? st : normal_byte(h, c, offset);
        }
        return err_here(h, EF_ERR_SYNTAX, h->line, h->col, "invalid character in a hex word: ", c);
    case S_SLASH:
        if (c == '/') {
            h->state = S_LINE_COMMENT;
            h->clen = 0;
            h->ctrunc = 0;
        } else if (c == '*') {
            h->state = S_BLOCK;
        } else {
            return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, h->scol,
                                  "invalid character '/' (comments start with // or /*)");
        }
        return EF_OK;
    case S_LINE_COMMENT:
        if (!h->words_seen) {
            if (h->clen < CBUF - 1)
                h->cbuf[h->clen++] = (char)c;
            else
                h->ctrunc = 1;
        }
        return EF_OK;
    case S_BLOCK:
        if (c == '*')
            h->state = S_BLOCK_STAR;
        return EF_OK;
    case S_BLOCK_STAR: h->state = c == '/' ? S_NORMAL : c == '*' ? S_BLOCK_STAR : S_BLOCK; return EF_OK;
    default: return normal_byte(h, c, offset);
    }
}

/* End of a line: words and line comments end, block comments go on. */
static ef_status newline(hex_state *h)
{
    ef_status st = EF_OK;
    switch (h->state) {
    case S_WORD: st = word_end(h); break;
    case S_SLASH:
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, h->scol,
                              "invalid character '/' (comments start with // or /*)");
    case S_LINE_COMMENT:
        h->state = S_NORMAL;
        if (!h->words_seen)
            st = header_line(h);
        break;
    case S_BLOCK_STAR: h->state = S_BLOCK; break;
    default: break;
    }
    h->line++;
    h->col = 0;
    return st;
}

static ef_status at_end(hex_state *h, uint64_t size)
{
    ef_status st = EF_OK;
    if (size == 0)
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, 1, 1,
                              "empty file: no header and no transactions (a dump of nothing should still hold a "
                              "comment; did the simulation end before the file was flushed?)");
    switch (h->state) {
    case S_WORD: st = word_end(h); break;
    case S_SLASH:
        st = ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, h->scol,
                            "invalid character '/' (comments start with // or /*)");
        break;
    case S_LINE_COMMENT:
        if (!h->words_seen)
            st = header_line(h);
        break;
    case S_BLOCK:
    case S_BLOCK_STAR:
        st = ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->sline, h->scol, "unterminated /* comment");
        break;
    default: break;
    }
    if (st != EF_OK)
        return st;
    if (h->iface < 0) {
        /* No word and no header: the interface is the hint's, or unknown. */
        if (h->want >= 0 || h->hint >= 0)
            ef_vr_dump_add_iface(h->out, h->want >= 0 ? h->want : h->hint);
        else
            return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->line, h->col + 1,
                                  "cannot tell which interface this file holds: no header line and no name "
                                  "starting with an interface name");
    }
    if (h->have_count && h->count != h->nwords)
        return ef_vr_err_line(h->err, EF_ERR_SYNTAX, h->name, h->count_line, h->count_col,
                              "the header says count %" PRIu64 ", the file holds %" PRIu64 " words", h->count,
                              h->nwords);
    return EF_OK;
}

/* Digit values, 0xFF for a byte that is not a hex digit (a constant table:
 * two threads of check read two files at once). */
#define HV(c) \
    ((c) >= '0' && (c) <= '9'   ? (c) - '0' \
     : (c) >= 'a' && (c) <= 'f' ? (c) - 'a' + 10 \
     : (c) >= 'A' && (c) <= 'F' ? (c) - 'A' + 10 \
                                : 0xFF)
#define HV16(r) \
    HV(r + 0), HV(r + 1), HV(r + 2), HV(r + 3), HV(r + 4), HV(r + 5), HV(r + 6), HV(r + 7), HV(r + 8), HV(r + 9), \
        HV(r + 10), HV(r + 11), HV(r + 12), HV(r + 13), HV(r + 14), HV(r + 15)
static const uint8_t hexval[256] = {
    HV16(0x00), HV16(0x10), HV16(0x20), HV16(0x30), HV16(0x40), HV16(0x50), HV16(0x60), HV16(0x70),
    HV16(0x80), HV16(0x90), HV16(0xa0), HV16(0xb0), HV16(0xc0), HV16(0xd0), HV16(0xe0), HV16(0xf0),
};
#undef HV16
#undef HV

/* Eight hex digits at p, the first the most significant, as a 32-bit
 * value: 1, or 0 if any byte is not a hex digit.  SWAR (one 64-bit word,
 * a byte per digit): no byte may have its top bit set, so the per-byte
 * additions of the range tests cannot carry into the next byte; a byte is
 * a digit when it is in '0'..'9' or, with 0x20 set, in 'a'..'f' (which
 * takes 'A'..'F' and nothing else).  The bytes are assembled by shifts, so
 * the host's byte order does not matter. */
static int hex8(const uint8_t *p, uint32_t *out)
{
    const uint64_t ones = UINT64_C(0x0101010101010101), high = ones * 0x80u;
    /* One expression, which compilers turn into one load where they can. */
    const uint64_t x = (uint64_t)p[0] | (uint64_t)p[1] << 8 | (uint64_t)p[2] << 16 | (uint64_t)p[3] << 24 |
                       (uint64_t)p[4] << 32 | (uint64_t)p[5] << 40 | (uint64_t)p[6] << 48 | (uint64_t)p[7] << 56;
    if (x & high) /* first: with a byte >= 0x80 the sums below would carry */
        return 0;
    const uint64_t lower = x | ones * 0x20u;
    const uint64_t digit = (x + ones * (0x80u - '0')) & ~(x + ones * (0x7Fu - '9'));
    const uint64_t alpha = (lower + ones * (0x80u - 'a')) & ~(lower + ones * (0x7Fu - 'f'));
    if (((digit | alpha) & high) != high)
        return 0;
    /* Each byte's value: its low nibble, plus 9 for a letter ('a' = 0x61). */
    const uint64_t nib = (x & ones * 0x0Fu) + ((alpha & high) >> 7) * 9u;
    /* Byte 0 is the first (most significant) digit: pair bytes, then pairs
     * of pairs, then halves. */
    const uint64_t t1 = ((nib << 4) | (nib >> 8)) & UINT64_C(0x00FF00FF00FF00FF);
    const uint64_t t2 = ((t1 << 8) | (t1 >> 16)) & UINT64_C(0x0000FFFF0000FFFF);
    *out = (uint32_t)((t2 << 16) | (t2 >> 32));
    return 1;
}

/* The common line, read whole: at the start of a line, with the interface
 * known, exactly the word's digit count of hex digits and a '\n', all in the
 * current chunk, and a value that fits the word (what the writer writes and
 * a `$fwrite("%h\n")` of a register of the word's width gives).  Such a line
 * means the same to the state machine - a word of at most maxd significant
 * digits, ended by the newline - so taking it here changes no result; any
 * other line (comments, CR LF, '_', other widths, errors) is left to the
 * state machine, byte by byte.  Returns 1 when the line was taken. */
static int fast_line(hex_state *h, ef_vr_src *s, ef_status *st)
{
    const unsigned nd = h->maxd;
    const uint8_t *p = s->p + s->pos;
    uint64_t w[4] = { 0, 0, 0, 0 };
    unsigned bad = 0;

    if (s->n - s->pos <= nd || p[nd] != '\n')
        return 0;
    /* Eight digits at a time from the right (32 bits each), the rest, the
     * most significant digits, one at a time. */
    unsigned left = nd, blk = 0;
    for (; left >= 8; left -= 8, blk++) {
        uint32_t v;
        if (!hex8(p + left - 8, &v))
            return 0;
        w[blk / 2] |= (uint64_t)v << (32 * (blk % 2));
    }
    uint64_t v = 0;
    for (unsigned j = 0; j < left; j++) {
        const unsigned d = hexval[p[j]];
        bad |= d;
        v = v << 4 | (d & 15u);
    }
    if (bad & 0xF0u)
        return 0;
    w[blk / 2] |= v << (32 * (blk % 2));
    /* The word is { cycle[47:0], payload[P-1:0] }: the payload is w's low
     * P bits, the cycle the 48 above them, and nothing may be above those. */
    const unsigned pw = h->pwidth, top = EF_CYCLE_BITS + pw, cw = pw / 64, cs = pw % 64;
    if (top % 64 && w[top / 64] >> (top % 64))
        return 0; /* too wide: the state machine reports it */
    for (unsigned k = (top + 63) / 64; k < 4; k++)
        if (w[k])
            return 0;
    uint64_t pay[EF_TXN_WORDS] = { 0 };
    for (unsigned k = 0; k < cw; k++)
        pay[k] = w[k];
    if (cs)
        pay[cw] = w[cw] & ((UINT64_C(1) << cs) - 1u);
    uint64_t cycle = w[cw] >> cs;
    if (cs > 64 - EF_CYCLE_BITS) /* masked: no bit shifted out */
        cycle |= (w[cw + 1] & (UINT64_MAX >> (64 - cs))) << (64 - cs);
    cycle &= (UINT64_C(1) << EF_CYCLE_BITS) - 1u;
    if (ef_vr_append(h->out, h->iface, cycle, pay, h->line, 0, 0)) {
        *st = ef_vr_err_file(h->err, EF_ERR_NOMEM, h->name, "out of memory");
        return 1;
    }
    h->nwords++;
    h->line++;
    s->pos += nd + 1u;
    return 1;
}

ef_status ef_vr_hex(ef_vr_src *s, const char *name, int want, int hint, ef_vec_dump *out, ef_vec_read_error *err)
{
    hex_state h;
    ef_status st = EF_OK;
    unsigned cont = 0; /* continuation bytes still due in the current UTF-8 sequence */

    memset(&h, 0, sizeof h);
    h.name = name;
    h.want = want >= 0 && want < EF_IF_COUNT ? want : -1;
    h.hint = h.want >= 0 ? h.want : hint >= 0 && hint < EF_IF_COUNT ? hint : -1;
    h.iface = -1;
    h.out = out;
    h.err = err;
    h.line = 1;
    h.size = s->size;
    ef_vr_dump_init(out, EF_VEC_FMT_HEX);
    for (;;) {
        /* At a line's start after the first word (col 0, nothing pending). */
        if (h.state == S_NORMAL && h.col == 0 && h.words_seen) {
            if (fast_line(&h, s, &st)) {
                if (st != EF_OK)
                    break;
                continue;
            }
        }
        uint64_t offset = ef_vr_tell(s);
        int c = ef_vr_getc(s);
        if (c < 0)
            break;
        if (c == '\n') {
            cont = 0;
            st = newline(&h);
        } else {
            /* Columns count characters: a UTF-8 sequence's continuation
             * bytes stay in their lead byte's column; a stray one is a
             * character of its own (it is then reported there). */
            if (cont > 0 && ((unsigned)c & 0xC0u) == 0x80u) {
                cont--;
            } else {
                h.col++;
                cont = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
            }
            st = step(&h, c, offset);
        }
        if (st != EF_OK)
            break;
    }
    if (st == EF_OK && !s->ioerr)
        st = at_end(&h, ef_vr_tell(s));
    if (st != EF_OK)
        ef_vec_dump_destroy(out);
    return st;
}
