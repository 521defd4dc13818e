/*
 * vec_formats.c - the one table of vector file formats (ef_vec.h): for each,
 * its name (--formats, the manifest's "format"), its --formats bit, whether
 * it is one file per interface or one for all, its extension, its writer and
 * which reader reads it back (for `edgeflag check`).  Adding a format (FST,
 * say) is one row here, its writer, and its reader if `check` is to read it
 * (docs/source.md, "To add a vector format").
 */
#include "ef_vec.h"
#include "ef_vec_read.h"

#include <string.h>

static int write_hex(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c, int iface)
{
    ef_vec_hex_write(o, info, c, iface);
    return 0;
}

static int write_vcd(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c, int iface)
{
    (void)iface;
    ef_vec_vcd_write(o, info, c);
    return 0;
}

static int write_bin(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c, int iface)
{
    (void)iface;
    return ef_vec_bin_write(o, info, c); /* -1: out of memory for its record block */
}

/* In writing order (the files of a run, the manifest's list). */
const ef_vec_format ef_vec_formats[EF_VEC_NFORMATS] = {
    { "hex", EF_VEC_F_HEX, 1, ".hex", write_hex, EF_VEC_FMT_HEX },
    { "vcd", EF_VEC_F_VCD, 0, ".vcd", write_vcd, 0 },
    { "bin", EF_VEC_F_BIN, 0, ".bin", write_bin, EF_VEC_FMT_BIN },
};

const ef_vec_format *ef_vec_format_named(const char *name)
{
    for (int k = 0; name && k < EF_VEC_NFORMATS; k++)
        if (strcmp(ef_vec_formats[k].name, name) == 0)
            return &ef_vec_formats[k];
    return NULL;
}

const ef_vec_format *ef_vec_format_of_path(const char *path)
{
    size_t n = strlen(path);
    for (int k = 0; k < EF_VEC_NFORMATS; k++) {
        size_t e = strlen(ef_vec_formats[k].ext);
        if (n >= e && strcmp(path + n - e, ef_vec_formats[k].ext) == 0)
            return &ef_vec_formats[k];
    }
    return NULL;
}
