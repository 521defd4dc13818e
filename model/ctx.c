/*
 * ctx.c - the model context: parameters, the derived per-N constants, and the
 * buffers whose size depends only on the canvas width (the scanline buffer)
 * and height (the edge-table slots).  Edge storage grows with the scene.
 */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

const char *ef_version(void) { return EF_VERSION_STRING; }

const char *ef_strerror(ef_status s)
{
    switch (s) {
    case EF_OK: return "success";
    case EF_ERR_NOMEM: return "out of memory";
    case EF_ERR_ARG: return "invalid argument";
    case EF_ERR_LIMIT: return "limit exceeded";
    case EF_ERR_SYNTAX: return "syntax error";
    case EF_ERR_RANGE: return "number out of range";
    case EF_ERR_IO: return "input/output error";
    case EF_ERR_UNSUPPORTED: return "unsupported feature";
    }
    return "unknown error";
}

ef_status ef_ctx_create(ef_ctx **out, int32_t width, int32_t height, int samples)
{
    *out = NULL;
    if (width < 1 || height < 1 || width > EF_MAX_CANVAS || height > EF_MAX_CANVAS || !ef_samples_valid(samples))
        return EF_ERR_ARG;
    ef_ctx *ctx = calloc(1, sizeof *ctx);
    if (!ctx)
        return EF_ERR_NOMEM;
    ctx->width = width;
    ctx->height = height;
    ctx->samples = samples;
    ctx->h = EF_DEV_ONE / samples;
    ctx->c = ctx->h / 2;
#if defined(EF_MUTATION) && EF_MUTATION == 3
    ctx->c = 0; /* test builds only: samples shifted half a sub-pixel (tests/mutants.sh) */
#endif
    const uint8_t *k = ef_pattern(samples);
    for (int s = 0; s < samples; s++) {
        ctx->off[s] = EF_DEV_ONE - ctx->h * k[s] - ctx->c; /* spec 6.1: 1 <= off <= 255 */
        ctx->mask_pairs[2 * s] = (int16_t)s;
        ctx->mask_pairs[2 * s + 1] = (int16_t)ctx->off[s];
    }

    size_t cells = (size_t)width + 1;
    ctx->slot = malloc((size_t)height * sizeof *ctx->slot);
    ctx->eo_cells = calloc(cells, sizeof *ctx->eo_cells);
    ctx->nz_cells = calloc(cells * (size_t)(samples / 8), sizeof *ctx->nz_cells);
    ctx->occ = calloc((cells + 63) / 64 + 1, sizeof *ctx->occ); /* + 1: MASK rows OR zeros past the last cell */
    ctx->crowd = calloc(cells + 1, sizeof *ctx->crowd);
    if (!ctx->slot || !ctx->eo_cells || !ctx->nz_cells || !ctx->occ || !ctx->crowd) {
        ef_ctx_destroy(ctx);
        return EF_ERR_NOMEM;
    }
    for (int32_t j = 0; j < height; j++)
        ctx->slot[j] = (ef_slot){ -1, 0 };
    *out = ctx;
    return EF_OK;
}

void ef_ctx_destroy(ef_ctx *ctx)
{
    if (!ctx)
        return;
    free(ctx->edges);
    free(ctx->aet);
    free(ctx->aet_saved);
    free(ctx->slot);
    free(ctx->eo_cells);
    free(ctx->nz_cells);
    free(ctx->occ);
    free(ctx->crowd);
    free(ctx->trace);
    ef_filt_free(ctx->filt);
    free(ctx);
}

int32_t ef_ctx_width(const ef_ctx *ctx) { return ctx->width; }
int32_t ef_ctx_height(const ef_ctx *ctx) { return ctx->height; }
int ef_ctx_samples(const ef_ctx *ctx) { return ctx->samples; }
void ef_ctx_diag(const ef_ctx *ctx, ef_diag *out) { *out = ctx->diag; }
