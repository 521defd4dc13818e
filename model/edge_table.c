/*
 * edge_table.c - the edge table (one slot per pixel row, unsorted singly
 * linked lists threaded through the edge records) and the active edge table
 * (an unsorted array of edge indices).  No sorting anywhere: the XOR and
 * winding buffers make plot order irrelevant to the result (spec 6).
 */
#include "internal.h"

void ef_et_reset(ef_ctx *ctx)
{
    ctx->naet = 0;
}

void ef_et_insert(ef_ctx *ctx, uint32_t edge_index, int32_t slot)
{
    /* Prepend; the activation below restores insertion order so the AET order
     * (which only the overflow diagnostic can observe) is that of the input. */
    ctx->edges[edge_index].next = ctx->slot[slot];
    ctx->slot[slot] = (int32_t)edge_index;
}

void ef_et_activate(ef_ctx *ctx, int32_t row)
{
    int32_t i = ctx->slot[row];
    if (i < 0)
        return;
    ctx->slot[row] = -1;
    /* The list is newest-first: append it reversed. */
    uint32_t n = 0;
    for (int32_t j = i; j >= 0; j = ctx->edges[j].next)
        n++;
    uint32_t at = ctx->naet + n;
    for (int32_t j = i; j >= 0; j = ctx->edges[j].next)
        ctx->aet[--at] = j;
    ctx->naet += n;
}

void ef_aet_retire(ef_ctx *ctx)
{
    uint32_t w = 0;
    for (uint32_t k = 0; k < ctx->naet; k++) {
        int32_t i = ctx->aet[k];
        if (ctx->edges[i].r <= ctx->edges[i].r1)
            ctx->aet[w++] = i;                         /* keeps AET order stable */
    }
    ctx->naet = w;
}
