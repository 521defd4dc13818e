/*
 * fuzz_board.c - libFuzzer target for the board engine (board/): its
 * frame parser, the protocol state machine and, behind it, the C model DUT's
 * command decoder (docs/board.md sections 2-4).
 *
 * The first byte picks how the rest reaches the board:
 *   even  raw bytes, cut into chunks whose sizes the following bytes choose,
 *         with the board's output taken between chunks;
 *   odd   frames made by the harness from [type][flags][seq][len][payload]
 *         groups and sealed with the right CRC, so the fuzzer spends its time
 *         past the CRC in the state machine and the DUT (DATA payloads are
 *         command words; START's picks the mode, the interfaces and samples).
 * Properties (each aborts, so libFuzzer keeps the input):
 *  - everything the board sends parses as whole, good frames of the
 *    board-to-host types (control replies of their fixed sizes included, the
 *    requests 0x10-0x12 being in the stream: docs/board.md 5.5), and its
 *    numbered frames count 0, 1, 2, ... in order (retransmissions aside, which
 *    never skip ahead; a reset's reply starts the count again);
 *  - status never claims more host frames taken than frames were fed;
 *  - the same input gives the same output bytes twice (no hidden state).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "ef_board.h"
#include "ef_frame.h"
#include "fuzz_common.h"

typedef struct out {
    uint8_t *b;
    size_t n, cap;
} out;

static void take(ef_board *b, out *o)
{
    uint8_t tmp[4096];
    size_t n;
    while ((n = ef_board_tx(b, tmp, sizeof tmp)) > 0) {
        if (o->n + n > o->cap) {
            o->cap = (o->n + n) * 2;
            o->b = realloc(o->b, o->cap);
            FUZZ_CHECK(o->b, "out of memory");
        }
        memcpy(o->b + o->n, tmp, n);
        o->n += n;
    }
}

static void run(const uint8_t *data, size_t size, out *o, uint64_t *fed)
{
    const ef_proto_info info = { "FUZZ", 7, 1u << 3 | 1u << 4 | 1u << 5, 256, 256, 4096, 4, 0x7f };
    ef_board *b = ef_board_new(&info, ef_board_dut_model());
    FUZZ_CHECK(b, "ef_board_new failed");
    *fed = 0;
    if (size && (data[0] & 1) == 0) {
        size_t i = 1;
        while (i < size) {
            size_t k = 1 + data[i] % 61u;
            i++;
            if (k > size - i)
                k = size - i;
            ef_board_rx(b, data + i, k);
            i += k;
            *fed += k / EF_PROTO_HEADER + 1; /* at most this many frames could have ended here */
            take(b, o);
        }
    } else if (size) {
        uint8_t *f = malloc(EF_PROTO_FRAME_MAX);
        FUZZ_CHECK(f, "out of memory");
        size_t i = 1;
        while (size - i >= 4) {
            const uint8_t type = data[i], flags = data[i + 1], seq = data[i + 2];
            size_t len = data[i + 3];
            i += 4;
            if (len > size - i)
                len = size - i;
            size_t n = ef_frame_put(f, type, flags, seq, data + i, (uint32_t)len);
            i += len;
            ef_board_rx(b, f, n);
            (*fed)++;
            take(b, o);
        }
        free(f);
    }
    take(b, o);
    uint8_t st[EF_PROTO_STATUS_LEN];
    ef_board_status(b, st);
    FUZZ_CHECK(ef_get32(st + 8) <= *fed, "status says %u frames taken, %llu fed", ef_get32(st + 8),
               (unsigned long long)*fed);
    ef_board_free(b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    out a = { 0 }, c = { 0 };
    uint64_t fed;
    run(data, size, &a, &fed);
    /* the board's output: good frames only, numbered ones never skipping ahead */
    size_t pos = 0;
    uint32_t next = 0;
    while (pos < a.n) {
        ef_frame f;
        size_t used;
        const int r = ef_frame_parse(a.b + pos, a.n - pos, &f, &used);
        FUZZ_CHECK(r == EF_FRAME_OK, "board output at byte %zu is not a whole good frame (%d)", pos, r);
        if (f.type >= (EF_FT_IDENTIFY | EF_FT_REPLY) && f.type <= (EF_FT_RESET | EF_FT_REPLY)) {
            /* a control reply (docs/board.md 5.5): its fixed size; after a reset, numbering restarts */
            static const uint32_t LEN[] = { EF_PROTO_IDENTIFY_LEN, EF_PROTO_STATUS_LEN, 0 };
            FUZZ_CHECK(f.len == LEN[f.type - (EF_FT_IDENTIFY | EF_FT_REPLY)], "control reply 0x%02x of %u bytes",
                       f.type, f.len);
            if (f.type == (EF_FT_RESET | EF_FT_REPLY))
                next = 0;
            pos += used;
            continue;
        }
        FUZZ_CHECK(f.type >= EF_FT_ACK && f.type <= EF_FT_ERROR, "board sent frame type 0x%02x", f.type);
        if (f.type == EF_FT_RESULT || f.type == EF_FT_DONE || f.type == EF_FT_ERROR) {
            FUZZ_CHECK(f.seq <= next, "numbered frame %u skips ahead of %u", f.seq, next);
            if (f.seq == next)
                next++;
        }
        pos += used;
    }
    run(data, size, &c, &fed);
    FUZZ_CHECK(a.n == c.n && (a.n == 0 || memcmp(a.b, c.b, a.n) == 0), "same input, different output");
    free(a.b);
    free(c.b);
    return 0;
}
