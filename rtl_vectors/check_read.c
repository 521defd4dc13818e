/*
 * check_read.c - reading ACTUAL beside EXPECTED: the two files of a pair are
 * parsed at the same time, the dump in a second thread, since reading is
 * most of what `edgeflag check` does and the two reads share nothing.  The
 * result is the serial one's: the caller takes the dump only when it was
 * read as it would have been after EXPECTED (the same interface wanted),
 * reports EXPECTED's error first, and reads again, serially, otherwise.
 * When no thread can be started the read happens here and now.
 */
#include "check_internal.h"

#include <string.h>

static int run(void *arg)
{
    chk_async_read *ar = arg;
    ar->st = ef_vec_read_path(ar->path, NULL, ar->want, ar->hint, &ar->dump, &ar->err);
    return 0;
}

void chk_read_start(chk_async_read *ar, const char *path, int want, int hint)
{
    memset(ar, 0, sizeof *ar);
    ar->path = path;
    ar->want = want;
    ar->hint = hint;
    /* The CRC-32's tables are built once under call_once, which is enough;
     * building them before the thread exists also keeps race detectors
     * (Helgrind does not model call_once) from flagging the first use. */
    (void)ef_vec_read_crc32(0, NULL, 0);
    ar->started = thrd_create(&ar->thr, run, ar) == thrd_success;
    if (!ar->started)
        run(ar);
}

void chk_read_wait(chk_async_read *ar)
{
    if (ar->started)
        thrd_join(ar->thr, NULL);
    ar->started = 0;
}

void chk_read_drop(chk_async_read *ar)
{
    chk_read_wait(ar);
    if (ar->st == EF_OK)
        ef_vec_dump_destroy(&ar->dump);
}
