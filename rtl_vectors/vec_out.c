/*
 * vec_out.c - the byte sink every writer uses (ef_vec.h): buffered, counted
 * and hashed as it goes, so the manifest's byte counts and SHA-256 are those
 * of the bytes actually handed to the file, and a write error is remembered
 * once and reported at the end instead of being checked after every line.
 * It runs in the caller's thread: `vectors` writes two files at once, each
 * formatted, hashed and written by one thread (cli/vectors_files.c), which
 * measured faster than handing every buffer to a hashing thread.
 */
#include "ef_vec.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* Hashes and writes n bytes at p. */
static void emit(ef_vec_out *o, const unsigned char *p, size_t n)
{
#ifndef EF_NO_MANIFEST
    if (o->flags & EF_VEC_OUT_SHA)
        ef_vec_sha256_update(&o->sha, p, n);
#endif
    if (o->flags & EF_VEC_OUT_CRC)
        o->crc = ef_vec_crc32(o->crc, p, n);
    if (o->fp && !o->err && fwrite(p, 1, n, o->fp) != n)
        o->err = errno ? errno : EIO;
}

void ef_vec_out_init(ef_vec_out *o, FILE *fp, unsigned flags)
{
    o->fp = fp;
#ifndef EF_NO_MANIFEST
    o->flags = flags;
    ef_vec_sha256_init(&o->sha);
#else
    o->flags = flags & ~(unsigned)EF_VEC_OUT_SHA; /* no hashing in this build */
#endif
    o->crc = 0;
    o->bytes = 0;
    o->err = 0;
    o->used = 0;
}

void ef_vec_out_drain(ef_vec_out *o)
{
    if (!o->used)
        return;
    emit(o, o->buf, o->used);
    o->used = 0;
}

void ef_vec_out_write(ef_vec_out *o, const void *data, size_t n)
{
    const unsigned char *p = data;
    if (n >= EF_VEC_OUT_BUF) {
        ef_vec_out_drain(o);
        o->bytes += n;
        emit(o, p, n);
        return;
    }
    if (EF_VEC_OUT_BUF - o->used < n)
        ef_vec_out_drain(o);
    memcpy(o->buf + o->used, p, n);
    o->used += n;
    o->bytes += n;
}

void ef_vec_out_puts(ef_vec_out *o, const char *s) { ef_vec_out_write(o, s, strlen(s)); }

size_t ef_vec_u64_dec(uint64_t v, char *buf)
{
    char tmp[20];
    size_t n = 0, i;
    do {
        tmp[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    for (i = 0; i < n; i++)
        buf[i] = tmp[n - 1 - i];
    buf[n] = '\0';
    return n;
}

void ef_vec_out_u64(ef_vec_out *o, uint64_t v)
{
    char buf[21];
    ef_vec_out_write(o, buf, ef_vec_u64_dec(v, buf));
}

int ef_vec_out_finish(ef_vec_out *o, uint8_t digest[32])
{
    ef_vec_out_drain(o);
#ifndef EF_NO_MANIFEST
    if (digest)
        ef_vec_sha256_final(&o->sha, digest);
#else
    if (digest)
        memset(digest, 0, 32);
#endif
    if (o->err) {
        errno = o->err;
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------ naming */

const char *ef_vec_rule_name(int rule)
{
    return rule == EF_RULE_NONZERO ? "nonzero" : rule == EF_RULE_EVENODD ? "evenodd" : "scene";
}

const char *ef_vec_role(int iface) { return iface == EF_IF_CMD ? "stim" : "expected"; }

char *ef_vec_hex_name(int iface, char *buf, size_t size)
{
    const ef_iface_desc *d = ef_iface_get(iface);
    snprintf(buf, size, "%s.%s.hex", d ? d->name : "unknown", ef_vec_role(iface));
    return buf;
}

const char *ef_vec_base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* '$' is escaped too: inside a VCD $comment the text "$end" would end it. */
void ef_vec_out_escaped(ef_vec_out *o, const char *s)
{
    static const char hex[] = "0123456789abcdef";
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p >= 0x20 && *p <= 0x7e && *p != '\\' && *p != '$') {
            ef_vec_out_write(o, p, 1);
        } else {
            char e[4] = { '\\', 'x', hex[*p >> 4], hex[*p & 15] };
            ef_vec_out_write(o, e, 4);
        }
    }
}

void ef_vec_out_run_line(ef_vec_out *o, const ef_vec_info *info)
{
    ef_vec_out_puts(o, "generator edgeflag " EF_VERSION_STRING "; input ");
    ef_vec_out_escaped(o, info->input);
    ef_vec_out_puts(o, "; size ");
    ef_vec_out_u64(o, (uint64_t)info->width);
    ef_vec_out_puts(o, "x");
    ef_vec_out_u64(o, (uint64_t)info->height);
    ef_vec_out_puts(o, "; samples ");
    ef_vec_out_u64(o, (uint64_t)info->samples);
    ef_vec_out_puts(o, "; rule ");
    ef_vec_out_puts(o, ef_vec_rule_name(info->rule));
    ef_vec_out_puts(o, "; seed ");
    ef_vec_out_u64(o, info->seed);
}
