/*
 * vec_crc32.c - CRC-32 of IEEE 802.3 / zlib / PNG for vectors.bin
 * (docs/vectors.md section 4), written from the polynomial: reflected
 * 0xEDB88320 (x^32 + x^26 + x^23 + ... + 1 with bit 0 the x^31 term), initial
 * value and final XOR 0xFFFFFFFF.  The table is built from the polynomial on
 * first use rather than pasted in, so the code shows where the numbers come
 * from.
 */
#include "ef_vec.h"

#define POLY UINT32_C(0xEDB88320)

static uint32_t table[256];
static int table_ready;

/* Entry b is the remainder of the byte b shifted through eight steps of the
 * bitwise (one bit per step) division.  The CLI is single-threaded; a second
 * thread racing here would only compute the same values again. */
static void build_table(void)
{
    for (uint32_t b = 0; b < 256; b++) {
        uint32_t r = b;
        for (int k = 0; k < 8; k++)
            r = (r & 1u) ? (r >> 1) ^ POLY : r >> 1;
        table[b] = r;
    }
    table_ready = 1;
}

uint32_t ef_vec_crc32(uint32_t crc, const void *data, size_t n)
{
    const unsigned char *p = data;
    uint32_t r = crc ^ UINT32_C(0xFFFFFFFF);   /* undo the previous call's final XOR */

    if (!table_ready)
        build_table();
    for (size_t i = 0; i < n; i++)
        r = (r >> 8) ^ table[(r ^ p[i]) & 0xFFu];
    return r ^ UINT32_C(0xFFFFFFFF);
}
