/*
 * atomic_file.c - temporary file + fsync + rename, with cleanup on
 * SIGINT/SIGTERM (see atomic_file.h for the why).
 */
#include "atomic_file.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

/* State shared with the signal handler: only static buffers and
 * sig_atomic_t flags, which is all an async-signal-safe handler may touch.
 * One slot per temporary open at once (vectors writes its files two at a
 * time, each into its own temporary); every slot is changed only by the
 * thread that opens and commits (atomic_file.h), with the signals blocked. */
static char tmp_path[EF_UTIL_ATOMIC_MAX][4352];
static volatile sig_atomic_t tmp_active[EF_UTIL_ATOMIC_MAX];
static unsigned char tmp_used[EF_UTIL_ATOMIC_MAX]; /* from open to commit or abort */
static int tmp_count;                              /* slots in use; the handlers are installed while > 0 */

static struct sigaction old_int, old_term, old_hup, old_xfsz;
static int handlers_installed;

static void on_signal(int sig)
{
    struct sigaction dfl;

    for (int k = 0; k < EF_UTIL_ATOMIC_MAX; k++)
        if (tmp_active[k])
            unlink(tmp_path[k]); /* async-signal-safe */
    /* Die of the same signal with the default action, so the parent sees
     * the usual "killed by SIGINT" status (a shell prints nothing, make
     * stops).  The signal stays blocked until we return, then fires. */
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    raise(sig);
}

static void block_signals(sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    sigprocmask(SIG_BLOCK, &set, old);
}

static void restore_signals(const sigset_t *old) { sigprocmask(SIG_SETMASK, old, NULL); }

/* A signal the user asked to ignore (nohup, `trap '' INT`) stays ignored. */
static void install_one(int sig, struct sigaction *old)
{
    struct sigaction sa;
    sigaction(sig, NULL, old);
    if (old->sa_handler == SIG_IGN)
        return;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    sigaddset(&sa.sa_mask, SIGHUP);
    sigaction(sig, &sa, NULL);
}

static void install_handlers(void)
{
    if (handlers_installed)
        return;
    struct sigaction ign;
    install_one(SIGINT, &old_int);
    install_one(SIGTERM, &old_term);
    install_one(SIGHUP, &old_hup);
    /* Past the file size limit (ulimit -f) the kernel sends SIGXFSZ, whose
     * default action kills the process with the temporary still on disk.
     * Ignored, the write fails with EFBIG instead and the ordinary error
     * path removes the temporary and exits 4. */
    memset(&ign, 0, sizeof ign);
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    sigaction(SIGXFSZ, &ign, &old_xfsz);
    handlers_installed = 1;
}

static void uninstall_handlers(void)
{
    if (!handlers_installed)
        return;
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    sigaction(SIGHUP, &old_hup, NULL);
    sigaction(SIGXFSZ, &old_xfsz, NULL);
    handlers_installed = 0;
}

/* Unlinks slot's temporary if it is still there and frees the slot (the
 * handlers go with the last one); errno is preserved for callers that are
 * about to report the original failure. */
static void remove_temp(int slot)
{
    sigset_t old;
    int saved = errno;

    block_signals(&old);
    if (tmp_active[slot]) {
        unlink(tmp_path[slot]);
        tmp_active[slot] = 0;
    }
    tmp_used[slot] = 0;
    if (--tmp_count == 0)
        uninstall_handlers();
    restore_signals(&old);
    errno = saved;
}

/* "dir/name" -> "dir/.name.XXXXXX" (mkstemp's template). */
static int make_template(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    size_t dirlen = slash ? (size_t)(slash - path) + 1 : 0;
    const char *base = path + dirlen;
    size_t baselen = strlen(base);

    if (baselen == 0) {
        errno = EISDIR; /* "dir/" names no file */
        return -1;
    }
    if (dirlen + 1 + baselen + 7 + 1 > size) {
        errno = ENAMETOOLONG;
        return -1;
    }
    memcpy(out, path, dirlen);
    out[dirlen] = '.';
    memcpy(out + dirlen + 1, base, baselen);
    memcpy(out + dirlen + 1 + baselen, ".XXXXXX", 8);
    return 0;
}

int ef_util_atomic_open(ef_util_atomic *af, const char *path)
{
    sigset_t old;
    int fd, saved, slot = 0;
    char tmpl[sizeof tmp_path[0]], *tp;
    mode_t mask;

    af->fp = NULL;
    af->path = path;
    af->slot = -1;
    af->synced = 0;
    while (slot < EF_UTIL_ATOMIC_MAX && tmp_used[slot])
        slot++;
    if (slot == EF_UTIL_ATOMIC_MAX) {
        errno = EBUSY; /* the handler knows EF_UTIL_ATOMIC_MAX paths */
        return -1;
    }
    /* Built in a buffer of its own, then copied whole into the slot (GCC's
     * bounds warnings do not follow make_template's check into a row of the
     * 2-D array at every -O level and target). */
    if (make_template(path, tmpl, sizeof tmpl) != 0)
        return -1;
    tp = tmp_path[slot];
    block_signals(&old);
    memcpy(tp, tmpl, sizeof tmpl);
    install_handlers();
    fd = mkstemp(tp);
    if (fd < 0) {
        saved = errno;
        if (tmp_count == 0)
            uninstall_handlers();
        restore_signals(&old);
        errno = saved;
        return -1;
    }
    af->slot = slot;
    tmp_used[slot] = 1;
    tmp_count++;
    tmp_active[slot] = 1;
    restore_signals(&old);

    /* mkstemp creates 0600; a finished image gets the permissions any new
     * file would (0666 minus the umask), as if written in place. */
    mask = umask(0);
    umask(mask);
    if (fchmod(fd, (mode_t)(0666 & ~mask)) != 0 || (af->fp = fdopen(fd, "wb")) == NULL) {
        saved = errno;
        close(fd);
        remove_temp(af->slot);
        af->slot = -1;
        errno = saved;
        return -1;
    }
    return 0;
}

int ef_util_atomic_sync(ef_util_atomic *af)
{
    if (!af->fp) {
        errno = EBADF;
        return -1;
    }
    if (fflush(af->fp) != 0)
        return -1;
    if (ferror(af->fp)) {
        errno = EIO;
        return -1;
    }
    /* Durable before visible: after a crash the destination holds either
     * the old file or the whole new one, never a hole. */
    if (fsync(fileno(af->fp)) != 0)
        return -1;
    af->synced = 1;
    return 0;
}

int ef_util_atomic_commit(ef_util_atomic *af)
{
    sigset_t old;
    int err = 0;

    if (!af->fp || af->slot < 0) {
        errno = EBADF;
        return -1;
    }
    if (!af->synced && ef_util_atomic_sync(af) != 0)
        err = errno;
    if (fclose(af->fp) != 0 && !err)
        err = errno;
    af->fp = NULL;
    if (!err) {
        block_signals(&old);
        if (rename(tmp_path[af->slot], af->path) != 0)
            err = errno;
        else
            tmp_active[af->slot] = 0;
        restore_signals(&old);
    }
    remove_temp(af->slot); /* after a rename: only frees the slot (and the handlers) */
    af->slot = -1;
    if (err) {
        errno = err;
        return -1;
    }

    /* Make the rename itself durable; best effort, the data already is. */
    {
        char dir[sizeof tmp_path[0]];
        const char *slash = strrchr(af->path, '/');
        size_t len = slash ? (size_t)(slash - af->path) : 0;
        int dfd;
        if (len == 0 && slash)
            len = 1; /* "/name": the root directory */
        if (len < sizeof dir) {
            if (len)
                memcpy(dir, af->path, len);
            else
                dir[len++] = '.';
            dir[len] = '\0';
            dfd = open(dir, O_RDONLY);
            if (dfd >= 0) {
                fsync(dfd);
                close(dfd);
            }
        }
    }
    return 0;
}

void ef_util_atomic_abort(ef_util_atomic *af)
{
    if (af->fp) {
        fclose(af->fp);
        af->fp = NULL;
    }
    if (af->slot >= 0)
        remove_temp(af->slot);
    af->slot = -1;
}

/* mkdir -p (atomic_file.h). */
int ef_util_make_dirs(const char *dir)
{
    char *p = strdup(dir);
    struct stat st;
    size_t n;
    int rc = -1;
    if (!p)
        return -1;
    n = strlen(p);
    while (n > 1 && p[n - 1] == '/')
        p[--n] = '\0';
    for (char *q = p + 1;; q++) {
        if (*q == '/' || *q == '\0') {
            char save = *q;
            *q = '\0';
            if (mkdir(p, 0777) != 0 && errno != EEXIST)
                goto out;
            *q = save;
            if (save == '\0')
                break;
        }
    }
    if (stat(p, &st) != 0)
        goto out;
    if (!S_ISDIR(st.st_mode)) {
        errno = ENOTDIR;
        goto out;
    }
    rc = 0;
out:
    free(p);
    return rc;
}
