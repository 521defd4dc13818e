#!/usr/bin/env bash
# tests/cov/rtl-coverage.sh - code coverage of the RTL (issue 27; make
# rtl-coverage, docs/testing.md "RTL code coverage").
#
#   1. Verilator --coverage (line, toggle and user points) builds the
#      whole-pipeline bench dv/tb/tb_raster.v over rtl/ at NS 8/16/32, as make
#      rtl-test builds it (W_MAX = H_MAX = 256, E_MAX = 16384), with
#      dv/coverage/vl_cov_main.cpp as main (it writes the counters);
#   2. runs make rtl-test's Verilator cases (every shared SVG at 24x18 and
#      every 11th `edgeflag gen` level-1 case, rotating over NS x rule, the
#      tiger with random back-pressure on pix, the tiger at W_MAX x H_MAX at
#      NS 8/16/32 and tests/cov/max_canvas.scene: the top rows and columns of the
#      build), dv/tb/tb_err.v (rtl-test's DUT limit checks) and make rtl-regress's (every
#      level-1 case at 8/16/32 x the three rule settings, those that fit the
#      build), each passing `edgeflag check` (a run that does not pass fails
#      this script: coverage of a failing run means nothing);
#   3. merges the counters with verilator_coverage, writes an lcov file and
#      Debian's genhtml report (OUT/html/index.html), and prints one line per
#      module (dv/coverage/cov_summary.py): lines, branches, toggle bits, with
#      the holes not waived in dv/coverage/waivers.tsv.
#
# usage: bash tests/cov/rtl-coverage.sh BUILD_DIR [OUT_DIR]   (OUT_DIR default
#        BUILD_DIR/rtl-coverage)
#   EF_COV_REGRESS=0     only rtl-test's cases (the slice, make test-rtl-cov, uses
#                        EF_COV_SLICE_ONLY=N: every Nth of them at NS 8);
#                        EF_COV_REGRESS=3: each level-1 case at three settings
#                        (NS 8/16/32, the rule rotating) instead of all nine
#   EF_COV_MAXCYC=N      leave out cases of more than N cycles (default: none);
#                        EF_COV_REG_MAXCYC=N only the level-1 regression's
#   EF_COV_REUSE=DIR     a work folder kept (EF_COV_KEEP=1) by an earlier run of
#                        the same tree: its --coverage builds are reused
#   EF_COV_REQUIRE=1     exit 1 unless the targets are met (every line and
#                        branch hit or waived, toggles >= 95 % per module)
#   EF_COV_JOBS (2), EF_COV_NS ("8 16 32")
# Ends with "N passed, M failed".
set -u
export LC_ALL=C
build=${1:?usage: tests/cov/rtl-coverage.sh BUILD_DIR [OUT_DIR]}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
out=${2:-$build/rtl-coverage}
case $out in /*) ;; *) out=$PWD/$out ;; esac
EF=$build/edgeflag
jobs=${EF_COV_JOBS:-2}
nslist=${EF_COV_NS:-8 16 32}
WM=256 HM=256 EM=16384
pass=0 fail=0
for t in verilator verilator_coverage python3 parallel; do
    command -v $t >/dev/null 2>&1 || { echo "rtl-coverage: $t is not installed ('make deps-test')"; echo "0 passed, 1 failed"; exit 1; }
done
[ -x "$EF" ] || { echo "rtl-coverage: $EF not built (make cli)"; echo "0 passed, 1 failed"; exit 1; }
tmpbase=${TMPDIR:-/tmp}
[ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
if [ -n "${EF_COV_REUSE:-}" ]; then
    work=$EF_COV_REUSE EF_COV_KEEP=1
    rm -rf "$work/dat" "$work/c" "$work"/batch.*
else
    work=$(mktemp -d "$tmpbase/edgeflag-rtlcov.XXXXXX") || exit 1
fi
if [ -n "${EF_COV_KEEP:-}" ]; then echo "rtl-coverage: keeping $work"; else trap 'rm -rf "$work"' EXIT; fi
t0=$(date +%s)
files=(ef_raster.v ef_dec.v ef_setup.v ef_div.v ef_etm.v ef_aet.v ef_plot.v ef_slb_fill.v ef_slb_ram.v ef_cov.v)
RTL=("${files[@]/#/$root/rtl/}")

# ------------------------------------------------------------ 1. builds
buildone() {
    [ -n "${EF_COV_REUSE:-}" ] && [ -x "$work/vl_$1/Vtb_raster" ] && return 0
    verilator --cc --exe --build --timing -O1 -Wno-fatal -Wno-WIDTH -I"$root/rtl" -I"$root/dv/tb" --coverage --Mdir "$work/vl_$1" \
        --top-module tb_raster -GNS="$1" -GW_MAX=$WM -GH_MAX=$HM -GE_MAX=$EM -GFB_BITS=16 \
        "$root/dv/tb/tb_raster.v" "${RTL[@]}" "$root/dv/coverage/vl_cov_main.cpp" >"$work/build_$1.log" 2>&1 ||
        { tail -20 "$work/build_$1.log"; return 1; }
}
# and dv/tb/tb_err.v (make rtl-test's DUT limit checks: the error paths that tb_raster's
# refusals keep from the DUT), W_MAX = H_MAX = 16, E_MAX = 8; --prefix gives its model the
# class name vl_cov_main.cpp runs
builderr() {
    [ -n "${EF_COV_REUSE:-}" ] && [ -x "$work/vl_err/Vtb_raster" ] && return 0
    verilator --cc --exe --build --timing -O1 -Wno-fatal -Wno-WIDTH -I"$root/rtl" -I"$root/dv/tb" --coverage --Mdir "$work/vl_err" \
        --top-module tb_err --prefix Vtb_raster "$root/dv/tb/tb_err.v" "${RTL[@]}" "$root/dv/coverage/vl_cov_main.cpp" \
        >"$work/build_err.log" 2>&1 || { tail -20 "$work/build_err.log"; return 1; }
}
pids=()
builderr & pids+=($!)
for ns in $nslist; do buildone "$ns" & pids+=($!); done
for p in "${pids[@]}"; do wait "$p" || { echo "FAIL rtl-coverage: Verilator --coverage build"; echo "0 passed, 1 failed"; exit 1; }; done
echo "rtl-coverage: --coverage builds at NS $nslist in $(( $(date +%s) - t0 )) s"

# ------------------------------------------------------------ 2. runs
[ -f "$work/gen/index.tsv" ] || "$EF" gen -o "$work/gen" >/dev/null 2>&1 || { echo "FAIL rtl-coverage: edgeflag gen"; echo "0 passed, 1 failed"; exit 1; }
rules=(scene nonzero evenodd)
{
    k=0
    for f in "$root"/tests/data/svg/*.svg; do
        echo "svg_$(basename "$f" .svg)|$f|$((8 << (k % 3)))|${rules[$(( (k / 3) % 3 ))]}|24x18|-"; k=$((k + 1))
    done
    while IFS=$'\t' read -r num file _ _ name _; do
        case $name in canvas-max*|zigzag-4096|same-cell-4096) continue ;; esac
        if [ $((num % 11)) = 0 ]; then
            echo "gen_$num|$work/gen/$file|$((8 << (k % 3)))|${rules[$(( (k / 3) % 3 ))]}|-|-"; k=$((k + 1))
        fi
    done < <(tail -n +3 "$work/gen/index.tsv")
    echo "bp_tiger|$root/tests/data/svg/tiger.svg|8|scene|24x18|424242"
    echo "tb_err|-|8|-|-|-"
    # directed (added after the first measurement): no case above reaches the build's top
    # rows and columns (coordinate bits 8 and up, occupancy rows past 138): the tiger filling
    # W_MAX x H_MAX does
    for ns in 8 16 32; do echo "max_tiger_$ns|$root/tests/data/svg/tiger.svg|$ns|scene|${WM}x$HM|-"; done
    # and the full width with the sink cell and the right clamp (tests/cov/max_canvas.scene)
    echo "max_rect_8|$root/tests/cov/max_canvas.scene|8|scene|${WM}x$HM|-"
    if [ "${EF_COV_REGRESS:-1}" != 0 ]; then
        while IFS=$'\t' read -r num file _ _ name _; do
            case $name in canvas-max*) continue ;; esac
            j=0
            for ns in 8 16 32; do for rule in scene nonzero evenodd; do
                j=$((j + 1))
                # EF_COV_REGRESS=3: the three of the nine settings on the case's diagonal
                [ "${EF_COV_REGRESS:-1}" = 3 ] && [ $(( (j - 1) % 3 )) != $(( ((j - 1) / 3 + num) % 3 )) ] && continue
                echo "reg_${num}_${ns}_$rule|$work/gen/$file|$ns|$rule|-|-"
            done; done
        done < <(tail -n +3 "$work/gen/index.tsv")
    fi
} >"$work/cases.all"
if [ -n "${EF_COV_SLICE_ONLY:-}" ]; then
    grep -v '^reg_' "$work/cases.all" | awk -F'|' -v n="$EF_COV_SLICE_ONLY" '$3 == 8 && (NR % n == 0 || $1 == "bp_tiger")' >"$work/cases.txt"
else
    cp "$work/cases.all" "$work/cases.txt"
fi
one() {   # one NAME INPUT NS RULE SIZE BP: "PASS NAME", "SKIP NAME why" or "FAIL NAME why"
    local d=$work/c/$1 a=$work/c/$1/act args=() w h me mode=--cycles pa=() r cyc
    if [ "$1" = tb_err ]; then
        r=$("$work/vl_err/Vtb_raster" +covfile="$work/dat/$1.dat" 2>&1)
        if echo "$r" | grep -q '^tb_err: PASS'; then echo "PASS $1"; else echo "FAIL $1 $(echo "$r" | grep 'tb_err' | head -n 1)"; fi
        return
    fi
    case " $nslist " in *" $3 "*) ;; *) echo "SKIP $1 NS $3 not built"; return ;; esac
    mkdir -p "$a"
    [ "$4" != scene ] && args+=(--rule "$4"); [ "$5" != - ] && args+=(--size "$5")
    "$EF" vectors "$2" -o "$d" --samples "$3" "${args[@]}" --formats hex >/dev/null 2>&1 || { echo "FAIL $1 vectors"; return; }
    read -r w h <<<"$(sed -n 's/.*; size \([0-9]*\)x\([0-9]*\);.*/\1 \2/p' "$d/cmd.stim.hex" | head -n 1)"
    if [ "$w" -gt $WM ] || [ "$h" -gt $HM ]; then echo "SKIP $1 canvas ${w}x$h over ${WM}x$HM"; rm -rf "$d"; return; fi
    me=$(awk '!/^\/\// && NF { op = substr($1, 13, 1); if (op == "2") n = 0; if (op == "3" && ++n > m) m = n } END { print m + 0 }' "$d/cmd.stim.hex")
    if [ "$me" -gt $EM ]; then echo "SKIP $1 a shape of $me edges"; rm -rf "$d"; return; fi
    cyc=$(sed -n 's/.*"cycles": \([0-9]*\).*/\1/p' "$d/manifest.json")
    if [ "${EF_COV_MAXCYC:-0}" -gt 0 ] && [ "$cyc" -gt "$EF_COV_MAXCYC" ]; then echo "SKIP $1 $cyc cycles"; rm -rf "$d"; return; fi
    case $1 in reg_*) if [ "${EF_COV_REG_MAXCYC:-0}" -gt 0 ] && [ "$cyc" -gt "$EF_COV_REG_MAXCYC" ]; then
        echo "SKIP $1 $cyc cycles"; rm -rf "$d"; return; fi ;; esac
    [ "$6" != - ] && { pa=(+bp="$6"); mode=--transactions; }
    r=$(cd "$d" && "$work/vl_$3/Vtb_raster" +cmd="$d/cmd.stim.hex" +out="$a/" +covfile="$work/dat/$1.dat" "${pa[@]}" 2>&1)
    if ! echo "$r" | grep -q '^tb_raster: DONE'; then echo "FAIL $1 bench: $(echo "$r" | grep 'tb_raster' | head -n 1)"
    elif ! "$EF" check "$d" "$a" $mode --errors 1 >/dev/null 2>&1; then echo "FAIL $1 edgeflag check $mode"
    else echo "PASS $1"; fi
    rm -rf "$d"
}
export -f one; export work EF WM HM EM nslist
mkdir -p "$work/dat" "$work/c"
parallel -j "$jobs" --colsep '\|' one '{1}' '{2}' '{3}' '{4}' '{5}' '{6}' <"$work/cases.txt" >"$work/runs.txt"
np=$(grep -c '^PASS' "$work/runs.txt"); nf=$(grep -c '^FAIL' "$work/runs.txt"); nsk=$(grep -c '^SKIP' "$work/runs.txt")
grep '^FAIL' "$work/runs.txt" | head -20
if [ "$nf" = 0 ] && [ "$np" -gt 0 ]; then
    pass=$((pass + 1)); echo "PASS rtl-coverage: $np runs under --coverage pass edgeflag check ($nsk left out: over the build's canvas, edges or EF_COV_MAXCYC)"
else
    fail=$((fail + 1)); echo "FAIL rtl-coverage: $nf of $((np + nf)) runs failed"
fi

# ------------------------------------------------------------ 3. merge, report
mkdir -p "$out"
find "$work/dat" -name '*.dat' >"$work/dats.txt"
# verilator_coverage takes the files as arguments: merge in batches
split -l 200 "$work/dats.txt" "$work/batch."
for b in "$work"/batch.*; do
    # shellcheck disable=SC2046
    verilator_coverage --write "$b.dat" $(cat "$b") >/dev/null 2>&1 || { echo "FAIL verilator_coverage merge"; fail=$((fail + 1)); }
done
verilator_coverage --write "$out/coverage.dat" "$work"/batch.*.dat >/dev/null 2>&1 || { echo "FAIL verilator_coverage merge"; fail=$((fail + 1)); }
verilator_coverage --write-info "$work/all.info" "$out/coverage.dat" >/dev/null 2>&1
if command -v lcov >/dev/null 2>&1 && command -v genhtml >/dev/null 2>&1; then
    lcov --quiet --extract "$work/all.info" "$root/rtl/*" -o "$out/rtl.info" >/dev/null 2>&1 &&
        genhtml --quiet "$out/rtl.info" -o "$out/html" >/dev/null 2>&1 &&
        [ -s "$out/html/index.html" ] && { pass=$((pass + 1)); echo "PASS rtl-coverage: HTML report $out/html/index.html (lcov/genhtml)"; } ||
        { fail=$((fail + 1)); echo "FAIL rtl-coverage: lcov/genhtml report"; }
else
    fail=$((fail + 1)); echo "FAIL rtl-coverage: lcov/genhtml not installed (tools/install-deps.sh test)"
fi
req=(); [ "${EF_COV_REQUIRE:-0}" = 1 ] && req=(--require)
python3 "$root/dv/coverage/cov_summary.py" "$out/coverage.dat" "$root/rtl" "$root/dv/coverage/waivers.tsv" \
    --holes "$out/holes.txt" "${req[@]}" | tee "$out/summary.txt"
if [ "${PIPESTATUS[0]}" = 0 ]; then pass=$((pass + 1)); echo "PASS rtl-coverage: summary $out/summary.txt${req:+ (targets met)}"
else fail=$((fail + 1)); echo "FAIL rtl-coverage: summary (targets not met or unreadable)"; fi
# The hole check must bite (issue 27): the same counters against the waivers without their first
# line waiver must give one unwaived hole more and fail --require.
wv=$root/dv/coverage/waivers.tsv
w1=$(awk -F'\t' '$1 == "line" { print $3; exit }' "$wv")
awk -F'\t' '!d && $1 == "line" { d = 1; next } { print }' "$wv" >"$work/waivers-1.tsv"
python3 "$root/dv/coverage/cov_summary.py" "$out/coverage.dat" "$root/rtl" "$work/waivers-1.tsv" \
    --holes "$work/holes-1.txt" --require >"$work/summary-1.txt" 2>&1; rc=$?
n0=$(grep -c '^HOLE' "$out/holes.txt" 2>/dev/null); n1=$(grep -c '^HOLE' "$work/holes-1.txt" 2>/dev/null)
if [ -n "$w1" ] && [ "$rc" = 1 ] && [ "${n1:-0}" -gt "${n0:-0}" ]; then
    pass=$((pass + 1)); echo "PASS rtl-coverage: the hole check bites: without the waiver '$w1' the summary has $n1 unwaived holes instead of $n0 and --require fails"
else
    fail=$((fail + 1)); echo "FAIL rtl-coverage: without the waiver '$w1' the hole check did not fail (exit $rc, $n0 -> $n1 unwaived holes)"
fi
echo "rtl-coverage: $(( $(date +%s) - t0 )) s"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
