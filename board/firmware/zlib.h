/*
 * zlib.h (board firmware) - the two zlib calls proto/ef_frame.c makes,
 * crc32() and crc32_combine(), for the SoC's firmware, which has no zlib:
 * implemented in crc32.c (the same CRC-32: IEEE 802.3, reflected, initial
 * value and final XOR 0xFFFFFFFF), so ef_frame.c compiles unchanged.  Only
 * on the firmware's include path (board/firmware/firmware.mk).
 */
#ifndef EF_FIRMWARE_ZLIB_H
#define EF_FIRMWARE_ZLIB_H

#include <stddef.h>
#include <stdint.h>

typedef unsigned int uInt;
typedef unsigned long uLong;
typedef long z_off_t;
typedef unsigned char Bytef;

uLong crc32(uLong crc, const Bytef *buf, uInt len);
uLong crc32_combine(uLong crc1, uLong crc2, z_off_t len2);

#endif /* EF_FIRMWARE_ZLIB_H */
