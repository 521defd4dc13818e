/*
 * vectors_files.h - the file side of `edgeflag vectors` (vectors_files.c):
 * which files a run writes, the refusal of existing ones, and writing them
 * two at a time through the atomic writer (each into its own temporary,
 * renamed into place when all are written), manifest.json last.
 */
#ifndef EF_CLI_VECTORS_FILES_H
#define EF_CLI_VECTORS_FILES_H

#include <stddef.h>
#include <stdint.h>

#include "edgeflag.h"
#include "ef_vec.h"

typedef struct ef_cli_vec_job {
    const char *dir;
    unsigned formats; /* EF_VEC_F_* bits (ef_vec.h) */
    uint32_t ifaces;  /* interfaces recorded */
    int force;
    int dump;                /* IFACE.actual.hex, vectors.actual.*, frame.actual.*, no manifest */
    const ef_vec_info *info; /* for ef_cli_vec_write */
    const ef_vec_collect *collect;
    const ef_image *img;
} ef_cli_vec_job;

/* Before anything is written: DIR must be a directory or absent, and
 * without --force no file of this run may exist in it.  -1 if so, else the
 * exit code (the problem has been reported). */
int ef_cli_vec_check_dir(const ef_cli_vec_job *job);

/* Creates DIR and writes every file, manifest.json last; *nfiles counts
 * them, the manifest included.  EF_CLI_EXIT_OK or the exit code. */
int ef_cli_vec_write(const ef_cli_vec_job *job, size_t *nfiles);

#endif /* EF_CLI_VECTORS_FILES_H */
