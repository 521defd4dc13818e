#!/usr/bin/env bash
# tests/rtl/rtl-regress.sh - the RTL regression (make rtl-regress, not in make
# test): ef_raster under Verilator on every `edgeflag gen` level-1 case at
# 8/16/32 samples x the three rule settings (scene, nonzero, evenodd), and the
# tiger at 640x480 at 8 samples; `edgeflag check --cycles` on all six
# interfaces for each.  Both configurations (EF_RTL_CONFIGS, default
# "reference fast"): ef_raster against the reference vectors, and
# ef_raster with SCHEDULE=1 (-DEF_FAST) against `edgeflag vectors --schedule
# overlap` (docs/microarch.md section 6), its cases named fast_*.  Prints one line per failure and a summary with the
# simulated cycles per second.  EF_RTL_JOBS (default 2); EF_RTL_SLICE=N runs
# every Nth gen case only (default 1: all), the tiger always.
# One build configuration (EF_RTL_W_MAX, EF_RTL_H_MAX, EF_RTL_E_MAX: default
# 16384 x 16384, 8192 edges, the frame memory model 2^21 pixels), built once
# per sample count: `edgeflag gen` gets these limits (docs/gen.md section 11)
# and fits every case to them or refuses it by name before any simulation, so
# the bench should refuse nothing; a case it refuses all the same (its
# REFUSED line quoted) is counted and listed apart from failures, as are gen's
# refusals, and neither fails the run.
# Simulation speed (issue 25): Verilator -O3 --x-assign fast --x-initial fast, the C++ compiled
# by clang++ -O3 when it is installed (about 1.3x less CPU time than g++ -O2 on the tiger), else
# g++; the summary gives simulated cycles per second of wall time and of CPU time (user + sys:
# on a shared machine the wall time measures the other jobs too).
# shellcheck disable=SC2086 # the RTL file lists ($RTL, $A_*) are split into words on purpose
set -u
export LC_ALL=C
build=${1:?usage: tests/rtl/rtl-regress.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
R=$root/rtl
RTL="$R/ef_raster.v $R/ef_dec.v $R/ef_setup.v $R/ef_div.v $R/ef_etm.v $R/ef_aet.v $R/ef_plot.v $R/ef_slb_fill.v $R/ef_slb_ram.v $R/ef_cov.v"
FAST="$RTL $R/ef_spanq.v"
configs=${EF_RTL_CONFIGS:-reference fast}
jobs=${EF_RTL_JOBS:-2}
slice=${EF_RTL_SLICE:-1}
work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-rtlregress.XXXXXX") || exit 1
[ -n "${EF_RTL_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
WM=${EF_RTL_W_MAX:-16384} HM=${EF_RTL_H_MAX:-16384} EM=${EF_RTL_E_MAX:-8192}
VLOPT=(-O3 --x-assign fast --x-initial fast -CFLAGS -O3)
if command -v clang++ >/dev/null 2>&1; then
    # Debian's Verilator is configured for g++ (-fcoroutines); clang++ takes -std=c++20 for --timing
    VLOPT+=(--compiler clang -MAKEFLAGS CXX=clang++ -MAKEFLAGS LINK=clang++ -MAKEFLAGS CFG_CXXFLAGS_COROUTINES=-std=c++20)
fi
for cfg in $configs; do
    case $cfg in reference) files=$RTL def=() ;; fast) files=$FAST def=(-DEF_FAST) ;; *) echo "rtl-regress: EF_RTL_CONFIGS: reference and/or fast, not '$cfg'"; exit 2 ;; esac
    for ns in 8 16 32; do
        verilator --binary --timing "${VLOPT[@]}" -Wall "$root/dv/lint/waivers.vlt" -I"$R" -I"$root/dv/tb" "${def[@]}" --Mdir "$work/vl_${cfg}_$ns" --top-module tb_raster \
            -GNS=$ns -GW_MAX="$WM" -GH_MAX="$HM" -GE_MAX="$EM" -GFB_BITS=21 -GCMD_MAX=1048576 \
            "$root/dv/tb/tb_raster.v" $files >"$work/build_${cfg}_$ns.log" 2>&1 || { tail "$work/build_${cfg}_$ns.log"; exit 1; }
    done
done
"$EF" gen -o "$work/gen" --dut-limits "${WM}x$HM" --dut-edges "$EM" --dut-samples 8,16,32 >"$work/gen.out" || exit 1
grep ' refused by the DUT' "$work/gen.out" | sed 's/^edgeflag gen: /rtl-regress: refused before simulation: /'
echo "rtl-regress: $(sed -n 's/.*the DUT.s limits (\(.*\)): \([0-9]*\) fitted, \([0-9]*\) refused.*/edgeflag gen: \2 cases fitted and \3 refused before simulation by the limits \1/p' "$work/gen.out")"
one() {   # one NAME INPUT NS RULE SIZE CONFIG
    local d=$work/c/$1 a=$work/c/$1/act args=() out t0 t1
    mkdir -p "$a"
    [ "$4" != scene ] && args+=(--rule "$4"); [ "$5" != - ] && args+=(--size "$5"); [ "$6" = fast ] && args+=(--schedule overlap)
    "$EF" vectors "$2" -o "$d" --samples "$3" "${args[@]}" --formats hex >/dev/null 2>&1 || { echo "FAIL $1: vectors"; return; }
    local vl=vl_$6_$3
    local cpu TIMEFORMAT='%U %S'
    t0=$(date +%s.%N)
    { time "$work/$vl/Vtb_raster" +cmd="$d/cmd.stim.hex" +out="$a" >"$d/sim.out" 2>&1; } 2>"$d/sim.time"
    t1=$(date +%s.%N)
    out=$(cat "$d/sim.out")
    cpu=$(awk '{ print $1 + $2 }' "$d/sim.time")
    if echo "$out" | grep -q '^tb_raster: REFUSED'; then
        echo "REFUSED $1: $(echo "$out" | grep -m1 '^tb_raster: REFUSED' | sed "s|$d/||")"; rm -rf "$d"; return
    fi
    echo "$out" | grep -q '^tb_raster: DONE' || { echo "FAIL $1: $(echo "$out" | grep -m1 '^tb_raster: ')"; rm -rf "$d"; return; }
    "$EF" check "$d" "$a" --cycles --errors 1 >/dev/null 2>&1 || { echo "FAIL $1: edgeflag check --cycles"; return; }
    echo "PASS $1 $(echo "$out" | sed -n 's/.* \([0-9]*\) cycles.*/\1/p') $(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }') $(grep -c . "$d/pix.expected.hex") $cpu"
    rm -rf "$d"
}
export -f one; export work EF
for cfg in $configs; do
    p=; [ "$cfg" = fast ] && p=fast_
    echo "${p}tiger_640x480_8|$root/tests/data/svg/tiger.svg|8|scene|640x480|$cfg"
    tail -n +3 "$work/gen/index.tsv" | while IFS=$'\t' read -r num file _; do
        [ $((num % slice)) = 0 ] || continue
        for ns in 8 16 32; do for rule in scene nonzero evenodd; do
            echo "${p}gen_${num}_${ns}_$rule|$work/gen/$file|$ns|$rule|-|$cfg"
        done; done
    done
done | parallel -j "$jobs" --colsep '\|' one '{1}' '{2}' '{3}' '{4}' '{5}' '{6}' >"$work/results.txt"
grep '^FAIL' "$work/results.txt"
grep '^PASS fast_tiger' "$work/results.txt" | awk '{ printf "rtl-regress: ef_raster SCHEDULE=1: tiger 640x480, 8 samples: %d cycles in %.1f s of Verilator (%.0f cycles/s), %.2f s of CPU (%.0f cycles/s)\n", $3, $4, $3 / $4, $6, $3 / ($6 > 0 ? $6 : 1e-9) }'
awk '/^PASS fast_/ { n++; c += $3 } /^(FAIL|REFUSED) fast_/ { f++ } END { if (n + f) printf "rtl-regress: ef_raster SCHEDULE=1 (the overlap schedule): %d passed cycle-exact, %d failed or refused (counted in the line below too), %d frame cycles\n", n, f, c }' "$work/results.txt"
grep '^PASS tiger' "$work/results.txt" | awk '{ printf "rtl-regress: tiger 640x480, 8 samples: %d cycles in %.1f s of Verilator (%.0f cycles/s), %.2f s of CPU (%.0f cycles/s)\n", $3, $4, $3 / $4, $6, $3 / ($6 > 0 ? $6 : 1e-9) }'
grep '^REFUSED' "$work/results.txt"
awk -v cfg="W_MAX $WM, H_MAX $HM, E_MAX $EM" -v g="$(tail -n +3 "$work/gen/refused.tsv" | wc -l)" '/^PASS/ { n++; c += $3; s += $4; u += $6 } /^FAIL/ { f++ } /^REFUSED/ { r++ }
    END { printf "rtl-regress: one build configuration (%s; one build per NS and top): %d passed, %d failed, %d refused by the bench, %d cases refused by gen before simulation (refusals are not failures); %d frame cycles simulated in %.0f s of simulation (%.0f cycles/s), %.0f s of CPU (%.0f cycles/s)\n", cfg, n, f, r, g, c, s, (s > 0 ? c / s : 0), u, (u > 0 ? c / u : 0) }' "$work/results.txt"
! grep -q '^FAIL' "$work/results.txt"
