/*
 * check_files.c - the verifier's two report files written atomically
 * (check_files.h).
 */
#include "check_files.h"

#include "atomic_file.h"

#include <errno.h>
#include <string.h>

/* The JUnit XML, atomically; 0, or -1 with errno. */
int ef_util_check_junit(const ef_check_result *res, const char *path)
{
    ef_util_atomic af;
    if (ef_util_atomic_open(&af, path) != 0)
        return -1;
    if (ef_check_junit(res, af.fp) != 0) {
        int saved = errno;
        ef_util_atomic_abort(&af);
        errno = saved;
        return -1;
    }
    return ef_util_atomic_commit(&af);
}

/* The diff image, atomically; 0, or -1 with a message in err and errno. */
int ef_util_check_diff_image(const ef_check_result *res, const char *path, ef_util_format fmt, char *err,
                             size_t errsize)
{
    ef_image img;
    ef_util_atomic af;
    int rc = -1;
    if (ef_check_diff_image(res, &img, err, errsize) != 0)
        return -1;
    errno = 0;
    if (ef_util_atomic_open(&af, path) != 0) {
        snprintf(err, errsize, "%s", strerror(errno));
    } else if (ef_util_write_image(af.fp, fmt, &img, err, errsize) != 0) {
        int saved = errno;
        ef_util_atomic_abort(&af);
        errno = saved;
    } else if (ef_util_atomic_commit(&af) != 0) {
        snprintf(err, errsize, "%s", strerror(errno));
    } else {
        rc = 0;
    }
    ef_image_destroy(&img);
    return rc;
}
