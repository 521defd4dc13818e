/*
 * edge_table.c - the edge table (one slot per pixel row, unsorted singly
 * linked lists threaded through the edge records) and the active edge table
 * (an unsorted array of edge indices).  No sorting anywhere: the XOR and
 * winding buffers make plot order irrelevant to the result (spec 6).
 *
 * Order (observable only through the winding-overflow diagnostic): the AET
 * holds edges in slot order and, within a slot, in input order.  Edge setup
 * inserts a polygon's edges in reverse input order and insertion prepends
 * (ef_et_insert, internal.h), so each list already reads in input order.
 * The plotter activates a row's list after the edges already active and
 * retires finished edges in the same pass (plotter.c).
 */
#include "internal.h"

void ef_et_reset(ef_ctx *ctx) { ctx->naet = 0; }

int32_t ef_et_take(ef_ctx *ctx, int32_t row, uint32_t *n)
{
    ef_slot *S = &ctx->slot[row];
    const int32_t head = S->head;
    *n = S->n;
    S->head = -1;
    S->n = 0;
    return head;
}
