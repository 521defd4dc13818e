/*
 * vec_seed.c - the seed of an `edgeflag gen` scene for the vectors' headers
 * (docs/vectors.md section 2): the `# seed N, level L, case K of T ...`
 * line of the file's leading comment block (docs/gen.md section 7).  Only
 * that block is searched, so a comment further down (or a hand-written
 * scene that mentions a seed after its drawing started) cannot pose as the
 * generator's header.
 */
#include "ef_vec.h"

#include <stdlib.h>
#include <string.h>

/* "# seed " then decimal digits <= 2^64-1, then the end of the line, ',',
 * ' ' or '\t'.  The line is p[0..n) without its newline. */
static int seed_line(const char *p, size_t n, uint64_t *seed)
{
    static const char tag[] = "# seed ";
    const size_t tn = sizeof tag - 1;
    uint64_t v = 0;
    size_t i;

    if (n < tn + 1 || memcmp(p, tag, tn) != 0)
        return 0;
    for (i = tn; i < n && p[i] >= '0' && p[i] <= '9'; i++) {
        unsigned d = (unsigned)(p[i] - '0');
        if (v > (UINT64_MAX - d) / 10u)
            return 0;
        v = v * 10u + d;
    }
    if (i == tn || (i < n && p[i] != ',' && p[i] != ' ' && p[i] != '\t' && p[i] != '\r'))
        return 0;
    *seed = v;
    return 1;
}

int ef_vec_scene_seed(const char *text, size_t len, uint64_t *seed)
{
    size_t pos = 0;
    while (pos < len) {
        const char *nl = memchr(text + pos, '\n', len - pos);
        size_t end = nl ? (size_t)(nl - text) : len, first = pos;
        while (first < end && (text[first] == ' ' || text[first] == '\t' || text[first] == '\r'))
            first++;
        if (first < end && text[first] != '#')
            return 0; /* the drawing starts: the header is over */
        if (seed_line(text + pos, end - pos, seed))
            return 1;
        pos = end + 1;
    }
    return 0;
}

int ef_vec_file_seed(const char *path, uint64_t *seed)
{
    enum { MAX = 64 * 1024 };
    FILE *f = fopen(path, "rb");
    char *buf;
    size_t n;
    int found;

    if (!f)
        return 0;
    buf = malloc(MAX);
    if (!buf) {
        fclose(f);
        return 0;
    }
    n = fread(buf, 1, MAX, f);
    fclose(f);
    if (n == MAX) { /* a line cut at the limit could be a cut number */
        while (n && buf[n - 1] != '\n')
            n--;
    }
    found = ef_vec_scene_seed(buf, n, seed);
    free(buf);
    return found;
}
