/*
 * scene.c - the scene container, error reports and file loading.
 *
 * Place in the pipeline: the hand-over point between the front end and the
 * model.  A scene is a list of shapes (fill rule + straight RGBA8 colour),
 * each a run of closed contours of device Q16.8 points, stored in three flat
 * arrays (shapes, contour starts, points) so a shape is an ef_polygon view
 * without copying.  Invariant: start[] holds ncontours + 1 entries once the
 * first shape exists, start[ncontours] == npoints.
 *
 * ef_scene_load_file reads the whole file (at most 64 MiB), then dispatches
 * by extension: ".svg" -> ef_scene_load_svg, ".scene"/".txt" ->
 * ef_scene_load_text.  Errors leave the scene empty (freed), never partial.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_internal.h"

/* ---------------------------------------------------------------- errors */

/* Messages quote the input ("not a number: '...'"), and a hostile file must
 * not be able to write control sequences to the user's terminal or invalid
 * UTF-8 to a log: control characters, bytes that are not part of a valid
 * UTF-8 sequence and the invisible U+FEFF (a byte order mark where none
 * belongs) are written as \xNN / \uFEFF.  Valid UTF-8 (ef_utf8_len) is copied. */
static void safe_text(char *out, size_t size, const char *in)
{
    size_t o = 0;
    const unsigned char *p = (const unsigned char *)in, *end = p + strlen(in);
    while (*p) {
        size_t n = ef_utf8_len(p, (size_t)(end - p));
        char esc[8];
        const char *src = (const char *)p;
        size_t len = n;
        if (n == 0 || (n == 1 && (*p < 0x20 || *p == 0x7F))) {
            snprintf(esc, sizeof esc, "\\x%02X", *p);
            src = esc;
            len = 4;
            n = 1;
        } else if (n == 3 && p[0] == 0xEF && p[1] == 0xBB && p[2] == 0xBF) {
            src = "\\uFEFF";
            len = 6;
        }
        if (o + len >= size)
            break;
        memcpy(out + o, src, len);
        o += len;
        p += n;
    }
    out[o] = '\0';
}

ef_status ef_error_set(ef_error *e, ef_status status, const char *file, uint32_t line, uint32_t col, const char *fmt,
                       ...)
{
    if (!e)
        return status;
    e->status = status;
    if (file) {
        size_t n = strlen(file);
        if (n >= sizeof e->file)
            n = sizeof e->file - 1;
        memcpy(e->file, file, n);
        e->file[n] = '\0';
    } else {
        e->file[0] = '\0';
    }
    e->line = line;
    e->col = col;
    char raw[sizeof e->msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    safe_text(e->msg, sizeof e->msg, raw);
    return status;
}

void ef_error_format(const ef_error *e, char *buf, size_t size)
{
    if (!buf || size == 0)
        return;
    const char *file = e->file[0] ? e->file : "<input>";
    if (e->line && e->col)
        snprintf(buf, size, "%s:%u:%u: %s", file, (unsigned)e->line, (unsigned)e->col, e->msg);
    else if (e->line)
        snprintf(buf, size, "%s:%u: %s", file, (unsigned)e->line, e->msg);
    else
        snprintf(buf, size, "%s: %s", file, e->msg);
}

/* ----------------------------------------------------------------- scene */

void ef_scene_create(ef_scene *s, int32_t width, int32_t height)
{
    memset(s, 0, sizeof *s);
    s->width = width;
    s->height = height;
}

void ef_scene_destroy(ef_scene *s)
{
    free(s->shapes);
    free(s->start);
    free(s->points);
    ef_scene_create(s, 0, 0);
}

/* The room of an array of `used` elements: what grow() allocated for it, 16
 * elements and doubling, at most limit.  The scene keeps no capacity field:
 * grow() allocates exactly this for the count it is asked for, the count only
 * ever grows to that request (or stays, when a later step fails: then the
 * array has more room than this says, never less), so the room follows from
 * the count. */
static uint64_t room(uint32_t used, uint32_t limit)
{
    if (used == 0)
        return 0;
    uint64_t n = 16;
    while (n < used)
        n *= 2;
    return n < limit ? n : limit;
}

/* Grows *arr (elements of size elt, `used` of them in use) to hold need
 * elements; caps at limit. */
static ef_status grow(void **arr, uint32_t used, uint32_t need, size_t elt, uint32_t limit)
{
    if (need == 0 || (*arr && need <= room(used, limit)))
        return EF_OK;
    if (need > limit)
        return EF_ERR_LIMIT;
    const uint64_t nc = room(need, limit);
    void *p = realloc(*arr, (size_t)nc * elt);
    if (!p)
        return EF_ERR_NOMEM;
    *arr = p;
    return EF_OK;
}

ef_status ef_scene_begin_shape(ef_scene *s, ef_rule rule, ef_rgba8 color)
{
    ef_status st;
    if (rule != EF_RULE_NONZERO && rule != EF_RULE_EVENODD)
        return EF_ERR_ARG;
    if ((st = grow((void **)&s->shapes, s->nshapes, s->nshapes + 1, sizeof *s->shapes, EF_IN_MAX_SHAPES)))
        return st;
    if ((st = grow((void **)&s->start, s->start ? s->ncontours + 1 : 0, s->ncontours + 1, sizeof *s->start,
                   EF_MAX_POINTS_PER_SCENE + 1)))
        return st;
    s->start[s->ncontours] = s->npoints;
    ef_shape *sh = &s->shapes[s->nshapes++];
    sh->rule = rule;
    sh->color = color;
    sh->first_contour = s->ncontours;
    sh->ncontours = 0;
    return EF_OK;
}

ef_status ef_scene_add_contour(ef_scene *s, const ef_point *pts, uint32_t n)
{
    ef_status st;
    if (s->nshapes == 0 || (n > 0 && !pts))
        return EF_ERR_ARG;
    for (uint32_t i = 0; i < n; i++)
        if (pts[i].x <= -EF_COORD_LIMIT || pts[i].x >= EF_COORD_LIMIT || pts[i].y <= -EF_COORD_LIMIT ||
            pts[i].y >= EF_COORD_LIMIT)
            return EF_ERR_RANGE;
    if (n > EF_MAX_POINTS_PER_SCENE - s->npoints || s->ncontours >= EF_MAX_POINTS_PER_SCENE)
        return EF_ERR_LIMIT;
    /* A shape of n points has n edges: the model takes EF_MAX_EDGES_PER_SHAPE
     * (ef_rasterize), so a scene never holds a shape it cannot draw. */
    if (n > EF_MAX_EDGES_PER_SHAPE - ef_in_shape_points(s))
        return EF_ERR_LIMIT;
    if ((st = grow((void **)&s->points, s->npoints, s->npoints + n, sizeof *s->points, EF_MAX_POINTS_PER_SCENE)))
        return st;
    if ((st = grow((void **)&s->start, s->ncontours + 1, s->ncontours + 2, sizeof *s->start,
                   EF_MAX_POINTS_PER_SCENE + 1)))
        return st;
    if (n > 0)
        memcpy(s->points + s->npoints, pts, (size_t)n * sizeof *pts);
    s->npoints += n;
    s->ncontours++;
    s->start[s->ncontours] = s->npoints;
    s->shapes[s->nshapes - 1].ncontours++;
    return EF_OK;
}

ef_polygon ef_scene_polygon(const ef_scene *s, uint32_t i)
{
    ef_polygon p = { NULL, NULL, 0 };
    if (i >= s->nshapes)
        return p;
    const ef_shape *sh = &s->shapes[i];
    p.pts = s->points;
    p.start = s->start + sh->first_contour;
    p.ncontours = sh->ncontours;
    return p;
}

/* ------------------------------------------------------------ shared glue */

void ef_in_note(const ef_load_opts *opts, ef_scene *s, const char *file, uint32_t line, uint32_t col, const char *msg)
{
    s->notes++;
    if (opts && opts->note)
        opts->note(opts->note_user, file, line, col, msg);
}

ef_status ef_in_canvas_size(ef_q32 v, int32_t *out)
{
    if (v.v <= 0)
        return EF_ERR_LIMIT;
    int64_t c = ef_ceildiv_i64(v.v, EF_Q32_ONE);
    if (c < 1 || c > EF_MAX_CANVAS)
        return EF_ERR_LIMIT;
    *out = (int32_t)c;
    return EF_OK;
}

uint32_t ef_in_utf8_col(const char *line_start, size_t off)
{
    uint32_t col = 1;
    for (size_t i = 0; i < off; i++)
        if (((unsigned char)line_start[i] & 0xC0u) != 0x80u)
            col++;
    return col;
}

/* ------------------------------------------------------------- loading */

static bool ends_with_ci(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    if (k > n)
        return false;
    for (size_t i = 0; i < k; i++) {
        char c = s[n - k + i];
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != suffix[i])
            return false;
    }
    return true;
}

ef_status ef_scene_load_file(const char *path, const ef_load_opts *opts, ef_scene *out, ef_error *err)
{
    ef_error local;
    if (!err)
        err = &local;
    ef_scene_create(out, 0, 0);
    if (!path)
        return ef_error_set(err, EF_ERR_ARG, NULL, 0, 0, "no file name");
    int kind = ends_with_ci(path, ".svg") ? 1 : (ends_with_ci(path, ".scene") || ends_with_ci(path, ".txt")) ? 2 : 0;
    if (kind == 0)
        return ef_error_set(err, EF_ERR_UNSUPPORTED, path, 0, 0, "unknown file type (expected .svg, .scene or .txt)");

    FILE *f = fopen(path, "rb");
    if (!f)
        return ef_error_set(err, EF_ERR_IO, path, 0, 0, "cannot open: %s", strerror(errno));
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    if (!buf) {
        fclose(f);
        return ef_error_set(err, EF_ERR_NOMEM, path, 0, 0, "out of memory");
    }
    /* Read in chunks (no fseek/ftell: pipes and special files work too) and
     * stop one byte past the limit, so a huge file costs no more than that. */
    for (;;) {
        if (len == cap) {
            if (cap > EF_IN_MAX_FILE_BYTES) {
                free(buf);
                fclose(f);
                return ef_error_set(err, EF_ERR_LIMIT, path, 0, 0, "file larger than %u MiB",
                                    (unsigned)(EF_IN_MAX_FILE_BYTES >> 20));
            }
            /* Never more than one byte past the limit. */
            size_t nc = cap * 2 > EF_IN_MAX_FILE_BYTES + 1 ? EF_IN_MAX_FILE_BYTES + 1 : cap * 2;
            char *nb = realloc(buf, nc);
            if (!nb) {
                free(buf);
                fclose(f);
                return ef_error_set(err, EF_ERR_NOMEM, path, 0, 0, "out of memory");
            }
            buf = nb;
            cap = nc;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0)
            break;
    }
    bool bad = ferror(f) != 0;
    int saved = errno;
    fclose(f);
    if (bad) {
        free(buf);
        return ef_error_set(err, EF_ERR_IO, path, 0, 0, "read error: %s", strerror(saved));
    }
    if (len > EF_IN_MAX_FILE_BYTES) {
        free(buf);
        return ef_error_set(err, EF_ERR_LIMIT, path, 0, 0, "file larger than %u MiB",
                            (unsigned)(EF_IN_MAX_FILE_BYTES >> 20));
    }
    ef_status st = kind == 1 ? ef_scene_load_svg(path, buf, len, opts, out, err)
                             : ef_scene_load_text(path, buf, len, opts, out, err);
    free(buf);
    return st;
}
