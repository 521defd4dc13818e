#!/usr/bin/env bash
# Builds upstream libgpiod v2.3 (the v2 API) into a private prefix under BUILD,
# so the GPIO transport's v2 backend can be tested on Debian 12, which ships
# only libgpiod 1.6 (docs/board-gpio.md section 7).  The release tree comes
# from ../shared/third_party (never copied into this repository); without it
# the script prints why and exits 77, the caller's "skip".
#   tests/host/libgpiod2.sh BUILD      -> BUILD/libgpiod2/prefix (pkg-config in lib/pkgconfig)
set -euo pipefail
build=${1:?usage: libgpiod2.sh BUILD}
# ../shared beside the repository; for a git worktree, beside its main clone.
repo=$(cd "$(dirname "$0")/../.." && pwd)
shared=${EF_SHARED:-$repo/../shared}
if [ -z "${EF_SHARED:-}" ] && [ ! -d "$shared" ] && common=$(git -C "$repo" rev-parse --path-format=absolute --git-common-dir 2>/dev/null); then
    shared=$(dirname "$(dirname "$common")")/shared
fi
tarball=$shared/third_party/libgpiod-2.3.tar.gz
sha=1a69754594f816c0ed425f117b56bd065d9bd1013e4685b8b04cbdf561dc519b
dir=$build/libgpiod2
prefix=$dir/prefix
if [ -f "$prefix/lib/pkgconfig/libgpiod.pc" ] || [ -f "$prefix/lib/x86_64-linux-gnu/pkgconfig/libgpiod.pc" ]; then
    exit 0
fi
if [ ! -f "$tarball" ]; then
    echo "SKIP: libgpiod v2: $tarball is absent (it lives outside the repository in ../shared)" >&2
    exit 77
fi
for tool in meson ninja; do
    command -v $tool >/dev/null || { echo "SKIP: libgpiod v2: $tool is not installed (tools/install-deps.sh test)" >&2; exit 77; }
done
echo "$sha  $tarball" | sha256sum -c --quiet - || { echo "libgpiod2.sh: $tarball: wrong sha256" >&2; exit 1; }
rm -rf "$dir" && mkdir -p "$dir/src"
tar -xzf "$tarball" -C "$dir/src" --strip-components=1
# tools and tests need more packages and are not what we test; the library and gpiod.h are.
meson setup "$dir/build" "$dir/src" --prefix="$(cd "$dir" && pwd)/prefix" --libdir=lib \
    -Dtools=disabled -Dtests=disabled -Dbindings-cxx=disabled -Dbindings-glib=disabled -Ddbus=disabled -Dintrospection=disabled -Dsystemd=disabled >"$dir/meson.log" 2>&1 ||
    { tail -n 30 "$dir/meson.log" >&2; exit 1; }
ninja -C "$dir/build" install >"$dir/ninja.log" 2>&1 || { tail -n 30 "$dir/ninja.log" >&2; exit 1; }
echo "libgpiod2.sh: built libgpiod $(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --modversion libgpiod) into $prefix"
