#!/usr/bin/env bash
# Describes the machine and the software a benchmark ran with (bench/RESULTS.md).
#   bench/machine.sh [EFBENCH]
set -u
cpu=$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //')
echo "date:       $(date -u +%Y-%m-%dT%H:%MZ)"
echo "cpu:        ${cpu:-unknown} ($(nproc 2>/dev/null || echo ?) cores online, shared with other jobs)"
echo "memory:     $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo 2>/dev/null)"
# shellcheck source=/dev/null
echo "os:         $(. /etc/os-release 2>/dev/null && echo "$PRETTY_NAME") ($(uname -sr))"
echo "compiler:   $(${CC:-cc} --version | head -n1); C++: $(${CXX:-g++} --version | head -n1)"
echo "flags:      edgeflag and the AGG adapter -O2 (OPT); Cairo, FreeType: Debian's shared libraries"
for p in libagg-dev libcairo2 libpixman-1-0 libfreetype6 libstb-dev; do
    printf '%-11s %s\n' "$p:" "$(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || echo '?')"
done
git_rev=$(git -C "$(dirname "$0")/.." rev-parse --short HEAD 2>/dev/null || echo '?')
dirty=$(git -C "$(dirname "$0")/.." status --porcelain -- model fixed bench ':!bench/results' ':!bench/RESULTS.md' 2>/dev/null | head -c1)
echo "edgeflag:   commit $git_rev${dirty:+ + local changes}"
