/*
 * check_files.h - the verifier's report files (rtl_vectors/ef_check.h), each
 * written atomically (atomic_file.h): what `edgeflag check` and
 * `edgeflag-host verify` both write for --junit and --diff-image.
 */
#ifndef EF_UTIL_CHECK_FILES_H
#define EF_UTIL_CHECK_FILES_H

#include <stddef.h>

#include "ef_check.h"
#include "image_write.h"

/* The JUnit XML of res at path; 0, or -1 with errno. */
int ef_util_check_junit(const ef_check_result *res, const char *path);

/* The diff image of res (it needs opts.keep_marks) at path in fmt; 0, or -1
 * with a message in err and errno (ENOMEM: out of memory). */
int ef_util_check_diff_image(const ef_check_result *res, const char *path, ef_util_format fmt, char *err,
                             size_t errsize);

#endif /* EF_UTIL_CHECK_FILES_H */
