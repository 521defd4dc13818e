#!/usr/bin/env bash
# tests/cov/func-coverage.sh - functional coverage of the project's own vector
# sets (issue 27, docs/testing.md): writes `edgeflag vectors` of the shared SVGs
# (tests/data/svg, at 24x18, rotating over NS 8/16/32 x rule nonzero/evenodd x
# the six filter/subpixel settings so every mode point is met) and of every
# `edgeflag gen` level-1 case (rotating over NS 8/16/32, each case under its own
# rules), then runs `edgeflag coverage --require all` over them: every cover
# point of dv/coverage/points.tsv must be hit.
#
# usage: bash tests/cov/func-coverage.sh BUILD_DIR [OUT_FILE]
#   EF_COV_SLICE=N: every Nth gen case only (default 1: all; the slice in make
#   test uses a larger N and requires only the points that slice can reach:
#   EF_COV_REQUIRE, default all).  OUT_FILE receives the full report.
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
build=${1:?usage: tests/cov/func-coverage.sh BUILD_DIR [OUT_FILE]}
out=${2:-}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
slice=${EF_COV_SLICE:-1}
require=${EF_COV_REQUIRE:-all}
jobs=${EF_COV_JOBS:-2}
[ -x "$EF" ] || { echo "func-coverage: $EF not built (make cli)"; exit 1; }
tmpbase=${TMPDIR:-/tmp}
[ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
work=$(mktemp -d "$tmpbase/edgeflag-funccov.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
t0=$(date +%s)
"$EF" gen -o "$work/gen" >/dev/null || { echo "func-coverage: edgeflag gen failed"; echo "0 passed, 1 failed"; exit 1; }
modes=()
for rule in nonzero evenodd; do for ns in 8 16 32; do for f in box tent; do for sp in none rgb bgr; do
    modes+=("$ns|$rule|$f|$sp")
done; done; done; done
{
    k=0
    for f in "$root"/tests/data/svg/*.svg; do
        for j in 0 1; do   # two settings per SVG: 24 SVGs x 2 >= the 36 modes
            IFS='|' read -r ns rule fl sp <<<"${modes[$(( (k * 2 + j) % ${#modes[@]} ))]}"
            echo "svg_$(basename "$f" .svg)_$j|$f|$ns|--rule $rule --filter $fl --subpixel $sp --size 24x18"
        done
        k=$((k + 1))
    done
    tail -n +3 "$work/gen/index.tsv" | while IFS=$'\t' read -r num file _ _ name _; do
        [ $((num % slice)) = 0 ] || continue
        case $name in canvas-max*) continue ;; esac   # 16383-pixel canvases: minutes of vectors, no point needs them
        echo "gen_$num|$work/gen/$file|$((8 << (num % 3)))|"
    done
} >"$work/cases.txt"
one() {   # one NAME INPUT NS ARGS
    # shellcheck disable=SC2086
    "$EF" vectors "$2" -o "$work/v/$1" --samples "$3" $4 --formats hex >/dev/null 2>"$work/v/$1.err" || echo "FAIL vectors $1"
}
mkdir -p "$work/v"
export -f one; export work EF
parallel -j "$jobs" --colsep '\|' one '{1}' '{2}' '{3}' '{4}' <"$work/cases.txt" >"$work/vec.txt"
pass=0 fail=0
if [ -s "$work/vec.txt" ]; then cat "$work/vec.txt"; fail=$((fail + $(grep -c . "$work/vec.txt"))); fi
n=$(grep -c . "$work/cases.txt")
"$EF" coverage "$work"/v/*/ --require "$require" >"$work/report.txt" 2>"$work/report.err"; rc=$?
[ -n "$out" ] && cp "$work/report.txt" "$out"
grep -v '^hit ' "$work/report.txt"
if [ $rc = 0 ]; then
    pass=$((pass + 1)); echo "PASS edgeflag coverage over $n vector sets (shared SVGs + gen level 1, slice $slice): every required point ($require) hit"
else
    head -5 "$work/report.err"
    fail=$((fail + 1)); echo "FAIL edgeflag coverage over $n vector sets (slice $slice): exit $rc"
fi
echo "func-coverage: $(( $(date +%s) - t0 )) s"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
