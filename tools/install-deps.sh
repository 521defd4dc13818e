#!/usr/bin/env bash
# Installs what edgeflag needs from Debian 12's packages, only when missing.
#   tools/install-deps.sh          build + demo: compiler, expat, libpng
#   tools/install-deps.sh test     + cmocka, clang, 32-bit multilib (the test suite)
set -euo pipefail

pkgs=(gcc make pkg-config libexpat1-dev libpng-dev)
if [ "${1:-}" = test ]; then
    pkgs+=(libcmocka-dev clang gcc-multilib libclang-rt-14-dev)
fi

missing=()
for p in "${pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "edgeflag: installing from Debian's packages: ${missing[*]}" >&2
SUDO=
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
        SUDO=sudo
    else
        echo "edgeflag: not root and no sudo; please install: ${missing[*]}" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
# A stale or empty package list makes apt-get install fail: refresh it once.
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
