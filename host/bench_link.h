/*
 * bench_link.h - `edgeflag-host bench`: throughput of the link and of the
 * host's own protocol code (docs/board.md section 8).
 */
#ifndef EF_BENCH_LINK_H
#define EF_BENCH_LINK_H

#include <stdint.h>

#include "transport.h"

typedef struct ef_bench_result {
    const char *name; /* sink, source, loopback, latency */
    int ran;          /* 0: not applicable to this transport (note says why) */
    uint64_t bytes;   /* payload bytes moved (loopback: each way) */
    double seconds;
    double mb_s;                  /* payload MB/s (10^6 bytes) */
    double usec_median, usec_min; /* latency only */
    char note[120];
} ef_bench_result;

/* Runs the four measurements; bytes is the payload per throughput test.
 * Returns 0, or a negative EF_HOST_E* when the link failed. */
int ef_bench_link(const ef_transport_ops *ops, ef_link *l, uint64_t bytes, int timeout_ms, ef_bench_result out[4]);

#endif /* EF_BENCH_LINK_H */
