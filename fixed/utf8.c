/*
 * utf8.c - the one UTF-8 validator (ef_fixed.h): the readers' error messages,
 * the manifest's JSON strings, its reader and the verifier's JUnit escape
 * text with it, so all four agree on what well-formed means.
 */
#include "fixed_internal.h"

size_t ef_utf8_len(const unsigned char *s, size_t n)
{
    if (n == 0)
        return 0;
    const unsigned c = s[0];
    if (c < 0x80u)
        return 1;
    /* Lead bytes: C2..DF (C0, C1 only start overlong forms), E0..EF, F0..F4
     * (F5 and up start values past U+10FFFF). */
    const size_t len = c >= 0xC2u && c <= 0xDFu ? 2 : c >= 0xE0u && c <= 0xEFu ? 3 : c >= 0xF0u && c <= 0xF4u ? 4 : 0;
    if (len == 0 || len > n)
        return 0;
    for (size_t k = 1; k < len; k++)
        if ((s[k] & 0xC0u) != 0x80u)
            return 0;
    /* The second byte's range where the lead alone does not decide: E0 A0..BF
     * (shortest form), ED 80..9F (no surrogates D800..DFFF), F0 90..BF
     * (shortest form), F4 80..8F (at most U+10FFFF). */
    if ((c == 0xE0u && s[1] < 0xA0u) || (c == 0xEDu && s[1] > 0x9Fu) || (c == 0xF0u && s[1] < 0x90u) ||
        (c == 0xF4u && s[1] > 0x8Fu))
        return 0;
    return len;
}
