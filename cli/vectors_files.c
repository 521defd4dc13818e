/*
 * vectors_files.c - writes the files of `edgeflag vectors` (docs/vectors.md
 * section 1) into DIR.  Each file goes through the atomic writer (whole or
 * absent; it holds one temporary at a time, so the files are written one
 * after another) and through an ef_vec_out that counts and hashes the bytes
 * on their way, so the manifest describes exactly what was written without
 * reading anything back.  manifest.json comes last and, with --force, the
 * old one is removed first: a directory without a manifest is incomplete,
 * and an interrupted run never leaves an old manifest beside new files.
 * A --dump run writes no manifest (it is not a set of expected vectors), nor
 * does a build without the manifest's SHA-256 (WITH_MANIFEST=0).
 */
#include "vectors_files.h"

#include "atomic_file.h"
#include "cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#define MANIFEST "manifest.json"
#define MAX_FILES (EF_IF_COUNT + 4)

/* The frame in the best format this build can write. */
static ef_cli_format frame_format(void)
{
    return ef_cli_format_available(EF_CLI_FMT_PNG) ? EF_CLI_FMT_PNG : EF_CLI_FMT_PAM;
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
    snprintf(f[n].name, sizeof f[n].name, "frame%s.%s", tag, frame_format() == EF_CLI_FMT_PNG ? "png" : "pam");
    f[n].format = frame_format() == EF_CLI_FMT_PNG ? "png" : "pam";
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
        return -1;                       /* absent (or unreachable): creating it will tell */
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

/* What goes into one file. */
typedef struct body {
    const ef_cli_vec_job *job;
    const ef_vec_file *files;    /* for the manifest */
    size_t nfiles;
    const unsigned char *bytes;  /* for the frame: encoded in memory */
    size_t len;
} body;

/* 0, or -1 when out of memory. */
static int fill(ef_vec_out *o, const ef_vec_file *f, const body *b)
{
    const ef_cli_vec_job *job = b->job;
    const ef_vec_format *fm = ef_vec_format_named(f->format);
    if (fm)
        return fm->write(o, job->info, job->collect, f->iface);
#ifndef EF_NO_MANIFEST
    else if (strcmp(f->name, MANIFEST) == 0)
        return ef_vec_manifest_write(o, job->info, job->collect, b->files, b->nfiles);
#endif
    else
        ef_vec_out_write(o, b->bytes, b->len);
    return 0;
}

/* Writes f atomically and records its size and hash in it. */
static int write_file(ef_vec_out *o, ef_vec_file *f, const body *b)
{
    char path[4096];
    ef_cli_atomic af;
    uint8_t digest[32];

    if (join(path, sizeof path, b->job->dir, f->name) != 0)
        return EF_CLI_EXIT_OUTPUT;
    if (ef_cli_atomic_open(&af, path) != 0) {
        ef_cli_error("cannot write '%s': %s", path, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    /* A second thread hashes and writes while this one formats. */
    ef_vec_out_init(o, af.fp, EF_VEC_OUT_SHA | EF_VEC_OUT_THREAD);
    if (fill(o, f, b) != 0) {
        (void)ef_vec_out_finish(o, digest);     /* ends the thread */
        ef_cli_atomic_abort(&af);
        ef_cli_error("out of memory writing '%s'", path);
        return EF_CLI_EXIT_INTERNAL;
    }
    if (ef_vec_out_finish(o, digest) != 0) {
        int e = errno;
        ef_cli_atomic_abort(&af);
        ef_cli_error("cannot write '%s': %s", path, strerror(e));
        return EF_CLI_EXIT_OUTPUT;
    }
    if (ef_cli_atomic_commit(&af) != 0) {
        ef_cli_error("cannot write '%s': %s", path, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    f->bytes = o->bytes;
    ef_vec_sha256_hex(digest, f->sha256);
    return EF_CLI_EXIT_OK;
}

/* The frame image encoded into memory, so that it can be hashed on its way
 * to the file like every other file. */
static int encode_frame(const ef_image *img, unsigned char **buf, size_t *len)
{
    char err[256];
    char *p = NULL;
    size_t n = 0;
    FILE *ms = open_memstream(&p, &n);
    int rc;
    if (!ms) {
        ef_cli_error("out of memory encoding the frame");
        return EF_CLI_EXIT_INTERNAL;
    }
    rc = ef_cli_write_image(ms, frame_format(), img, err, sizeof err);
    if (fclose(ms) != 0 || rc != 0) {
        free(p);
        ef_cli_error("cannot encode the frame: %s", rc ? err : strerror(errno));
        return EF_CLI_EXIT_INTERNAL;
    }
    *buf = (unsigned char *)p;
    *len = n;
    return EF_CLI_EXIT_OK;
}

int ef_cli_vec_write(const ef_cli_vec_job *job, size_t *nfiles)
{
    ef_vec_file f[MAX_FILES];
    body b;
    ef_vec_out *o = malloc(sizeof *o);
    char path[4096];
    size_t n = plan(job, f);
    int rc = EF_CLI_EXIT_OK;

    memset(&b, 0, sizeof b);
    b.job = job;
    *nfiles = 0;
    if (!o) {
        ef_cli_error("out of memory");
        return EF_CLI_EXIT_INTERNAL;
    }
    if (ef_cli_make_dirs(job->dir) != 0) {
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
    for (size_t k = 0; k < n && rc == EF_CLI_EXIT_OK; k++) {
        const ef_image *img = job->img;
        unsigned char *frame = NULL;
        if (f[k].iface >= 0)
            f[k].count = ef_vec_collect_count(job->collect, f[k].iface);
        else if (strcmp(f[k].role, "all") == 0)
            f[k].count = ef_vec_collect_total(job->collect, job->ifaces);
        else                                       /* the frame: its pixels */
            f[k].count = (uint64_t)img->width * (uint64_t)img->height;
        if (strcmp(f[k].role, "expected") == 0 && f[k].iface < 0 &&
            (rc = encode_frame(img, &frame, &b.len)) != EF_CLI_EXIT_OK)
            break;
        b.bytes = frame;
        rc = write_file(o, &f[k], &b);
        free(frame);
        b.bytes = NULL;
        if (rc == EF_CLI_EXIT_OK)
            (*nfiles)++;
    }
#ifdef EF_NO_MANIFEST
    const int manifest = 0;     /* a build without Nettle (WITH_MANIFEST=0) hashes nothing */
#else
    const int manifest = !job->dump;
#endif
    if (rc == EF_CLI_EXIT_OK && manifest) {
        ef_vec_file m;
        memset(&m, 0, sizeof m);
        strcpy(m.name, MANIFEST);
        m.format = "json";
        m.iface = -1;
        m.role = "manifest";
        b.files = f;
        b.nfiles = n;
        if ((rc = write_file(o, &m, &b)) == EF_CLI_EXIT_OK)
            (*nfiles)++;
    }
out:
    free(o);
    return rc;
}
