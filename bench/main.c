/*
 * main.c - efbench: edgeflag against AGG, Cairo, FreeType and stb_truetype on
 * the paper's protocol, side by side in one process (bench/README.md).
 *
 *   efbench run [--sizes 320x240,640x480,1280x960] [--frames 200] [--repeat 3]
 *               [--chunk 10] [--renderers LIST] CASE...        -> CSV on stdout
 *   efbench quality [--size 640x480] [--frame-list 0,50,100,150]
 *               [--renderers LIST] [--pictures DIR] CASE...    -> CSV on stdout
 *   efbench report [--quality Q.csv] [--outdir DIR] BENCH.csv  -> JSON, tables, plot data
 *   efbench profile CASE [--size WxH] [--renderer ef8] [--frames N]   (for callgrind)
 *   efbench render CASE [--size WxH] [--renderer R] [--frame K] -o OUT.png
 *
 * CASE is PATH[@evenodd|@nonzero][+white]: an SVG or peerbench .txt/.scene
 * file (or the word `text` for the DejaVu paragraph), optionally with every
 * shape's fill rule overridden so that all renderers fill with the same rule,
 * and optionally drawn over an opaque white background (the scene's name gets
 * "_white"): how LCD text is drawn, and where the RGB channel offsets show as
 * colour fringes (on a transparent canvas black text's premultiplied colour is
 * zero and only alpha, which comes from G, is stored).
 *
 * Protocol (run): every scene is fitted to each size and rendered for
 * --frames frames while it rotates 0.1 degree and moves (0.05, 0.03) px per
 * frame (peerbench SPEC section 3), so nothing can be cached.  A frame's
 * vertices are computed once, outside the timed region, and the same doubles
 * go to every renderer.  Renderers are interleaved: the frames are cut into
 * chunks of --chunk frames, and for each chunk every renderer renders it in
 * turn (the order rotates from chunk to chunk), so slow drifts of a shared
 * machine hit all renderers alike.  Only the render call is timed (buffer
 * clears are not).  This is repeated --repeat times; the reports are the
 * median over the repeats of ms/frame and of the ratio to AGG (and to
 * edgeflag 8x) computed within each repeat.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cairo.h>

#include "bench.h"

#define MAX_R 16
#define MAX_SIZES 8
#define MAX_REPEAT 101

static const brenderer *const kAll[] = { &br_agg,       &br_cairo,     &br_cairo_noaa, &br_freetype, &br_stb,
                                         &br_ef8,       &br_ef16,      &br_ef32,       &br_truth,    &br_ef8t,
                                         &br_ef16t,     &br_ef32t,     &br_ef16rgb,    &br_ef16trgb, &br_truth_tent,
                                         &br_truth_rgb, &br_truth_trgb };
static const char *const kDefaultRenderers = "agg,cairo,cairo-noaa,freetype,stb,ef8,ef16,ef32";
static const char *const kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
#define FIT_W 1280
#define FIT_H 960

static void die(const char *msg, const char *arg)
{
    fprintf(stderr, "efbench: %s%s%s\n", msg, arg ? " " : "", arg ? arg : "");
    exit(2);
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(const double *v, int n)
{
    double t[MAX_REPEAT];
    memcpy(t, v, (size_t)n * sizeof *t);
    qsort(t, (size_t)n, sizeof *t, cmp_d);
    return n % 2 ? t[n / 2] : (t[n / 2 - 1] + t[n / 2]) / 2;
}

static const brenderer *find_renderer(const char *name)
{
    for (size_t i = 0; i < sizeof kAll / sizeof kAll[0]; i++)
        if (!strcmp(kAll[i]->name, name))
            return kAll[i];
    die("unknown renderer", name);
    return NULL;
}

static int parse_renderers(const char *list, const brenderer **out)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", list);
    int n = 0;
    for (char *t = strtok(buf, ","); t; t = strtok(NULL, ",")) {
        if (n == MAX_R)
            die("too many renderers", NULL);
        out[n++] = find_renderer(t);
    }
    return n;
}

static int parse_size(const char *s, int *w, int *h)
{
    return sscanf(s, "%dx%d", w, h) == 2 && *w > 0 && *h > 0 && *w <= 16384 && *h <= 16384;
}

/* ------------------------------------------------------------------ cases */

typedef struct bcase {
    bscene sc;
    char scene[64]; /* display name without the rule suffix */
    char rule[16];  /* evenodd, nonzero or mixed */
    char set[8];    /* real or paper */
} bcase;

static void load_case(bcase *c, const char *spec)
{
    char path[1024], err[600];
    snprintf(path, sizeof path, "%s", spec);
    int rule = -1, white = 0;
    size_t len = strlen(path);
    if (len > 6 && !strcmp(path + len - 6, "+white")) {
        white = 1;
        path[len - 6] = '\0';
    }
    char *at = strrchr(path, '@');
    if (at) {
        if (!strcmp(at + 1, "evenodd"))
            rule = B_EVENODD;
        else if (!strcmp(at + 1, "nonzero"))
            rule = B_NONZERO;
        else
            die("case rule must be @evenodd or @nonzero:", spec);
        *at = '\0';
    }
    memset(c, 0, sizeof *c);
    int rc = !strcmp(path, "text") ? bscene_text(&c->sc, kFont, err, sizeof err)
                                   : bscene_load(&c->sc, path, FIT_W, FIT_H, err, sizeof err);
    if (rc)
        die(err, NULL);
    if (white && bscene_add_background(&c->sc))
        die("out of memory", NULL);
    bscene_set_rule(&c->sc, rule); /* the background too: a rectangle fills alike under both rules */
    int eo = 0, nz = 0;
    for (uint32_t i = 0; i < c->sc.nshapes; i++)
        *(c->sc.shapes[i].rule == B_EVENODD ? &eo : &nz) += 1;
    snprintf(c->rule, sizeof c->rule, "%s", eo && nz ? "mixed" : eo ? "evenodd" : "nonzero");
    snprintf(c->scene, sizeof c->scene, "%s", c->sc.name);
    size_t n = strlen(c->scene), k = strlen(c->rule);
    if (n > k + 1 && c->scene[n - k - 1] == '_' && !strcmp(c->scene + n - k, c->rule))
        c->scene[n - k - 1] = '\0'; /* paper_star_evenodd -> paper_star */
    snprintf(c->set, sizeof c->set, "%s", !strncmp(c->scene, "paper_", 6) ? "paper" : "real");
}

/* -------------------------------------------------------------------- run */

static int cmd_run(int argc, char **argv)
{
    int sizes[MAX_SIZES][2], nsizes = 0, frames = 200, repeat = 3, chunk = 10;
    const char *rlist = kDefaultRenderers;
    const char *cases[1024];
    int ncases = 0;
    const char *size_list = "320x240,640x480,1280x960";
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--sizes") && i + 1 < argc)
            size_list = argv[++i];
        else if (!strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--repeat") && i + 1 < argc)
            repeat = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--chunk") && i + 1 < argc)
            chunk = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--renderers") && i + 1 < argc)
            rlist = argv[++i];
        else if (argv[i][0] == '-')
            die("unknown option", argv[i]);
        else if (ncases < 1024)
            cases[ncases++] = argv[i];
    }
    if (frames < 1 || repeat < 1 || repeat > MAX_REPEAT || chunk < 1 || ncases == 0)
        die("run needs --frames >= 1, 1 <= --repeat <= 101, --chunk >= 1 and at least one case", NULL);
    char sbuf[256];
    snprintf(sbuf, sizeof sbuf, "%s", size_list);
    for (char *t = strtok(sbuf, ","); t; t = strtok(NULL, ",")) {
        if (nsizes == MAX_SIZES || !parse_size(t, &sizes[nsizes][0], &sizes[nsizes][1]))
            die("bad --sizes", size_list);
        nsizes++;
    }
    const brenderer *R[MAX_R];
    int nr = parse_renderers(rlist, R);
    int i_agg = -1, i_ef8 = -1;
    for (int r = 0; r < nr; r++) {
        if (!strcmp(R[r]->name, "agg"))
            i_agg = r;
        if (!strcmp(R[r]->name, "ef8"))
            i_ef8 = r;
    }

    printf("set,scene,rule,width,height,shapes,points,renderer,frames,repeats,ms_per_frame,ms_min,ms_max,"
           "ratio_vs_agg,ratio_vs_ef8,note\n");
    fflush(stdout);
    static bcase cs[1024];
    for (int ci = 0; ci < ncases; ci++)
        load_case(&cs[ci], cases[ci]);
    for (int zi = 0; zi < nsizes; zi++) {
        const int W = sizes[zi][0], H = sizes[zi][1];
        for (int ci = 0; ci < ncases; ci++) {
            const bcase *cp = &cs[ci];
            const bcase c = *cp;
            const bscene *sc = &cp->sc;
            void *st[MAX_R];
            const char *why[MAX_R];
            static double tot[MAX_R][MAX_REPEAT];
            memset(tot, 0, sizeof tot);
            bpoint *fr = malloc((size_t)chunk * (sc->npoints ? sc->npoints : 1) * sizeof *fr);
            if (!fr)
                die("out of memory", NULL);
            bscene_frame(sc, W, H, 0, fr);
            for (int r = 0; r < nr; r++) {
                why[r] = R[r]->unsupported(sc);
                st[r] = NULL;
                if (why[r])
                    continue;
                st[r] = R[r]->create(W, H);
                if (!st[r])
                    die("cannot create renderer", R[r]->name);
                R[r]->clear(st[r]);
                R[r]->render(st[r], sc, fr); /* untimed warm-up: buffers grow here */
            }
            fprintf(stderr, "efbench: %dx%d %s %s (%u shapes, %u points) ...\n", W, H, c.scene, c.rule, sc->nshapes,
                    sc->npoints);
            for (int rep = 0; rep < repeat; rep++) {
                for (int c0 = 0, chunk_i = 0; c0 < frames; c0 += chunk, chunk_i++) {
                    int n = frames - c0 < chunk ? frames - c0 : chunk;
                    for (int k = 0; k < n; k++)
                        bscene_frame(sc, W, H, c0 + k, fr + (size_t)k * sc->npoints);
                    for (int o = 0; o < nr; o++) {
                        int r = (o + chunk_i + rep) % nr;
                        if (!st[r])
                            continue;
                        double t = 0;
                        for (int k = 0; k < n; k++) {
                            R[r]->clear(st[r]);
                            double t0 = now_ms();
                            R[r]->render(st[r], sc, fr + (size_t)k * sc->npoints);
                            t += now_ms() - t0;
                        }
                        tot[r][rep] += t;
                    }
                }
            }
            for (int r = 0; r < nr; r++) {
                printf("%s,%s,%s,%d,%d,%u,%u,%s,", c.set, c.scene, c.rule, W, H, sc->nshapes, sc->npoints, R[r]->name);
                if (!st[r]) {
                    printf("0,0,,,,,,\"unsupported: %s\"\n", why[r]);
                    continue;
                }
                double ms[MAX_REPEAT], ra[MAX_REPEAT], re[MAX_REPEAT];
                double lo = INFINITY, hi = 0;
                for (int rep = 0; rep < repeat; rep++) {
                    ms[rep] = tot[r][rep] / frames;
                    lo = fmin(lo, ms[rep]);
                    hi = fmax(hi, ms[rep]);
                    if (i_agg >= 0 && st[i_agg])
                        ra[rep] = tot[r][rep] / tot[i_agg][rep];
                    if (i_ef8 >= 0 && st[i_ef8])
                        re[rep] = tot[r][rep] / tot[i_ef8][rep];
                }
                printf("%d,%d,%.4f,%.4f,%.4f,", frames, repeat, median(ms, repeat), lo, hi);
                if (i_agg >= 0 && st[i_agg])
                    printf("%.4f", median(ra, repeat));
                printf(",");
                if (i_ef8 >= 0 && st[i_ef8])
                    printf("%.4f", median(re, repeat));
                printf(",\n");
            }
            fflush(stdout);
            for (int r = 0; r < nr; r++)
                if (st[r])
                    R[r]->destroy(st[r]);
            free(fr);
        }
    }
    for (int ci = 0; ci < ncases; ci++)
        bscene_free(&cs[ci].sc);
    return 0;
}

/* ---------------------------------------------------------------- quality */

typedef struct qstats {
    double max, sum2;
    double amax, asum2;
    double n, an, diff;
} qstats;

static void qcompare(qstats *q, const uint8_t *a, const uint8_t *t, size_t npx)
{
    for (size_t i = 0; i < npx; i++) {
        int md = 0;
        for (int ch = 0; ch < 4; ch++) {
            int d = abs((int)a[i * 4 + ch] - (int)t[i * 4 + ch]);
            md = d > md ? d : md;
            q->sum2 += (double)d * d;
            q->n++;
            if (ch == 3) {
                q->asum2 += (double)d * d;
                q->an++;
                if (d > q->amax)
                    q->amax = d;
            }
        }
        if (md > q->max)
            q->max = md;
        if (md)
            q->diff++;
    }
}

static double psnr(double sum2, double n)
{
    double rmse = sqrt(sum2 / n);
    return rmse > 0 ? 20 * log10(255.0 / rmse) : INFINITY;
}

/* Premultiplied RGBA over white -> ARGB32 for cairo (opaque). */
static void to_argb_white(const uint8_t *rgba, uint32_t *out, size_t npx)
{
    for (size_t i = 0; i < npx; i++) {
        const uint8_t *p = rgba + i * 4;
        uint32_t r = p[0] + 255u - p[3], g = p[1] + 255u - p[3], b = p[2] + 255u - p[3];
        out[i] = 0xFF000000u | r << 16 | g << 8 | b;
    }
}

/* A Figure 7 style sheet: the same crop of every renderer's frame, magnified
 * with nearest-neighbour sampling, composited over white, labelled. */
typedef struct sheet {
    cairo_surface_t *surf;
    cairo_t *cr;
    int cols, tile_w, tile_h, label_h, n;
} sheet;

static void sheet_begin(sheet *s, int ntiles, int tile_w, int tile_h)
{
    s->cols = ntiles < 3 ? ntiles : 3;
    int rows = (ntiles + s->cols - 1) / s->cols;
    s->tile_w = tile_w;
    s->tile_h = tile_h;
    s->label_h = 22;
    s->n = 0;
    s->surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, s->cols * (tile_w + 8) + 8,
                                         rows * (tile_h + s->label_h + 8) + 8);
    s->cr = cairo_create(s->surf);
    cairo_set_source_rgb(s->cr, 0.85, 0.85, 0.85);
    cairo_paint(s->cr);
}

static void sheet_add(sheet *s, const char *label, const uint8_t *rgba, int W, int H, int cx, int cy, int cw, int ch)
{
    uint32_t *argb = malloc((size_t)W * (size_t)H * 4);
    if (!argb)
        return;
    to_argb_white(rgba, argb, (size_t)W * (size_t)H);
    cairo_surface_t *img = cairo_image_surface_create_for_data((unsigned char *)argb, CAIRO_FORMAT_ARGB32, W, H, W * 4);
    int col = s->n % s->cols, row = s->n / s->cols;
    double x0 = 8 + col * (s->tile_w + 8), y0 = 8 + row * (s->tile_h + s->label_h + 8);
    cairo_t *cr = s->cr;
    cairo_save(cr);
    cairo_rectangle(cr, x0, y0 + s->label_h, s->tile_w, s->tile_h);
    cairo_clip(cr);
    cairo_translate(cr, x0, y0 + s->label_h);
    cairo_scale(cr, (double)s->tile_w / cw, (double)s->tile_h / ch);
    cairo_set_source_surface(cr, img, -cx, -cy);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 14);
    cairo_move_to(cr, x0 + 2, y0 + 16);
    cairo_show_text(cr, label);
    cairo_surface_destroy(img);
    free(argb);
    s->n++;
}

static void sheet_end(sheet *s, const char *path)
{
    cairo_surface_flush(s->surf);
    if (cairo_surface_write_to_png(s->surf, path) != CAIRO_STATUS_SUCCESS)
        fprintf(stderr, "efbench: cannot write %s\n", path);
    cairo_destroy(s->cr);
    cairo_surface_destroy(s->surf);
}

static int cmd_quality(int argc, char **argv)
{
    int W = 640, H = 480;
    const char *rlist = "ef8,ef16,ef32,agg,cairo,cairo-noaa,freetype,stb,ef8t,ef16t,ef32t,ef16rgb,ef16trgb",
               *flist = "0,50,100,150", *pics = NULL;
    const char *cases[256];
    int ncases = 0;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (!parse_size(argv[++i], &W, &H))
                die("bad --size", argv[i]);
        } else if (!strcmp(argv[i], "--frame-list") && i + 1 < argc)
            flist = argv[++i];
        else if (!strcmp(argv[i], "--renderers") && i + 1 < argc)
            rlist = argv[++i];
        else if (!strcmp(argv[i], "--pictures") && i + 1 < argc)
            pics = argv[++i];
        else if (argv[i][0] == '-')
            die("unknown option", argv[i]);
        else if (ncases < 256)
            cases[ncases++] = argv[i];
    }
    int fl[64], nf = 0;
    char fbuf[256];
    snprintf(fbuf, sizeof fbuf, "%s", flist);
    for (char *t = strtok(fbuf, ","); t && nf < 64; t = strtok(NULL, ","))
        fl[nf++] = atoi(t);
    if (!nf || !ncases)
        die("quality needs frames and cases", NULL);
    const brenderer *R[MAX_R];
    int nr = parse_renderers(rlist, R);
    size_t npx = (size_t)W * (size_t)H;
    uint8_t *truths[4], *img = malloc(npx * 4);
    for (int k = 0; k < 4; k++)
        if (!(truths[k] = malloc(npx * 4 * (size_t)nf)))
            die("out of memory", NULL);
    uint8_t *truth = truths[0];
    if (!img)
        die("out of memory", NULL);
    printf("scene,rule,width,height,frames,renderer,max_abs,rmse,psnr_db,alpha_max,alpha_rmse,alpha_psnr_db,"
           "pct_px_diff,note\n");
    for (int ci = 0; ci < ncases; ci++) {
        bcase c;
        load_case(&c, cases[ci]);
        bpoint *fr = malloc((c.sc.npoints ? c.sc.npoints : 1) * sizeof *fr);
        if (!fr)
            die("out of memory", NULL);
        /* The box truth, and each filtered truth (docs/spec.md 10, truth_filter.c)
         * a renderer of the list is measured against. */
        const brenderer *tk[4] = { &br_truth, NULL, NULL, NULL };
        int ntk = 1;
        for (int r = 0; r < nr; r++) {
            const brenderer *t = bench_truth_of(R[r]);
            int seen = 0;
            for (int k = 0; k < ntk; k++)
                seen |= tk[k] == t;
            if (!seen && ntk < 4)
                tk[ntk++] = t;
        }
        for (int k = 0; k < ntk; k++) {
            void *ts = tk[k]->create(W, H);
            if (!ts)
                die("out of memory", NULL);
            for (int f = 0; f < nf; f++) {
                fprintf(stderr, "efbench: %s %s %dx%d frame %d ...\n", tk[k]->name, c.scene, W, H, fl[f]);
                bscene_frame(&c.sc, W, H, fl[f], fr);
                tk[k]->clear(ts);
                tk[k]->render(ts, &c.sc, fr);
                tk[k]->read(ts, truths[k] + npx * 4 * (size_t)f);
            }
            tk[k]->destroy(ts);
        }
        /* Crop for the pictures: the centre, an eighth of the canvas each way
         * (the star's centre is where point sampling shows). */
        int cw = W / 8, chh = H / 8, cx = (W - cw) / 2, cy = (H - chh) / 2;
        sheet sh;
        if (pics) {
            sheet_begin(&sh, nr + ntk, cw * 4, chh * 4);
            sheet_add(&sh, "truth 64x64", truth, W, H, cx, cy, cw, chh);
            for (int k = 1; k < ntk; k++)
                sheet_add(&sh, tk[k]->name, truths[k], W, H, cx, cy, cw, chh);
        }
        char fls[256] = "";
        for (int f = 0; f < nf; f++)
            snprintf(fls + strlen(fls), sizeof fls - strlen(fls), "%s%d", f ? ";" : "", fl[f]);
        for (int r = 0; r < nr; r++) {
            const char *why = R[r]->unsupported(&c.sc);
            if (why) {
                printf("%s,%s,%d,%d,%s,%s,,,,,,,,\"unsupported: %s\"\n", c.scene, c.rule, W, H, fls, R[r]->name, why);
                continue;
            }
            int tki = 0; /* the truth this renderer is measured against */
            while (tki < ntk - 1 && tk[tki] != bench_truth_of(R[r]))
                tki++;
            void *st = R[r]->create(W, H);
            qstats q;
            memset(&q, 0, sizeof q);
            for (int f = 0; f < nf; f++) {
                bscene_frame(&c.sc, W, H, fl[f], fr);
                R[r]->clear(st);
                R[r]->render(st, &c.sc, fr);
                R[r]->read(st, img);
                qcompare(&q, img, truths[tki] + npx * 4 * (size_t)f, npx);
                if (f == 0 && pics)
                    sheet_add(&sh, R[r]->name, img, W, H, cx, cy, cw, chh);
            }
            R[r]->destroy(st);
            printf("%s,%s,%d,%d,%s,%s,%.0f,%.4f,%.2f,%.0f,%.4f,%.2f,%.3f,%s\n", c.scene, c.rule, W, H, fls, R[r]->name,
                   q.max, sqrt(q.sum2 / q.n), psnr(q.sum2, q.n), q.amax, sqrt(q.asum2 / q.an), psnr(q.asum2, q.an),
                   100.0 * q.diff / ((double)npx * nf), tki ? tk[tki]->name : "");
            fflush(stdout);
        }
        if (pics) {
            char path[1200];
            snprintf(path, sizeof path, "%s/fig7_%s.png", pics, c.scene);
            sheet_end(&sh, path);
        }
        free(fr);
        bscene_free(&c.sc);
    }
    for (int k = 0; k < 4; k++)
        free(truths[k]);
    free(img);
    return 0;
}

/* ------------------------------------------------------- profile / render */

static int cmd_profile(int argc, char **argv, int render_png)
{
    int W = 640, H = 480, frames = 20, frame = 0;
    const char *rname = "ef8", *out = NULL, *spec = NULL;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (!parse_size(argv[++i], &W, &H))
                die("bad --size", argv[i]);
        } else if (!strcmp(argv[i], "--renderer") && i + 1 < argc)
            rname = argv[++i];
        else if (!strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--frame") && i + 1 < argc)
            frame = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out = argv[++i];
        else if (argv[i][0] == '-')
            die("unknown option", argv[i]);
        else
            spec = argv[i];
    }
    if (!spec || (render_png && !out))
        die(render_png ? "usage: efbench render CASE [--size WxH] [--renderer R] [--frame K] -o OUT.png"
                       : "usage: efbench profile CASE [--size WxH] [--renderer R] [--frames N]",
            NULL);
    const brenderer *r = find_renderer(rname);
    bcase c;
    load_case(&c, spec);
    const char *why = r->unsupported(&c.sc);
    if (why)
        die(why, NULL);
    bpoint *fr = malloc((c.sc.npoints ? c.sc.npoints : 1) * sizeof *fr);
    void *st = r->create(W, H);
    if (!fr || !st)
        die("out of memory", NULL);
    if (render_png) {
        bscene_frame(&c.sc, W, H, frame, fr);
        r->clear(st);
        r->render(st, &c.sc, fr);
        uint8_t *img = malloc((size_t)W * (size_t)H * 4);
        r->read(st, img);
        sheet sh;
        sheet_begin(&sh, 1, W, H);
        sheet_add(&sh, r->name, img, W, H, 0, 0, W, H);
        sheet_end(&sh, out);
        free(img);
    } else {
        double t = 0;
        for (int k = 0; k < frames; k++) {
            bscene_frame(&c.sc, W, H, k, fr);
            r->clear(st);
            double t0 = now_ms();
            r->render(st, &c.sc, fr);
            t += now_ms() - t0;
        }
        printf("%s %s %s %dx%d: %d frames, %.4f ms/frame\n", r->name, c.scene, c.rule, W, H, frames, t / frames);
    }
    r->destroy(st);
    free(fr);
    bscene_free(&c.sc);
    return 0;
}

/* efbench hash: one line per case, size, frame and sample count with the
 * hashes of edgeflag's image and spans and its diagnostics, to prove that an
 * optimisation of the model changed no bit (diff the output of two builds). */
static int cmd_hash(int argc, char **argv)
{
    const char *sizes = "320x240,640x480", *flist = "0,37,111";
    const char *cases[256];
    int ncases = 0;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "--sizes") && i + 1 < argc)
            sizes = argv[++i];
        else if (!strcmp(argv[i], "--frame-list") && i + 1 < argc)
            flist = argv[++i];
        else if (argv[i][0] == '-')
            die("unknown option", argv[i]);
        else if (ncases < 256)
            cases[ncases++] = argv[i];
    }
    int bad = 0;
    for (int ci = 0; ci < ncases; ci++) {
        bcase c;
        load_case(&c, cases[ci]);
        bpoint *fr = malloc((c.sc.npoints ? c.sc.npoints : 1) * sizeof *fr);
        char sbuf[256];
        snprintf(sbuf, sizeof sbuf, "%s", sizes);
        for (char *sp = sbuf, *tok; (tok = strtok(sp, ",")); sp = NULL) {
            int W, H;
            if (!parse_size(tok, &W, &H))
                die("bad --sizes", sizes);
            char fbuf[256];
            snprintf(fbuf, sizeof fbuf, "%s", flist);
            char *save = NULL;
            for (char *ft = strtok_r(fbuf, ",", &save); ft; ft = strtok_r(NULL, ",", &save)) {
                int k = atoi(ft);
                bscene_frame(&c.sc, W, H, k, fr);
                for (int n = 8; n <= 32; n *= 2) {
                    uint64_t ih, sh, dg[3];
                    int rc = bench_ef_hash(n, W, H, &c.sc, fr, &ih, &sh, dg);
                    bad |= rc != 0;
                    printf("%s %s %dx%d frame %d N=%d image %016llx spans %016llx edges %llu dropped %llu "
                           "overflows %llu%s\n",
                           c.scene, c.rule, W, H, k, n, (unsigned long long)ih, (unsigned long long)sh,
                           (unsigned long long)dg[0], (unsigned long long)dg[1], (unsigned long long)dg[2],
                           rc ? " DIAG-MISMATCH" : "");
                }
            }
        }
        free(fr);
        bscene_free(&c.sc);
    }
    return bad;
}

int bench_report(int argc, char **argv); /* report.c */

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: efbench run|quality|report|profile|render|list ... (bench/README.md)\n");
        return 2;
    }
    const char *cmd = argv[1];
    if (!strcmp(cmd, "run"))
        return cmd_run(argc - 2, argv + 2);
    if (!strcmp(cmd, "quality"))
        return cmd_quality(argc - 2, argv + 2);
    if (!strcmp(cmd, "report"))
        return bench_report(argc - 2, argv + 2);
    if (!strcmp(cmd, "profile"))
        return cmd_profile(argc - 2, argv + 2, 0);
    if (!strcmp(cmd, "render"))
        return cmd_profile(argc - 2, argv + 2, 1);
    if (!strcmp(cmd, "hash"))
        return cmd_hash(argc - 2, argv + 2);
    if (!strcmp(cmd, "list")) {
        for (size_t i = 0; i < sizeof kAll / sizeof kAll[0]; i++)
            printf("%s\n", kAll[i]->name);
        return 0;
    }
    die("unknown command", cmd);
    return 2;
}
