/*
 * host_link.h - the host's side of the board protocol (docs/board.md): a
 * command stream from a vectors.bin goes out as START, DATA... END frames
 * through any transport, the board's RESULT records come back into a
 * results folder as vectors.actual.bin, with retransmission, a credit window
 * and resume after an interruption.
 */
#ifndef EF_HOST_LINK_H
#define EF_HOST_LINK_H

#include <stdint.h>
#include <stdio.h>

#include "ef_board.h"
#include "transport.h"

/* Exit codes of edgeflag-host (docs/board.md section 7). */
enum {
    EF_HX_OK = 0,
    EF_HX_MISMATCH = 1, /* verify: the results differ from the vectors */
    EF_HX_USAGE = 2,
    EF_HX_INPUT = 3,   /* the vectors file is unreadable or malformed */
    EF_HX_OUTPUT = 4,  /* the results folder cannot be written */
    EF_HX_LOST = 5,    /* link lost (unplugged, not answering): --resume continues */
    EF_HX_BOARD = 6,   /* the board failed, broke the protocol, was reset, or is another protocol */
    EF_HX_NOBOARD = 7, /* no board, or several and no selector */
    EF_HX_ACCESS = 8,  /* permission denied */
    EF_HX_INTERNAL = 70
};

/* The exit code for a transport's EF_HOST_E* error (the one mapping, for
 * opening a link and for a run). */
int ef_host_exit_code(int err);

/* The board's identify answer, decoded. */
typedef struct ef_host_ident {
    unsigned protocol, window;
    uint32_t caps, iface_mask, samples_mask, width_max, height_max, edges_max;
    char serial[17];
} ef_host_ident;
/* 0, or EF_HOST_EPROTO when the bytes are not an edgeflag board's. */
int ef_host_ident_parse(const uint8_t raw[EF_PROTO_IDENTIFY_LEN], ef_host_ident *id);
void ef_host_ident_describe(const ef_host_ident *id, char *buf, size_t size);

typedef struct ef_host_stream_opts {
    const char *vectors; /* vectors.bin (must record cmd) */
    const char *results; /* folder for vectors.actual.bin and the resume state */
    uint32_t iface_mask; /* interfaces to ask back (0: pix) */
    int resume;
    unsigned frame_cmds; /* commands per DATA frame (0: the largest that fits) */
    int timeout_ms;      /* no progress for this long: retransmit; 4 times: give up */
    int progress;        /* draw a progress bar on stderr */
    int quiet;
    uint32_t digest;       /* digest mode (docs/board.md 4.5): transactions per window; 0: full records */
    int digest_optional;   /* 1: full records when the board has no digest mode (auto's choice) */
    unsigned digest_fetch; /* differing windows fetched per interface (0: 16) */
} ef_host_stream_opts;

typedef struct ef_host_stream_report {
    uint64_t cmds, frames_sent, retransmits, naks, timeouts, result_frames, records, result_bytes;
    uint64_t resumed_from;                                  /* first frame sent by this run (0 when not resumed) */
    uint32_t digest;                                        /* the window of a digest run, 0 for full records */
    uint64_t digest_windows, digest_differ, digest_fetched; /* windows compared, differing, fetched */
    double seconds;
    int samples;
    int32_t width, height;
} ef_host_stream_report;

/* Streams opts->vectors to the board behind (ops, link).  Returns an EF_HX_*
 * code and prints what went wrong on stderr ("edgeflag-host: ..."). */
int ef_host_stream(const ef_transport_ops *ops, ef_link *link, const ef_host_stream_opts *opts,
                   ef_host_stream_report *rep);

#endif /* EF_HOST_LINK_H */
