#!/usr/bin/env bash
# tools/format.sh [--check]: brings every tracked C and C++ file to .clang-format (`make format`),
# or with --check only reports the files and lines that differ (`make test-format`, exit 1 if any).
#
# The style is stated for clang-format 14 (Debian 12's `clang-format`); other major versions lay
# out some constructs differently, so the check skips, saying why, under any other version rather
# than fail a tree that follows the house style.  EF_CLANG_FORMAT names the binary to use.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=fix
[ "${1:-}" = --check ] && mode=check

cf=${EF_CLANG_FORMAT:-}
if [ -z "$cf" ]; then
    for c in clang-format-14 clang-format; do
        if command -v "$c" >/dev/null 2>&1; then cf=$c; break; fi
    done
fi
if [ -z "$cf" ]; then
    echo "format: SKIP: no clang-format on PATH (Debian 12: apt-get install clang-format)"
    exit 0
fi
major=$("$cf" --version | sed -n 's/.*version \([0-9]*\)\..*/\1/p' | head -n 1)
if [ "$major" != 14 ]; then
    echo "format: SKIP: $cf is version ${major:-unknown}; .clang-format is stated for clang-format 14"
    exit 0
fi

# Tracked files when this is a git checkout, else every C/C++ file outside build/.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files '*.c' '*.h' '*.cpp')
else
    mapfile -t files < <(find . -path ./build -prune -o -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) -print | sort)
fi
[ "${#files[@]}" -gt 0 ] || { echo "format: no C files found" >&2; exit 1; }

if [ $mode = fix ]; then
    "$cf" -i --style=file "${files[@]}"
    echo "format: ${#files[@]} files formatted with $cf"
    exit 0
fi

bad=0
for f in "${files[@]}"; do
    if ! "$cf" --style=file --dry-run --Werror "$f" >/dev/null 2>&1; then
        bad=$((bad + 1))
        # The first differing lines, as clang-format reports them (FILE:LINE:COL).
        { "$cf" --style=file --dry-run "$f" 2>&1 || true; } | grep -E '^[^ ]+:[0-9]+:[0-9]+:' | sed -n '1,3s/^/    /p'
    fi
done
if [ $bad -ne 0 ]; then
    echo "format: FAIL: $bad of ${#files[@]} files differ from .clang-format; run 'make format' (clang-format 14)"
    exit 1
fi
echo "format: ${#files[@]} files follow .clang-format ($cf)"
