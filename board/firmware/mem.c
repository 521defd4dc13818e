/*
 * mem.c (board firmware) - memset, memcpy and memmove a word at a time when
 * the addresses allow, in place of picolibc's size-optimised byte loops (5
 * sys cycles a byte on VexRiscv lite).  They matter: picolibc's malloc clears
 * every block it gives (the engine's 32 KiB result frames, its 128 KiB
 * receive buffer), and the engine copies every byte it receives and sends
 * (docs/board-ulx3s.md, "The UART at 3 Mbaud").  Large blocks go in pieces,
 * the UART's receive FIFO emptied into its ring between them.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

void fw_link_poll(void); /* link.h: the UART's bytes to its ring, during long work */

/* Blocks go in pieces, the UART polled between, each piece well inside the
 * 6,400 sys cycles in which the UART's FIFO fills: VexRiscv lite has no data
 * cache, so every load and store is a bus access (a byte copied from main RAM
 * to main RAM takes about 15 sys cycles, a word cleared about 8). */
#define PIECE 64u      /* copies */
#define SET_PIECE 512u /* clearing */

/* (no loop here may become a call of the function it is in) */
#define NO_LIBCALL __attribute__((optimize("no-tree-loop-distribute-patterns")))

NO_LIBCALL static void set(uint8_t *d, int c, size_t n)
{
    for (; n && ((uintptr_t)d & 3u); n--)
        *d++ = (uint8_t)c;
    const uint32_t w = 0x01010101u * (uint8_t)c;
    for (; n >= 16; n -= 16, d += 16) {
        ((uint32_t *)d)[0] = w;
        ((uint32_t *)d)[1] = w;
        ((uint32_t *)d)[2] = w;
        ((uint32_t *)d)[3] = w;
    }
    for (; n >= 4; n -= 4, d += 4)
        *(uint32_t *)d = w;
    while (n--)
        *d++ = (uint8_t)c;
}

NO_LIBCALL void *memset(void *dst, int c, size_t n)
{
    uint8_t *d = dst;
    for (; n > SET_PIECE; n -= SET_PIECE, d += SET_PIECE) {
        set(d, c, SET_PIECE);
        fw_link_poll();
    }
    set(d, c, n);
    return dst;
}

/* Forwards: memcpy, and memmove to a lower address. */
NO_LIBCALL static void copy_up(uint8_t *d, const uint8_t *s, size_t n)
{
    if ((((uintptr_t)d ^ (uintptr_t)s) & 3u) == 0) {
        for (; n && ((uintptr_t)d & 3u); n--)
            *d++ = *s++;
        for (; n >= 16; n -= 16, d += 16, s += 16) {
            const uint32_t a = ((const uint32_t *)s)[0], b = ((const uint32_t *)s)[1];
            const uint32_t c = ((const uint32_t *)s)[2], e = ((const uint32_t *)s)[3];
            ((uint32_t *)d)[0] = a;
            ((uint32_t *)d)[1] = b;
            ((uint32_t *)d)[2] = c;
            ((uint32_t *)d)[3] = e;
        }
        for (; n >= 4; n -= 4, d += 4, s += 4)
            *(uint32_t *)d = *(const uint32_t *)s;
    }
    while (n--)
        *d++ = *s++;
}

/* Forwards in pieces, the UART polled between. */
NO_LIBCALL static void copy_up_polled(uint8_t *d, const uint8_t *s, size_t n)
{
    for (; n > PIECE; n -= PIECE, d += PIECE, s += PIECE) {
        copy_up(d, s, PIECE);
        fw_link_poll();
    }
    copy_up(d, s, n);
}

NO_LIBCALL void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
    copy_up_polled(dst, src, n);
    return dst;
}

NO_LIBCALL void *memmove(void *dst, const void *src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    if (d <= s || d >= s + n) {
        copy_up_polled(d, s, n);
    } else { /* backwards: the ranges overlap with d above s (rare: small moves) */
        d += n, s += n;
        while (n--)
            *--d = *--s;
    }
    return dst;
}
