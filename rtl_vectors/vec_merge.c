/*
 * vec_merge.c - the interfaces' transactions in one global order for the
 * binary stream and the VCD: by cycle, ties by interface number (pipeline
 * order), then production order (docs/vectors.md section 4).  Each list is
 * already in cycle order, so a k-way merge of 7 cursors suffices; a linear
 * scan of 7 heads per step is cheaper than keeping a heap that small, and a
 * strict "<" on the cycle keeps the lowest interface first on a tie.
 */
#include "ef_vec.h"

#include <string.h>

void ef_vec_merge_init(ef_vec_merge *m, const ef_vec_collect *c, uint32_t mask)
{
    memset(m, 0, sizeof *m);
    m->c = c;
    m->mask = mask;
}

int ef_vec_merge_next(ef_vec_merge *m, ef_txn *out)
{
    int best = -1;
    uint64_t best_cycle = 0;

    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_vec_list *l = &m->c->list[i];
        uint64_t cyc;
        if (!(m->mask >> i & 1u) || m->pos[i] >= l->count)
            continue;
        cyc = l->rec[m->pos[i] * (1u + l->nw)];
        if (best < 0 || cyc < best_cycle) {
            best = i;
            best_cycle = cyc;
        }
    }
    if (best < 0)
        return 0;
    ef_vec_collect_get(m->c, best, m->pos[best]++, out);
    return 1;
}
