/*
 * crc32.c (board firmware) - crc32() and crc32_combine() with zlib's
 * signatures (zlib.h here) for proto/ef_frame.c.  A 256-entry table built at
 * the first call (1 KiB of SRAM); the combine feeds the first CRC's register
 * through len2 zero bytes, which is what appending the second block's bytes
 * does to it, and adds the second CRC: O(len2), a few milliseconds for a
 * 32 KiB RESULT frame, far below that frame's time on the wire.
 */
#include "zlib.h"

#define POLY 0xEDB88320u

static uint32_t table[256];
static int table_ready;

static void make_table(void)
{
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = n;
        for (int k = 0; k < 8; k++)
            c = c & 1u ? (c >> 1) ^ POLY : c >> 1;
        table[n] = c;
    }
    table_ready = 1;
}

uLong crc32(uLong crc, const Bytef *buf, uInt len)
{
    if (!table_ready)
        make_table();
    uint32_t c = (uint32_t)crc ^ 0xFFFFFFFFu;
    if (buf)
        while (len--)
            c = table[(c ^ *buf++) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

/* crc(A B) from crc(A), crc(B) and |B|: the register after A, pushed
 * through |B| zero bytes, XOR crc(B) (the pre- and post-conditioning of the
 * two cancel: both are linear in the register). */
uLong crc32_combine(uLong crc1, uLong crc2, z_off_t len2)
{
    if (!table_ready)
        make_table();
    uint32_t c = (uint32_t)crc1;
    for (z_off_t i = 0; i < len2; i++)
        c = table[c & 0xFFu] ^ (c >> 8);
    return c ^ (uint32_t)crc2;
}
