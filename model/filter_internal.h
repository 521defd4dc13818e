/*
 * filter_internal.h - the state of the section 3.5 options (docs/spec.md
 * section 10) shared by the fast path (filter.c) and the timing model
 * (trace_filter.c).  Not installed.
 */
#ifndef EF_FILTER_INTERNAL_H
#define EF_FILTER_INTERNAL_H

#include "ef_filter.h"
#include "internal.h"

#define EF_SUBPIXEL_SHIFT 85 /* Q16.8: 85/256 px, the nearest to a third of a pixel */

struct ef_filt {
    int filter, subpixel, nch, e;
    int pos_of_colour[3];       /* R, G, B -> channel context (0 left, 1 centre, 2 right) */
    ef_ctx *ch[3];              /* (W+e) x (H+e) mask canvases */
    int32_t tx[3], ty;          /* geometry translation of each channel, Q16.8 */
    uint32_t *line[3][2];       /* W+e masks each: [saved, current] */
    int32_t lo[3][2], hi[3][2]; /* non-zero masks lie in [lo, hi] */
    int32_t *iv[3][2];          /* the spans written into each line, (first, last) pairs */
    uint32_t niv[3][2];
    int32_t *merge; /* 6 lines' spans, merged: the columns an output row visits */
    int cur;        /* which of the two lines is current */
    uint32_t *tab;  /* tent: [a*2+b][byte g][256] weight sums */
    uint32_t *sum;  /* W x 3 sums of the output row */
    ef_point *pts;  /* the translated polygon */
    size_t pts_cap;
};

/* The channel context whose samples are not shifted sideways (spec 10.1):
 * its edge records are the ones the timing model's SETUP produces. */
static inline int ef_filt_centre(const struct ef_filt *f) { return f->nch == 3 ? 1 : 0; }

#endif /* EF_FILTER_INTERNAL_H */
