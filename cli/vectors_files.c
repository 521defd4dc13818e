/*
 * vectors_files.c - writes the files of `edgeflag vectors` (docs/vectors.md
 * section 1) into DIR.  Each file goes through the atomic writer (whole or
 * absent) and through an ef_vec_out that counts and hashes the bytes on
 * their way, so the manifest describes exactly what was written without
 * reading anything back.  The files are written two at a time (run_lanes:
 * both cores busy), every one into its own temporary, and renamed into
 * place in the manifest's order only when all are written: a failure leaves
 * none of this run's files.  manifest.json comes last and, with --force, the
 * old one is removed first: a directory without a manifest is incomplete,
 * and an interrupted run never leaves an old manifest beside new files.
 * A --dump run writes no manifest (it is not a set of expected vectors), nor
 * does a build without the manifest's SHA-256 (WITH_MANIFEST=0).
 */
#include "vectors_files.h"

#include "atomic_file.h"
#include "cli.h"

#include <errno.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <pthread.h>
#include <unistd.h>

#define MANIFEST "manifest.json"
#define MAX_FILES (EF_IF_COUNT + 4)
_Static_assert(MAX_FILES <= EF_UTIL_ATOMIC_MAX, "every file's temporary is open at once");

/* The frame in the best format this build can write. */
static ef_util_format frame_format(void)
{
    return ef_util_format_available(EF_UTIL_FMT_PNG) ? EF_UTIL_FMT_PNG : EF_UTIL_FMT_PAM;
}

/* The files of this run in writing order, without the manifest.  With
 * --dump the names are a DUT's dump set (docs/vectors.md section 7):
 * IFACE.actual.hex, vectors.actual.bin, ... */
static size_t plan(const ef_cli_vec_job *job, ef_vec_file *f)
{
    size_t n = 0;
    const char *tag = job->dump ? ".actual" : "";
    memset(f, 0, MAX_FILES * sizeof *f);
    for (int k = 0; k < EF_VEC_NFORMATS; k++) {
        const ef_vec_format *fm = &ef_vec_formats[k];
        if (!(job->formats & fm->bit))
            continue;
        if (!fm->per_iface) {
            snprintf(f[n].name, sizeof f[n].name, "vectors%s%s", tag, fm->ext);
            f[n].format = fm->name;
            f[n].iface = -1;
            f[n].role = "all";
            n++;
            continue;
        }
        for (int i = 0; i < EF_IF_COUNT; i++) {
            if (!(job->ifaces >> i & 1u))
                continue;
            snprintf(f[n].name, sizeof f[n].name, "%s.%s%s", ef_iface_get(i)->name,
                     job->dump ? "actual" : ef_vec_role(i), fm->ext);
            f[n].format = fm->name;
            f[n].iface = i;
            f[n].role = ef_vec_role(i);
            n++;
        }
    }
    snprintf(f[n].name, sizeof f[n].name, "frame%s.%s", tag, frame_format() == EF_UTIL_FMT_PNG ? "png" : "pam");
    f[n].format = frame_format() == EF_UTIL_FMT_PNG ? "png" : "pam";
    f[n].iface = -1;
    f[n].role = "expected";
    n++;
    return n;
}

static int join(char *out, size_t size, const char *dir, const char *name)
{
    size_t n = strlen(dir);
    int w = snprintf(out, size, "%s%s%s", dir, (n && dir[n - 1] == '/') ? "" : "/", name);
    if (w < 0 || (size_t)w >= size) {
        ef_cli_error("'%s': path too long", dir);
        return -1;
    }
    return 0;
}

int ef_cli_vec_check_dir(const ef_cli_vec_job *job)
{
    ef_vec_file f[MAX_FILES];
    char path[4096];
    struct stat st;
    size_t n;

    if (stat(job->dir, &st) != 0)
        return -1; /* absent (or unreachable): creating it will tell */
    if (!S_ISDIR(st.st_mode)) {
        ef_cli_error("cannot create directory '%s': %s", job->dir, strerror(ENOTDIR));
        return EF_CLI_EXIT_OUTPUT;
    }
    if (job->force)
        return -1;
    n = plan(job, f);
    strcpy(f[n++].name, MANIFEST);
    for (size_t k = 0; k < n; k++) {
        if (join(path, sizeof path, job->dir, f[k].name) != 0)
            return EF_CLI_EXIT_OUTPUT;
        if (lstat(path, &st) == 0) {
            ef_cli_error("'%s' exists: use --force to replace it, or a new directory", path);
            return EF_CLI_EXIT_OUTPUT;
        }
    }
    return -1;
}

/* manifest.json: listed files and their sizes and hashes. */
typedef struct body {
    const ef_cli_vec_job *job;
    const ef_vec_file *files;
    size_t nfiles;
} body;

/* Writes the manifest atomically (the files it lists are already in place). */
static int write_manifest(ef_vec_out *o, ef_vec_file *m, const body *b)
{
    char path[4096];
    ef_util_atomic af;

    if (join(path, sizeof path, b->job->dir, m->name) != 0)
        return EF_CLI_EXIT_OUTPUT;
    if (ef_util_atomic_open(&af, path) != 0) {
        ef_cli_error("cannot write '%s': %s", path, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    ef_vec_out_init(o, af.fp, 0);
#ifndef EF_NO_MANIFEST
    if (ef_vec_manifest_write(o, b->job->info, b->job->collect, b->files, b->nfiles) != 0) {
        (void)ef_vec_out_finish(o, NULL);
        ef_util_atomic_abort(&af);
        ef_cli_error("out of memory writing '%s'", path);
        return EF_CLI_EXIT_INTERNAL;
    }
#endif
    if (ef_vec_out_finish(o, NULL) != 0) {
        int e = errno;
        ef_util_atomic_abort(&af);
        ef_cli_error("cannot write '%s': %s", path, strerror(e));
        return EF_CLI_EXIT_OUTPUT;
    }
    if (ef_util_atomic_commit(&af) != 0) {
        ef_cli_error("cannot write '%s': %s", path, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    return EF_CLI_EXIT_OK;
}

/* One file of the run: its temporary (opened by the main thread, written by
 * whichever lane takes it) and how its writing went. */
typedef struct file_job {
    ef_vec_file *f;
    char path[4096];
    ef_util_atomic af;
    int rc;        /* EF_CLI_EXIT_OK, or the exit code of its failure */
    int err;       /* errno of a failed write */
    char why[256]; /* the frame's encoder's message */
} file_job;

/* The files are shared out between two lanes (this thread and one more),
 * each taking the next file of `order` and formatting, hashing and writing
 * it alone: no hand-over per buffer, and the two cores busy (the VCD is
 * about half of the work, so it goes first and the other lane takes the
 * binary stream and the hex files meanwhile).  Which lane writes a file
 * does not change a byte of it. */
typedef struct lanes {
    const ef_cli_vec_job *job;
    file_job *files;
    size_t n;
    size_t order[MAX_FILES];
    atomic_size_t next;
    atomic_int stop; /* a file failed: take no more */
} lanes;

/* The frame image encoded into memory (hashed on its way like every other
 * file).  0, or -1 with j->why set. */
static int encode_frame(const ef_image *img, unsigned char **buf, size_t *len, file_job *j)
{
    char *p = NULL;
    size_t n = 0;
    FILE *ms = open_memstream(&p, &n);
    int rc;
    if (!ms) {
        snprintf(j->why, sizeof j->why, "out of memory");
        return -1;
    }
    rc = ef_util_write_image(ms, frame_format(), img, j->why, sizeof j->why);
    if (fclose(ms) != 0 || rc != 0) {
        free(p);
        if (!rc)
            snprintf(j->why, sizeof j->why, "%s", strerror(errno));
        return -1;
    }
    *buf = (unsigned char *)p;
    *len = n;
    return 0;
}

/* Formats, hashes and writes one file into its temporary; records its size
 * and hash, or its failure. */
static void write_one(ef_vec_out *o, const ef_cli_vec_job *job, file_job *j)
{
    ef_vec_file *f = j->f;
    const ef_vec_format *fm = ef_vec_format_named(f->format);
    uint8_t digest[32];
    int nomem = 0;

    ef_vec_out_init(o, j->af.fp, EF_VEC_OUT_SHA);
    if (fm) {
        nomem = fm->write(o, job->info, job->collect, f->iface) != 0;
    } else { /* the frame */
        unsigned char *frame = NULL;
        size_t len = 0;
        if (encode_frame(job->img, &frame, &len, j) != 0) {
            (void)ef_vec_out_finish(o, digest);
            j->rc = EF_CLI_EXIT_INTERNAL;
            return;
        }
        ef_vec_out_write(o, frame, len);
        free(frame);
    }
    if (ef_vec_out_finish(o, digest) != 0 || ef_util_atomic_sync(&j->af) != 0) {
        j->err = errno;
        j->rc = EF_CLI_EXIT_OUTPUT;
    } else if (nomem) {
        j->rc = EF_CLI_EXIT_INTERNAL;
    } else {
        f->bytes = o->bytes;
        ef_vec_sha256_hex(digest, f->sha256);
    }
}

static void *lane(void *arg)
{
    lanes *l = arg;
    ef_vec_out *o = malloc(sizeof *o);
    for (;;) {
        size_t k = atomic_fetch_add(&l->next, 1);
        if (k >= l->n || atomic_load(&l->stop))
            break;
        file_job *j = &l->files[l->order[k]];
        if (!o) {
            j->rc = EF_CLI_EXIT_INTERNAL;
        } else {
            write_one(o, l->job, j);
        }
        if (j->rc != EF_CLI_EXIT_OK)
            atomic_store(&l->stop, 1);
    }
    free(o);
    return NULL;
}

/* Bigger work first (longest processing time first keeps the two lanes
 * even), by an estimate of each file's time in nanoseconds from what the
 * tiger at 640x480 took per byte (CPU time of the writing thread: format,
 * SHA-256 and the copy into the file): hex 1.3 ns a byte, the binary stream
 * 2.2 ns a byte (its records are built twice: for the CRC, then to go out),
 * the VCD 1.4 ns a byte with about 23 bytes a cycle and 26 a transaction,
 * the PNG frame 45 ns a pixel (zlib's deflate).  Only the order matters:
 * a lane takes the next file when it is free. */
static uint64_t cost(const ef_cli_vec_job *job, const ef_vec_file *f)
{
    const uint64_t txns = ef_vec_collect_total(job->collect, job->ifaces);
    if (strcmp(f->format, "vcd") == 0)
        return (23u * job->info->cycles + 26u * txns) * 14u / 10u;
    if (strcmp(f->format, "bin") == 0) {
        uint64_t bytes = 0;
        for (int i = 0; i < EF_IF_COUNT; i++)
            if (job->ifaces >> i & 1u)
                bytes += (uint64_t)ef_vec_collect_count(job->collect, i) * (10u + (ef_iface_get(i)->width + 7u) / 8u);
        return bytes * 22u / 10u;
    }
    if (f->iface >= 0)
        return (uint64_t)ef_vec_collect_count(job->collect, f->iface) * (ef_vec_hex_digits(f->iface) + 1u) * 13u / 10u;
    return 45u * f->count; /* the frame: count is its pixels */
}

static void run_lanes(lanes *l)
{
    sigset_t block, old;
    pthread_t t;
    int started;

    for (size_t k = 0; k < l->n; k++) { /* insertion sort by cost, stable */
        size_t i = k;
        while (i > 0 && cost(l->job, l->files[l->order[i - 1]].f) < cost(l->job, l->files[k].f)) {
            l->order[i] = l->order[i - 1];
            i--;
        }
        l->order[i] = k;
    }
    atomic_init(&l->next, 0);
    atomic_init(&l->stop, 0);
    /* The other lane starts with SIGINT, SIGTERM and SIGHUP blocked, so the
     * atomic writer's handler (which removes the temporaries) only ever runs
     * in this thread, never beside this thread's own changes to its slots. */
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    started = pthread_create(&t, NULL, lane, l) == 0; /* POSIX threads: ThreadSanitizer follows them */
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    lane(l); /* without a second thread: every file here */
    if (started)
        pthread_join(t, NULL);
}

int ef_cli_vec_write(const ef_cli_vec_job *job, size_t *nfiles)
{
    ef_vec_file f[MAX_FILES];
    file_job *files = calloc(MAX_FILES, sizeof *files);
    lanes *l = calloc(1, sizeof *l);
    ef_vec_out *o = malloc(sizeof *o);
    char path[4096];
    size_t n = plan(job, f), opened = 0;
    int rc = EF_CLI_EXIT_OK;

    *nfiles = 0;
    if (!files || !l || !o) {
        ef_cli_error("out of memory");
        rc = EF_CLI_EXIT_INTERNAL;
        goto out;
    }
    if (ef_util_make_dirs(job->dir) != 0) {
        ef_cli_error("cannot create directory '%s': %s", job->dir, strerror(errno));
        rc = EF_CLI_EXIT_OUTPUT;
        goto out;
    }
    if (join(path, sizeof path, job->dir, MANIFEST) != 0) {
        rc = EF_CLI_EXIT_OUTPUT;
        goto out;
    }
    if (unlink(path) != 0 && errno != ENOENT) {
        ef_cli_error("cannot remove '%s': %s", path, strerror(errno));
        rc = EF_CLI_EXIT_OUTPUT;
        goto out;
    }
    /* Every file's temporary first, in the manifest's order (the files
     * appear under their names only when all are written). */
    for (size_t k = 0; k < n; k++, opened++) {
        file_job *j = &files[k];
        const ef_image *img = job->img;
        j->f = &f[k];
        if (f[k].iface >= 0)
            f[k].count = ef_vec_collect_count(job->collect, f[k].iface);
        else if (strcmp(f[k].role, "all") == 0)
            f[k].count = ef_vec_collect_total(job->collect, job->ifaces);
        else /* the frame: its pixels */
            f[k].count = (uint64_t)img->width * (uint64_t)img->height;
        if (join(j->path, sizeof j->path, job->dir, f[k].name) != 0) {
            rc = EF_CLI_EXIT_OUTPUT;
            goto out;
        }
        if (ef_util_atomic_open(&j->af, j->path) != 0) {
            ef_cli_error("cannot write '%s': %s", j->path, strerror(errno));
            rc = EF_CLI_EXIT_OUTPUT;
            goto out;
        }
    }
    l->job = job;
    l->files = files;
    l->n = n;
    run_lanes(l);
    /* The first failure in the manifest's order is the one reported;
     * nothing of this run is renamed into place then. */
    for (size_t k = 0; k < n && rc == EF_CLI_EXIT_OK; k++) {
        file_job *j = &files[k];
        rc = j->rc;
        if (rc == EF_CLI_EXIT_OUTPUT)
            ef_cli_error("cannot write '%s': %s", j->path, strerror(j->err));
        else if (rc != EF_CLI_EXIT_OK && j->why[0])
            ef_cli_error("cannot encode the frame: %s", j->why);
        else if (rc != EF_CLI_EXIT_OK)
            ef_cli_error("out of memory writing '%s'", j->path);
    }
    for (size_t k = 0; k < n && rc == EF_CLI_EXIT_OK; k++) {
        if (ef_util_atomic_commit(&files[k].af) != 0) {
            ef_cli_error("cannot write '%s': %s", files[k].path, strerror(errno));
            rc = EF_CLI_EXIT_OUTPUT;
        } else {
            (*nfiles)++;
        }
    }
#ifdef EF_NO_MANIFEST
    const int manifest = 0; /* a build without Nettle (WITH_MANIFEST=0) hashes nothing */
#else
    const int manifest = !job->dump;
#endif
    if (rc == EF_CLI_EXIT_OK && manifest) {
        ef_vec_file m;
        body b;
        memset(&m, 0, sizeof m);
        strcpy(m.name, MANIFEST);
        m.format = "json";
        m.iface = -1;
        m.role = "manifest";
        b.job = job;
        b.files = f;
        b.nfiles = n;
        if ((rc = write_manifest(o, &m, &b)) == EF_CLI_EXIT_OK)
            (*nfiles)++;
    }
out:
    for (size_t k = 0; k < opened; k++)
        ef_util_atomic_abort(&files[k].af); /* those not committed: removed */
    free(files);
    free(l);
    free(o);
    return rc;
}
