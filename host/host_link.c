/*
 * host_link.c - edgeflag-host's side of the board protocol (docs/board.md
 * sections 3 and 4), the same for every transport.
 *
 * Sending: frame 0 is START, frames 1..n carry the commands (frame_cmds of
 * them each, the last one fewer), frame n+1 is END.  At most `window` frames
 * are unacknowledged; a NAK rewinds to the frame it names, and a timeout with
 * no progress rewinds to the oldest unacknowledged frame (go-back-N), so every
 * frame reaches the board exactly once however many copies are sent.
 *
 * Receiving: RESULT frames are appended to RESULTS/.results.part strictly in
 * sequence; a gap or damage asks the board to resend (ACKR with RESEND).  The
 * state needed to resume (how many result frames and bytes are safely on
 * disk, which vectors file, how the stream was cut) is written to
 * RESULTS/.resume before each ACKR, so a result the board forgets has always
 * reached the disk first.  At DONE the counts and CRCs both sides kept are
 * compared and vectors.actual.bin is written whole (header from the records'
 * own counts and CRC), or not at all.
 */
#include "host_link.h"

#include <errno.h>
#include <stdarg.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "atomic_file.h"
#include "ef_frame.h"
#include "ef_trace.h"
#include "ef_vec.h"
#include "ef_vec_read.h"

#define MAX_TRIES 4  /* timeouts in a row before giving up */
#define ACKR_EVERY 4 /* result frames between two ACKRs */

typedef struct hl {
    const ef_transport_ops *ops;
    ef_link *l;
    const ef_host_stream_opts *o;
    ef_host_stream_report *rep;

    /* what goes out */
    uint8_t *cmds; /* packed 13-byte commands */
    uint64_t ncmds;
    uint32_t per_frame, last_seq; /* last_seq = END */
    uint32_t base, next, window;
    uint32_t input_crc;
    uint8_t *fbuf;
    uint32_t start_payload_mask;
    int samples;

    /* what comes back */
    uint8_t *rbuf;
    size_t rlen, rcap;
    uint32_t res_next;
    int resend_asked, unacked, ackr_due;
    FILE *part;
    uint64_t part_bytes, records, counts[EF_IF_COUNT];
    uint32_t results_crc;
    int done;
    uint8_t done_payload[EF_PROTO_DONE_LEN];

    char dir[4096], part_path[4200], state_path[4200];
    uint32_t vec_crc; /* identifies the vectors file for --resume */
    uint64_t vec_size;
    ef_vec_info info;

    /* digest mode (docs/board.md 4.5) */
    uint32_t digest;     /* transactions per window; 0: full records */
    int phase;           /* PH_FULL, PH_DIGEST (digests come back) or PH_SELECT (chosen windows' records) */
    uint32_t *sel, nsel; /* PH_SELECT: interface << 24 | window, ascending */
    ef_vec_dump exp;     /* the expected transactions (digest mode and --resume) */
    int have_exp;
    char dig_path[4200]; /* RESULTS/.digests: the digest run's records */
    int digest_ok;       /* the board has digest mode and it was asked for */
} hl;

enum { PH_FULL = 0, PH_DIGEST = 1, PH_SELECT = 2 };

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

int ef_host_exit_code(int err)
{
    switch (err) {
    case EF_HOST_EINVAL: return EF_HX_USAGE;
    case EF_HOST_EUNSUPPORTED: return EF_HX_NOBOARD;
    case EF_HOST_ENODEV:
    case EF_HOST_ETIMEDOUT: return EF_HX_LOST;
    case EF_HOST_EACCESS: return EF_HX_ACCESS;
    case EF_HOST_ENOTFOUND:
    case EF_HOST_EAMBIGUOUS: return EF_HX_NOBOARD;
    case EF_HOST_ENOMEM: return EF_HX_INTERNAL;
    default: return EF_HX_BOARD;
    }
}

/* ------------------------------------------------------------- identify */
int ef_host_ident_parse(const uint8_t r[EF_PROTO_IDENTIFY_LEN], ef_host_ident *id)
{
    if (memcmp(r, EF_PROTO_MAGIC, 4) != 0)
        return EF_HOST_EPROTO;
    id->protocol = r[4] | (unsigned)r[5] << 8;
    id->window = r[6] | (unsigned)r[7] << 8;
    id->caps = ef_get32(r + 8);
    id->iface_mask = ef_get32(r + 12);
    id->samples_mask = ef_get32(r + 16);
    id->width_max = ef_get32(r + 20);
    id->height_max = ef_get32(r + 24);
    id->edges_max = ef_get32(r + 28);
    memcpy(id->serial, r + 32, 16);
    id->serial[16] = 0;
    for (char *p = id->serial; *p; p++)
        if (*p < 0x20 || *p > 0x7e)
            *p = '?';
    return id->protocol == EF_PROTO_PROTOCOL ? 0 : EF_HOST_EPROTO;
}

void ef_host_ident_describe(const ef_host_ident *id, char *buf, size_t size)
{
    char s[32] = "";
    size_t k = 0;
    for (unsigned n = 8; n <= 32; n *= 2)
        if (id->samples_mask >> ef_proto_samples_bit(n) & 1u)
            k += (size_t)snprintf(s + k, sizeof s - k, "%s%u", k ? "/" : "", n);
    snprintf(buf, size,
             "serial %s, protocol %u, samples %s, canvas up to %" PRIu32 "x%" PRIu32 ", %" PRIu32 " edges, window %u",
             id->serial[0] ? id->serial : "(none)", id->protocol, k ? s : "none", id->width_max, id->height_max,
             id->edges_max, id->window);
}

/* --------------------------------------------------------------- output */
__attribute__((format(printf, 3, 4))) static int fail(hl *h, int code, const char *fmt, ...)
{
    va_list ap;
    (void)h;
    fputs("edgeflag-host: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return code;
}

/* A transport's failure: what failed, the generic text, and the
 * transport's own words when it has them. */
static int link_fail(hl *h, const char *what, int err)
{
    const char *d = h->ops->detail ? h->ops->detail(h->l) : NULL;
    fprintf(stderr, "edgeflag-host: %s failed: %s%s%s\n", what, ef_host_strerror(err), d && *d ? ": " : "", d ? d : "");
    return ef_host_exit_code(err);
}

static int lost(hl *h, int err)
{
    const char *d = h->ops->detail ? h->ops->detail(h->l) : NULL;
    if (d && *d)
        fprintf(stderr, "edgeflag-host: %s\n", d);
    /* --resume needs the resume state; lost before the run's first state was
     * written (at identify or reset), there is nothing to resume */
    if (h->state_path[0] == '\0' || access(h->state_path, F_OK) != 0) {
        fprintf(stderr, "edgeflag-host: %s before the run started; nothing to resume: run the same command again\n",
                err == EF_HOST_ENODEV ? "the board went away (unplugged?)" : "the board stopped answering");
        return EF_HX_LOST;
    }
    fprintf(stderr,
            "edgeflag-host: %s after %" PRIu32 " of %" PRIu32 " frames acknowledged and %" PRIu32
            " result frames kept in %s; run the same command with --resume to continue\n",
            err == EF_HOST_ENODEV ? "the board went away (unplugged?)" : "the board stopped answering", h->base,
            h->last_seq + 1, h->res_next, h->dir);
    return EF_HX_LOST;
}

/* The resume state, one "key value" per line.  Written to a temporary and
 * renamed, so it is always whole. */
static int save_state(hl *h)
{
    char tmp[4300];
    snprintf(tmp, sizeof tmp, "%s.tmp", h->state_path);
    FILE *f = fopen(tmp, "w");
    if (!f)
        return -1;
    fprintf(f,
            "edgeflag-host resume 1\nvectors_size %" PRIu64 "\nvectors_crc %08" PRIx32 "\nper_frame %" PRIu32
            "\nmask %" PRIu32 "\nres_next %" PRIu32 "\npart_bytes %" PRIu64 "\nrecords %" PRIu64
            "\nresults_crc %08" PRIx32 "\ncounts",
            h->vec_size, h->vec_crc, h->per_frame, h->start_payload_mask, h->res_next, h->part_bytes, h->records,
            h->results_crc);
    for (int i = 0; i < EF_IF_COUNT; i++)
        fprintf(f, " %" PRIu64, h->counts[i]);
    fprintf(f, "\ndigest %" PRIu32 " phase %d nsel %" PRIu32, h->digest, h->phase, h->nsel);
    for (uint32_t k = 0; k < h->nsel; k++)
        fprintf(f, " %" PRIu32, h->sel[k]);
    fputc('\n', f);
    const int bad = ferror(f) | (fclose(f) != 0);
    if (bad || rename(tmp, h->state_path) != 0) {
        unlink(tmp);
        return -1;
    }
    return 0;
}

static int load_state(hl *h)
{
    FILE *f = fopen(h->state_path, "r");
    if (!f)
        return -1;
    unsigned v = 0;
    uint32_t crc = 0, rcrc = 0;
    uint64_t size = 0;
    int ok = fscanf(f,
                    "edgeflag-host resume %u vectors_size %" SCNu64 " vectors_crc %" SCNx32 " per_frame %" SCNu32
                    " mask %" SCNu32 " res_next %" SCNu32 " part_bytes %" SCNu64 " records %" SCNu64
                    " results_crc %" SCNx32 " counts",
                    &v, &size, &crc, &h->per_frame, &h->start_payload_mask, &h->res_next, &h->part_bytes, &h->records,
                    &rcrc) == 9;
    for (int i = 0; ok && i < EF_IF_COUNT; i++)
        ok = fscanf(f, "%" SCNu64, &h->counts[i]) == 1;
    /* a digest or select run's own fields (absent: full records) */
    h->digest = 0, h->phase = PH_FULL, h->nsel = 0;
    if (ok && fscanf(f, " digest %" SCNu32 " phase %d nsel %" SCNu32, &h->digest, &h->phase, &h->nsel) == 3) {
        ok = h->phase >= PH_FULL && h->phase <= PH_SELECT && h->nsel <= EF_PROTO_SELECT_MAX &&
             (h->phase == PH_FULL) == (h->digest == 0);
        h->sel = ok ? malloc(4 * (size_t)h->nsel + 4) : NULL;
        ok = ok && h->sel;
        for (uint32_t k = 0; ok && k < h->nsel; k++)
            ok = fscanf(f, "%" SCNu32, &h->sel[k]) == 1;
    }
    fclose(f);
    if (!ok || v != 1 || size != h->vec_size || crc != h->vec_crc)
        return -2;
    h->results_crc = rcrc;
    return 0;
}

/* ---------------------------------------------------------------- frames */
static int put_frame(hl *h, uint32_t seq)
{
    size_t n;
    if (seq == 0) {
        uint8_t p[EF_PROTO_START_LEN];
        ef_put32(p, h->start_payload_mask);
        ef_put32(p + 4, (uint32_t)h->samples);
        ef_put32(p + 8, EF_MODE_DUT);
        ef_put32(p + 12, 0);
        ef_put64(p + 16, h->ncmds);
        if (h->phase == PH_FULL) {
            n = ef_frame_put(h->fbuf, EF_FT_START, 0, 0, p, sizeof p);
        } else { /* the digest's window, and a select run's windows */
            uint8_t *q = h->fbuf + EF_PROTO_HEADER;
            memcpy(q, p, sizeof p);
            ef_put32(q + 24, h->digest);
            uint32_t len = EF_PROTO_START_DIGEST_LEN;
            if (h->phase == PH_SELECT) {
                ef_put32(q + 28, h->nsel);
                for (uint32_t k = 0; k < h->nsel; k++)
                    ef_put32(q + 32 + 4 * k, h->sel[k]);
                len = 32 + 4 * h->nsel;
            }
            n = ef_frame_seal(h->fbuf, EF_FT_START, h->phase == PH_SELECT ? EF_START_SELECT : EF_START_DIGEST, 0, len);
        }
    } else if (seq == h->last_seq) {
        n = ef_frame_put(h->fbuf, EF_FT_END, 0, seq, NULL, 0);
    } else {
        const uint64_t first = (uint64_t)(seq - 1) * h->per_frame;
        const uint64_t k = h->ncmds - first < h->per_frame ? h->ncmds - first : h->per_frame;
        n = ef_frame_put(h->fbuf, EF_FT_DATA, 0, seq, h->cmds + first * EF_PROTO_CMD_BYTES,
                         (uint32_t)(k * EF_PROTO_CMD_BYTES));
    }
    h->rep->frames_sent++;
    return h->ops->write(h->l, h->fbuf, n, h->o->timeout_ms);
}

static int send_ackr(hl *h, int resend)
{
    if (h->part && fflush(h->part) != 0)
        return fail(h, EF_HX_OUTPUT, "cannot write the results: %s", strerror(errno));
    if (save_state(h) != 0)
        return fail(h, EF_HX_OUTPUT, "cannot write the resume state: %s", strerror(errno));
    uint8_t p[4], f[EF_PROTO_HEADER + 4 + EF_PROTO_TRAILER];
    ef_put32(p, h->res_next);
    const int r =
        h->ops->write(h->l, f, ef_frame_put(f, EF_FT_ACKR, resend ? EF_ACKR_RESEND : 0, 0, p, 4), h->o->timeout_ms);
    h->unacked = 0;
    if (resend)
        h->resend_asked = 1;
    return r < 0 ? -r + 1000 : 0; /* transport errors come back as 1000 + -err */
}

/* Checks the records of a RESULT payload and counts them. */
static int take_records(hl *h, const uint8_t *p, uint32_t n)
{
    uint32_t o = 0;
    while (h->phase == PH_DIGEST && o < n) { /* digests: the transactions they stand for */
        if (n - o < EF_PROTO_DIGEST_LEN || p[o] >= EF_IF_COUNT || !(h->start_payload_mask >> p[o] & 1u) ||
            p[o + 1] != EF_PROTO_DIGEST_MARK || ef_get32(p + o + 6) == 0 || ef_get32(p + o + 6) > h->digest)
            return -1;
        h->counts[p[o]] += ef_get32(p + o + 6);
        h->records += ef_get32(p + o + 6);
        o += EF_PROTO_DIGEST_LEN;
    }
    while (o < n) {
        if (n - o < 10 || p[o] >= EF_IF_COUNT || !(h->start_payload_mask >> p[o] & 1u) ||
            p[o + 1] != (ef_iface_get(p[o])->width + 7u) / 8u || n - o < 10u + p[o + 1]) {
            return -1;
        }
        h->counts[p[o]]++;
        h->records++;
        o += 10u + p[o + 1];
    }
    return 0;
}

static void describe_error(const ef_frame *f, char *buf, size_t size)
{
    const uint32_t code = f->len >= 4 ? ef_get32(f->payload) : 0;
    int n = f->len > 4 ? (int)(f->len - 4) : 0;
    snprintf(buf, size, "code %" PRIu32 ": %.*s", code, n, (const char *)f->payload + 4);
    for (char *c = buf; *c; c++)
        if (*c < 0x20 || *c > 0x7e)
            *c = '?';
}

/* One good frame from the board.  Returns 0, or an EF_HX_* code to stop. */
static int take(hl *h, const ef_frame *f, int *progress)
{
    char why[300];
    switch (f->type) {
    case EF_FT_ACK: {
        if (f->len < 12)
            return fail(h, EF_HX_BOARD, "the board sent a malformed ACK");
        const uint32_t next = ef_get32(f->payload), credits = ef_get32(f->payload + 4);
        if (next > h->last_seq + 1)
            return fail(h, EF_HX_BOARD, "the board acknowledged frames that were never sent");
        if (next > h->base) {
            h->base = next;
            *progress = 1;
        }
        if (h->next < h->base)
            h->next = h->base;
        if (credits && credits < h->window)
            h->window = credits;
        return 0;
    }
    case EF_FT_NAK: {
        if (f->len < 8)
            return fail(h, EF_HX_BOARD, "the board sent a malformed NAK");
        const uint32_t want = ef_get32(f->payload);
        h->rep->naks++;
        if (want < h->base)
            return fail(h, EF_HX_BOARD,
                        "the board asks again for frames it had acknowledged: it was reset or lost its state "
                        "during the run; run again without --resume");
        if (want < h->next) {
            h->rep->retransmits += h->next - want;
            h->next = want; /* go back */
        }
        return 0;
    }
    case EF_FT_RESULT:
    case EF_FT_DONE:
    case EF_FT_ERROR:
        if (f->seq < h->res_next) { /* a copy of one already kept: say so again, */
            h->ackr_due = 1;        /* or copies could fill the board's window */
            return 0;
        }
        if (f->seq > h->res_next) { /* one was lost: ask again, once */
            if (!h->resend_asked) {
                const int r = send_ackr(h, 1);
                if (r >= 1000)
                    return ef_host_exit_code(-(r - 1000)) == EF_HX_LOST ? lost(h, -(r - 1000)) : EF_HX_BOARD;
                if (r)
                    return r;
            }
            return 0;
        }
        h->resend_asked = 0;
        *progress = 1;
        if (f->type == EF_FT_ERROR) {
            describe_error(f, why, sizeof why);
            return fail(h, EF_HX_BOARD, "the board reports an error: %s", why);
        }
        if (f->type == EF_FT_DONE) {
            /* DONE is acknowledged only once the results are on disk (run's end):
             * a board keeps it until then, so a host killed in between gets it
             * again on --resume */
            if (f->len != EF_PROTO_DONE_LEN)
                return fail(h, EF_HX_BOARD, "the board sent a malformed DONE");
            memcpy(h->done_payload, f->payload, EF_PROTO_DONE_LEN);
            h->done = 1;
            return 0;
        }
        h->res_next++;
        h->unacked++;
        h->rep->result_frames++;
        if (take_records(h, f->payload, f->len) != 0) {
            snprintf(why, sizeof why,
                     "result frame %" PRIu32 " holds a record that is not a %s of an interface asked for", f->seq,
                     h->phase == PH_DIGEST ? "digest (docs/board.md 4.5)" : "vectors.bin record");
            return fail(h, EF_HX_BOARD, "%s", why);
        }
        if (fwrite(f->payload, 1, f->len, h->part) != f->len)
            return fail(h, EF_HX_OUTPUT, "cannot write the results: %s", strerror(errno));
        h->part_bytes += f->len;
        h->results_crc = ef_frame_crc32_combine(h->results_crc, f->payload_crc, f->len);
        return 0;
    default:
        snprintf(why, sizeof why, "the board sent a frame of unknown type 0x%02x", f->type);
        return fail(h, EF_HX_BOARD, "%s", why);
    }
}

/* Parses what arrived; returns 0 or an EF_HX_* code. */
static int take_bytes(hl *h, int *progress)
{
    size_t pos = 0;
    int code = 0;
    while (pos < h->rlen && !code) {
        ef_frame f;
        size_t used;
        const int r = ef_frame_parse(h->rbuf + pos, h->rlen - pos, &f, &used);
        if (r == EF_FRAME_MORE)
            break;
        if (r == EF_FRAME_BAD) { /* damaged on the way: resync, the timeout recovers */
            pos += ef_frame_resync(h->rbuf + pos, h->rlen - pos);
            continue;
        }
        code = take(h, &f, progress);
        pos += used;
    }
    memmove(h->rbuf, h->rbuf + pos, h->rlen - pos);
    h->rlen -= pos;
    return code;
}

static void draw_progress(hl *h, double t0, int final)
{
    static double last;
    const double t = now_s();
    if (!final && t - last < 0.2)
        return;
    last = t;
    const double frac = h->last_seq ? (double)h->base / (h->last_seq + 1) : 1.0;
    const double mb = (double)h->base * h->per_frame * EF_PROTO_CMD_BYTES / 1e6;
    const double el = t - t0, rate = el > 0 ? mb / el : 0, eta = frac > 0 ? el / frac - el : 0;
    char bar[31];
    int k = (int)(frac * 30);
    for (int i = 0; i < 30; i++)
        bar[i] = i < k ? '#' : '.';
    bar[30] = 0;
    fprintf(stderr, "\r[%s] %3d%% %8.1f MB/s  ETA %5.1f s  results %" PRIu64 " records%s", bar, (int)(frac * 100), rate,
            eta, h->records, final ? "\n" : "");
}

/* vectors.actual.bin made whole (or, after a failed write, left out). */
static int commit_results(hl *h, ef_util_atomic *af, int bad)
{
    if (bad)
        ef_util_atomic_abort(af);
    if (bad || ef_util_atomic_commit(af) != 0)
        return fail(h, EF_HX_OUTPUT, "cannot write vectors.actual.bin: %s", strerror(errno));
    return 0;
}

/* Writes RESULTS/vectors.actual.bin from the header and .results.part. */
static int write_results(hl *h)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/vectors.actual.bin", h->dir);
    ef_util_atomic af;
    if (ef_util_atomic_open(&af, path) != 0)
        return fail(h, EF_HX_OUTPUT, "cannot write vectors.actual.bin: %s", strerror(errno));
    uint8_t hd[EF_VEC_BIN_HEADER];
    ef_vec_info info = h->info;
    info.mask = h->start_payload_mask;
    ef_vec_bin_header_counts(hd, &info, h->counts, h->results_crc);
    int bad = fwrite(hd, 1, sizeof hd, af.fp) != sizeof hd;
    rewind(h->part);
    uint8_t buf[65536];
    size_t n;
    uint64_t left = h->part_bytes;
    while (!bad && left && (n = fread(buf, 1, left < sizeof buf ? left : sizeof buf, h->part)) > 0) {
        bad = fwrite(buf, 1, n, af.fp) != n;
        left -= n;
    }
    return commit_results(h, &af, bad || left);
}

static int check_done(hl *h)
{
    const uint8_t *d = h->done_payload;
    char why[200];
    if (ef_get64(d + 16) != h->ncmds || ef_get32(d + 24) != h->input_crc) {
        snprintf(why, sizeof why,
                 "the board took %" PRIu64 " commands with CRC %08" PRIx32 ", %" PRIu64 " with CRC %08" PRIx32
                 " were sent",
                 ef_get64(d + 16), ef_get32(d + 24), h->ncmds, h->input_crc);
        return fail(h, EF_HX_BOARD, "input differs: %s", why);
    }
    if (ef_get64(d) != h->records || ef_get64(d + 8) != h->part_bytes || ef_get32(d + 28) != h->results_crc) {
        snprintf(why, sizeof why,
                 "the board sent %" PRIu64 " records (%" PRIu64 " bytes, CRC %08" PRIx32 "), %" PRIu64 " (%" PRIu64
                 " bytes, CRC %08" PRIx32 ") arrived",
                 ef_get64(d), ef_get64(d + 8), ef_get32(d + 28), h->records, h->part_bytes, h->results_crc);
        return fail(h, EF_HX_BOARD, "results differ: %s", why);
    }
    return 0;
}

/* ---------------------------------------------------------- digest mode */
/* docs/board.md 4.5: the board returns a CRC-32 per window of `digest`
 * transactions of each interface; the host computes the same from the
 * expected vectors.  Windows that differ are fetched whole by a second run
 * (select); vectors.actual.bin is then rebuilt from the expected records of
 * the windows whose count and CRC-32 agree and the board's own records of the
 * fetched ones, in the global order of vectors.bin, so that `edgeflag check`
 * names the first mismatching transaction, cycle and field as with full
 * records. */
typedef struct dwin {
    uint32_t count, crc;
    uint8_t have, src; /* src: 0 not rebuilt (a cut), 1 expected records, 2 the board's fetched records */
} dwin;

typedef struct digests {
    dwin *w[EF_IF_COUNT];
    uint64_t nw[EF_IF_COUNT]; /* the board's windows per interface */
    uint8_t *fetched;         /* a select run's records (the .results.part) */
    const uint8_t **frec[EF_IF_COUNT];
    uint64_t nfrec[EF_IF_COUNT];
} digests;

static void digests_free(digests *g)
{
    for (int i = 0; i < EF_IF_COUNT; i++)
        free(g->w[i]), free(g->frec[i]);
    free(g->fetched);
}

/* Reads a whole small file into memory (*n bytes).  NULL on failure. */
static uint8_t *slurp(const char *path, uint64_t max, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    uint8_t *b = malloc(max + 1);
    *n = b ? fread(b, 1, max, f) : 0;
    const int bad = ferror(f);
    fclose(f);
    if (bad || *n != max) {
        free(b);
        return NULL;
    }
    return b;
}

/* The digest run's records, kept in .digests, by interface and window. */
static int load_digests(hl *h, digests *g)
{
    struct stat sb;
    size_t n;
    uint8_t *p = stat(h->dig_path, &sb) == 0 ? slurp(h->dig_path, (uint64_t)sb.st_size, &n) : NULL;
    if (!p)
        return fail(h, EF_HX_OUTPUT, "cannot read the digests %s: %s", h->dig_path, strerror(errno));
    int code = 0;
    for (size_t o = 0; o + EF_PROTO_DIGEST_LEN <= n && !code; o += EF_PROTO_DIGEST_LEN) {
        const unsigned i = p[o];
        const uint32_t w = ef_get32(p + o + 2);
        if (w >= n / EF_PROTO_DIGEST_LEN) { /* windows are numbered from 0 without a gap */
            code = fail(h, EF_HX_BOARD, "the board's digests of %s skip windows", ef_iface_get((int)i)->name);
            break;
        }
        if (w >= g->nw[i]) {
            const uint64_t cap = w + 1 > 2 * g->nw[i] ? (uint64_t)w + 1 : 2 * g->nw[i];
            dwin *t = realloc(g->w[i], cap * sizeof *t);
            if (!t) {
                code = fail(h, EF_HX_INTERNAL, "out of memory");
                break;
            }
            memset(t + g->nw[i], 0, (cap - g->nw[i]) * sizeof *t);
            g->w[i] = t, g->nw[i] = cap;
        }
        if (g->w[i][w].have)
            code = fail(h, EF_HX_BOARD, "the board sent the digest of %s's window %" PRIu32 " twice",
                        ef_iface_get((int)i)->name, w);
        g->w[i][w] = (dwin){ ef_get32(p + o + 6), ef_get32(p + o + 10), 1, 0 };
    }
    free(p);
    for (int i = 0; i < EF_IF_COUNT && !code; i++) {
        while (g->nw[i] && !g->w[i][g->nw[i] - 1].have)
            g->nw[i]--; /* the spare room grown above */
        for (uint64_t w = 0; w < g->nw[i] && !code; w++)
            if (!g->w[i][w].have || (w + 1 < g->nw[i] && g->w[i][w].count != h->digest))
                code = fail(h, EF_HX_BOARD, "the board's digests of %s are not whole windows of %" PRIu32,
                            ef_iface_get(i)->name, h->digest);
    }
    return code;
}

/* The expected transactions' count and CRC-32 in interface i's window w. */
static void expected_digest(const hl *h, int i, uint64_t w, uint32_t *count, uint32_t *crc)
{
    const ef_vec_seq *q = &h->exp.seq[i];
    const uint64_t first = w * h->digest, end = first + h->digest < q->n ? first + h->digest : q->n;
    *count = 0, *crc = 0;
    for (uint64_t k = first; k < end; k++) {
        ef_txn t;
        uint8_t r[EF_VEC_BIN_RECORD_MAX];
        ef_vec_dump_txn(&h->exp, i, (size_t)k, &t);
        *crc = ef_frame_crc32(*crc, r, ef_vec_bin_record(&t, r));
        ++*count;
    }
}

static uint64_t expected_windows(const hl *h, int i) { return (h->exp.seq[i].n + h->digest - 1) / h->digest; }

/* Compares the board's digests with the expected ones; marks each window's
 * source and, after the digest run, chooses the windows to fetch (h->sel). */
static int digest_compare(hl *h, digests *g, int choose)
{
    const unsigned fetch_max = h->o->digest_fetch ? h->o->digest_fetch : 16;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        if (!(h->start_payload_mask >> i & 1u))
            continue;
        const uint64_t we = expected_windows(h, i), nw = we > g->nw[i] ? we : g->nw[i];
        uint64_t differ = 0, first = 0, chosen = 0;
        for (uint64_t w = 0; w < nw; w++) {
            uint32_t c = 0, crc = 0;
            if (w < we)
                expected_digest(h, i, w, &c, &crc);
            dwin *d = w < g->nw[i] ? &g->w[i][w] : NULL;
            if (d && w < we && d->count == c && d->crc == crc) {
                d->src = 1;
                continue;
            }
            if (!differ++)
                first = w;
            if (choose && d && chosen < fetch_max && h->nsel < EF_PROTO_SELECT_MAX && w < 1u << 24) {
                h->sel[h->nsel++] = (uint32_t)i << 24 | (uint32_t)w;
                chosen++;
            }
        }
        h->rep->digest_windows += choose ? nw : 0;
        h->rep->digest_differ += choose ? differ : 0;
        h->rep->digest_fetched += chosen;
        if (!choose || h->o->quiet)
            continue;
        if (!differ)
            fprintf(stderr, "edgeflag-host: digest: %s: %" PRIu64 " windows of %" PRIu32 " transactions: all equal\n",
                    ef_iface_get(i)->name, nw, h->digest);
        else
            fprintf(stderr,
                    "edgeflag-host: digest: %s: %" PRIu64 " of %" PRIu64 " windows differ, the first at window %" PRIu64
                    " (transactions %" PRIu64 " on); fetching %" PRIu64 " of them whole\n",
                    ef_iface_get(i)->name, differ, nw, first, first * h->digest, chosen);
    }
    return 0;
}

/* A select run's records: each fetched window's, checked against its digest
 * (the board must give the same records twice). */
static int take_fetched(hl *h, digests *g)
{
    size_t n = 0;
    if (h->part_bytes && !(g->fetched = slurp(h->part_path, h->part_bytes, &n)))
        return fail(h, EF_HX_OUTPUT, "cannot read the fetched results: %s", strerror(errno));
    for (int pass = 0; pass < 2; pass++) { /* count, then point */
        memset(g->nfrec, 0, sizeof g->nfrec);
        for (size_t o = 0; o < n; o += 10u + g->fetched[o + 1]) {
            const int i = g->fetched[o];
            if (pass)
                g->frec[i][g->nfrec[i]] = g->fetched + o;
            g->nfrec[i]++;
        }
        for (int i = 0; !pass && i < EF_IF_COUNT; i++)
            if (!(g->frec[i] = malloc((g->nfrec[i] + 1) * sizeof *g->frec[i])))
                return fail(h, EF_HX_INTERNAL, "out of memory");
    }
    uint64_t pos[EF_IF_COUNT] = { 0 };
    for (uint32_t k = 0; k < h->nsel; k++) {
        const int i = (int)(h->sel[k] >> 24);
        const uint32_t w = h->sel[k] & 0xffffffu;
        dwin *d = w < g->nw[i] ? &g->w[i][w] : NULL;
        uint32_t crc = 0;
        for (uint32_t j = 0; d && j < d->count && pos[i] + j < g->nfrec[i]; j++) {
            const uint8_t *r = g->frec[i][pos[i] + j];
            crc = ef_frame_crc32(crc, r, 10u + r[1]);
        }
        if (!d || pos[i] + d->count > g->nfrec[i] || crc != d->crc)
            return fail(h, EF_HX_BOARD,
                        "%s's window %" PRIu32 " came back different from its digest: the board's results "
                        "changed between the digest run and the fetch run (not deterministic)",
                        ef_iface_get(i)->name, w);
        d->src = 2;
        pos[i] += d->count;
    }
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (pos[i] != g->nfrec[i])
            return fail(h, EF_HX_BOARD,
                        "the fetch run returned %" PRIu64 " records of %s, the windows asked for hold %" PRIu64,
                        g->nfrec[i], ef_iface_get(i)->name, pos[i]);
    return 0;
}

/* One interface's rebuilt transactions, window after window. */
typedef struct cursor {
    uint64_t w, nwin, k, kend, fpos;
    int fetched, have;
    uint8_t rec[EF_VEC_BIN_RECORD_MAX];
    size_t len;
} cursor;

static int cursor_next(const hl *h, const digests *g, int i, cursor *c)
{
    for (;;) {
        if (c->k < c->kend) {
            if (c->fetched) {
                const uint8_t *r = g->frec[i][c->k];
                c->len = 10u + r[1];
                memcpy(c->rec, r, c->len);
            } else {
                ef_txn t;
                ef_vec_dump_txn(&h->exp, i, (size_t)c->k, &t);
                c->len = ef_vec_bin_record(&t, c->rec);
            }
            c->k++;
            return c->have = 1;
        }
        if (c->w >= c->nwin)
            return c->have = 0;
        const dwin *d = &g->w[i][c->w];
        c->fetched = d->src == 2;
        if (c->fetched)
            c->k = c->fpos, c->fpos += d->count;
        else
            c->k = c->w * h->digest;
        c->kend = c->k + d->count;
        c->w++;
    }
}

/* vectors.actual.bin rebuilt (see above): the records in the global order of
 * vectors.bin (cycle, then interface), each interface up to its first window
 * that differs and was not fetched. */
static int write_rebuilt(hl *h)
{
    digests g;
    memset(&g, 0, sizeof g);
    int code = load_digests(h, &g);
    if (!code)
        code = digest_compare(h, &g, 0);
    if (!code && h->phase == PH_SELECT)
        code = take_fetched(h, &g);
    cursor c[EF_IF_COUNT];
    memset(c, 0, sizeof c);
    for (int i = 0; i < EF_IF_COUNT && !code; i++) {
        if (!(h->start_payload_mask >> i & 1u))
            continue;
        while (c[i].nwin < g.nw[i] && g.w[i][c[i].nwin].src)
            c[i].nwin++;
        if (c[i].nwin < g.nw[i] && !h->o->quiet)
            fprintf(stderr,
                    "edgeflag-host: digest: %s: window %" PRIu64 " differs and was not fetched (--digest-fetch): its "
                    "results stop at transaction %" PRIu64 ", and check counts the rest as missing\n",
                    ef_iface_get(i)->name, c[i].nwin, c[i].nwin * h->digest);
        cursor_next(h, &g, i, &c[i]);
    }
    char path[4200];
    snprintf(path, sizeof path, "%s/vectors.actual.bin", h->dir);
    ef_util_atomic af;
    if (!code && ef_util_atomic_open(&af, path) != 0)
        code = fail(h, EF_HX_OUTPUT, "cannot write vectors.actual.bin: %s", strerror(errno));
    if (code) {
        digests_free(&g);
        return code;
    }
    uint8_t hd[EF_VEC_BIN_HEADER] = { 0 };
    uint64_t counts[EF_IF_COUNT] = { 0 };
    uint32_t crc = 0;
    int bad = fwrite(hd, 1, sizeof hd, af.fp) != sizeof hd;
    for (;;) {
        int best = -1;
        for (int i = 0; i < EF_IF_COUNT; i++)
            if (c[i].have && (best < 0 || ef_get64(c[i].rec + 2) < ef_get64(c[best].rec + 2)))
                best = i;
        if (best < 0)
            break;
        bad |= fwrite(c[best].rec, 1, c[best].len, af.fp) != c[best].len;
        crc = ef_frame_crc32(crc, c[best].rec, c[best].len);
        counts[best]++;
        cursor_next(h, &g, best, &c[best]);
    }
    digests_free(&g);
    ef_vec_info info = h->info;
    info.mask = h->start_payload_mask;
    ef_vec_bin_header_counts(hd, &info, counts, crc);
    bad |= fseek(af.fp, 0, SEEK_SET) != 0 || fwrite(hd, 1, sizeof hd, af.fp) != sizeof hd;
    return commit_results(h, &af, bad);
}

/* After the digest run: the windows that differ, if any, to fetch. */
static int choose_windows(hl *h)
{
    digests g;
    memset(&g, 0, sizeof g);
    free(h->sel);
    h->nsel = 0;
    h->sel = malloc(4 * EF_PROTO_SELECT_MAX);
    int code = h->sel ? load_digests(h, &g) : fail(h, EF_HX_INTERNAL, "out of memory");
    if (!code)
        code = digest_compare(h, &g, 1);
    digests_free(&g);
    return code;
}

/* ------------------------------------------------------------ the stream */
static int load_vectors(hl *h)
{
    const char *path = h->o->vectors;
    struct stat sb;
    if (stat(path, &sb) != 0) {
        fprintf(stderr, "edgeflag-host: %s: %s\n", path, strerror(errno));
        return EF_HX_INPUT;
    }
    const size_t L = strlen(path);
    if (L < 4 || strcmp(path + L - 4, ".bin") != 0) {
        fprintf(stderr, "edgeflag-host: %s: not a binary vector stream (vectors.bin, docs/vectors.md section 4)\n",
                path);
        return EF_HX_INPUT;
    }
    ef_vec_dump d;
    ef_vec_read_error err;
    memset(&d, 0, sizeof d);
    if (ef_vec_read_path(path, NULL, -1, -1, &d, &err) != EF_OK) {
        char buf[900];
        ef_vec_read_error_format(&err, buf, sizeof buf);
        fprintf(stderr, "edgeflag-host: %s\n", buf);
        ef_vec_dump_destroy(&d);
        return err.status == EF_ERR_NOMEM ? EF_HX_INTERNAL : EF_HX_INPUT;
    }
    if (!(d.mask & 1u << EF_IF_CMD) || d.seq[EF_IF_CMD].n == 0) {
        fprintf(stderr,
                "edgeflag-host: %s: records no cmd transactions: nothing to send (write it with "
                "edgeflag vectors, whose default records every interface)\n",
                path);
        ef_vec_dump_destroy(&d);
        return EF_HX_INPUT;
    }
    const ef_vec_seq *s = &d.seq[EF_IF_CMD];
    h->ncmds = s->n;
    h->cmds = malloc(s->n * EF_PROTO_CMD_BYTES);
    if (!h->cmds) {
        ef_vec_dump_destroy(&d);
        return fail(h, EF_HX_INTERNAL, "out of memory");
    }
    for (size_t k = 0; k < s->n; k++) {
        uint8_t *c = h->cmds + k * EF_PROTO_CMD_BYTES;
        const uint64_t w0 = s->pay[k * s->nw], w1 = s->pay[k * s->nw + 1];
        for (int i = 0; i < 8; i++)
            c[i] = (uint8_t)(w0 >> (8 * i));
        for (int i = 0; i < 5; i++)
            c[8 + i] = (uint8_t)(w1 >> (8 * i));
    }
    h->input_crc = ef_frame_crc32(0, h->cmds, s->n * EF_PROTO_CMD_BYTES);
    h->vec_size = (uint64_t)sb.st_size;
    h->vec_crc = h->input_crc;
    memset(&h->info, 0, sizeof h->info);
    h->info.width = d.width;
    h->info.height = d.height;
    h->info.samples = d.samples;
    h->info.rule = d.rule == 0 ? EF_RULE_NONZERO : d.rule == 1 ? EF_RULE_EVENODD : -1;
    h->info.seed = d.seed;
    h->samples = d.samples;
    h->rep->samples = d.samples;
    h->rep->width = d.width;
    h->rep->height = d.height;
    if (h->o->digest || h->o->resume) /* the expected transactions, for their digests */
        h->exp = d, h->have_exp = 1;
    else
        ef_vec_dump_destroy(&d);
    return 0;
}

static int prepare_dir(hl *h)
{
    snprintf(h->dir, sizeof h->dir, "%s", h->o->results);
    if (ef_util_make_dirs(h->dir) != 0) {
        fprintf(stderr, "edgeflag-host: %s: cannot create the results folder: %s\n", h->dir, strerror(errno));
        return EF_HX_OUTPUT;
    }
    snprintf(h->part_path, sizeof h->part_path, "%s/.results.part", h->dir);
    snprintf(h->state_path, sizeof h->state_path, "%s/.resume", h->dir);
    snprintf(h->dig_path, sizeof h->dig_path, "%s/.digests", h->dir);
    if (!h->o->resume) {
        /* a new run: results of an earlier one must not outlive it looking complete */
        char path[4200];
        snprintf(path, sizeof path, "%s/vectors.actual.bin", h->dir);
        if (unlink(path) != 0 && errno != ENOENT) {
            fprintf(stderr, "edgeflag-host: %s: cannot remove the previous results: %s\n", path, strerror(errno));
            return EF_HX_OUTPUT;
        }
    }
    return 0;
}

/* A new run on the board: reset, then START from frame 0. */
static int start_fresh(hl *h)
{
    int r;
    if ((r = h->ops->reset(h->l)) < 0)
        return r == EF_HOST_ENODEV || r == EF_HOST_ETIMEDOUT ? lost(h, r) : link_fail(h, "reset", r);
    if (h->part)
        fclose(h->part);
    h->part = fopen(h->part_path, "w+b");
    if (!h->part)
        return fail(h, EF_HX_OUTPUT, "cannot create the results: %s", strerror(errno));
    h->base = h->next = h->res_next = 0;
    h->resend_asked = h->unacked = h->ackr_due = h->done = 0;
    h->part_bytes = h->records = 0;
    h->results_crc = 0;
    h->rlen = 0;
    memset(h->counts, 0, sizeof h->counts);
    if (save_state(h) != 0)
        return fail(h, EF_HX_OUTPUT, "cannot write the resume state: %s", strerror(errno));
    return 0;
}

/* Frames out, results in, until DONE; then DONE checked.  0 or an EF_HX_* code. */
static int stream_loop(hl *h)
{
    const ef_host_stream_opts *o = h->o;
    const int timeout = o->timeout_ms > 0 ? o->timeout_ms : 2000;
    const double t0 = now_s();
    double last_progress = t0;
    int tries = 0, r, code;
    while (!h->done) {
        while (h->next <= h->last_seq && h->next - h->base < h->window) {
            if ((r = put_frame(h, h->next)) < 0)
                return ef_host_exit_code(r) == EF_HX_LOST ? lost(h, r) : link_fail(h, "sending", r);
            h->next++;
        }
        const int can_send = h->next <= h->last_seq && h->next - h->base < h->window;
        size_t got = 0;
        if (h->rlen == h->rcap)
            h->rlen = 0; /* cannot happen with frames <= FRAME_MAX; be safe */
        r = h->ops->read(h->l, h->rbuf + h->rlen, h->rcap - h->rlen, &got, can_send ? 0 : 10);
        if (r < 0 && r != EF_HOST_ETIMEDOUT)
            return ef_host_exit_code(r) == EF_HX_LOST ? lost(h, r) : link_fail(h, "receiving", r);
        h->rlen += got;
        int progress = 0;
        if ((code = take_bytes(h, &progress)) != 0)
            return code;
        if (h->unacked >= ACKR_EVERY || (h->done && h->unacked) || h->ackr_due) {
            h->ackr_due = 0;
            if ((r = send_ackr(h, 0)) != 0)
                return r >= 1000 ? lost(h, -(r - 1000)) : r;
        }
        const double t = now_s();
        if (progress) {
            last_progress = t;
            tries = 0;
        } else if ((t - last_progress) * 1000 >= timeout) {
            h->rep->timeouts++;
            if (++tries >= MAX_TRIES)
                return lost(h, EF_HOST_ETIMEDOUT);
            /* go back: resend every unacknowledged frame, ask for every result again */
            h->rep->retransmits += h->next - h->base;
            h->next = h->base;
            if ((r = send_ackr(h, 1)) != 0)
                return r >= 1000 ? lost(h, -(r - 1000)) : r;
            last_progress = t;
        }
        if (o->progress)
            draw_progress(h, t0, 0);
    }
    if (o->progress)
        draw_progress(h, t0, 1);
    h->rep->seconds += now_s() - t0;
    h->rep->cmds = h->ncmds;
    h->rep->records = h->records;
    h->rep->result_bytes += h->part_bytes;
    return check_done(h);
}

static int run(hl *h)
{
    const ef_host_stream_opts *o = h->o;
    int code = load_vectors(h);
    if (code)
        return code;
    if ((code = prepare_dir(h)) != 0)
        return code;

    uint8_t raw[EF_PROTO_IDENTIFY_LEN];
    int r = h->ops->identify(h->l, raw);
    ef_host_ident id;
    if (r < 0)
        return r == EF_HOST_ENODEV || r == EF_HOST_ETIMEDOUT ? lost(h, r) : link_fail(h, "identify", r);
    if ((r = ef_host_ident_parse(raw, &id)) != 0) {
        if (memcmp(raw, EF_PROTO_MAGIC, 4) == 0) {
            char b[64];
            snprintf(b, sizeof b, "%u", id.protocol);
            return fail(h, EF_HX_BOARD, "the board speaks protocol version %s; this edgeflag-host speaks 1", b);
        }
        return fail(h, EF_HX_BOARD, "the device did not answer identify as an edgeflag board (no \"EFB1\")");
    }
    if (!(id.samples_mask >> ef_proto_samples_bit((unsigned)h->samples) & 1u) ||
        (uint32_t)h->info.width > id.width_max || (uint32_t)h->info.height > id.height_max) {
        char b[300], d[200];
        ef_host_ident_describe(&id, d, sizeof d);
        snprintf(b, sizeof b, "%s: %d samples at %" PRId32 "x%" PRId32 " does not fit this board (%s)", o->vectors,
                 h->samples, h->info.width, h->info.height, d);
        return fail(h, EF_HX_INPUT, "%s", b);
    }
    h->window = id.window ? id.window : 1;
    h->digest_ok = o->digest && (id.caps & EF_PROTO_CAP_DIGEST);
    if (o->digest && !h->digest_ok && !o->digest_optional && !o->resume)
        return fail(h, EF_HX_BOARD, "the board has no digest mode (identify's capability bit 3); run without --digest");
    if (o->iface_mask & ~id.iface_mask)
        return fail(h, EF_HX_BOARD,
                    "the board cannot return the internal interfaces asked for (it returns "
                    "only what identify lists); use --interfaces pix");

    uint8_t st[EF_PROTO_STATUS_LEN] = { 0 };
    int fresh = !o->resume;
    if (o->resume) {
        const int s = load_state(h);
        if (s != 0)
            return fail(h, EF_HX_USAGE,
                        s == -1 ? "--resume: no resume state in the results folder (nothing was interrupted)"
                                : "--resume: the resume state belongs to another vectors file or is damaged");
        if ((r = h->ops->status(h->l, st)) < 0)
            return r == EF_HOST_ENODEV || r == EF_HOST_ETIMEDOUT ? lost(h, r) : link_fail(h, "status", r);
        if (memcmp(st, EF_PROTO_MAGIC, 4) != 0)
            return fail(h, EF_HX_BOARD, "the board's status answer is malformed");
        if (st[6] == EF_BS_IDLE || ef_get32(st + 8) == 0) {
            /* The state is written at the run's reset, before START: a host
             * stopped in between leaves a state with nothing in it and a board
             * without the run (so does a board reset before any result was
             * kept).  Starting over then loses nothing. */
            if (h->phase == PH_SELECT || h->res_next != 0 || h->part_bytes != 0)
                return fail(h, EF_HX_BOARD,
                            "the board has no run to resume (it was reset or power-cycled); run "
                            "again without --resume");
            fprintf(stderr, "edgeflag-host: --resume: the board has no run (it never took this run's first frame, "
                            "or it was reset) and no result was kept: starting the run from frame 0\n");
            fresh = 1;
        }
    }
    if (!fresh) {
        const uint32_t rx_seq = ef_get32(st + 8), res_made = ef_get32(st + 12);
        uint64_t taken = (uint64_t)(rx_seq - 1) * h->per_frame; /* commands in the DATA frames it took */
        if (taken > h->ncmds)
            taken = h->ncmds;
        if (ef_get32(st + 20) != ef_frame_crc32(0, h->cmds, (size_t)taken * EF_PROTO_CMD_BYTES))
            return fail(h, EF_HX_BOARD,
                        "the board's run is not this vectors file (its input CRC differs); run "
                        "again without --resume");
        if (res_made < h->res_next)
            return fail(h, EF_HX_BOARD, "the board made fewer result frames than were kept: not the same run");
        h->last_seq = (uint32_t)((h->ncmds + h->per_frame - 1) / h->per_frame) + 1;
        h->base = h->next = rx_seq;
        h->rep->resumed_from = rx_seq;
        h->part = fopen(h->part_path, "r+b");
        if (!h->part || ftruncate(fileno(h->part), (off_t)h->part_bytes) != 0 ||
            fseeko(h->part, (off_t)h->part_bytes, SEEK_SET) != 0)
            return fail(h, EF_HX_OUTPUT, "--resume: cannot reopen the kept results: %s", strerror(errno));
        if (h->digest && !h->have_exp)
            return fail(h, EF_HX_INTERNAL, "--resume of a digest run without the expected vectors");
        if ((r = send_ackr(h, 1)) != 0)
            return r >= 1000 ? lost(h, -(r - 1000)) : r;
    } else {
        /* the largest DATA payload the board takes (identify's capabilities, bits 16-23) */
        const unsigned kib = EF_PROTO_CAP_DATA_KIB(id.caps), most = (kib ? kib * 1024u : EF_PROTO_PAYLOAD_MAX);
        unsigned per = o->frame_cmds ? o->frame_cmds : most / EF_PROTO_CMD_BYTES;
        if (per > most / EF_PROTO_CMD_BYTES)
            per = most / EF_PROTO_CMD_BYTES;
        h->per_frame = per;
        h->start_payload_mask = o->iface_mask ? o->iface_mask : 1u << EF_IF_PIX;
        h->last_seq = (uint32_t)((h->ncmds + per - 1) / per) + 1;
        h->digest = h->digest_ok ? o->digest : 0;
        h->phase = h->digest ? PH_DIGEST : PH_FULL;
        if ((code = start_fresh(h)) != 0)
            return code;
    }

    h->fbuf = malloc(EF_PROTO_FRAME_MAX);
    h->rcap = 4 * EF_PROTO_FRAME_MAX;
    h->rbuf = malloc(h->rcap);
    if (!h->fbuf || !h->rbuf)
        return fail(h, EF_HX_INTERNAL, "out of memory");
    h->rep->digest = h->digest;
    if ((code = stream_loop(h)) != 0)
        return code;
    if (h->phase == PH_DIGEST) { /* the digests kept; the windows that differ fetched whole */
        fclose(h->part);
        h->part = NULL;
        if (rename(h->part_path, h->dig_path) != 0)
            return fail(h, EF_HX_OUTPUT, "cannot keep the digests: %s", strerror(errno));
        if ((code = choose_windows(h)) != 0)
            return code;
        if (h->nsel) {
            h->phase = PH_SELECT;
            if ((code = start_fresh(h)) != 0 || (code = stream_loop(h)) != 0)
                return code;
        }
    }
    if ((code = h->phase == PH_FULL ? write_results(h) : write_rebuilt(h)) != 0)
        return code;
    if (h->part)
        fclose(h->part);
    h->part = NULL;
    /* the resume state first: killed between the two, --resume says there is
     * nothing to resume, and the results are whole */
    unlink(h->state_path);
    unlink(h->part_path);
    unlink(h->dig_path);
    /* now DONE may go; a board that misses this ACKR still holds a finished run */
    uint8_t p[4], fr[EF_PROTO_HEADER + 4 + EF_PROTO_TRAILER];
    ef_put32(p, h->res_next + 1);
    (void)h->ops->write(h->l, fr, ef_frame_put(fr, EF_FT_ACKR, 0, 0, p, 4), h->o->timeout_ms);
    (void)h->ops->flush(h->l, h->o->timeout_ms);
    return EF_HX_OK;
}

int ef_host_stream(const ef_transport_ops *ops, ef_link *link, const ef_host_stream_opts *opts,
                   ef_host_stream_report *rep)
{
    hl *h = calloc(1, sizeof *h);
    if (!h) {
        fprintf(stderr, "edgeflag-host: out of memory\n");
        return EF_HX_INTERNAL;
    }
    memset(rep, 0, sizeof *rep);
    h->ops = ops, h->l = link, h->o = opts, h->rep = rep;
    const int code = run(h);
    if (h->part)
        fclose(h->part);
    if (h->have_exp)
        ef_vec_dump_destroy(&h->exp);
    free(h->sel);
    free(h->cmds);
    free(h->fbuf);
    free(h->rbuf);
    free(h);
    return code;
}
