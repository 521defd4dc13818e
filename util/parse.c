/*
 * parse.c - exact decimal numbers of a command line (parse.h).
 */
#include "parse.h"

#include <string.h>

/* Digits s[0..n) only, value in [min, max]. */
static int parse_digits(const char *s, size_t n, int32_t min, int32_t max, int32_t *out)
{
    int64_t v = 0;
    if (n == 0)
        return 0;
    for (size_t i = 0; i < n; i++) {
        if (s[i] < '0' || s[i] > '9')
            return 0;
        v = v * 10 + (s[i] - '0');
        if (v > max)
            return 0; /* also keeps v far from int64 overflow */
    }
    if (v < min)
        return 0;
    *out = (int32_t)v;
    return 1;
}

int ef_util_parse_int(const char *s, int32_t min, int32_t max, int32_t *out)
{
    return s ? parse_digits(s, strlen(s), min, max, out) : 0;
}

int ef_util_parse_size(const char *s, int32_t max, int32_t *w, int32_t *h)
{
    const char *x;
    int32_t tw, th;

    if (!s || (x = strchr(s, 'x')) == NULL)
        return 0;
    /* Both sides parsed alike (leading zeros included), stored only if both are good. */
    if (!parse_digits(s, (size_t)(x - s), 1, max, &tw) || !parse_digits(x + 1, strlen(x + 1), 1, max, &th))
        return 0;
    *w = tw;
    *h = th;
    return 1;
}
