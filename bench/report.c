/*
 * report.c - `efbench report`: turns the CSV of `efbench run` (and of
 * `efbench quality`) into the machine-readable JSON, the markdown tables of
 * bench/RESULTS.md and the data and gnuplot scripts of the Figure 6 style
 * plots (per test, time relative to edgeflag 8x).
 *
 *   efbench report [--quality Q.csv] [--machine M.txt] [--outdir DIR]
 *                  [--results-md FILE] [--command TEXT] BENCH.csv
 *
 * Ratios are the claims: each is the median over the repeats of a ratio
 * measured within one repeat of interleaved renderers (see main.c); the
 * summaries are medians over scenes of those ratios.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define MAXF 20
#define MAXROWS 5000
#define MAXNAMES 32

typedef struct row {
    char f[MAXF][160];
    int n;
} row;

typedef struct table {
    row *rows;
    int n;
    char hdr[MAXF][64];
    int nh;
} table;

static int split_csv(char *line, char out[MAXF][160])
{
    int n = 0;
    char *p = line;
    while (n < MAXF) {
        char *o = out[n];
        size_t k = 0;
        if (*p == '"') {
            p++;
            while (*p && *p != '"') {
                if (k < 159)
                    o[k++] = *p;
                p++;
            }
            if (*p == '"')
                p++;
        } else {
            while (*p && *p != ',' && *p != '\n' && *p != '\r') {
                if (k < 159)
                    o[k++] = *p;
                p++;
            }
        }
        o[k] = '\0';
        n++;
        if (*p != ',')
            break;
        p++;
    }
    return n;
}

static int load_table(table *t, const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    t->rows = calloc(MAXROWS, sizeof *t->rows);
    t->n = t->nh = 0;
    if (!t->rows) {
        fclose(f);
        return -1;
    }
    char line[4096];
    int first = 1;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '\n' || line[0] == '#')
            continue;
        char tmp[MAXF][160];
        int n = split_csv(line, tmp);
        if (first) {
            for (int i = 0; i < n; i++)
                snprintf(t->hdr[i], sizeof t->hdr[i], "%.63s", tmp[i]);
            t->nh = n;
            first = 0;
            continue;
        }
        if (!strcmp(tmp[0], t->hdr[0]))
            continue; /* a repeated header (concatenated files) */
        if (t->n == MAXROWS)
            break;
        memcpy(t->rows[t->n].f, tmp, sizeof tmp);
        t->rows[t->n].n = n;
        t->n++;
    }
    fclose(f);
    return 0;
}

static int col(const table *t, const char *name)
{
    for (int i = 0; i < t->nh; i++)
        if (!strcmp(t->hdr[i], name))
            return i;
    fprintf(stderr, "efbench report: no column %s\n", name);
    exit(2);
}

static const char *get(const table *t, int r, const char *name) { return t->rows[r].f[col(t, name)]; }
static double getd(const table *t, int r, const char *name)
{
    const char *s = get(t, r, name);
    return *s ? atof(s) : NAN;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double med(double *v, int n)
{
    if (n == 0)
        return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* Distinct values of a column in order of first appearance. */
static int distinct(const table *t, const char *name, char out[][64], int max)
{
    int n = 0, c = col(t, name);
    for (int r = 0; r < t->n; r++) {
        int k;
        for (k = 0; k < n; k++)
            if (!strcmp(out[k], t->rows[r].f[c]))
                break;
        if (k == n && n < max)
            snprintf(out[n++], 64, "%s", t->rows[r].f[c]);
    }
    return n;
}

static void json_str(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\')
            fprintf(f, "\\%c", ch);
        else if (ch == '\n')
            fputs("\\n", f);
        else if (ch < 0x20)
            fprintf(f, "\\u%04x", ch);
        else
            fputc(ch, f);
    }
    fputc('"', f);
}

static void json_num(FILE *f, double v)
{
    if (isnan(v) || isinf(v))
        fputs("null", f);
    else
        fprintf(f, "%.6g", v);
}

/* Writes the table as a JSON array of objects, numbers as numbers. */
static void json_table(FILE *f, const table *t)
{
    fputs("[\n", f);
    for (int r = 0; r < t->n; r++) {
        fputs("  {", f);
        for (int i = 0; i < t->nh; i++) {
            const char *v = i < t->rows[r].n ? t->rows[r].f[i] : "";
            char *end;
            double d = strtod(v, &end);
            json_str(f, t->hdr[i]);
            fputs(": ", f);
            if (*v && !*end && strcmp(t->hdr[i], "frames") != 0)
                json_num(f, d);
            else if (*v && !*end)
                fputs(v, f);
            else if (!*v)
                fputs("null", f);
            else
                json_str(f, v);
            if (i + 1 < t->nh)
                fputs(", ", f);
        }
        fprintf(f, "}%s\n", r + 1 < t->n ? "," : "");
    }
    fputs("]", f);
}

static const char *short_rule(const char *rule)
{
    return !strcmp(rule, "evenodd") ? "eo" : !strcmp(rule, "nonzero") ? "nz" : "mixed";
}

typedef struct summary {
    double med, lo, hi;
    int n;
} summary;

/* Median (and range) over the rows of one size and set (NULL: all) of a
 * column, for one renderer. */
static summary summarize(const table *t, const char *size, const char *set, const char *rname, const char *column)
{
    double v[MAXROWS / 4];
    int n = 0;
    for (int r = 0; r < t->n && n < MAXROWS / 4; r++) {
        char sz[64];
        snprintf(sz, sizeof sz, "%sx%s", get(t, r, "width"), get(t, r, "height"));
        if (strcmp(sz, size) || strcmp(get(t, r, "renderer"), rname))
            continue;
        if (set && strcmp(get(t, r, "set"), set))
            continue;
        double d = getd(t, r, column);
        if (!isnan(d))
            v[n++] = d;
    }
    summary s = { NAN, NAN, NAN, n };
    if (n) {
        s.med = med(v, n);
        s.lo = v[0];
        s.hi = v[n - 1];
    }
    return s;
}

static void fmt_summary(char *buf, size_t n, summary s)
{
    if (s.n == 0)
        snprintf(buf, n, "n/a");
    else
        snprintf(buf, n, "%.2f (%.2f–%.2f)", s.med, s.lo, s.hi);
}

/* docs/spec.md section 10: each option renderer's time over the box filter's
 * at the same N, per scene (same size, scene and rule, within one repeat's
 * ratios to ef8), median and range over the scenes. */
static void write_filter_cost(FILE *f, const table *t, char sizes[][64], int ns)
{
    static const char *const opt[][2] = {
        { "ef8t", "ef8" }, { "ef16t", "ef16" }, { "ef32t", "ef32" }, { "ef16rgb", "ef16" }, { "ef16trgb", "ef16" }
    };
    static const char *const what[] = { "tent, 8 samples", "tent, 16 samples", "tent, 32 samples",
                                        "box, RGB offsets, 16 samples", "tent, RGB offsets, 16 samples" };
    int any = 0;
    for (int r = 0; r < t->n && !any; r++)
        for (size_t k = 0; k < sizeof opt / sizeof opt[0]; k++)
            any |= !strcmp(get(t, r, "renderer"), opt[k][0]);
    if (!any)
        return;
    fprintf(f, "## Filter base and channel offsets (docs/spec.md 10): time relative to the box at the same N\n\n"
               "Median over scenes (min–max) of the option's time over the box filter's, both measured in the same "
               "interleaved repeats.\n\n| renderer | option |");
    for (int z = 0; z < ns; z++)
        fprintf(f, " %s |", sizes[z]);
    fprintf(f, "\n|---|---|");
    for (int z = 0; z < ns; z++)
        fprintf(f, "---:|");
    fprintf(f, "\n");
    for (size_t k = 0; k < sizeof opt / sizeof opt[0]; k++) {
        fprintf(f, "| %s | %s |", opt[k][0], what[k]);
        for (int z = 0; z < ns; z++) {
            double v[MAXROWS / 4];
            int n = 0;
            for (int r = 0; r < t->n && n < MAXROWS / 4; r++) {
                char sz[64];
                snprintf(sz, sizeof sz, "%sx%s", get(t, r, "width"), get(t, r, "height"));
                if (strcmp(sz, sizes[z]) || strcmp(get(t, r, "renderer"), opt[k][0]))
                    continue;
                for (int r2 = 0; r2 < t->n; r2++) {
                    if (strcmp(get(t, r2, "renderer"), opt[k][1]) || strcmp(get(t, r2, "scene"), get(t, r, "scene")) ||
                        strcmp(get(t, r2, "rule"), get(t, r, "rule")) ||
                        strcmp(get(t, r2, "width"), get(t, r, "width")) ||
                        strcmp(get(t, r2, "height"), get(t, r, "height")))
                        continue;
                    const double a = getd(t, r, "ratio_vs_ef8"), b = getd(t, r2, "ratio_vs_ef8");
                    if (!isnan(a) && !isnan(b) && b > 0)
                        v[n++] = a / b;
                    break;
                }
            }
            if (n) {
                const double m = med(v, n);
                fprintf(f, " %.2f (%.2f–%.2f) |", m, v[0], v[n - 1]);
            } else {
                fprintf(f, " n/a |");
            }
        }
        fprintf(f, "\n");
    }
    fprintf(f, "\n");
}

static void write_md(FILE *f, const table *t, const table *q, const char *machine, const char *command)
{
    char sizes[8][64], rn[MAXNAMES][64];
    int ns = 0, nr = 0;
    for (int r = 0; r < t->n; r++) {
        char sz[64];
        snprintf(sz, sizeof sz, "%sx%s", get(t, r, "width"), get(t, r, "height"));
        int k;
        for (k = 0; k < ns; k++)
            if (!strcmp(sizes[k], sz))
                break;
        if (k == ns && ns < 8)
            snprintf(sizes[ns++], 64, "%s", sz);
    }
    nr = distinct(t, "renderer", rn, MAXNAMES);
    int frames = t->n ? atoi(get(t, 0, "frames")) : 0, reps = t->n ? atoi(get(t, 0, "repeats")) : 0;
    for (int r = 0; r < t->n && !frames; r++) {
        frames = atoi(get(t, r, "frames"));
        reps = atoi(get(t, r, "repeats"));
    }

    fprintf(f, "# edgeflag against its peers: results\n\n");
    fprintf(f,
            "Generated by `make bench` (`efbench report`); do not edit by hand.  %d frames per scene and size, "
            "median of %d interleaved repeats.  **Ratios are the claims**, not absolute times: the machine is "
            "shared and noisy.  Ratios are *time of the renderer / time of the reference* measured within the "
            "same repeat, so **< 1 means faster than the reference**.\n\n",
            frames, reps);
    if (machine && *machine)
        fprintf(f, "## Machine\n\n```\n%s```\n\n", machine);
    fprintf(f, "## How to reproduce\n\n```\n%s\n```\n\n", command && *command ? command : "make bench");

    /* The targets, checked on the real-life set (medians over its
     * scenes, both rules) at 640x480 if it was measured, else the first size. */
    const char *tsize = ns ? sizes[0] : "";
    for (int z = 0; z < ns; z++)
        if (!strcmp(sizes[z], "640x480"))
            tsize = sizes[z];
    if (ns) {
        fprintf(f,
                "## Targets (real-life set at %s, median over scenes and both rules)\n\n"
                "| claim | measured | target | met |\n|---|---:|---:|---|\n",
                tsize);
        summary a = summarize(t, tsize, "real", "agg", "ratio_vs_ef8");
        if (a.n)
            fprintf(f, "| edgeflag 8x speed-up over AGG (AGG time / 8x time) | %.2fx | >= 2.5x | %s |\n", a.med,
                    a.med >= 2.5 ? "yes" : "no");
        for (int i = 0; i < nr; i++) {
            if (!strncmp(rn[i], "ef", 2))
                continue;
            summary p = summarize(t, tsize, "real", rn[i], "ratio_vs_ef8");
            if (p.n)
                fprintf(f, "| %s time / edgeflag 8x time | %.2f | > 1 | %s |\n", rn[i], p.med,
                        p.med > 1 ? "yes" : "no");
        }
        summary r32 = summarize(t, tsize, "real", "ef32", "ratio_vs_ef8");
        if (r32.n)
            fprintf(f, "| edgeflag 32x time / 8x time | %.2f | <= 1.5 | %s |\n", r32.med,
                    r32.med <= 1.5 ? "yes" : "no");
        summary r32p = summarize(t, tsize, "paper", "ef32", "ratio_vs_ef8");
        summary a8p = summarize(t, tsize, "paper", "agg", "ratio_vs_ef8");
        if (r32p.n && a8p.n)
            fprintf(f,
                    "\nOn the paper's synthetic tests at %s: AGG takes %.2fx the time of edgeflag 8x (median), "
                    "and 32x takes %.2fx the time of 8x.\n",
                    tsize, a8p.med, r32p.med);
        fprintf(f, "\n");
    }

    /* Headline: median over scenes, per size, real-life and paper sets. */
    static const char *const sets[] = { "real", "paper" };
    static const char *const set_names[] = { "real-life set (illustrations + text, both rules)",
                                             "the paper's 10 synthetic tests (both rules)" };
    for (int si = 0; si < 2; si++) {
        fprintf(f,
                "## Time relative to AGG, %s\n\nMedian over scenes (min–max); `n/a`: the renderer cannot draw "
                "those scenes (stb: even-odd; FreeType: shapes over 32767 points).\n\n| renderer |",
                set_names[si]);
        for (int z = 0; z < ns; z++)
            fprintf(f, " %s |", sizes[z]);
        fprintf(f, "\n|---|");
        for (int z = 0; z < ns; z++)
            fprintf(f, "---:|");
        fprintf(f, "\n");
        for (int i = 0; i < nr; i++) {
            fprintf(f, "| %s |", rn[i]);
            for (int z = 0; z < ns; z++) {
                char b[64];
                fmt_summary(b, sizeof b, summarize(t, sizes[z], sets[si], rn[i], "ratio_vs_agg"));
                fprintf(f, " %s |", b);
            }
            fprintf(f, "\n");
        }
        fprintf(f, "\n");
    }
    /* Relative to edgeflag 8x, as in the paper's Figure 6. */
    fprintf(f,
            "## Time relative to edgeflag 8x (the paper's Figure 6 measure), median over all scenes\n\n| renderer |");
    for (int z = 0; z < ns; z++)
        fprintf(f, " %s real | %s paper |", sizes[z], sizes[z]);
    fprintf(f, "\n|---|");
    for (int z = 0; z < ns; z++)
        fprintf(f, "---:|---:|");
    fprintf(f, "\n");
    for (int i = 0; i < nr; i++) {
        fprintf(f, "| %s |", rn[i]);
        for (int z = 0; z < ns; z++)
            for (int si = 0; si < 2; si++) {
                summary s = summarize(t, sizes[z], sets[si], rn[i], "ratio_vs_ef8");
                if (s.n)
                    fprintf(f, " %.2f |", s.med);
                else
                    fprintf(f, " n/a |");
            }
        fprintf(f, "\n");
    }
    fprintf(f, "\nPlots: `bench/results/fig6_<size>.png` (one point per test and renderer, log scale).\n\n");
    write_filter_cost(f, t, sizes, ns);

    /* Full tables. */
    for (int z = 0; z < ns; z++) {
        fprintf(f, "## All tests at %s: ms/frame (time relative to AGG)\n\n| set | scene | rule | shapes | points |",
                sizes[z]);
        for (int i = 0; i < nr; i++)
            fprintf(f, " %s |", rn[i]);
        fprintf(f, "\n|---|---|---|---:|---:|");
        for (int i = 0; i < nr; i++)
            fprintf(f, "---:|");
        fprintf(f, "\n");
        for (int r = 0; r < t->n; r++) {
            char sz[64];
            snprintf(sz, sizeof sz, "%sx%s", get(t, r, "width"), get(t, r, "height"));
            if (strcmp(sz, sizes[z]) || strcmp(get(t, r, "renderer"), rn[0]))
                continue;
            fprintf(f, "| %s | %s | %s | %s | %s |", get(t, r, "set"), get(t, r, "scene"), get(t, r, "rule"),
                    get(t, r, "shapes"), get(t, r, "points"));
            for (int i = 0; i < nr; i++) {
                int found = 0;
                for (int r2 = r; r2 < t->n && r2 < r + nr + 2; r2++) {
                    if (strcmp(get(t, r2, "renderer"), rn[i]) || strcmp(get(t, r2, "scene"), get(t, r, "scene")) ||
                        strcmp(get(t, r2, "rule"), get(t, r, "rule")))
                        continue;
                    double ms = getd(t, r2, "ms_per_frame"), ra = getd(t, r2, "ratio_vs_agg");
                    if (isnan(ms) || !*get(t, r2, "ms_min"))
                        fprintf(f, " n/a |");
                    else if (isnan(ra))
                        fprintf(f, " %.3f |", ms);
                    else
                        fprintf(f, " %.3f (%.2f) |", ms, ra);
                    found = 1;
                    break;
                }
                if (!found)
                    fprintf(f, " – |");
            }
            fprintf(f, "\n");
        }
        fprintf(f, "\n");
    }

    if (q && q->n) {
        fprintf(f, "## Quality against exact dense sampling (the paper's Figure 7 as numbers)\n\n"
                   "Reference: 64 x 64 point samples per pixel, exact integer crossing tests (bench/truth.c), "
                   "composited like the renderers.  PSNR over R, G, B, A pooled and over alpha alone; max = largest "
                   "absolute error of any channel (alpha).  Pictures: `bench/results/fig7_<scene>.png` (the centre "
                   "of frame 0, magnified 4x).\n\n"
                   "| scene | size | frames | renderer | PSNR dB | max | alpha PSNR dB | alpha max | %% px differ |\n"
                   "|---|---|---|---|---:|---:|---:|---:|---:|\n");
        for (int r = 0; r < q->n; r++) {
            if (!*get(q, r, "psnr_db")) {
                fprintf(f, "| %s | %sx%s | %s | %s | n/a | | | | |\n", get(q, r, "scene"), get(q, r, "width"),
                        get(q, r, "height"), get(q, r, "frames"), get(q, r, "renderer"));
                continue;
            }
            fprintf(f, "| %s | %sx%s | %s | %s | %s | %s | %s | %s | %s |\n", get(q, r, "scene"), get(q, r, "width"),
                    get(q, r, "height"), get(q, r, "frames"), get(q, r, "renderer"), get(q, r, "psnr_db"),
                    get(q, r, "max_abs"), get(q, r, "alpha_psnr_db"), get(q, r, "alpha_max"), get(q, r, "pct_px_diff"));
        }
        fprintf(f, "\n");
    }
}

/* Figure 6 data and script for one size: per test, time relative to ef8 (%). */
static void write_fig6(const table *t, const char *outdir, const char *size)
{
    char rn[MAXNAMES][64];
    int nr = distinct(t, "renderer", rn, MAXNAMES);
    char path[1200];
    snprintf(path, sizeof path, "%s/fig6_%s.dat", outdir, size);
    FILE *f = fopen(path, "w");
    if (!f)
        return;
    fprintf(f, "idx test");
    for (int i = 0; i < nr; i++)
        fprintf(f, " %s", rn[i]);
    fprintf(f, "\n");
    int idx = 0, first_paper = -1;
    for (int r = 0; r < t->n; r++) {
        char sz[64];
        snprintf(sz, sizeof sz, "%sx%s", get(t, r, "width"), get(t, r, "height"));
        if (strcmp(sz, size) || strcmp(get(t, r, "renderer"), rn[0]))
            continue;
        if (first_paper < 0 && !strcmp(get(t, r, "set"), "paper"))
            first_paper = idx;
        const char *scene = get(t, r, "scene");
        if (!strncmp(scene, "paper_", 6))
            scene += 6;
        fprintf(f, "%d \"%s %s\"", idx++, scene, short_rule(get(t, r, "rule")));
        for (int i = 0; i < nr; i++) {
            double v = NAN;
            for (int r2 = r; r2 < t->n && r2 < r + nr + 2; r2++)
                if (!strcmp(get(t, r2, "renderer"), rn[i]) && !strcmp(get(t, r2, "scene"), get(t, r, "scene")) &&
                    !strcmp(get(t, r2, "rule"), get(t, r, "rule")))
                    v = getd(t, r2, "ratio_vs_ef8") * 100;
            if (isnan(v))
                fprintf(f, " NaN");
            else
                fprintf(f, " %.2f", v);
        }
        fprintf(f, "\n");
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/fig6_%s.gp", outdir, size);
    f = fopen(path, "w");
    if (!f)
        return;
    fprintf(f, "# gnuplot script written by efbench report: gnuplot %s\n", path);
    fprintf(f, "set terminal pngcairo size 1500,640 font 'DejaVu Sans,10' noenhanced\n");
    fprintf(f, "set output '%s/fig6_%s.png'\n", outdir, size);
    fprintf(f, "set title 'Time relative to edgeflag 8x at %s (log scale; below 100%%: faster than edgeflag 8x)'\n",
            size);
    fprintf(f, "set datafile missing 'NaN'\nset logscale y 2\nset ylabel 'time relative to edgeflag 8x (%%)'\n");
    fprintf(f, "set format y '%%g%%%%'\nset grid ytics\nset key outside right top\n");
    fprintf(f, "set xtics rotate by -60 left font ',8' nomirror\nset xrange [-1:%d]\nset bmargin 9\n", idx);
    fprintf(f, "set arrow from graph 0, first 100 to graph 1, first 100 nohead lw 2 lc rgb 'black'\n");
    if (first_paper > 0) {
        fprintf(f, "set arrow from %g, graph 0 to %g, graph 1 nohead dt 2 lc rgb 'gray40'\n", first_paper - 0.5,
                first_paper - 0.5);
        fprintf(f, "set label 'real-life (illustrations, text)' at %g, graph 0.97 center\n", (first_paper - 1) / 2.0);
        fprintf(f, "set label \"the paper's synthetic tests\" at %g, graph 0.97 center\n",
                (first_paper + idx - 1) / 2.0);
    }
    fprintf(f, "plot ");
    int k = 0;
    for (int i = 0; i < nr; i++) {
        if (!strcmp(rn[i], "ef8"))
            continue;
        fprintf(f, "%s'%s/fig6_%s.dat' using 1:%d:xtic(2) with points pt %d ps 1.4 title '%s'", k ? ", \\\n     " : "",
                outdir, size, i + 3, 4 + k, rn[i]);
        k++;
    }
    fprintf(f, "\n");
    fclose(f);
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NULL;
    char *b = calloc(1, 1 << 16);
    size_t n = b ? fread(b, 1, (1 << 16) - 1, f) : 0;
    (void)n;
    fclose(f);
    return b;
}

int bench_report(int argc, char **argv);
int bench_report(int argc, char **argv)
{
    const char *qpath = NULL, *mpath = NULL, *outdir = "bench/results", *md = NULL, *bpath = NULL, *command = NULL;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--quality") && i + 1 < argc)
            qpath = argv[++i];
        else if (!strcmp(argv[i], "--machine") && i + 1 < argc)
            mpath = argv[++i];
        else if (!strcmp(argv[i], "--outdir") && i + 1 < argc)
            outdir = argv[++i];
        else if (!strcmp(argv[i], "--results-md") && i + 1 < argc)
            md = argv[++i];
        else if (!strcmp(argv[i], "--command") && i + 1 < argc)
            command = argv[++i];
        else
            bpath = argv[i];
    }
    if (!bpath) {
        fprintf(stderr, "usage: efbench report [--quality Q.csv] [--machine M.txt] [--outdir DIR] [--results-md F] "
                        "BENCH.csv\n");
        return 2;
    }
    table t, q;
    memset(&q, 0, sizeof q);
    if (load_table(&t, bpath)) {
        fprintf(stderr, "efbench report: cannot read %s\n", bpath);
        return 2;
    }
    if (qpath && load_table(&q, qpath)) {
        fprintf(stderr, "efbench report: cannot read %s\n", qpath);
        free(t.rows);
        free(q.rows);
        return 2;
    }
    char *machine = mpath ? slurp(mpath) : NULL;
    char path[1200];
    snprintf(path, sizeof path, "%s/bench.json", outdir);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "efbench report: cannot write %s\n", path);
        free(machine);
        free(t.rows);
        free(q.rows);
        return 2;
    }
    fputs("{\n\"machine\": ", f);
    json_str(f, machine ? machine : "");
    fputs(",\n\"note\": \"ratio_vs_X = time of renderer / time of X within one interleaved repeat, median over "
          "repeats; < 1 is faster than X\",\n\"results\": ",
          f);
    json_table(f, &t);
    fputs("\n}\n", f);
    fclose(f);
    if (q.n) {
        snprintf(path, sizeof path, "%s/quality.json", outdir);
        f = fopen(path, "w");
        if (f) {
            json_table(f, &q);
            fputs("\n", f);
            fclose(f);
        }
    }
    char sizes[8][64];
    int ns = 0;
    for (int r = 0; r < t.n; r++) {
        char sz[64];
        snprintf(sz, sizeof sz, "%sx%s", get(&t, r, "width"), get(&t, r, "height"));
        int k;
        for (k = 0; k < ns; k++)
            if (!strcmp(sizes[k], sz))
                break;
        if (k == ns && ns < 8)
            snprintf(sizes[ns++], 64, "%s", sz);
    }
    for (int z = 0; z < ns; z++)
        write_fig6(&t, outdir, sizes[z]);
    if (md) {
        f = fopen(md, "w");
        if (!f) {
            fprintf(stderr, "efbench report: cannot write %s\n", md);
            free(machine);
            free(t.rows);
            free(q.rows);
            return 2;
        }
        write_md(f, &t, &q, machine, command);
        fclose(f);
    }
    free(machine);
    free(t.rows);
    free(q.rows);
    return 0;
}
