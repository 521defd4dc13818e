/*
 * check_dir.c - `edgeflag check` on two directories (docs/vectors.md section
 * 7): which expected files there are (the manifest's, or without one every
 * *.expected.hex and vectors.bin, with a warning) and which file of ACTUAL
 * each is compared with: STEM.expected.hex with STEM.actual.hex, STEM.bin
 * with STEM.actual.bin, never an expected file (a dump folder that holds
 * copies of the expected vectors must not pass).  A manifest's names were
 * checked to be plain file names by its reader, so nothing outside EXPECTED
 * is ever opened.
 */
#include "check_internal.h"

#include <dirent.h>
#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

/* The format of an expected file `name` that check reads (by its extension,
 * ef_vec_formats), and its stem: STEM.expected.hex (a per-interface format)
 * or vectors.bin (one file for all).  NULL for any other file. */
static const ef_vec_format *expected_format(const char *name, size_t *stem)
{
    const ef_vec_format *fm = ef_vec_format_of_path(name);
    size_t n = strlen(name);
    if (!fm || !fm->reader)
        return NULL;
    if (fm->per_iface) {
        size_t k = strlen(".expected") + strlen(fm->ext);
        if (n < k || strncmp(name + n - k, ".expected", strlen(".expected")) != 0)
            return NULL;
        *stem = n - k;
    } else {
        *stem = n - strlen(fm->ext);
    }
    return fm;
}

/* The dump in ACTUAL of EXPECTED's file `name`: STEM.actual.hex for
 * STEM.expected.hex, STEM.actual.bin for STEM.bin.  NULL if there is none. */
static char *counterpart(const char *adir, const char *name)
{
    size_t stem = strlen(name);
    const ef_vec_format *fm = expected_format(name, &stem);
    if (!fm) /* a manifest's expected file of another name: NAME.actual.EXT */
        fm = ef_vec_format_of_path(name);
    if (!fm)
        return NULL;
    const char *ext = fm->ext;
    char *nm = malloc(stem + strlen(".actual") + strlen(ext) + 1);
    if (!nm)
        return NULL;
    memcpy(nm, name, stem);
    strcpy(nm + stem, ".actual");
    strcat(nm + stem, ext);
    char *p = chk_join(adir, nm);
    free(nm);
    if (p && !chk_is_file(p)) {
        free(p);
        p = NULL;
    }
    return p;
}

/* Without a manifest, the files compared: every STEM.expected.EXT of a
 * per-interface format and vectors.EXT of a one-file format that check reads. */
static int scanned(const char *name)
{
    size_t stem;
    const ef_vec_format *fm = expected_format(name, &stem);
    return fm && (fm->per_iface || (stem == strlen("vectors") && strncmp(name, "vectors", stem) == 0));
}

static int cmp_names(const void *x, const void *y) { return strcmp(*(char *const *)x, *(char *const *)y); }

/* Without a manifest: EXPECTED's *.expected.hex and vectors.bin, sorted. */
static int scan_dir(const char *dir, char ***names, size_t *n)
{
    DIR *d = opendir(dir);
    struct dirent *de;
    size_t cap = 0;
    *names = NULL;
    *n = 0;
    if (!d)
        return -1;
    while ((de = readdir(d)) != NULL) {
        if (!scanned(de->d_name))
            continue;
        char **nn = *n < cap ? *names : realloc(*names, (cap = cap ? cap * 2 : 16) * sizeof *nn);
        char *nm = nn ? malloc(strlen(de->d_name) + 1) : NULL;
        if (nn)
            *names = nn;
        if (!nm) { /* out of memory: no partial list (a missed file would pass silently) */
            closedir(d);
            while (*n > 0)
                free((*names)[--*n]);
            free(*names);
            *names = NULL;
            errno = ENOMEM;
            return -1;
        }
        strcpy(nm, de->d_name);
        (*names)[(*n)++] = nm;
    }
    closedir(d);
    if (*n)
        qsort(*names, *n, sizeof **names, cmp_names);
    return 0;
}

/* One expected file of the directory; *compared counts the pairs run. */
static int dir_entry(chk_run *r, const char *name, const ef_vec_manifest_file *mf, const char *mname, int *compared)
{
    const char *E = r->a->expected, *A = r->a->actual;
    char *ep = chk_join(E, name), *ap = counterpart(A, name);
    int rc = 0;
    if (!ep) {
        free(ap);
        return EF_CHECK_NOMEM;
    }
    if (mf && !chk_is_file(ep)) {
        char buf[1024];
        snprintf(buf, sizeof buf, "%s: files[%zu].name: the manifest names '%s', which is not in %s", mname, mf->index,
                 name, E);
        rc = chk_input_error(r, EF_ERR_SYNTAX, buf, ep, "-");
    } else if (ap) {
        rc = chk_pair(r, ep, ap, mf, mname);
        ++*compared;
    } else {
        /* Read anyway: the interfaces it holds are required (a missing dump
         * fails at the end), and the pix are the picture of --diff-image. */
        rc = chk_pair(r, ep, NULL, mf, mname);
    }
    free(ep);
    free(ap);
    return rc;
}

int chk_dirs(chk_run *r)
{
    const char *E = r->a->expected;
    char *mpath = chk_join(E, "manifest.json");
    ef_vec_manifest m;
    ef_vec_read_error err;
    int rc = 0, compared = 0;

    memset(&m, 0, sizeof m);
    if (!mpath)
        return EF_CHECK_NOMEM;
    if (chk_is_file(mpath)) {
        ef_status st = ef_vec_read_manifest_path(mpath, NULL, &m, &err);
        if (st != EF_OK) {
            rc = chk_read_error(r, st, &err, mpath, r->a->actual);
            free(mpath);
            return rc;
        }
        r->width = m.width;
        r->height = m.height;
        for (size_t k = 0; k < m.nfiles && rc == 0; k++) {
            const ef_vec_manifest_file *f = &m.files[k];
            /* The manifest's format names the table's row (else the extension does); a
             * per-interface file is compared when it is expected (not the stimulus). */
            const ef_vec_format *fm = f->format ? ef_vec_format_named(f->format) : ef_vec_format_of_path(f->name);
            size_t stem;
            int read = fm && fm->reader &&
                       (!fm->per_iface ||
                        (f->role ? strcmp(f->role, "expected") == 0 : expected_format(f->name, &stem) != NULL));
            if (read)
                rc = dir_entry(r, f->name, f, mpath, &compared);
        }
    } else {
        char **names;
        size_t n;
        chk_status(r,
                   "edgeflag: warning: %s has no manifest.json (an incomplete `edgeflag vectors` run?): "
                   "comparing its *.expected.hex and vectors.bin\n",
                   E);
        if (scan_dir(E, &names, &n) != 0) {
            char buf[1024];
            int saved = errno;
            snprintf(buf, sizeof buf, "%s: cannot read the directory: %s", E, strerror(saved));
            rc = chk_input_error(r, saved == ENOMEM ? EF_ERR_NOMEM : EF_ERR_IO, buf, E, r->a->actual);
        }
        for (size_t k = 0; k < n; k++) {
            if (rc == 0)
                rc = dir_entry(r, names[k], NULL, NULL, &compared);
            free(names[k]);
        }
        free(names);
    }
    if (rc == 0 && compared == 0) {
        char buf[1024], *pix = chk_join(r->a->actual, "pix.expected.hex");
        snprintf(buf, sizeof buf,
                 "%s: nothing to compare: no IFACE.actual.hex or vectors.actual.bin matching an "
                 "expected file of %s%s",
                 r->a->actual, E,
                 pix && chk_is_file(pix) ? " (it holds expected files: the DUT's dumps are named IFACE.actual.hex, "
                                           "and an expected file is never taken for one)"
                                         : "");
        free(pix);
        rc = chk_input_error(r, EF_ERR_SYNTAX, buf, E, r->a->actual);
    }
    ef_vec_manifest_destroy(&m);
    free(mpath);
    return rc;
}
