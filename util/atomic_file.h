/*
 * atomic_file.h - write a file so that it appears whole or not at all.
 *
 * The data goes to a temporary ".NAME.XXXXXX" in the destination's own
 * directory (rename is only atomic within one file system), is fsync'ed and
 * then renamed onto the destination.  On any error, and on SIGINT/SIGTERM
 * while it is open, the temporary is unlinked: a failed or interrupted run
 * never leaves a truncated image where a previous good one was, nor a stray
 * temporary.
 *
 * At most EF_UTIL_ATOMIC_MAX atomic files at a time per process: the signal
 * handler can only use async-signal-safe state, so each temporary's path
 * lives in a static buffer of its own.  Open, commit and abort them from one
 * thread (the one that may take SIGINT/SIGTERM/SIGHUP); other threads may
 * write into af->fp, with those signals blocked (`vectors` writes two files
 * at a time this way).
 */
#ifndef EF_UTIL_ATOMIC_FILE_H
#define EF_UTIL_ATOMIC_FILE_H

#include <stdio.h>

#define EF_UTIL_ATOMIC_MAX 16

typedef struct ef_util_atomic {
    FILE *fp;         /* write here between open and commit/abort */
    const char *path; /* the destination */
    int slot;         /* the handler's slot of its temporary; -1 none */
    int synced;       /* ef_util_atomic_sync done: commit need not flush again */
} ef_util_atomic;

/* Creates the temporary next to `path`.  0 on success; -1 with errno set
 * (nothing is left on disk). */
int ef_util_atomic_open(ef_util_atomic *af, const char *path);

/* Flushes and fsyncs the temporary (no rename): the slow part of a commit,
 * which, unlike open, commit and abort, any thread may do (vectors' writing
 * threads do it for their files, so that their fsyncs overlap).  0, or -1
 * with errno set; the temporary stays for commit or abort. */
int ef_util_atomic_sync(ef_util_atomic *af);

/* Flushes and fsyncs (unless ef_util_atomic_sync did), closes and renames onto
 * the destination.  0 on success; -1 with errno set, and the temporary
 * removed.  Either way af->fp is gone. */
int ef_util_atomic_commit(ef_util_atomic *af);

/* Closes and removes the temporary.  Safe after a failed open. */
void ef_util_atomic_abort(ef_util_atomic *af);

/* mkdir -p: creates dir and its missing parents.  An existing directory is
 * fine (another shard of a farm run may have made it a moment ago).  0, or -1
 * with errno set (ENOTDIR when dir exists and is not a directory). */
int ef_util_make_dirs(const char *dir);

#endif /* EF_UTIL_ATOMIC_FILE_H */
