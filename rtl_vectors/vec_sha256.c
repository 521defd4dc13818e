/*
 * vec_sha256.c - SHA-256 of the manifest's file hashes, by GNU Nettle
 * (`sha256sum` must agree with every hash, and a hash computed while writing
 * describes exactly the bytes that went out).  Nettle picks the CPU's SHA
 * instructions at run time where it has them (its x86-64 "fat" build); the
 * tests check it against FIPS 180-4's examples and against sha256sum.
 * Builds without Nettle (WITH_MANIFEST=0) have no manifest and no hashes.
 */
#include "ef_vec.h"

#ifndef EF_NO_MANIFEST
#include <nettle/sha2.h>

/* ef_vec.h keeps Nettle's state in opaque storage: it must fit, aligned. */
_Static_assert(sizeof(struct sha256_ctx) <= sizeof(((ef_vec_sha256 *)0)->state),
               "Nettle's sha256_ctx fits ef_vec_sha256's storage");
_Static_assert(_Alignof(struct sha256_ctx) <= _Alignof(uint64_t), "and its alignment");

static struct sha256_ctx *ctx_of(ef_vec_sha256 *s) { return (struct sha256_ctx *)(void *)s->state.bytes; }

void ef_vec_sha256_init(ef_vec_sha256 *s) { sha256_init(ctx_of(s)); }

void ef_vec_sha256_update(ef_vec_sha256 *s, const void *data, size_t n) { sha256_update(ctx_of(s), n, data); }

void ef_vec_sha256_final(ef_vec_sha256 *s, uint8_t digest[32]) { sha256_digest(ctx_of(s), SHA256_DIGEST_SIZE, digest); }

#endif

void ef_vec_sha256_hex(const uint8_t digest[32], char out[65])
{
    static const char hex[] = "0123456789abcdef";
    for (int i = 0; i < 32; i++) {
        out[2 * i] = hex[digest[i] >> 4];
        out[2 * i + 1] = hex[digest[i] & 15];
    }
    out[64] = '\0';
}
