#!/usr/bin/env bash
# The library as a user links it: install into a scratch prefix, compile a
# small program against it with pkg-config (static and shared), run both.
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
pre=$(mktemp -d)
trap 'rm -rf "$pre"' EXIT
make --no-print-directory -s BUILD="$build" PREFIX="$pre" install >/dev/null
# Only what is installed: the program is compiled in the scratch prefix, away from the
# source tree, with nothing but pkg-config's flags, and uses every public header.
cat >"$pre/use.c" <<'C'
#include <edgeflag.h>
#include <ef_patterns.h>
#include <ef_scene.h>
#include <ef_trace.h>
#include <stdio.h>
#include <string.h>
static unsigned long txns;
static void txn(void *u, const ef_txn *t) { (void)u; (void)t; txns++; }
static unsigned long covered;
static void span(void *u, int32_t y, int32_t x, int32_t len, uint32_t mask)
{ (void)u; (void)y; (void)x; covered += (unsigned long)len * (mask == 0xffffu); }
int main(void)
{
    ef_ctx *ctx;
    if (ef_ctx_create(&ctx, 8, 8, 16) != EF_OK) return 1;
    ef_point p[4] = { { 256, 256 }, { 1024, 256 }, { 1024, 1024 }, { 256, 1024 } };
    uint32_t start[2] = { 0, 4 };
    ef_polygon poly = { p, start, 1 };
    if (ef_rasterize(ctx, &poly, EF_RULE_NONZERO, span, NULL) != EF_OK) return 1;
    ef_ctx_destroy(ctx);
    /* The readers and the trace, through the scene container. */
    static const char svg[] = "<svg xmlns='http://www.w3.org/2000/svg' width='8' height='8'>"
                              "<rect x='1' y='1' width='3' height='3'/></svg>";
    ef_scene sc;
    ef_error err;
    ef_load_opts opts = { 0, 0, NULL, NULL };
    ef_image img;
    if (ef_scene_load_svg("use.svg", svg, strlen(svg), &opts, &sc, &err) != EF_OK || sc.nshapes != 1) return 1;
    if (ef_ctx_create(&ctx, sc.width, sc.height, 8) != EF_OK || ef_image_alloc(&img, sc.width, sc.height) != EF_OK)
        return 1;
    if (ef_trace_enable(ctx, EF_IF_ALL, txn, NULL) != EF_OK || ef_trace_frame_begin(ctx) != EF_OK ||
        ef_scene_render(ctx, &sc, -1, &img) != EF_OK || ef_trace_frame_end(ctx, NULL) != EF_OK)
        return 1;
    int solid = img.px[2 * img.stride + 2 * 4 + 3] == 255 && img.px[6 * img.stride + 6 * 4 + 3] == 0;
    ef_image_free(&img);
    ef_ctx_destroy(ctx);
    ef_scene_free(&sc);
    printf("%lu %lu\n", covered, txns);
    return covered == 9 && solid && txns > 9 && ef_pattern_is_nrooks(8, ef_pattern(8)) ? 0 : 1;
}
C
export PKG_CONFIG_PATH="$pre/lib/pkgconfig"
cd "$pre"
cc -std=c11 -Wall -Wextra -Werror use.c -o use_shared $(pkg-config --cflags --libs edgeflag)
cc -std=c11 -Wall -Wextra -Werror use.c -o use_static $(pkg-config --cflags edgeflag) lib/libedgeflag.a \
    $(pkg-config --libs-only-l --static expat)
cd - >/dev/null
LD_LIBRARY_PATH="$pre/lib" "$pre/use_shared" >/dev/null
"$pre/use_static" >/dev/null
# The command is installed too, and runs from there.
"$pre/bin/edgeflag" patterns --samples 8 >/dev/null
[ -x "$pre/bin/ef-regress-shard" ] && [ -x "$pre/bin/ef-regress-merge" ]
# The shared library exports exactly the functions the installed headers declare EF_API
# (built with -fvisibility=hidden): no internals (ef_in_*, ef_plot_*, ...), nothing missing.
grep -h 'EF_API' "$pre"/include/edgeflag/*.h | grep -v '^ *#' | grep -o 'EF_API[^(]*(' | sed 's/($//; s/.*[ *]//' | sort -u >"$pre/declared"
nm -D --defined-only "$pre/lib/libedgeflag.so.0" | awk '$2 == "T" || $2 == "D" || $2 == "B" || $2 == "R" { print $3 }' |
    sort -u >"$pre/exported"
# A public function declared without EF_API would be hidden from the shared library.
if grep -nE '^(const )?[a-z_0-9]+ \*?ef_[a-z0-9_]+\(' "$pre"/include/edgeflag/*.h; then
    echo "install: the declarations above lack EF_API (include/edgeflag/ef_api.h)"; exit 1
fi
[ -s "$pre/declared" ] || { echo "install: no EF_API declaration found in the installed headers"; exit 1; }
if ! cmp -s "$pre/declared" "$pre/exported"; then
    echo "install: libedgeflag.so's exports differ from the EF_API declarations (< declared, > exported):"
    diff "$pre/declared" "$pre/exported" | grep '^[<>]'
    exit 1
fi
echo "install: libedgeflag.so exports exactly the $(wc -l <"$pre/declared") functions its headers declare EF_API"
echo "install: pkg-config, shared and static linking work; bin/edgeflag and the regression scripts installed"
