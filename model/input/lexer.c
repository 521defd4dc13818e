/*
 * lexer.c - separators and numbers of the SVG attribute grammars.
 *
 * Place in the pipeline: the first step from text to numbers.  Path data,
 * points lists, viewBox, transform lists and lengths all share SVG 1.1's
 * tokens (8.3.9): white space is space, tab, CR and LF (the XML set), a
 * comma-wsp is wsp+ ','? wsp* or ',' wsp*, and a number is the grammar of
 * ef_parse_decimal_q32, which rounds the exact decimal value once to Q31.32.
 * No locale, no strtod: the same text gives the same bits everywhere.
 */
#include "input_internal.h"

size_t ef_in_lex_wsp(ef_in_lex *l)
{
    size_t p0 = l->pos;
    while (l->pos < l->len && ef_in_is_wsp(l->s[l->pos]))
        l->pos++;
    return l->pos - p0;
}

int ef_in_lex_sep(ef_in_lex *l)
{
    int r = ef_in_lex_wsp(l) ? 1 : 0;
    if (l->pos < l->len && l->s[l->pos] == ',') {
        l->pos++;
        ef_in_lex_wsp(l);
        r = 2;
    }
    return r;
}

bool ef_in_lex_at_number(const ef_in_lex *l)
{
    char c = ef_in_lex_peek(l);
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

ef_status ef_in_lex_number(ef_in_lex *l, ef_q32 *out, ef_error *err)
{
    size_t used = 0;
    ef_num_status st = ef_parse_decimal_q32(l->s + l->pos, l->len - l->pos, out, &used);
    if (st == EF_NUM_SYNTAX || used == 0)
        return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "number expected");
    if (st == EF_NUM_RANGE)
        return ef_error_set(err, EF_ERR_RANGE, NULL, 0, 0, "number out of range (the magnitude must be below 2^31)");
    l->pos += used;
    return EF_OK;
}
