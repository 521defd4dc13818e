#!/usr/bin/env bash
# tests/cov/rtl-coverage.sh - code coverage of the RTL (issue 27; make
# rtl-coverage, docs/testing.md "RTL code coverage").
#
#   1. Verilator --coverage (line, toggle and user points) builds the
#      whole-pipeline bench dv/tb/tb_raster.v over rtl/ at NS 8/16/32, as make
#      rtl-test builds it (W_MAX = H_MAX = 256, E_MAX = 16384), with
#      dv/coverage/vl_cov_main.cpp as main (it writes the counters), in both
#      configurations: the reference top and the fast one (the overlap
#      schedule, docs/microarch.md section 6: the skipping scan and the span
#      queue, which only its runs reach), as rtl-test's stage 6 builds it;
#   2. runs make rtl-test's Verilator cases (every shared SVG at 24x18 and
#      every 11th `edgeflag gen` level-1 case, rotating over NS x rule, the
#      tiger with random back-pressure on pix, the tiger at W_MAX x H_MAX at
#      NS 8/16/32 and tests/cov/max_canvas.scene: the top rows and columns of the
#      build), dv/tb/tb_err.v (rtl-test's DUT limit checks) and make rtl-regress's (every
#      level-1 case at 8/16/32 x the three rule settings, those that fit the
#      build), each passing `edgeflag check` (a run that does not pass fails
#      this script: coverage of a failing run means nothing); the fast
#      configuration runs the same cases against `edgeflag vectors --schedule
#      overlap` (rtl-test's stage 6 and its back-pressure tiger, the directed
#      ones, and the level-1 regression on another diagonal of the NS x rule
#      settings than the reference's);
#   3. merges the counters of both configurations (a block both use is one
#      row) with verilator_coverage, writes an lcov file and
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
#   EF_COV_CONFIGS ("ref fast"): the configurations run ("ref": only the
#                        reference top, as before the fast one existed)
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
configs=${EF_COV_CONFIGS:-ref fast}
# build keys: NS for the reference top, fNS for the fast one (rtl-test's naming)
keys=
for c in $configs; do
    case $c in ref) p= ;; fast) p=f ;; *) echo "rtl-coverage: EF_COV_CONFIGS: '$c' is not ref or fast"; echo "0 passed, 1 failed"; exit 1 ;; esac
    for ns in $nslist; do keys="$keys $p$ns"; done
done
keys=${keys# }
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
# the fast configuration (rtl-test's rtl_files_fast and its define): the same files and the span
# queue, tb_raster's EF_FAST (ef_raster SCHEDULE = 1: ef_slb_fill SKIP = 1, ef_spanq)
FRTL=("${RTL[@]}" "$root/rtl/ef_spanq.v")
FDEF=(-DEF_FAST)

# ------------------------------------------------------------ 1. builds
buildone() {     # buildone KEY: NS (the reference top) or fNS (the fast one)
    local ns=${1#f} src=("${RTL[@]}") def=()
    [ "$1" != "$ns" ] && { src=("${FRTL[@]}"); def=("${FDEF[@]}"); }
    [ -n "${EF_COV_REUSE:-}" ] && [ -x "$work/vl_$1/Vtb_raster" ] && return 0
    verilator --cc --exe --build --timing -O1 -Wno-fatal -Wno-WIDTH -I"$root/rtl" -I"$root/dv/tb" "${def[@]}" --coverage --Mdir "$work/vl_$1" \
        --top-module tb_raster -GNS="$ns" -GW_MAX=$WM -GH_MAX=$HM -GE_MAX=$EM -GFB_BITS=16 \
        "$root/dv/tb/tb_raster.v" "${src[@]}" "$root/dv/coverage/vl_cov_main.cpp" >"$work/build_$1.log" 2>&1 ||
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
# two builds at a time (EF_COV_JOBS): a --coverage build of this design takes a core and ~1 GB
for k in $keys; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
    buildone "$k" & pids+=($!)
done
for p in "${pids[@]}"; do wait "$p" || { echo "FAIL rtl-coverage: Verilator --coverage build"; echo "0 passed, 1 failed"; exit 1; }; done
echo "rtl-coverage: --coverage builds $keys (fN: the fast top) in $(( $(date +%s) - t0 )) s"

# ------------------------------------------------------------ 2. runs
[ -f "$work/gen/index.tsv" ] || "$EF" gen -o "$work/gen" >/dev/null 2>&1 || { echo "FAIL rtl-coverage: edgeflag gen"; echo "0 passed, 1 failed"; exit 1; }
rules=(scene nonzero evenodd)
awk 'BEGIN { print "scene 128 64"; print "shape evenodd 255 255 255 255"; printf "contour"
    for (i = 0; i < 1050; i++) printf " %.2f 1 %.2f 2", i * 0.1, i * 0.1 + 0.05; printf "\n"
    print "contour 10 40 20 45 12 50" }' >"$work/late_head.scene"
fastp=; case " $configs " in *" fast "*) fastp=f ;; esac
refon=; case " $configs " in *" ref "*) refon=1 ;; esac
# a case line: NAME|INPUT|KEY|RULE|SIZE|BP, KEY the build (NS, or fNS: the fast top, whose
# vectors are the overlap schedule's): the reference's lines and, with the fast
# configuration, each again as fast_NAME on the fast build
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
    # a row whose first record is number 2,048 or more (bit 11 of ETM's slot-list head, which
    # no level-1 case sets: their big shapes start every row's list early): a zigzag of 2,100
    # edges in pixel rows 1-2, then a triangle from row 40 (its records 2,100-2,102)
    echo "late_head_8|$work/late_head.scene|8|scene|-|-"
} >"$work/cases.base"
{
    [ -n "$refon" ] && cat "$work/cases.base"
    [ -n "$fastp" ] && awk -F'|' -v OFS='|' '$1 != "tb_err" { $1 = "fast_" $1; $3 = "f" $3; print }' "$work/cases.base"
    if [ "${EF_COV_REGRESS:-1}" != 0 ]; then
        while IFS=$'\t' read -r num file _ _ name _; do
            case $name in canvas-max*) continue ;; esac
            j=0
            for ns in 8 16 32; do for rule in scene nonzero evenodd; do
                j=$((j + 1))
                # EF_COV_REGRESS=3: the three of the nine settings on the case's diagonal (the fast
                # configuration's the next diagonal: together six of the nine)
                d=$(( (j - 1) % 3 )) r=$(( ((j - 1) / 3 + num) % 3 ))
                if [ -n "$refon" ] && { [ "${EF_COV_REGRESS:-1}" != 3 ] || [ $d = $r ]; }; then
                    echo "reg_${num}_${ns}_$rule|$work/gen/$file|$ns|$rule|-|-"
                fi
                if [ -n "$fastp" ] && { [ "${EF_COV_REGRESS:-1}" != 3 ] || [ $d = $(( (r + 1) % 3 )) ]; }; then
                    echo "fast_reg_${num}_${ns}_$rule|$work/gen/$file|f$ns|$rule|-|-"
                fi
            done; done
        done < <(tail -n +3 "$work/gen/index.tsv")
    fi
} >"$work/cases.all"
if [ -n "${EF_COV_SLICE_ONLY:-}" ]; then
    grep -v '^\(fast_\)\?reg_' "$work/cases.all" |
        awk -F'|' -v n="$EF_COV_SLICE_ONLY" '($3 == 8 || $3 == "f8") && (NR % n == 0 || $1 ~ /^(fast_)?bp_tiger$/)' >"$work/cases.txt"
else
    cp "$work/cases.all" "$work/cases.txt"
fi
one() {   # one NAME INPUT KEY RULE SIZE BP: "PASS NAME", "SKIP NAME why" or "FAIL NAME why"
    local d=$work/c/$1 a=$work/c/$1/act args=() w h me mode=--cycles pa=() r cyc ns=${3#f}
    if [ "$1" = tb_err ]; then
        r=$("$work/vl_err/Vtb_raster" +covfile="$work/dat/$1.dat" 2>&1)
        if echo "$r" | grep -q '^tb_err: PASS'; then echo "PASS $1"; else echo "FAIL $1 $(echo "$r" | grep 'tb_err' | head -n 1)"; fi
        return
    fi
    case " $keys " in *" $3 "*) ;; *) echo "SKIP $1 build $3 not built"; return ;; esac
    mkdir -p "$a"
    [ "$4" != scene ] && args+=(--rule "$4"); [ "$5" != - ] && args+=(--size "$5")
    [ "$3" != "$ns" ] && args+=(--schedule overlap)
    "$EF" vectors "$2" -o "$d" --samples "$ns" "${args[@]}" --formats hex >/dev/null 2>&1 || { echo "FAIL $1 vectors"; return; }
    read -r w h <<<"$(sed -n 's/.*; size \([0-9]*\)x\([0-9]*\);.*/\1 \2/p' "$d/cmd.stim.hex" | head -n 1)"
    if [ "$w" -gt $WM ] || [ "$h" -gt $HM ]; then echo "SKIP $1 canvas ${w}x$h over ${WM}x$HM"; rm -rf "$d"; return; fi
    me=$(awk '!/^\/\// && NF { op = substr($1, 13, 1); if (op == "2") n = 0; if (op == "3" && ++n > m) m = n } END { print m + 0 }' "$d/cmd.stim.hex")
    if [ "$me" -gt $EM ]; then echo "SKIP $1 a shape of $me edges"; rm -rf "$d"; return; fi
    cyc=$(sed -n 's/.*"cycles": \([0-9]*\).*/\1/p' "$d/manifest.json")
    if [ "${EF_COV_MAXCYC:-0}" -gt 0 ] && [ "$cyc" -gt "$EF_COV_MAXCYC" ]; then echo "SKIP $1 $cyc cycles"; rm -rf "$d"; return; fi
    case $1 in reg_*|fast_reg_*) if [ "${EF_COV_REG_MAXCYC:-0}" -gt 0 ] && [ "$cyc" -gt "$EF_COV_REG_MAXCYC" ]; then
        echo "SKIP $1 $cyc cycles"; rm -rf "$d"; return; fi ;; esac
    [ "$6" != - ] && { pa=(+bp="$6"); mode=--transactions; }
    r=$(cd "$d" && "$work/vl_$3/Vtb_raster" +cmd="$d/cmd.stim.hex" +out="$a/" +covfile="$work/dat/$1.dat" "${pa[@]}" 2>&1)
    if ! echo "$r" | grep -q '^tb_raster: DONE'; then echo "FAIL $1 bench: $(echo "$r" | grep 'tb_raster' | head -n 1)"
    elif ! "$EF" check "$d" "$a" $mode --errors 1 >/dev/null 2>&1; then echo "FAIL $1 edgeflag check $mode"
    else echo "PASS $1"; fi
    rm -rf "$d"
}
export -f one; export work EF WM HM EM keys
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
