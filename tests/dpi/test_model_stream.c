/*
 * test_model_stream.c - the model fed one command at a time
 * (dv/dpi/ef_model_stream.h) against the files `edgeflag vectors`
 * wrote for the same scene: an independent path (the CLI renders the scene's
 * polygons and writes files; here only the command words of cmd.stim.hex go
 * in and every interface's transactions come out of the stream).
 *
 * usage: test_model_stream SET...  where a SET is STIM_DIR,EXP_DIR,SAMPLES,RULE:
 *   the commands of STIM_DIR/cmd.stim.hex are fed to a model with SAMPLES
 *   and RULE (scene | nonzero | evenodd) and every interface must equal
 *   EXP_DIR's files, transaction for transaction, cycle for cycle.  A
 *   different STIM_DIR and EXP_DIR test the rule override (the stimulus of
 *   a run under each shape's rule, the files of a run under --rule).
 * tests/dpi/run.sh makes the vectors and passes the sets.
 *
 * Also: feeding and popping interleaved (the lockstep use: EMPTY until a
 * shape's SHAPE_END, then the shape's transactions), two models fed
 * alternately, four models built and run in four threads at once, the
 * scoreboard's messages, and every refusal of a bad command stream.
 */
#include <inttypes.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ef_model_stream.h"
#include "ef_vec_read.h"

typedef struct vec_set {
    char stim[512], exp[512];
    int samples, rule;
    ef_vec_dump cmd;               /* the stimulus */
    ef_vec_dump want[EF_IF_COUNT]; /* EXP_DIR's files */
    uint64_t cycles;               /* manifest.json's "cycles" */
} vec_set;

static vec_set sets[8];
static int nsets;

/* ------------------------------------------------------------- the files */

static void read_hex(const char *dir, const char *role, int iface, ef_vec_dump *d)
{
    char path[700];
    ef_vec_read_error e;
    snprintf(path, sizeof path, "%s/%s.%s.hex", dir, ef_iface_get(iface)->name, role);
    if (ef_vec_read_path(path, NULL, iface, -1, d, &e) != EF_OK) {
        char msg[1024];
        ef_vec_read_error_format(&e, msg, sizeof msg);
        fail_msg("%s", msg);
    }
}

static uint64_t manifest_cycles(const char *dir)
{
    char path[700], buf[4096];
    snprintf(path, sizeof path, "%s/manifest.json", dir);
    FILE *f = fopen(path, "r");
    if (!f)
        fail_msg("%s: cannot open", path);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    const char *p = strstr(buf, "\"cycles\": ");
    if (!p)
        fail_msg("%s: no cycles", path);
    return strtoull(p + 10, NULL, 10);
}

static int load_sets(int argc, char **argv)
{
    for (int i = 1; i < argc && nsets < 8; i++) {
        vec_set *s = &sets[nsets];
        char rule[16];
        if (sscanf(argv[i], "%511[^,],%511[^,],%d,%15s", s->stim, s->exp, &s->samples, rule) != 4) {
            fprintf(stderr, "test_model_stream: bad set '%s' (STIM_DIR,EXP_DIR,SAMPLES,RULE)\n", argv[i]);
            return 0;
        }
        s->rule = !strcmp(rule, "scene")     ? EF_MS_RULE_CMD
                  : !strcmp(rule, "evenodd") ? EF_RULE_EVENODD
                                             : EF_RULE_NONZERO;
        nsets++;
    }
    return nsets > 0;
}

static int setup_sets(void **state)
{
    (void)state;
    for (int k = 0; k < nsets; k++) {
        vec_set *s = &sets[k];
        read_hex(s->stim, "stim", EF_IF_CMD, &s->cmd);
        read_hex(s->exp, "stim", EF_IF_CMD, &s->want[EF_IF_CMD]);
        for (int i = 1; i < EF_IF_COUNT; i++)
            read_hex(s->exp, "expected", i, &s->want[i]);
        s->cycles = manifest_cycles(s->exp);
    }
    return 0;
}

static ef_mstream *model_for(const vec_set *s)
{
    ef_mstream_params p;
    ef_mstream_params_default(&p);
    p.samples = s->samples;
    p.rule = s->rule;
    ef_mstream *m = NULL;
    assert_int_equal(ef_mstream_create(&m, &p), EF_MS_OK);
    assert_non_null(m);
    return m;
}

/* The payload of stimulus word k as the two halves ef_mstream_cmd takes. */
static void stim_word(const vec_set *s, size_t k, uint64_t w[2])
{
    ef_txn t;
    ef_vec_dump_txn(&s->cmd, EF_IF_CMD, k, &t);
    w[0] = t.w[0];
    w[1] = t.w[1];
}

/* One popped transaction against expected transaction k of iface; a message
 * naming the first difference (for threads, which cannot fail_msg). */
static int same_as_file(const vec_set *s, int iface, size_t k, const ef_txn *got, char *why, size_t size)
{
    const ef_vec_seq *q = &s->want[iface].seq[iface];
    if (k >= q->n) {
        snprintf(why, size, "%s: the stream has more than the file's %zu transactions", ef_iface_get(iface)->name,
                 q->n);
        return 0;
    }
    ef_txn e;
    ef_vec_dump_txn(&s->want[iface], iface, k, &e);
    if (e.cycle != got->cycle || memcmp(e.w, got->w, sizeof e.w) != 0 || got->iface != iface) {
        char fe[400], fg[400];
        ef_mstream_format(&e, NULL, fe, sizeof fe);
        ef_mstream_format(got, &e, fg, sizeof fg);
        snprintf(why, size, "%s transaction %zu: file: cycle %" PRIu64 " %s; stream: cycle %" PRIu64 " %s",
                 ef_iface_get(iface)->name, k, e.cycle, fe, got->cycle, fg);
        return 0;
    }
    return 1;
}

/* Feeds the whole stimulus, then pops everything: 1 if it all equals the files. */
static int run_bulk(const vec_set *s, char *why, size_t size)
{
    ef_mstream_params p;
    ef_mstream_params_default(&p);
    p.samples = s->samples;
    p.rule = s->rule;
    ef_mstream *m = NULL;
    int ok = ef_mstream_create(&m, &p) == EF_MS_OK;
    const ef_vec_seq *c = &s->cmd.seq[EF_IF_CMD];
    for (size_t k = 0; ok && k < c->n; k++) {
        uint64_t w[2];
        stim_word(s, k, w);
        if (ef_mstream_cmd(m, w) != EF_MS_OK) {
            snprintf(why, size, "command %zu: %s", k + 1, ef_mstream_message(m));
            ok = 0;
        }
    }
    for (int i = 0; ok && i < EF_IF_COUNT; i++) {
        ef_txn t;
        size_t k = 0;
        int st;
        while (ok && (st = ef_mstream_pop(m, i, &t)) == EF_MS_OK)
            ok = same_as_file(s, i, k++, &t, why, size);
        if (ok && (st != EF_MS_END || k != s->want[i].seq[i].n)) {
            snprintf(why, size, "%s: %zu transactions then status %d, the file has %zu", ef_iface_get(i)->name, k, st,
                     s->want[i].seq[i].n);
            ok = 0;
        }
    }
    uint64_t cycles = 0;
    if (ok && (!ef_mstream_frame_cycles(m, &cycles) || cycles != s->cycles)) {
        snprintf(why, size, "frame length %" PRIu64 ", manifest %" PRIu64, cycles, s->cycles);
        ok = 0;
    }
    ef_mstream_destroy(m);
    return ok;
}

/* --------------------------------------------------------------- tests */

static void test_bulk_equals_files(void **state)
{
    (void)state;
    char why[1200];
    for (int k = 0; k < nsets; k++) {
        if (!run_bulk(&sets[k], why, sizeof why))
            fail_msg("set %s -> %s: %s", sets[k].stim, sets[k].exp, why);
        uint64_t n = 0;
        for (int i = 0; i < EF_IF_COUNT; i++)
            n += sets[k].want[i].seq[i].n;
        printf("model stream: %s (%d samples) equals %s: %" PRIu64 " transactions, %" PRIu64 " cycles\n", sets[k].stim,
               sets[k].samples, sets[k].exp, n, sets[k].cycles);
    }
}

/* The lockstep use: one command, then whatever is poppable.  Before a
 * shape's SHAPE_END nothing of its rasterization is there (EMPTY, never
 * END); after FRAME_END every interface says END. */
static void test_interleaved(void **state)
{
    (void)state;
    const vec_set *s = &sets[0];
    ef_mstream *m = model_for(s);
    size_t got[EF_IF_COUNT] = { 0 };
    char why[1200];
    const ef_vec_seq *c = &s->cmd.seq[EF_IF_CMD];
    for (size_t k = 0; k < c->n; k++) {
        uint64_t w[2];
        stim_word(s, k, w);
        assert_int_equal(ef_mstream_cmd(m, w), EF_MS_OK);
        assert_int_equal(ef_mstream_commands(m), k + 1);
        for (int i = 0; i < EF_IF_COUNT; i++) {
            ef_txn t;
            int st;
            while ((st = ef_mstream_pop(m, i, &t)) == EF_MS_OK)
                if (!same_as_file(s, i, got[i]++, &t, why, sizeof why))
                    fail_msg("after command %zu: %s", k + 1, why);
            assert_int_equal(st, k + 1 == c->n ? EF_MS_END : EF_MS_EMPTY);
        }
        /* A shape's spans exist only once its SHAPE_END is in. */
        const unsigned op = (unsigned)(w[1] >> 32) & 0xf;
        if (op == EF_OP_EDGE || op == EF_OP_SHAPE)
            assert_int_equal(ef_mstream_pending(m, EF_IF_SPAN), 0);
    }
    for (int i = 0; i < EF_IF_COUNT; i++)
        assert_int_equal(got[i], s->want[i].seq[i].n);
    ef_mstream_destroy(m);
}

/* Two models in one process, fed alternately: no state is shared. */
static void test_two_models(void **state)
{
    (void)state;
    const vec_set *a = &sets[0], *b = &sets[nsets > 1 ? 1 : 0];
    ef_mstream *ma = model_for(a), *mb = model_for(b);
    const size_t na = a->cmd.seq[EF_IF_CMD].n, nb = b->cmd.seq[EF_IF_CMD].n;
    for (size_t k = 0; k < na || k < nb; k++) {
        uint64_t w[2];
        if (k < na) {
            stim_word(a, k, w);
            assert_int_equal(ef_mstream_cmd(ma, w), EF_MS_OK);
        }
        if (k < nb) {
            stim_word(b, k, w);
            assert_int_equal(ef_mstream_cmd(mb, w), EF_MS_OK);
        }
    }
    char why[1200];
    for (int i = 0; i < EF_IF_COUNT; i++) {
        ef_txn t;
        size_t k = 0;
        while (ef_mstream_pop(ma, i, &t) == EF_MS_OK)
            if (!same_as_file(a, i, k++, &t, why, sizeof why))
                fail_msg("model A: %s", why);
        assert_int_equal(k, a->want[i].seq[i].n);
        k = 0;
        while (ef_mstream_pop(mb, i, &t) == EF_MS_OK)
            if (!same_as_file(b, i, k++, &t, why, sizeof why))
                fail_msg("model B: %s", why);
        assert_int_equal(k, b->want[i].seq[i].n);
    }
    ef_mstream_destroy(ma);
    ef_mstream_destroy(mb);
}

typedef struct job {
    const vec_set *s;
    int ok;
    char why[1200];
} job;

static void *worker(void *arg)
{
    job *j = arg;
    j->ok = run_bulk(j->s, j->why, sizeof j->why);
    return NULL;
}

/* Construction and use from several threads at once (a simulator running
 * models in parallel threads): every thread's result equals the files. */
static void test_threads(void **state)
{
    (void)state;
    enum { N = 4 };
    pthread_t th[N];
    job jobs[N];
    for (int k = 0; k < N; k++) {
        jobs[k] = (job){ .s = &sets[k % nsets] };
        assert_int_equal(pthread_create(&th[k], NULL, worker, &jobs[k]), 0);
    }
    for (int k = 0; k < N; k++) {
        assert_int_equal(pthread_join(th[k], NULL), 0);
        if (!jobs[k].ok)
            fail_msg("thread %d: %s", k, jobs[k].why);
    }
}

/* The scoreboard: equal, a changed field, a late one, an extra, a missing. */
static void test_expect(void **state)
{
    (void)state;
    const vec_set *s = &sets[0];
    ef_mstream *m = model_for(s);
    const ef_vec_seq *c = &s->cmd.seq[EF_IF_CMD];
    for (size_t k = 0; k < c->n; k++) {
        uint64_t w[2];
        stim_word(s, k, w);
        assert_int_equal(ef_mstream_cmd(m, w), EF_MS_OK);
    }
    const ef_vec_seq *q = &s->want[EF_IF_SPAN].seq[EF_IF_SPAN];
    assert_true(q->n >= 5);
    ef_txn t;
    ef_vec_dump_txn(&s->want[EF_IF_SPAN], EF_IF_SPAN, 0, &t);
    assert_int_equal(ef_mstream_expect(m, &t, 1), EF_MS_OK);

    ef_vec_dump_txn(&s->want[EF_IF_SPAN], EF_IF_SPAN, 1, &t);
    const uint64_t len = ef_txn_field(&t, 2);
    ef_txn_set_field(&t, 2, len - 1); /* a span cut one pixel short */
    assert_int_equal(ef_mstream_expect(m, &t, 1), EF_MS_MISMATCH);
    const char *msg = ef_mstream_message(m);
    char want[64];
    snprintf(want, sizeof want, " len=%" PRIu64 "*", len - 1);
    if (!strstr(msg, "span: cycle ") || !strstr(msg, "fields differ: expected y=") || !strstr(msg, want) ||
        !strstr(msg, "mask=0x"))
        fail_msg("message '%s'", msg);

    ef_vec_dump_txn(&s->want[EF_IF_SPAN], EF_IF_SPAN, 2, &t);
    t.cycle += 2; /* two cycles late */
    assert_int_equal(ef_mstream_expect(m, &t, 1), EF_MS_MISMATCH);
    if (!strstr(ef_mstream_message(m), "cycle differs: expected") || !strstr(ef_mstream_message(m), "late by 2"))
        fail_msg("message '%s'", ef_mstream_message(m));
    ef_vec_dump_txn(&s->want[EF_IF_SPAN], EF_IF_SPAN, 3, &t);
    t.cycle += 2; /* --transactions style: the cycle is not compared */
    assert_int_equal(ef_mstream_expect(m, &t, 0), EF_MS_OK);

    ef_vec_dump_txn(&s->want[EF_IF_SPAN], EF_IF_SPAN, 4, &t);
    const uint64_t c4 = t.cycle;
    t.cycle -= 1; /* one early, and the mask differs */
    ef_txn_set_field(&t, 3, ef_txn_field(&t, 3) ^ 1u);
    assert_int_equal(ef_mstream_expect(m, &t, 1), EF_MS_MISMATCH);
    snprintf(want, sizeof want, "*; and the cycle differs too (expected %" PRIu64 ", actual %" PRIu64 ")", c4, c4 - 1);
    if (!strstr(ef_mstream_message(m), want) || !strstr(ef_mstream_message(m), "mask=0x"))
        fail_msg("message '%s' (want '%s')", ef_mstream_message(m), want);

    assert_int_equal(ef_mstream_expect_done(m, EF_IF_SPAN), q->n > 5 ? EF_MS_MISMATCH : EF_MS_OK);
    if (q->n > 5 && !strstr(ef_mstream_message(m), "missing transaction: expected y="))
        fail_msg("message '%s'", ef_mstream_message(m));
    while (ef_mstream_pop(m, EF_IF_SPAN, &t) == EF_MS_OK)
        ;
    assert_int_equal(ef_mstream_expect_done(m, EF_IF_SPAN), EF_MS_OK);
    assert_int_equal(ef_mstream_expect(m, &t, 1), EF_MS_END);
    if (!strstr(ef_mstream_message(m), "extra transaction: actual y="))
        fail_msg("message '%s'", ef_mstream_message(m));
    ef_mstream_destroy(m);
}

/* ---------------------------------------------------------- bad streams */

static ef_mstream *small_model(int32_t wmax, int32_t hmax, uint32_t emax)
{
    ef_mstream_params p;
    ef_mstream_params_default(&p);
    p.width_max = wmax;
    p.height_max = hmax;
    p.edges_max = emax;
    ef_mstream *m = NULL;
    assert_int_equal(ef_mstream_create(&m, &p), EF_MS_OK);
    return m;
}

#define Q(v) ((v)*256) /* Q16.8 */

/* Feeds a frame's commands up to the failing one; checks its status, that
 * the message names the command number and says `what`, and stickiness. */
static void refuse(ef_mstream *m, int n, const int32_t cmds[][5], int st, const char *what)
{
    for (int k = 0; k < n; k++) {
        const int got = ef_mstream_cmd_fields(m, (unsigned)cmds[k][0], cmds[k][1], cmds[k][2], cmds[k][3], cmds[k][4]);
        if (k < n - 1 && got != EF_MS_OK)
            fail_msg("command %d: %d '%s'", k + 1, got, ef_mstream_message(m));
        if (k == n - 1 && got != st)
            fail_msg("command %d: status %d, want %d ('%s')", k + 1, got, st, ef_mstream_message(m));
    }
    char num[32];
    snprintf(num, sizeof num, "command %d (", n);
    if (strncmp(ef_mstream_message(m), num, strlen(num)) != 0 || !strstr(ef_mstream_message(m), what))
        fail_msg("message '%s' (want '%s...%s')", ef_mstream_message(m), num, what);
    assert_int_equal(ef_mstream_cmd_fields(m, EF_OP_FRAME_END, 0, 0, 0, 0), EF_MS_ERR_STOPPED);
    ef_mstream_destroy(m);
}

static void test_refusals(void **state)
{
    (void)state;
    enum { F = EF_OP_FRAME, S = EF_OP_SHAPE, E = EF_OP_EDGE, SE = EF_OP_SHAPE_END, FE = EF_OP_FRAME_END };
    refuse(small_model(64, 64, 16), 1, (const int32_t[][5]){ { 7, 0, 0, 0, 0 } }, EF_MS_ERR_OP, "not a command");
    refuse(small_model(64, 64, 16), 1, (const int32_t[][5]){ { F, 65, 10, 0, 0 } }, EF_MS_ERR_LIMIT,
           "canvas 65x10 over width_max x height_max 64x64");
    refuse(small_model(64, 64, 16), 1, (const int32_t[][5]){ { F, 0, 10, 0, 0 } }, EF_MS_ERR_FIELD, "canvas 0x10");
    refuse(small_model(64, 64, 16), 1, (const int32_t[][5]){ { F, 8, 8, 1, 0 } }, EF_MS_ERR_FIELD, "must be 0");
    refuse(small_model(64, 64, 16), 2, (const int32_t[][5]){ { F, 8, 8, 0, 0 }, { E, 0, 0, 0, 0 } }, EF_MS_ERR_ORDER,
           "EDGE outside SHAPE");
    refuse(small_model(64, 64, 16), 2, (const int32_t[][5]){ { F, 8, 8, 0, 0 }, { F, 8, 8, 0, 0 } }, EF_MS_ERR_ORDER,
           "FRAME inside a frame");
    refuse(small_model(64, 64, 16), 1, (const int32_t[][5]){ { S, 0, 0, 255, 0 } }, EF_MS_ERR_ORDER,
           "SHAPE outside a frame");
    refuse(small_model(64, 64, 16), 2, (const int32_t[][5]){ { F, 8, 8, 0, 0 }, { S, 2, 0, 255, 0 } }, EF_MS_ERR_FIELD,
           "rule a=2");
    refuse(small_model(64, 64, 16), 2, (const int32_t[][5]){ { F, 8, 8, 0, 0 }, { S, 0, 0, 256, 0 } }, EF_MS_ERR_FIELD,
           "alpha c=256");
    refuse(small_model(64, 64, 16), 3,
           (const int32_t[][5]){ { F, 8, 8, 0, 0 }, { S, 0, 0, 255, 0 }, { FE, 0, 0, 0, 0 } }, EF_MS_ERR_ORDER,
           "FRAME_END inside a shape");
    /* Two edges of a triangle, then SHAPE_END: the contour is open. */
    refuse(small_model(64, 64, 16), 5,
           (const int32_t[][5]){ { F, 8, 8, 0, 0 },
                                 { S, 0, 0, 255, 0 },
                                 { E, Q(1), Q(1), Q(5), Q(1) },
                                 { E, Q(5), Q(1), Q(3), Q(6) },
                                 { SE, 0, 0, 0, 0 } },
           EF_MS_ERR_CONTOUR, "is not closed");
    /* An edge that does not start where the last one ended. */
    refuse(small_model(64, 64, 16), 4,
           (const int32_t[][5]){
               { F, 8, 8, 0, 0 }, { S, 0, 0, 255, 0 }, { E, Q(1), Q(1), Q(5), Q(1) }, { E, Q(2), Q(2), Q(3), Q(6) } },
           EF_MS_ERR_CONTOUR, "does not start where the previous edge ended");
    /* E_MAX = 2: a triangle's third edge is one too many. */
    refuse(small_model(64, 64, 2), 5,
           (const int32_t[][5]){ { F, 8, 8, 0, 0 },
                                 { S, 0, 0, 255, 0 },
                                 { E, Q(1), Q(1), Q(5), Q(1) },
                                 { E, Q(5), Q(1), Q(3), Q(6) },
                                 { E, Q(3), Q(6), Q(1), Q(1) } },
           EF_MS_ERR_LIMIT, "more than edges_max = 2");
    /* A coordinate of -2^23 is outside |v| < 2^23: the model refuses the shape. */
    refuse(small_model(64, 64, 16), 6,
           (const int32_t[][5]){ { F, 8, 8, 0, 0 },
                                 { S, 0, 0, 255, 0 },
                                 { E, -0x800000, Q(1), Q(5), Q(1) },
                                 { E, Q(5), Q(1), Q(3), Q(6) },
                                 { E, Q(3), Q(6), -0x800000, Q(1) },
                                 { SE, 0, 0, 0, 0 } },
           EF_MS_ERR_MODEL, "the model refused the shape: invalid argument");

    /* Bits above bit 99. */
    ef_mstream *m = small_model(64, 64, 16);
    const uint64_t w[2] = { 0, (uint64_t)EF_OP_FRAME << 32 | UINT64_C(1) << 36 };
    assert_int_equal(ef_mstream_cmd(m, w), EF_MS_ERR_FIELD);
    assert_non_null(strstr(ef_mstream_message(m), "above bit 99"));
    ef_mstream_destroy(m);

    /* Interfaces not queued, bad parameters, statuses. */
    ef_mstream_params p;
    ef_mstream_params_default(&p);
    p.ifaces = 1u << EF_IF_SPAN;
    assert_int_equal(ef_mstream_create(&m, &p), EF_MS_OK);
    ef_txn t;
    assert_int_equal(ef_mstream_pop(m, EF_IF_PIX, &t), EF_MS_ERR_ARG);
    assert_int_equal(ef_mstream_pop(m, EF_IF_SPAN, &t), EF_MS_EMPTY);
    assert_int_equal(ef_mstream_pop(m, EF_IF_COUNT, &t), EF_MS_ERR_ARG);
    ef_mstream_destroy(m);
    const int bad[][3] = { { 12, 64, 64 }, { 8, 0, 64 }, { 8, 64, 16385 } };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        ef_mstream_params_default(&p);
        p.samples = bad[k][0];
        p.width_max = bad[k][1];
        p.height_max = bad[k][2];
        m = (ef_mstream *)&p;
        assert_int_equal(ef_mstream_create(&m, &p), EF_MS_ERR_ARG);
        assert_null(m);
    }
    ef_mstream_params_default(&p);
    p.rule = 2;
    assert_int_equal(ef_mstream_create(&m, &p), EF_MS_ERR_ARG);
    ef_mstream_params_default(&p);
    p.edges_max = 0;
    assert_int_equal(ef_mstream_create(&m, &p), EF_MS_ERR_ARG);
    assert_int_equal(ef_mstream_cmd(NULL, w), EF_MS_ERR_ARG);
    for (int st = EF_MS_ERR_STOPPED; st <= EF_MS_MISMATCH; st++)
        for (int st2 = EF_MS_ERR_STOPPED; st2 < st; st2++)
            assert_string_not_equal(ef_mstream_strerror(st), ef_mstream_strerror(st2));
    assert_string_equal(ef_mstream_strerror(99), "unknown status");
}

/* A hand-made frame of two shapes (a square with a hole by even-odd, given as
 * two contours, then a contour passing through its first point twice), and
 * a second FRAME of another size: cycles start again at 0, the frame buffer
 * is cleared, and the scoreboard-free facts hold. */
static void test_two_frames(void **state)
{
    (void)state;
    ef_mstream *m = small_model(64, 64, 64);
    const int32_t frame1[][5] = {
        { EF_OP_FRAME, 16, 12, 0, 0 },
        { EF_OP_SHAPE, 1, 0xff0000, 255, 0 },
        { EF_OP_EDGE, Q(1), Q(1), Q(9), Q(1) },
        { EF_OP_EDGE, Q(9), Q(1), Q(9), Q(9) },
        { EF_OP_EDGE, Q(9), Q(9), Q(1), Q(9) },
        { EF_OP_EDGE, Q(1), Q(9), Q(1), Q(1) },
        { EF_OP_EDGE, Q(3), Q(3), Q(3), Q(6) },
        { EF_OP_EDGE, Q(3), Q(6), Q(6), Q(6) },
        { EF_OP_EDGE, Q(6), Q(6), Q(3), Q(3) },
        { EF_OP_SHAPE_END, 0, 0, 0, 0 },
        /* A bow tie through its first point: A->B, B->A (closes), A->C, C->A. */
        { EF_OP_SHAPE, 0, 0x00ff00, 128, 0 },
        { EF_OP_EDGE, Q(10), Q(2), Q(15), Q(2) + 77 },
        { EF_OP_EDGE, Q(15), Q(2) + 77, Q(10), Q(2) },
        { EF_OP_EDGE, Q(10), Q(2), Q(12), Q(11) },
        { EF_OP_EDGE, Q(12), Q(11), Q(10), Q(2) },
        { EF_OP_SHAPE_END, 0, 0, 0, 0 },
        { EF_OP_FRAME_END, 0, 0, 0, 0 },
    };
    for (size_t k = 0; k < sizeof frame1 / sizeof *frame1; k++)
        if (ef_mstream_cmd_fields(m, (unsigned)frame1[k][0], frame1[k][1], frame1[k][2], frame1[k][3], frame1[k][4]) !=
            EF_MS_OK)
            fail_msg("command %zu: %s", k + 1, ef_mstream_message(m));
    uint64_t cycles;
    assert_int_equal(ef_mstream_frame_cycles(m, &cycles), 1);
    ef_txn t, last = { 0 };
    size_t ncmd = 0, npix = 0;
    while (ef_mstream_pop(m, EF_IF_CMD, &t) == EF_MS_OK) {
        assert_true(ncmd == 0 || t.cycle > last.cycle);
        last = t;
        ncmd++;
    }
    assert_int_equal(ncmd, sizeof frame1 / sizeof *frame1);
    assert_true(last.cycle < cycles);
    while (ef_mstream_pop(m, EF_IF_PIX, &t) == EF_MS_OK)
        npix++;
    assert_true(npix > 20);
    const ef_image *img = ef_mstream_frame(m);
    assert_non_null(img);
    assert_int_equal(img->width, 16);
    assert_int_equal(img->px[(2 * img->stride) + 7 * 4 + 0], 255); /* pixel (7,2): inside, red, opaque */
    assert_int_equal(img->px[(2 * img->stride) + 7 * 4 + 3], 255);
    assert_int_equal(img->px[(5 * img->stride) + 3 * 4 + 3], 0); /* (3,5): wholly in the hole */

    assert_int_equal(ef_mstream_cmd_fields(m, EF_OP_FRAME, 8, 8, 0, 0), EF_MS_OK);
    assert_int_equal(ef_mstream_frame_cycles(m, &cycles), 0);
    assert_int_equal(ef_mstream_pop(m, EF_IF_CMD, &t), EF_MS_OK);
    assert_int_equal(t.cycle, 0);
    assert_int_equal(ef_txn_field(&t, 1), 8);
    assert_int_equal(ef_mstream_pop(m, EF_IF_PIX, &t), EF_MS_EMPTY); /* frame open: feed more */
    assert_int_equal(ef_mstream_cmd_fields(m, EF_OP_FRAME_END, 0, 0, 0, 0), EF_MS_OK);
    assert_int_equal(ef_mstream_pop(m, EF_IF_PIX, &t), EF_MS_END);
    img = ef_mstream_frame(m);
    for (int k = 0; k < 8 * 8 * 4; k++)
        assert_int_equal(img->px[k], 0);
    ef_mstream_destroy(m);
}

int main(int argc, char **argv)
{
    if (!load_sets(argc, argv)) {
        fprintf(stderr, "usage: test_model_stream STIM_DIR,EXP_DIR,SAMPLES,RULE...\n");
        return 2;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bulk_equals_files), cmocka_unit_test(test_interleaved), cmocka_unit_test(test_two_models),
        cmocka_unit_test(test_threads),           cmocka_unit_test(test_expect),      cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_two_frames),
    };
    return cmocka_run_group_tests(tests, setup_sets, NULL);
}
