/*
 * vec_crc32.c - CRC-32 of IEEE 802.3 / zlib / PNG for vectors.bin
 * (docs/vectors.md section 4): reflected polynomial 0xEDB88320, initial value
 * and final XOR 0xFFFFFFFF, chained like zlib's crc32().
 *
 * Why not zlib's crc32(): every build of the portability matrix writes and
 * compares this CRC, and the 32-bit x86 and the static aarch64/s390x builds
 * cannot have zlib here (Debian 12's foreign -dev packages cannot be
 * installed on these machines), so one implementation serves every build.
 *
 * Slicing-by-16 (Kounavis and Berry's slicing-by-8, 2008, twice as wide):
 * sixteen 256-entry tables, T[0] the classic byte table and T[k][b] the CRC
 * of byte b followed by k zero bytes, so sixteen input bytes fold into the
 * remainder with sixteen independent lookups (16 KiB of tables: they stay
 * in the L1 cache; by 16 measured about 1.4x faster than by 8 here, on
 * vectors.bin and on check's reading of it).  Bytes are assembled by shifts,
 * so the host's byte order does not matter.  The tables are built once,
 * under call_once: two threads (two DPI-C models, say) starting together
 * cannot race on them.
 */
#include "ef_vec.h"

#include <threads.h>

#define POLY UINT32_C(0xEDB88320)

static uint32_t T[16][256];
static once_flag tables_once = ONCE_FLAG_INIT;

static void build_tables(void)
{
    for (uint32_t b = 0; b < 256; b++) {
        uint32_t r = b;
        for (int k = 0; k < 8; k++)
            r = (r & 1u) ? (r >> 1) ^ POLY : r >> 1;
        T[0][b] = r;
    }
    for (uint32_t b = 0; b < 256; b++)
        for (int k = 1; k < 16; k++)
            T[k][b] = (T[k - 1][b] >> 8) ^ T[0][T[k - 1][b] & 0xFFu];
}

uint32_t ef_vec_crc32(uint32_t crc, const void *data, size_t n)
{
    const unsigned char *p = data;
    uint32_t r = crc ^ UINT32_C(0xFFFFFFFF); /* undo the previous call's final XOR */

    call_once(&tables_once, build_tables);
    for (; n >= 16; n -= 16, p += 16) {
        const uint32_t lo = r ^ ((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24);
        r = T[15][lo & 0xFFu] ^ T[14][lo >> 8 & 0xFFu] ^ T[13][lo >> 16 & 0xFFu] ^ T[12][lo >> 24] ^ T[11][p[4]] ^
            T[10][p[5]] ^ T[9][p[6]] ^ T[8][p[7]] ^ T[7][p[8]] ^ T[6][p[9]] ^ T[5][p[10]] ^ T[4][p[11]] ^ T[3][p[12]] ^
            T[2][p[13]] ^ T[1][p[14]] ^ T[0][p[15]];
    }
    for (; n; n--, p++)
        r = (r >> 8) ^ T[0][(r ^ *p) & 0xFFu];
    return r ^ UINT32_C(0xFFFFFFFF);
}
