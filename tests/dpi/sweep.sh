#!/usr/bin/env bash
# tests/dpi/sweep.sh - `make dpi-sweep` (not in `make test`): the lockstep
# bench (dv/dpi/tb_lockstep.sv, docs/dpi.md) with the SLB + FILL DUT
# (-DEF_TB_DUT_SLB) over every `edgeflag gen`
# level-1 case at NS = 8, 16, 32 under each shape's own rule, non-zero and
# even-odd: 261 x 9 = 2,349 runs, each a PASS with every span checked in
# lockstep or the first mismatch.  One Verilator build per NS (W_MAX = H_MAX =
# 16384, so that every canvas fits); the command stream of a case does not
# depend on NS or the rule (the bench's +rule overrides it), so each case's
# vectors are written once (cmd only).
#
# usage: bash tests/dpi/sweep.sh BUILD_DIR   (EF_DPI_KEEP=1 keeps the work dir)
# Ends with the totals; exit 0 only if every run passed.
# shellcheck disable=SC2086 # the RTL file lists ($RTL, $A_*) are split into words on purpose
set -u
export LC_ALL=C
ulimit -c 0

build=${1:?usage: tests/dpi/sweep.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
DPI=$root/dv/dpi
RTL="$root/rtl/ef_slb_fill.v $root/rtl/ef_slb_ram.v"
command -v verilator >/dev/null 2>&1 || { echo "dpi-sweep: verilator is not installed"; exit 1; }
for f in "$EF" "$build/libef_dpi.a"; do [ -e "$f" ] || { echo "dpi-sweep: $f not built"; exit 1; }; done

tmpbase=${TMPDIR:-/tmp}
[ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
work=$(mktemp -d "$tmpbase/edgeflag-dpi-sweep.XXXXXX") || exit 1
if [ -n "${EF_DPI_KEEP:-}" ]; then echo "dpi-sweep: keeping $work"; else trap 'rm -rf "$work"' EXIT; fi
t0=$(date +%s)
"$EF" vectors --rtl-headers -o "$work/hdr" >"$work/hdr.log" 2>&1 || { cat "$work/hdr.log"; exit 1; }

for ns in 8 16 32; do
    verilator --binary --timing --timescale 1ns/1ns -j 2 --Mdir "$work/vl$ns" --top-module tb_lockstep \
        -GNS="$ns" -GW_MAX=16384 -GH_MAX=16384 -GE_MAX=4194304 -DEF_TB_DUT_SLB -I"$root/rtl" "$work/hdr/ef_ifaces_pkg.sv" "$DPI/ef_model_pkg.sv" "$DPI/tb_lockstep.sv" $RTL \
        "$build/libef_dpi.a" -o tb >"$work/build$ns.log" 2>&1 ||
        { tail -n 30 "$work/build$ns.log"; echo "dpi-sweep: verilator build NS=$ns failed"; exit 1; }
done
echo "dpi-sweep: 3 builds in $(( $(date +%s) - t0 )) s"

"$EF" gen -o "$work/gen" >"$work/gen.log" 2>&1 || { cat "$work/gen.log"; exit 1; }
runs=0 failed=0 spans=0
while IFS=$'\t' read -r k f kind _ name _; do
    case $k in ''|'#'*|case) continue ;; esac
    d=$work/v/$k
    if ! "$EF" vectors "$work/gen/$f" -o "$d" --formats hex --interfaces cmd >"$work/vectors.log" 2>&1; then
        cat "$work/vectors.log"; echo "FAIL $f ($name): edgeflag vectors"; failed=$((failed + 1)); continue
    fi
    for ns in 8 16 32; do
        for rule in scene nonzero evenodd; do
            runs=$((runs + 1))
            ( "$work/vl$ns/tb" +cmd="$d/cmd.stim.hex" +rule="$rule" >"$work/sim" 2>&1; echo $? >"$work/rc" ) 2>/dev/null
            line=$(grep -m1 '^tb_lockstep: \(PASS\|FAIL\)' "$work/sim")
            if [ "$(cat "$work/rc")" = 0 ] && [ "${line#tb_lockstep: PASS}" != "$line" ]; then
                n=$(printf '%s\n' "$line" | sed -n 's/.*, \([0-9]*\) span, .*/\1/p')
                spans=$((spans + ${n:-0}))
            else
                failed=$((failed + 1))
                echo "FAIL $f ($kind $name) NS=$ns rule=$rule: ${line:-no result (exit $(cat "$work/rc"))}"
            fi
        done
    done
    rm -rf "$d"
done <"$work/gen/index.tsv"
echo "dpi-sweep: $runs runs ($(( runs / 9 )) gen level-1 cases x NS 8/16/32 x 3 rule settings), $spans spans checked in lockstep, $failed failed, $(( $(date +%s) - t0 )) s"
[ "$failed" -eq 0 ]
