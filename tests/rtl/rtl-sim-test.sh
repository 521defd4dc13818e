#!/usr/bin/env bash
# tests/rtl/rtl-sim-test.sh - `make test-rtl-sim`: the one command from vectors
# to a verdict (`edgeflag rtl-sim`, which runs dv/rtl-sim.sh; docs/cli.md) as
# a user runs it,
# under Icarus (a one-second build; the Verilator build is the same command
# with --sim verilator, shown in the README):
#   1. a shared SVG's vectors: exit 0, the bench's DONE line with the frame
#      length the manifest holds, edgeflag check's PASS;
#   2. the same vectors against a user's own top (--top: the RTL variant with
#      the planted fault `span`, a design with ef_raster's ports): exit 1,
#      edgeflag check's mismatches on span (and the interfaces its timing moves);
#   3. a case the DUT must refuse (a build of W_MAX 16 for a 32-pixel-wide
#      canvas): exit 3, the bench's own REFUSED line naming the file and line;
#   4. the second run of a configuration reuses its build ("cached");
#   5. usage errors: exit 2.
# usage: bash tests/rtl/rtl-sim-test.sh BUILD_DIR
set -u
export LC_ALL=C
build=${1:?usage: tests/rtl/rtl-sim-test.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
for t in iverilog vvp; do
    command -v $t >/dev/null 2>&1 || { echo "test-rtl-sim: $t is not installed ('make deps-test')"; exit 1; }
done
[ -x "$EF" ] || { echo "test-rtl-sim: $EF not built (make cli)"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-rtlsim.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
t0=$(date +%s)
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1"; [ -n "${2:-}" ] && printf '%s\n' "$2" | tail -n 15 | sed 's/^/    /'; }
S=$root/dv/rtl-sim.sh
# sim ARGS...: `edgeflag rtl-sim` of this tree
sim() { EDGEFLAG_SOURCE=$root "$EF" rtl-sim "$@"; }
svg=$root/tests/data/svg/stress_pixi_fill_rule_star_nonzero.svg
"$EF" vectors "$svg" -o "$work/v" --size 32x24 --samples 8 --formats hex >"$work/vec.log" 2>&1 ||
    { cat "$work/vec.log"; echo "test-rtl-sim: edgeflag vectors failed"; exit 1; }
cycles=$(sed -n 's/.*"cycles": \([0-9]*\).*/\1/p' "$work/v/manifest.json")

# 1. PASS
out=$(sim "$work/v" --sim icarus --cache "$work/cache" 2>&1); rc=$?
if [ $rc = 0 ] && printf '%s\n' "$out" | grep -q "^tb_raster: DONE NS=8: .*a frame of $cycles cycles;" &&
   printf '%s\n' "$out" | grep -q '^edgeflag check: PASS: 6 comparisons'; then
    ok "rtl-sim $(basename "$svg") 32x24 under Icarus: exit 0, a frame of $cycles cycles (the manifest's), edgeflag check PASS on 6 interfaces"
else
    bad "rtl-sim on a shared SVG: exit $rc" "$out"
fi
# 4. cached
out=$(sim "$work/v" --sim icarus --cache "$work/cache" --out "$work/again" 2>&1); rc=$?
if [ $rc = 0 ] && printf '%s\n' "$out" | grep -q '^rtl-sim: bench icarus-ns8-.* (cached in '; then
    ok "a second run reuses the configuration's build (cached) and passes"
else
    bad "the second run: exit $rc, no 'cached'" "$out"
fi
# 2. a user's top: the span fault variant
bash "$root/dv/rtl-variant.sh" "$work/mine" span >/dev/null || bad "dv/rtl-variant.sh span"
tops=()
for f in "$work"/mine/*.v; do tops+=(--top "$f"); done
out=$(sim "$work/v" --sim icarus --cache "$work/cache" "${tops[@]}" 2>&1); rc=$?
if [ $rc = 1 ] && printf '%s\n' "$out" | grep -q '^tb_raster: DONE' &&
   printf '%s\n' "$out" | grep -Eq '^edgeflag check: span: .* [1-9][0-9]* mismatches'; then
    ok "rtl-sim --top (a user's design with ef_raster's ports: the span-fault variant): exit 1 from edgeflag check, mismatches on span ($(printf '%s\n' "$out" | sed -n 's/^edgeflag check: span: .*, \([0-9]*\) mismatches.*/\1/p'))"
else
    bad "rtl-sim --top: exit $rc, expected 1 with a span mismatch" "$out"
fi
# 3. refused: a 32-pixel-wide canvas on a W_MAX 16 build
out=$(sim "$work/v" --sim icarus --cache "$work/cache" --w-max 16 --h-max 16 2>&1); rc=$?
line=$(grep -vn '^//' "$work/v/cmd.stim.hex" | head -n 1 | cut -d: -f1)
if [ $rc = 3 ] && printf '%s\n' "$out" | grep -qF "tb_raster: REFUSED $work/v/cmd.stim.hex:$line: FRAME canvas over the hardware's W_MAX x H_MAX" &&
   printf '%s\n' "$out" | grep -q 'rtl-sim: REFUSED: the case does not fit this build'; then
    ok "a canvas over the build's W_MAX: exit 3, the DUT's own reason printed (cmd.stim.hex:$line), nothing compared"
else
    bad "the refused case: exit $rc, expected 3 with the REFUSED line" "$out"
fi
# 5. usage
u_ok=1
for args in "" "--sim modelsim $work/v" "--ns 12 $work/v" "$work/no-such-dir" "--bogus $work/v"; do
    # shellcheck disable=SC2086 # the arguments split on purpose
    sim $args --cache "$work/cache" >"$work/usage.out" 2>&1; rc=$?
    [ $rc = 2 ] || { u_ok=0; bad "rtl-sim $args: exit $rc, expected 2" "$(cat "$work/usage.out")"; }
done
[ $u_ok = 1 ] && ok "usage errors (no folder, --sim modelsim, --ns 12, a missing folder, an unknown option): exit 2"
# the script alone, as make rtl-sim runs it
out=$(bash "$S" "$work/v" --sim icarus --cache "$work/cache" --edgeflag "$EF" --out "$work/script" 2>&1); rc=$?
if [ $rc = 0 ] && printf '%s\n' "$out" | grep -q '^edgeflag check: PASS'; then ok "dv/rtl-sim.sh alone (make rtl-sim): exit 0, PASS"
else bad "dv/rtl-sim.sh alone: exit $rc" "$out"; fi
echo "test-rtl-sim: $(( $(date +%s) - t0 )) s"
echo "test-rtl-sim: $pass passed, $fail failed"
[ $fail = 0 ]
