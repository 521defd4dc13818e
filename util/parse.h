/*
 * parse.h - exact decimal numbers of a command line, shared by `edgeflag`
 * (cli/) and `edgeflag-host` (host/).
 *
 * Values are parsed by hand rather than with strtol: strtol accepts leading
 * blanks, a sign, "0x" and trailing junk unless every caller checks carefully,
 * and a model used as a golden reference should refuse "--samples 8x" rather
 * than quietly render something else.
 */
#ifndef EF_UTIL_PARSE_H
#define EF_UTIL_PARSE_H

#include <stdint.h>

/* Exact decimal integer: one or more ASCII digits and nothing else (no sign,
 * no spaces, no base prefix), value in [min, max].  Returns 1 and stores it,
 * or 0.  Overflow is impossible: digits stop counting once past max. */
int ef_util_parse_int(const char *s, int32_t min, int32_t max, int32_t *out);

/* "WxH" (lower-case x), each in [1, max].  Returns 1 or 0. */
int ef_util_parse_size(const char *s, int32_t max, int32_t *w, int32_t *h);

#endif /* EF_UTIL_PARSE_H */
