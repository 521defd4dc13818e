/*
 * crc32.c (board firmware) - crc32() and crc32_combine() with zlib's
 * signatures (zlib.h here) for proto/ef_frame.c.  A 256-entry table built at
 * the first call (1 KiB of SRAM); the combine multiplies the first CRC's
 * register by x^(8 len2) modulo the polynomial, which is what appending len2
 * bytes does to it, and adds the second CRC: O(log len2).
 */
#include "zlib.h"

#define POLY 0xEDB88320u

void fw_link_poll(void); /* link.h: the UART's bytes to its ring, during long work */

static uint32_t table[256];
static uint32_t zeros[32]; /* x^(8 * 2^k) modulo the polynomial: 2^k zero bytes */
static int table_ready;

static uint32_t mul_mod(uint32_t a, uint32_t b);

static void make_table(void)
{
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = n;
        for (int k = 0; k < 8; k++)
            c = c & 1u ? (c >> 1) ^ POLY : c >> 1;
        table[n] = c;
    }
    zeros[0] = 0x00800000u; /* x^8 (the reflected form: bit 31 is x^0) */
    for (int k = 1; k < 32; k++)
        zeros[k] = mul_mod(zeros[k - 1], zeros[k - 1]);
    table_ready = 1;
}

uLong crc32(uLong crc, const Bytef *buf, uInt len)
{
    if (!table_ready)
        make_table();
    uint32_t c = (uint32_t)crc ^ 0xFFFFFFFFu;
    if (buf)
        while (len) {
            uInt k = len < 32 ? len : 32; /* 32 bytes: about 800 sys cycles */
            len -= k;
            while (k--)
                c = table[(c ^ *buf++) & 0xFFu] ^ (c >> 8);
            fw_link_poll();
        }
    return c ^ 0xFFFFFFFFu;
}

/* a * b modulo the CRC's polynomial, both in the CRC's reflected form (bit 31
 * is x^0, bit 0 x^31): b times x for each bit of a from x^0 up. */
static uint32_t mul_mod(uint32_t a, uint32_t b)
{
    uint32_t p = 0;
    for (uint32_t m = 0x80000000u; m && a; m >>= 1) {
        if (a & m) {
            p ^= b;
            a ^= m;
        }
        b = b & 1u ? (b >> 1) ^ POLY : b >> 1;
    }
    return p;
}

/* crc(A B) from crc(A), crc(B) and |B|: the register after A, pushed
 * through |B| zero bytes, XOR crc(B) (the pre- and post-conditioning of the
 * two cancel: both are linear in the register).  Pushing through n zero
 * bytes multiplies by x^(8n) modulo the polynomial: by the table's powers
 * for the bits of n, one product each (a 64 KiB frame's combine had been
 * 64 Ki table steps). */
uLong crc32_combine(uLong crc1, uLong crc2, z_off_t len2)
{
    if (!table_ready)
        make_table();
    uint32_t c = (uint32_t)crc1;
    for (uint32_t n = (uint32_t)len2, k = 0; n; k++, n >>= 1) /* (z_off_t: 32 bits here) */
        if (n & 1u) {
            c = mul_mod(zeros[k], c); /* about 800 sys cycles (shifts take a cycle a bit) */
            fw_link_poll();
        }
    return c ^ (uint32_t)crc2;
}
