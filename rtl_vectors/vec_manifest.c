/*
 * vec_manifest.c - manifest.json (docs/vectors.md section 6): the run's
 * parameters, the recorded interfaces with their widths and counts, and
 * every file written with its size and SHA-256.  Written last by the
 * command, so its presence marks a complete directory.
 *
 * The JSON is json-c's (Debian's libjson-c): it escapes the strings and
 * prints every integer exactly, the seed's full 0..2^64-1 included
 * (json_object_new_uint64; Jansson's integers are signed 64-bit, so a seed
 * of 2^63 or more could not be written as a number).  The layout is fixed
 * so that the same run gives the same bytes and a line-oriented tool (grep,
 * sed) reads it as well as a JSON parser: json-c's pretty printer (two-space
 * indentation, one key per line) for the top level, and each interface and
 * file entry on one line in json-c's spaced form ({ "k": v, ... }).  An
 * entry is put in the tree as a placeholder whose serializer prints the
 * entry's own one-line text.  Builds without the manifest (WITH_MANIFEST=0)
 * have no json-c and write none.
 */
#include "ef_vec.h"
#include "ef_fixed.h" /* ef_utf8_len */

#ifndef EF_NO_MANIFEST

#include <json-c/json.h>
#include <stdlib.h>
#include <string.h>

#define FLAGS_LINE (JSON_C_TO_STRING_SPACED | JSON_C_TO_STRING_NOSLASHESCAPE)
#define FLAGS_TOP (JSON_C_TO_STRING_PRETTY | JSON_C_TO_STRING_SPACED | JSON_C_TO_STRING_NOSLASHESCAPE)

/* s as a json-c string, every byte that is not well-formed UTF-8 replaced
 * by U+FFFD; NULL when out of memory. */
static json_object *utf8_string(const char *s)
{
    size_t n = strlen(s), o = 0;
    const unsigned char *p = (const unsigned char *)s;
    char *d = n < SIZE_MAX / 3 ? malloc(3 * n + 1) : NULL;
    json_object *j;
    if (!d)
        return NULL;
    while (n) {
        size_t len = ef_utf8_len(p, n);
        if (len == 0) {
            memcpy(d + o, "\xef\xbf\xbd", 3);
            o += 3;
            len = 1;
        } else {
            memcpy(d + o, p, len);
            o += len;
        }
        p += len;
        n -= len;
    }
    j = json_object_new_string_len(d, (int)o);
    free(d);
    return j;
}

/* The placeholder's serializer: the entry (its userdata) on one line. */
static int entry_to_string(json_object *jso, struct printbuf *pb, int level, int flags)
{
    size_t n = 0;
    const char *s = json_object_to_json_string_length(json_object_get_userdata(jso), FLAGS_LINE, &n);
    (void)level;
    (void)flags;
    return s ? printbuf_memappend(pb, s, (int)n) : -1;
}

static void entry_free(json_object *jso, void *userdata)
{
    (void)jso;
    json_object_put(userdata);
}

/* Appends entry to array as a one-line placeholder; takes entry. */
static int add_entry(json_object *array, json_object *entry)
{
    json_object *ph = entry ? json_object_new_boolean(0) : NULL;
    if (!ph) {
        json_object_put(entry);
        return -1;
    }
    json_object_set_serializer(ph, entry_to_string, entry, entry_free);
    if (json_object_array_add(array, ph) != 0) {
        json_object_put(ph);
        return -1;
    }
    return 0;
}

/* json_object_object_add that takes v even on failure, counting failures:
 * a NULL v other than a wanted null is a failed allocation. */
static void put(json_object *o, const char *key, json_object *v, int *bad)
{
    if (!v || json_object_object_add(o, key, v) != 0) {
        json_object_put(v);
        ++*bad;
    }
}

static void put_null(json_object *o, const char *key, int *bad)
{
    if (json_object_object_add(o, key, NULL) != 0)
        ++*bad;
}

static json_object *manifest_tree(const ef_vec_info *info, const ef_vec_collect *c, const ef_vec_file *files,
                                  size_t nfiles)
{
    json_object *top = json_object_new_object(), *ifs = json_object_new_array(), *fs = json_object_new_array();
    int bad = 0;

    if (!top || !ifs || !fs) {
        json_object_put(top);
        json_object_put(ifs);
        json_object_put(fs);
        return NULL;
    }
    put(top, "format", json_object_new_string("edgeflag-vectors"), &bad);
    put(top, "version", json_object_new_uint64(EF_VEC_FORMAT), &bad);
    put(top, "generator", json_object_new_string("edgeflag " EF_VERSION_STRING), &bad);
    put(top, "input", utf8_string(info->input), &bad);
    put(top, "width", json_object_new_uint64((uint64_t)info->width), &bad);
    put(top, "height", json_object_new_uint64((uint64_t)info->height), &bad);
    put(top, "samples", json_object_new_uint64((uint64_t)info->samples), &bad);
    put(top, "rule", json_object_new_string(ef_vec_rule_name(info->rule)), &bad);
    put(top, "seed", json_object_new_uint64(info->seed), &bad);
    put(top, "cycles", json_object_new_uint64(info->cycles), &bad);
    put(top, "transactions", json_object_new_uint64(ef_vec_collect_total(c, info->mask)), &bad);
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        json_object *e;
        if (!(info->mask >> i & 1u))
            continue;
        if ((e = json_object_new_object()) == NULL) {
            bad++;
            continue;
        }
        put(e, "name", json_object_new_string(d->name), &bad);
        put(e, "bits", json_object_new_uint64(d->width), &bad);
        put(e, "count", json_object_new_uint64(ef_vec_collect_count(c, i)), &bad);
        bad += add_entry(ifs, e) != 0;
    }
    put(top, "interfaces", ifs, &bad);
    for (size_t k = 0; k < nfiles; k++) {
        const ef_vec_file *f = &files[k];
        json_object *e = json_object_new_object();
        if (!e) {
            bad++;
            continue;
        }
        put(e, "name", utf8_string(f->name), &bad);
        put(e, "format", json_object_new_string(f->format), &bad);
        if (f->iface >= 0)
            put(e, "interface", json_object_new_string(ef_iface_get(f->iface)->name), &bad);
        else
            put_null(e, "interface", &bad);
        put(e, "role", json_object_new_string(f->role), &bad);
        put(e, "count", json_object_new_uint64(f->count), &bad);
        put(e, "bytes", json_object_new_uint64(f->bytes), &bad);
        put(e, "sha256", json_object_new_string(f->sha256), &bad);
        bad += add_entry(fs, e) != 0;
    }
    put(top, "files", fs, &bad);
    if (bad) {
        json_object_put(top);
        return NULL;
    }
    return top;
}

int ef_vec_manifest_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c, const ef_vec_file *files,
                          size_t nfiles)
{
    json_object *top = manifest_tree(info, c, files, nfiles);
    size_t n = 0;
    const char *s = top ? json_object_to_json_string_length(top, FLAGS_TOP, &n) : NULL;
    if (!s) {
        json_object_put(top);
        return -1;
    }
    ef_vec_out_write(o, s, n);
    ef_vec_out_puts(o, "\n");
    json_object_put(top);
    return 0;
}

#endif /* EF_NO_MANIFEST */
