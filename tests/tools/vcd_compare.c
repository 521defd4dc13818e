/*
 * vcd_compare.c - compares two VCD files signal by signal and value change
 * by value change, independently of how each was formatted.  It exists for
 * the GTKWave round trip of tests/vectors/run.sh (vcd2fst, then fst2vcd,
 * then this): vcd2fst exits 0 even on garbage, so only a comparison proves
 * that every signal and change survived.  It shares no code with the
 * writer (rtl_vectors/vec_vcd.c).
 *
 * Normalised away: identifier codes (signals are matched by scope path and
 * name), declaration order, the order of changes within one time step,
 * vector formatting (values are left-extended to the declared width as IEEE
 * 1364 section 18 says: with 0 after a leading 0 or 1, else with the leading
 * x or z), upper/lower case of x and z, a change to the value a signal
 * already has, a range written [W-1:0] or not at all, $date, $version and
 * $comment.  Compared: the timescale, each signal's width and its list of
 * (time, value) changes from its first value on, and the last timestamp.
 *
 * With --words IFACE it acts as a testbench instead: at every rising edge
 * of edgeflag.clk (time 10c + 5, cycle c) where edgeflag.IFACE.valid and
 * .ready are 1, it prints the word { cycle[47:0], the scope's other signals
 * concatenated in declaration order } as ceil(bits / 4) hex digits, which
 * must be the data lines of IFACE's hex file (docs/vectors.md section 3).
 *
 * With --words all, every interface scope in declaration order, each line
 * prefixed with the interface's name.
 *
 *   usage: vcd_compare A.vcd B.vcd
 *          vcd_compare --words IFACE|all FILE.vcd
 *   exit 0 identical (or words printed), 1 different (the first difference
 *        is printed), 2 unreadable or malformed
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct change {
    uint64_t time;
    size_t val; /* offset of the value (width chars) in the pool */
} change;

typedef struct signal {
    char *name; /* scope.path.name */
    unsigned width;
    change *ch;
    size_t n, cap;
    size_t cur; /* pool offset of the current value; SIZE_MAX before the first */
} signal;

typedef struct idmap { /* identifier code -> signals (codes may alias) */
    char *id;
    size_t *sig;
    size_t nsig;
} idmap;

typedef struct vcd {
    const char *path;
    char timescale[64];
    signal *sig;
    size_t nsig, capsig;
    idmap *ids; /* open addressing, capids a power of two */
    size_t nids, capids;
    char *pool;
    size_t pool_len, pool_cap;
    uint64_t last_time;
    size_t nchanges;
} vcd;

static void *xrealloc(void *p, size_t n)
{
    p = realloc(p, n ? n : 1);
    if (!p) {
        fputs("vcd_compare: out of memory\n", stderr);
        exit(2);
    }
    return p;
}

static char *xstrdup(const char *s)
{
    size_t n = strlen(s) + 1;
    return memcpy(xrealloc(NULL, n), s, n);
}

static void malformed(const vcd *v, const char *what, const char *tok)
{
    fprintf(stderr, "vcd_compare: %s: %s%s%s%s\n", v->path, what, tok ? " '" : "", tok ? tok : "", tok ? "'" : "");
    exit(2);
}

/* ------------------------------------------------------------ tokens */

typedef struct lexer {
    char *p, *end;
} lexer;

/* Next whitespace-separated token (NUL-terminated in place), or NULL. */
static char *next(lexer *lx)
{
    char *s;
    while (lx->p < lx->end && (*lx->p == ' ' || *lx->p == '\t' || *lx->p == '\n' || *lx->p == '\r'))
        lx->p++;
    if (lx->p >= lx->end)
        return NULL;
    s = lx->p;
    while (lx->p < lx->end && !(*lx->p == ' ' || *lx->p == '\t' || *lx->p == '\n' || *lx->p == '\r'))
        lx->p++;
    *lx->p = '\0'; /* the buffer has one spare byte at the end */
    if (lx->p < lx->end)
        lx->p++;
    return s;
}

static void skip_to_end(vcd *v, lexer *lx, const char *what)
{
    char *t;
    while ((t = next(lx)) != NULL)
        if (strcmp(t, "$end") == 0)
            return;
    malformed(v, "no $end after", what);
}

/* ------------------------------------------------------------ identifiers */

static uint64_t hash(const char *s)
{
    uint64_t h = UINT64_C(1469598103934665603);
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * UINT64_C(1099511628211);
    return h;
}

static idmap *id_slot(vcd *v, const char *id)
{
    size_t i = (size_t)hash(id) & (v->capids - 1);
    while (v->ids[i].id && strcmp(v->ids[i].id, id) != 0)
        i = (i + 1) & (v->capids - 1);
    return &v->ids[i];
}

static void id_add(vcd *v, const char *id, size_t sig)
{
    idmap *m;
    if (2 * (v->nids + 1) > v->capids) { /* grow and rehash */
        idmap *old = v->ids;
        size_t oldcap = v->capids;
        v->capids = oldcap ? 2 * oldcap : 64;
        v->ids = calloc(v->capids, sizeof *v->ids);
        if (!v->ids)
            malformed(v, "out of memory", NULL);
        for (size_t k = 0; k < oldcap; k++)
            if (old[k].id)
                *id_slot(v, old[k].id) = old[k];
        free(old);
    }
    m = id_slot(v, id);
    if (!m->id) {
        m->id = xstrdup(id);
        v->nids++;
    }
    m->sig = xrealloc(m->sig, (m->nsig + 1) * sizeof *m->sig);
    m->sig[m->nsig++] = sig;
}

static const idmap *id_find(const vcd *v, const char *id)
{
    if (!v->capids)
        return NULL;
    const idmap *m = id_slot((vcd *)v, id);
    return m->id ? m : NULL;
}

/* ------------------------------------------------------------ header */

/* "$var TYPE WIDTH ID NAME [RANGE] $end" */
static void parse_var(vcd *v, lexer *lx, const char *scope)
{
    char *type = next(lx), *w = next(lx), *id = next(lx), *t;
    char ref[512] = "", full[1024];
    unsigned width = 0;
    if (!type || !w || !id)
        malformed(v, "truncated $var", NULL);
    for (const char *p = w; *p; p++) {
        if (*p < '0' || *p > '9' || width > 100000)
            malformed(v, "bad $var width", w);
        width = width * 10 + (unsigned)(*p - '0');
    }
    if (width == 0)
        malformed(v, "bad $var width", w);
    while ((t = next(lx)) != NULL && strcmp(t, "$end") != 0) {
        if (strlen(ref) + strlen(t) + 1 > sizeof ref)
            malformed(v, "name too long", t);
        strcat(ref, t);
    }
    if (!t)
        malformed(v, "no $end after $var", id);
    /* A range [W-1:0] (or [0] / [0:0] for one bit) says nothing the width does not. */
    char *br = strchr(ref, '[');
    if (br) {
        char want[32], want1[32];
        snprintf(want, sizeof want, "[%u:0]", width - 1);
        snprintf(want1, sizeof want1, "[%u]", width - 1);
        if (strcmp(br, want) == 0 || (width == 1 && strcmp(br, want1) == 0))
            *br = '\0';
    }
    snprintf(full, sizeof full, "%s%s%s", scope, *scope ? "." : "", ref);
    if (v->nsig == v->capsig) {
        v->capsig = v->capsig ? 2 * v->capsig : 64;
        v->sig = xrealloc(v->sig, v->capsig * sizeof *v->sig);
    }
    signal *s = &v->sig[v->nsig];
    memset(s, 0, sizeof *s);
    s->name = xstrdup(full);
    s->width = width;
    s->cur = SIZE_MAX;
    id_add(v, id, v->nsig);
    v->nsig++;
}

static void parse_header(vcd *v, lexer *lx)
{
    char scope[1024] = "";
    char *t;
    while ((t = next(lx)) != NULL) {
        if (strcmp(t, "$enddefinitions") == 0) {
            skip_to_end(v, lx, t);
            return;
        } else if (strcmp(t, "$scope") == 0) {
            char *type = next(lx), *name = next(lx);
            if (!type || !name)
                malformed(v, "truncated $scope", NULL);
            if (strlen(scope) + strlen(name) + 2 > sizeof scope)
                malformed(v, "scope too deep", name);
            if (*scope)
                strcat(scope, ".");
            strcat(scope, name);
            skip_to_end(v, lx, "$scope");
        } else if (strcmp(t, "$upscope") == 0) {
            char *dot = strrchr(scope, '.');
            if (!*scope)
                malformed(v, "$upscope without $scope", NULL);
            if (dot)
                *dot = '\0';
            else
                scope[0] = '\0';
            skip_to_end(v, lx, "$upscope");
        } else if (strcmp(t, "$var") == 0) {
            parse_var(v, lx, scope);
        } else if (strcmp(t, "$timescale") == 0) {
            char *u;
            v->timescale[0] = '\0';
            while ((u = next(lx)) != NULL && strcmp(u, "$end") != 0)
                if (strlen(v->timescale) + strlen(u) < sizeof v->timescale)
                    strcat(v->timescale, u); /* "1 ns" and "1ns" alike */
            if (!u)
                malformed(v, "no $end after", "$timescale");
        } else if (strcmp(t, "$date") == 0 || strcmp(t, "$version") == 0 || strcmp(t, "$comment") == 0) {
            skip_to_end(v, lx, t);
        } else {
            malformed(v, "unexpected in the header:", t);
        }
    }
    malformed(v, "no $enddefinitions", NULL);
}

/* ------------------------------------------------------------ changes */

static size_t pool_add(vcd *v, const char *val, unsigned width)
{
    size_t at = v->pool_len;
    if (v->pool_len + width > v->pool_cap) {
        v->pool_cap = (v->pool_cap + width) * 2;
        v->pool = xrealloc(v->pool, v->pool_cap);
    }
    memcpy(v->pool + at, val, width);
    v->pool_len += width;
    return at;
}

/* Sets the signals of id to value bits (MSB first, len chars). */
static void set_value(vcd *v, uint64_t time, const char *bits, size_t len, const char *id)
{
    const idmap *m = id_find(v, id);
    char norm[4096];
    if (!m)
        malformed(v, "change of an undeclared identifier", id);
    for (size_t k = 0; k < m->nsig; k++) {
        signal *s = &v->sig[m->sig[k]];
        if (s->width > sizeof norm)
            malformed(v, "signal too wide", s->name);
        if (len > s->width) { /* only extra leading zeros are harmless */
            for (size_t i = 0; i < len - s->width; i++)
                if (bits[i] != '0')
                    malformed(v, "value wider than its signal", id);
        }
        size_t skip = len > s->width ? len - s->width : 0, have = len - skip, pad = s->width - have;
        char fill = (bits[skip] == 'x' || bits[skip] == 'z') ? bits[skip] : '0';
        memset(norm, fill, pad);
        memcpy(norm + pad, bits + skip, have);
        if (s->cur != SIZE_MAX && memcmp(v->pool + s->cur, norm, s->width) == 0)
            continue; /* no change */
        if (s->n == s->cap) {
            s->cap = s->cap ? 2 * s->cap : 16;
            s->ch = xrealloc(s->ch, s->cap * sizeof *s->ch);
        }
        s->cur = pool_add(v, norm, s->width);
        s->ch[s->n].time = time;
        s->ch[s->n].val = s->cur;
        s->n++;
        v->nchanges++;
    }
}

static void lower_xz(vcd *v, char *s)
{
    for (; *s; s++) {
        if (*s == 'X' || *s == 'Z')
            *s = (char)(*s - 'A' + 'a');
        if (*s != '0' && *s != '1' && *s != 'x' && *s != 'z')
            malformed(v, "bad value digit in", s);
    }
}

static void parse_body(vcd *v, lexer *lx)
{
    uint64_t time = 0;
    int have_time = 0;
    char *t;
    while ((t = next(lx)) != NULL) {
        if (t[0] == '#') {
            uint64_t n = 0;
            if (!t[1])
                malformed(v, "empty timestamp", t);
            for (const char *p = t + 1; *p; p++) {
                if (*p < '0' || *p > '9' || n > (UINT64_MAX - 9) / 10)
                    malformed(v, "bad timestamp", t);
                n = n * 10 + (uint64_t)(*p - '0');
            }
            if (have_time && n < time)
                malformed(v, "time goes backwards at", t);
            time = n;
            have_time = 1;
            v->last_time = n;
        } else if (strcmp(t, "$dumpvars") == 0 || strcmp(t, "$dumpall") == 0 || strcmp(t, "$dumpon") == 0 ||
                   strcmp(t, "$dumpoff") == 0 || strcmp(t, "$end") == 0) {
            continue;
        } else if (strcmp(t, "$comment") == 0) {
            skip_to_end(v, lx, t);
        } else if (t[0] == 'b' || t[0] == 'B') {
            char *id = next(lx);
            if (!t[1] || !id)
                malformed(v, "truncated vector change", t);
            lower_xz(v, t + 1);
            set_value(v, time, t + 1, strlen(t + 1), id);
        } else if (strchr("01xXzZ", t[0]) && t[1]) {
            char bit = t[0];
            if (bit == 'X' || bit == 'Z')
                bit = (char)(bit - 'A' + 'a');
            set_value(v, time, &bit, 1, t + 1);
        } else {
            malformed(v, "unexpected value change", t);
        }
    }
}

static void load(vcd *v, const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t len = 0, cap = 0, got;
    lexer lx;
    memset(v, 0, sizeof *v);
    v->path = path;
    if (!f) {
        perror(path);
        exit(2);
    }
    do {
        if (cap - len < 65536) {
            cap = cap ? 2 * cap : 1 << 20;
            buf = xrealloc(buf, cap + 1);
        }
        got = fread(buf + len, 1, cap - len, f);
        len += got;
    } while (got);
    if (ferror(f)) {
        perror(path);
        exit(2);
    }
    fclose(f);
    buf[len] = '\0';
    lx.p = buf;
    lx.end = buf + len;
    parse_header(v, &lx);
    parse_body(v, &lx);
    free(buf);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(((const signal *)a)->name, ((const signal *)b)->name);
}

static void show(const vcd *v, const signal *s, size_t k, char *out, size_t size)
{
    if (k >= s->n) {
        snprintf(out, size, "(no change %zu)", k);
        return;
    }
    snprintf(out, size, "#%llu %.*s", (unsigned long long)s->ch[k].time, (int)(s->width > 200 ? 200 : s->width),
             v->pool + s->ch[k].val);
}

/* The value of s in effect at time t (changes at t included); *k is a
 * cursor that only moves forward, as t does. */
static const char *at(const vcd *v, const signal *s, size_t *k, uint64_t t)
{
    while (*k + 1 < s->n && s->ch[*k + 1].time <= t)
        (*k)++;
    if (!s->n || s->ch[*k].time > t)
        return NULL;
    return v->pool + s->ch[*k].val;
}

/* The transfers of scope edgeflag.IFACE of v as hex words, each line
 * prefixed with "IFACE " when prefix is set. */
static void words_of(const vcd *v, const char *iface, int prefix)
{
    static const char hex[] = "0123456789abcdef";
    char pre[256];
    const signal *clk = NULL, *valid = NULL, *ready = NULL;
    size_t *fields, nf = 0, *cur, kv = 0, kr = 0;
    unsigned bits = 48;
    char *word;

    snprintf(pre, sizeof pre, "edgeflag.%s.", iface);
    fields = xrealloc(NULL, (v->nsig + 1) * sizeof *fields);
    cur = xrealloc(NULL, (v->nsig + 1) * sizeof *cur);
    memset(cur, 0, (v->nsig + 1) * sizeof *cur);
    for (size_t i = 0; i < v->nsig; i++) {
        const signal *s = &v->sig[i];
        if (strcmp(s->name, "edgeflag.clk") == 0)
            clk = s;
        else if (strncmp(s->name, pre, strlen(pre)) != 0)
            continue;
        else if (strcmp(s->name + strlen(pre), "valid") == 0)
            valid = s;
        else if (strcmp(s->name + strlen(pre), "ready") == 0)
            ready = s;
        else {
            fields[nf++] = i;
            bits += s->width;
        }
    }
    if (!clk || !valid || !ready || !nf)
        malformed(v, "no clk, or no valid, ready and fields in scope", iface);
    word = xrealloc(NULL, bits + 8);
    for (size_t k = 0; k < clk->n; k++) {
        const uint64_t t = clk->ch[k].time;
        const char *vv, *rr;
        size_t n = 0;
        if (v->pool[clk->ch[k].val] != '1')
            continue; /* not a rising edge */
        if (t % 10 != 5)
            malformed(v, "clk rises off the 10c + 5 grid", NULL);
        vv = at(v, valid, &kv, t);
        rr = at(v, ready, &kr, t);
        if (!vv || !rr || vv[0] != '1')
            continue;
        if (rr[0] != '1')
            malformed(v, "valid while ready is not 1", NULL);
        /* bits MSB first, left-padded to whole hex digits */
        for (unsigned p = 0; p < (4 - bits % 4) % 4; p++)
            word[n++] = '0';
        for (int b = 47; b >= 0; b--)
            word[n++] = (char)('0' + ((t - 5) / 10 >> b & 1u));
        for (size_t f = 0; f < nf; f++) {
            const signal *s = &v->sig[fields[f]];
            const char *x = at(v, s, &cur[fields[f]], t);
            if (!x || memchr(x, 'x', s->width) || memchr(x, 'z', s->width))
                malformed(v, "a field is x or z during a transfer in", s->name);
            memcpy(word + n, x, s->width);
            n += s->width;
        }
        if (prefix)
            printf("%s ", iface);
        for (size_t d = 0; d < n / 4; d++) {
            unsigned h = 0;
            for (int b = 0; b < 4; b++)
                h = h << 1 | (unsigned)(word[4 * d + (size_t)b] - '0');
            putchar(hex[h]);
        }
        putchar('\n');
    }
    free(word);
    free(cur);
    free(fields);
}

/* --words all: every sub-scope of edgeflag, in declaration order. */
static int words(const char *iface, const char *path)
{
    vcd v;
    load(&v, path);
    if (strcmp(iface, "all") != 0) {
        words_of(&v, iface, 0);
        return 0;
    }
    char done[4096] = "|";
    for (size_t i = 0; i < v.nsig; i++) {
        const char *n = v.sig[i].name, *dot;
        char scope[256], key[260];
        if (strncmp(n, "edgeflag.", 9) != 0 || (dot = strchr(n + 9, '.')) == NULL ||
            (size_t)(dot - n - 9) >= sizeof scope)
            continue;
        memcpy(scope, n + 9, (size_t)(dot - n - 9));
        scope[dot - n - 9] = '\0';
        snprintf(key, sizeof key, "|%s|", scope);
        if (strstr(done, key))
            continue;
        if (strlen(done) + strlen(scope) + 2 < sizeof done) {
            strcat(done, scope);
            strcat(done, "|");
        }
        words_of(&v, scope, 1);
    }
    return 0;
}

int main(int argc, char **argv)
{
    vcd a, b;
    if (argc == 4 && strcmp(argv[1], "--words") == 0)
        return words(argv[2], argv[3]);
    if (argc != 3) {
        fputs("usage: vcd_compare A.vcd B.vcd\n       vcd_compare --words IFACE FILE.vcd\n", stderr);
        return 2;
    }
    load(&a, argv[1]);
    load(&b, argv[2]);
    if (strcmp(a.timescale, b.timescale) != 0) {
        printf("vcd_compare: timescale '%s' vs '%s'\n", a.timescale, b.timescale);
        return 1;
    }
    qsort(a.sig, a.nsig, sizeof *a.sig, by_name);
    qsort(b.sig, b.nsig, sizeof *b.sig, by_name);
    for (size_t i = 0; i < a.nsig || i < b.nsig; i++) {
        if (i >= a.nsig || i >= b.nsig || strcmp(a.sig[i].name, b.sig[i].name) != 0) {
            printf("vcd_compare: signal sets differ: '%s' in %s vs '%s' in %s\n", i < a.nsig ? a.sig[i].name : "-",
                   a.path, i < b.nsig ? b.sig[i].name : "-", b.path);
            return 1;
        }
        if (i > 0 && strcmp(a.sig[i].name, a.sig[i - 1].name) == 0) {
            printf("vcd_compare: %s declares '%s' twice\n", a.path, a.sig[i].name);
            return 1;
        }
        const signal *sa = &a.sig[i], *sb = &b.sig[i];
        if (sa->width != sb->width) {
            printf("vcd_compare: %s: width %u vs %u\n", sa->name, sa->width, sb->width);
            return 1;
        }
        for (size_t k = 0; k < sa->n || k < sb->n; k++) {
            if (k < sa->n && k < sb->n && sa->ch[k].time == sb->ch[k].time &&
                memcmp(a.pool + sa->ch[k].val, b.pool + sb->ch[k].val, sa->width) == 0)
                continue;
            char x[256], y[256];
            show(&a, sa, k, x, sizeof x);
            show(&b, sb, k, y, sizeof y);
            printf("vcd_compare: %s: value change %zu differs: %s in %s vs %s in %s\n", sa->name, k, x, a.path, y,
                   b.path);
            return 1;
        }
    }
    if (a.last_time != b.last_time) {
        printf("vcd_compare: last timestamp #%llu vs #%llu\n", (unsigned long long)a.last_time,
               (unsigned long long)b.last_time);
        return 1;
    }
    printf("vcd_compare: identical: %zu signals, %zu value changes, last time #%llu\n", a.nsig, a.nchanges,
           (unsigned long long)a.last_time);
    return 0;
}
