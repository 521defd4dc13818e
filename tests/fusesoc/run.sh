#!/usr/bin/env bash
# tests/fusesoc/run.sh - the FuseSoC core ef_raster.core as a lowRISC-style
# flow meets it (issue 27, make test-fusesoc): FuseSoC (PyPI, pinned in
# tools/requirements/fusesoc.txt, installed into build/venv) finds the core in
# the tree, its lint target (Verilator -Wall on ef_raster) passes, and its
# sim_icarus target runs the whole-pipeline bench on an `edgeflag vectors` set
# (a shared SVG at 16x12, 8 samples) whose dumps pass `edgeflag check --cycles`;
# and the same two with the overlap schedule (lint --SCHEDULE=1, sim_icarus
# --EF_FAST on `edgeflag vectors --schedule overlap`, docs/microarch.md section 6).
# usage: bash tests/fusesoc/run.sh BUILD_DIR.  Ends with "N passed, M failed".
set -u
export LC_ALL=C
build=${1:?usage: tests/fusesoc/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "PASS $*"; }
ko() { fail=$((fail + 1)); echo "FAIL $*"; }
[ -x "$EF" ] || { echo "fusesoc: $EF not built (make cli)"; echo "0 passed, 1 failed"; exit 1; }
EF_VENV=${EF_VENV:-$build/venv} bash "$root/tools/install-venv.sh" fusesoc >/dev/null ||
    { echo "fusesoc: tools/install-venv.sh fusesoc failed"; echo "0 passed, 1 failed"; exit 1; }
FS=${EF_VENV:-$build/venv}/bin/fusesoc
work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-fusesoc.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
core=edgeflag:ip:ef_raster

if "$FS" --cores-root "$root" core list 2>/dev/null | grep -q "^$core:0"; then
    ok "fusesoc core list finds $core in the tree"
else ko "fusesoc core list does not list $core"; fi

if "$FS" --cores-root "$root" run --build-root "$work/lint" --target lint "$core" >"$work/lint.log" 2>&1 &&
   ! grep -q '%Warning\|%Error' "$work/lint.log"; then
    ok "fusesoc run --target lint $core: Verilator -Wall on ef_raster silent"
else tail -15 "$work/lint.log"; ko "fusesoc run --target lint $core"; fi
if "$FS" --cores-root "$root" run --build-root "$work/lintf" --target lint "$core" --SCHEDULE=1 >"$work/lintf.log" 2>&1 &&
   ! grep -q '%Warning\|%Error' "$work/lintf.log"; then
    ok "fusesoc run --target lint $core --SCHEDULE=1: Verilator -Wall on ef_raster (the overlap schedule) silent"
else tail -15 "$work/lintf.log"; ko "fusesoc run --target lint $core --SCHEDULE=1"; fi

"$EF" vectors "$root/tests/data/svg/stress_pixi_bowtie.svg" -o "$work/vec" --samples 8 --size 16x12 --formats hex >/dev/null 2>&1 ||
    ko "edgeflag vectors"
mkdir -p "$work/act"
if "$FS" --cores-root "$root" run --build-root "$work/sim" --target sim_icarus "$core" \
        --cmd="$work/vec/cmd.stim.hex" --out="$work/act/" >"$work/sim.log" 2>&1 &&
   grep -q '^tb_raster: DONE' "$work/sim.log" &&
   "$EF" check "$work/vec" "$work/act" --cycles >"$work/check.log" 2>&1; then
    ok "fusesoc run --target sim_icarus $core: the bench's dumps pass edgeflag check --cycles ($(tail -n 1 "$work/check.log" | sed 's/^edgeflag check: //'))"
else tail -15 "$work/sim.log"; tail -3 "$work/check.log" 2>/dev/null; ko "fusesoc run --target sim_icarus $core"; fi

svg=$root/tests/data/svg/stress_pixi_bowtie.svg
"$EF" vectors "$svg" -o "$work/vecf" --samples 8 --size 16x12 --formats hex --schedule overlap >/dev/null 2>&1 ||
    ko "edgeflag vectors --schedule overlap"
mkdir -p "$work/actf"
if "$FS" --cores-root "$root" run --build-root "$work/simf" --target sim_icarus "$core" --EF_FAST \
        --cmd="$work/vecf/cmd.stim.hex" --out="$work/actf/" >"$work/simf.log" 2>&1 &&
   grep -q '^tb_raster: DONE' "$work/simf.log" &&
   "$EF" check "$work/vecf" "$work/actf" --cycles >"$work/checkf.log" 2>&1; then
    ok "fusesoc run --target sim_icarus $core --EF_FAST: the overlap schedule's dumps pass edgeflag check --cycles ($(tail -n 1 "$work/checkf.log" | sed 's/^edgeflag check: //'))"
else tail -15 "$work/simf.log"; tail -3 "$work/checkf.log" 2>/dev/null; ko "fusesoc run --target sim_icarus $core --EF_FAST"; fi

echo "$pass passed, $fail failed"
[ $fail = 0 ]
