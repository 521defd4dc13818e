#!/usr/bin/env bash
# The library as a user links it: install into a scratch prefix, compile a
# small program against it with pkg-config (static and shared), run both.
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
pre=$(mktemp -d)
trap 'rm -rf "$pre"' EXIT
make --no-print-directory -s BUILD="$build" PREFIX="$pre" install >/dev/null
cat >"$pre/use.c" <<'C'
#include <edgeflag.h>
#include <stdio.h>
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
    printf("%lu\n", covered);
    return covered == 9 ? 0 : 1;
}
C
export PKG_CONFIG_PATH="$pre/lib/pkgconfig"
cc -std=c11 "$pre/use.c" -o "$pre/use_shared" $(pkg-config --cflags --libs edgeflag)
cc -std=c11 "$pre/use.c" -o "$pre/use_static" $(pkg-config --cflags edgeflag) "$pre/lib/libedgeflag.a" $(pkg-config --libs-only-l --static expat)
LD_LIBRARY_PATH="$pre/lib" "$pre/use_shared" >/dev/null
"$pre/use_static" >/dev/null
# The command is installed too, and runs from there.
"$pre/bin/edgeflag" patterns --samples 8 >/dev/null
[ -x "$pre/bin/ef-regress-shard" ] && [ -x "$pre/bin/ef-regress-merge" ]
echo "install: pkg-config, shared and static linking work; bin/edgeflag and the regression scripts installed"
