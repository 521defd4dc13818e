/*
 * vec_manifest.c - manifest.json (docs/vectors.md section 6): the run's
 * parameters, the recorded interfaces with their widths and counts, and
 * every file written with its size and SHA-256.  Written last by the
 * command, so its presence marks a complete directory.  The layout is fixed
 * (one key order, two-space indentation, one interface or file per line) so
 * that the same run gives the same bytes and a line-oriented tool (grep,
 * sed) can read it as well as a JSON parser.
 */
#include "ef_vec.h"
#include "ef_fixed.h"   /* ef_utf8_len */

#include <string.h>

/* A JSON string (RFC 8259): '"' and '\' escaped, control characters as
 * \u00XX, well-formed UTF-8 copied, and each byte of anything else as
 * \uFFFD, so the manifest is valid UTF-8 whatever the file name's bytes. */
static void out_json_string(ef_vec_out *o, const char *s)
{
    static const char hex[] = "0123456789abcdef";
    const unsigned char *p = (const unsigned char *)s;
    size_t n = strlen(s);
    ef_vec_out_puts(o, "\"");
    while (n) {
        size_t len = ef_utf8_len(p, n);
        if (len == 1 && (*p == '"' || *p == '\\')) {
            char e[2] = { '\\', (char)*p };
            ef_vec_out_write(o, e, 2);
        } else if (len == 1 && (*p < 0x20 || *p == 0x7f)) {
            char e[6] = { '\\', 'u', '0', '0', hex[*p >> 4], hex[*p & 15] };
            ef_vec_out_write(o, e, 6);
        } else if (len == 0) {
            ef_vec_out_puts(o, "\\ufffd");
            len = 1;
        } else {
            ef_vec_out_write(o, p, len);
        }
        p += len;
        n -= len;
    }
    ef_vec_out_puts(o, "\"");
}

static void key_u64(ef_vec_out *o, const char *key, uint64_t v, const char *after)
{
    ef_vec_out_puts(o, "\"");
    ef_vec_out_puts(o, key);
    ef_vec_out_puts(o, "\": ");
    ef_vec_out_u64(o, v);
    ef_vec_out_puts(o, after);
}

static void key_str(ef_vec_out *o, const char *key, const char *v, const char *after)
{
    ef_vec_out_puts(o, "\"");
    ef_vec_out_puts(o, key);
    ef_vec_out_puts(o, "\": ");
    out_json_string(o, v);
    ef_vec_out_puts(o, after);
}

void ef_vec_manifest_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c,
                           const ef_vec_file *files, size_t nfiles)
{
    int first = 1;

    ef_vec_out_puts(o, "{\n  ");
    key_str(o, "format", "edgeflag-vectors", ",\n  ");
    key_u64(o, "version", EF_VEC_FORMAT, ",\n  ");
    key_str(o, "generator", "edgeflag " EF_VERSION_STRING, ",\n  ");
    key_str(o, "input", info->input, ",\n  ");
    key_u64(o, "width", (uint64_t)info->width, ",\n  ");
    key_u64(o, "height", (uint64_t)info->height, ",\n  ");
    key_u64(o, "samples", (uint64_t)info->samples, ",\n  ");
    key_str(o, "rule", ef_vec_rule_name(info->rule), ",\n  ");
    key_u64(o, "seed", info->seed, ",\n  ");
    key_u64(o, "cycles", info->cycles, ",\n  ");
    key_u64(o, "transactions", ef_vec_collect_total(c, info->mask), ",\n  ");
    ef_vec_out_puts(o, "\"interfaces\": [");
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        if (!(info->mask >> i & 1u))
            continue;
        ef_vec_out_puts(o, first ? "\n    { " : ",\n    { ");
        first = 0;
        key_str(o, "name", d->name, ", ");
        key_u64(o, "bits", d->width, ", ");
        key_u64(o, "count", ef_vec_collect_count(c, i), " }");
    }
    ef_vec_out_puts(o, "\n  ],\n  \"files\": [");
    for (size_t k = 0; k < nfiles; k++) {
        const ef_vec_file *f = &files[k];
        ef_vec_out_puts(o, k ? ",\n    { " : "\n    { ");
        key_str(o, "name", f->name, ", ");
        key_str(o, "format", f->format, ", ");
        if (f->iface >= 0)
            key_str(o, "interface", ef_iface_get(f->iface)->name, ", ");
        else
            ef_vec_out_puts(o, "\"interface\": null, ");
        key_str(o, "role", f->role, ", ");
        key_u64(o, "count", f->count, ", ");
        key_u64(o, "bytes", f->bytes, ", ");
        key_str(o, "sha256", f->sha256, " }");
    }
    ef_vec_out_puts(o, nfiles ? "\n  ]\n}\n" : "]\n}\n");
}
