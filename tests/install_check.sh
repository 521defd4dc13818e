#!/usr/bin/env bash
# The libraries as a user links them: install into a scratch prefix, compile
# small programs against them with pkg-config alone (static and shared), run
# them: the core (edgeflag.pc) and the vectors library (edgeflag-vectors.pc:
# read a vectors.bin, run the checker on two pairs of files, get a status).
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
pre=$(mktemp -d)
trap 'rm -rf "$pre"' EXIT
make --no-print-directory -s BUILD="$build" PREFIX="$pre" install >/dev/null
# Only what is installed: the program is compiled in the scratch prefix, away from the
# source tree, with nothing but pkg-config's flags, and uses every public header.
cat >"$pre/use.c" <<'C'
#include <edgeflag/edgeflag.h>
#include <edgeflag/ef_patterns.h>
#include <edgeflag/ef_scene.h>
#include <edgeflag.h> /* the short spelling works too */
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
    if (ef_ctx_create(&ctx, sc.width, sc.height, 8) != EF_OK || ef_image_create(&img, sc.width, sc.height) != EF_OK)
        return 1;
    if (ef_trace_enable(ctx, EF_IF_ALL, txn, NULL) != EF_OK || ef_trace_frame_begin(ctx) != EF_OK ||
        ef_scene_render(ctx, &sc, -1, &img) != EF_OK || ef_trace_frame_end(ctx, NULL) != EF_OK)
        return 1;
    int solid = img.px[2 * img.stride + 2 * 4 + 3] == 255 && img.px[6 * img.stride + 6 * 4 + 3] == 0;
    ef_image_destroy(&img);
    ef_ctx_destroy(ctx);
    ef_scene_destroy(&sc);
    printf("%lu %lu %s\n", covered, txns, ef_version());
    return covered == 9 && solid && txns > 9 && ef_pattern_is_nrooks(8, ef_pattern(8)) &&
                   strcmp(ef_version(), EF_VERSION_STRING) == 0
               ? 0
               : 1;
}
C
export PKG_CONFIG_PATH="$pre/lib/pkgconfig"
cd "$pre"
# shellcheck disable=SC2046 # pkg-config's words are separate arguments
cc -std=c11 -Wall -Wextra -Werror use.c -o use_shared $(pkg-config --cflags --libs edgeflag)
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror use.c -o use_static $(pkg-config --cflags edgeflag) lib/libedgeflag.a \
    $(pkg-config --libs-only-l --static expat)
cd - >/dev/null
LD_LIBRARY_PATH="$pre/lib" "$pre/use_shared" >/dev/null
"$pre/use_static" >/dev/null
# The command is installed too, and runs from there.
"$pre/bin/edgeflag" patterns --samples 8 >/dev/null
[ -x "$pre/bin/ef-regress-shard" ] && [ -x "$pre/bin/ef-regress-merge" ]
# The vectors library, as a testbench uses it: only `pkg-config --cflags --libs edgeflag-vectors`.
# Two runs of the installed edgeflag give the files: the tiger's vectors, the same written as a
# DUT's dumps (equal: pass), and another scene's dumps (a mismatch: fail).
"$pre/bin/edgeflag" vectors tests/data/svg/lion.svg -o "$pre/V" --samples 8 --size 32x24 --formats bin >/dev/null 2>&1
"$pre/bin/edgeflag" vectors tests/data/svg/lion.svg -o "$pre/D" --samples 8 --size 32x24 --formats bin --dump >/dev/null 2>&1
"$pre/bin/edgeflag" vectors tests/data/svg/tiger.svg -o "$pre/X" --samples 8 --size 32x24 --formats bin --dump >/dev/null 2>&1
cat >"$pre/use_vec.c" <<'C'
#include <edgeflag/ef_check.h>
#include <edgeflag/ef_gen.h>
#include <edgeflag/ef_vec.h>
#include <edgeflag/ef_vec_read.h>
#include <inttypes.h>
#include <stdio.h>
#include <string.h>
/* usage: use_vec VECTORS.bin SAME.actual.bin OTHER.actual.bin */
int main(int argc, char **argv)
{
    if (argc != 4) return 2;
    ef_vec_dump d;
    ef_vec_read_error err;
    if (ef_vec_read_path(argv[1], NULL, -1, -1, &d, &err) != EF_OK) return 1;
    const size_t npix = d.seq[EF_IF_PIX].n;
    ef_vec_dump_destroy(&d);
    ef_check_opts o;
    ef_check_result res;
    ef_check_opts_defaults(&o);
    o.expected = argv[1];
    o.actual = argv[2];
    const ef_check_status same = ef_check_run(&o, &res);
    const uint64_t compared = res.transactions;
    ef_check_result_destroy(&res);
    o.actual = argv[3];
    const ef_check_status other = ef_check_run(&o, &res);
    const uint64_t mismatches = res.mismatches;
    ef_check_result_destroy(&res);
    ef_gen_config c;
    if (ef_gen_config_defaults(&c, 1) != EF_OK) return 1;
    printf("pix %zu; same: %s, %" PRIu64 " transactions; other: %s, %" PRIu64 " mismatches; gen %u cases\n", npix,
           ef_check_status_name(same), compared, ef_check_status_name(other), mismatches, ef_gen_total(&c));
    return npix > 0 && same == EF_CHECK_PASS && compared > npix && other == EF_CHECK_FAIL && mismatches > 0 ? 0 : 1;
}
C
# A C++ testbench sees the same API (extern "C" in every header).
printf '#include <edgeflag/edgeflag.h>\n#include <edgeflag/ef_check.h>\n#include <edgeflag/ef_gen.h>\n#include <edgeflag/ef_vec.h>\n#include <edgeflag/ef_vec_read.h>\n#include <edgeflag/ef_scene.h>\n#include <edgeflag/ef_trace.h>\nint main() { return ef_check_status_name(EF_CHECK_PASS)[0] != 112; }\n' >"$pre/use_cxx.cpp"
(
    cd "$pre"
    # shellcheck disable=SC2046 # pkg-config's words are separate arguments
    cc -std=c11 -Wall -Wextra -Werror use_vec.c -o use_vec $(pkg-config --cflags --libs edgeflag-vectors)
    if command -v c++ >/dev/null 2>&1; then
        # shellcheck disable=SC2046
        c++ -std=c++11 -Wall -Wextra -Werror use_cxx.cpp -o use_cxx $(pkg-config --cflags --libs edgeflag-vectors)
    fi
)
vec_out=$(LD_LIBRARY_PATH="$pre/lib" "$pre/use_vec" "$pre/V/vectors.bin" "$pre/D/vectors.actual.bin" "$pre/X/vectors.actual.bin") ||
    { echo "install: the vectors library program failed: $vec_out"; exit 1; }
if [ -x "$pre/use_cxx" ]; then LD_LIBRARY_PATH="$pre/lib" "$pre/use_cxx"; fi
# Each shared library exports exactly the functions (and tables) its installed headers declare
# EF_API (built with -fvisibility=hidden): no internals (ef_in_*, ef_plot_*, chk_*, ...), nothing missing.
declared() { grep -hE '^EF_API ' "$@" | sed -E 's/\(.*//; s/\[.*//; s/;.*//; s/.*[ *]//' | sort -u; }
exported() { nm -D --defined-only "$1" | awk '$2 == "T" || $2 == "D" || $2 == "B" || $2 == "R" { print $3 }' | sort -u; }
inc=$pre/include/edgeflag
core_h=("$inc/edgeflag.h" "$inc/ef_api.h" "$inc/ef_filter.h" "$inc/ef_patterns.h" "$inc/ef_scene.h"
        "$inc/ef_scene_container.h" "$inc/ef_trace.h")
vec_h=("$inc/ef_vec.h" "$inc/ef_vec_read.h" "$inc/ef_check.h" "$inc/ef_gen.h")
[ "$(find "$inc" -name '*.h' | wc -l)" = $((${#core_h[@]} + ${#vec_h[@]})) ] ||
    { echo "install: headers installed: $(ls "$inc"), not the ${#core_h[@]} + ${#vec_h[@]} this test knows"; exit 1; }
# A public function declared without EF_API would be hidden from the shared library.
if grep -nE '^(const )?(unsigned )?[a-z_0-9]+ \*?ef_[a-z0-9_]+\(' "$inc"/*.h; then
    echo "install: the declarations above lack EF_API (include/edgeflag/ef_api.h)"; exit 1
fi
for lib in core vectors; do
    if [ $lib = core ]; then so=$pre/lib/libedgeflag.so.0 hs=("${core_h[@]}"); else so=$pre/lib/libedgeflag_vectors.so.0 hs=("${vec_h[@]}"); fi
    declared "${hs[@]}" >"$pre/declared"
    exported "$so" >"$pre/exported"
    [ -s "$pre/declared" ] || { echo "install: no EF_API declaration found in the $lib headers"; exit 1; }
    if ! cmp -s "$pre/declared" "$pre/exported"; then
        echo "install: $(basename "$so")'s exports differ from the EF_API declarations (< declared, > exported):"
        diff "$pre/declared" "$pre/exported" | grep '^[<>]'
        exit 1
    fi
    echo "install: $(basename "$so") exports exactly the $(wc -l <"$pre/declared") names its headers declare EF_API"
done
echo "install: pkg-config, shared and static linking work; bin/edgeflag and the regression scripts installed"
echo "install: the vectors library through pkg-config edgeflag-vectors: $vec_out"
