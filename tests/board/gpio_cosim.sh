#!/usr/bin/env bash
# tests/board/gpio_cosim.sh - edgeflag-host over GPIO into the simulated board's gateware
# (docs/board-gpio.md section 8, "Co-simulation with the gateware"): the simulated board
# (board/sim/board_sim.cpp with --gpio-listen: the SoC's GPIO bus slave board/soc/ef_gpio.py, the
# firmware's link_gpio.c, the engine, ef_raster) behind the emulated gpiochip of the tests
# (tests/host/gpio_chip.c's second back end), driven through the real libgpiod by edgeflag-host
# itself (tests/host/gpio_cosim: host/main.c compiled unchanged, in the emulator's process):
#   1. the bus through the transport (gpio_cosim --selftest): identify from the firmware, the
#      host's timing, an engine failure (err, cause ENGINE, the ERROR frame arrives), a stuck data
#      line (CONTROL), a take with nothing there (UNDERRUN), RESET clearing each;
#   2. `verify` of a bundled SVG at a small canvas (digest mode: the whole results cost minutes at
#      the emulator's speed): PASS cycle-exact;
#   3. the cable pulled mid-run (the lines go dead after 250 bytes to the board): exit 5; then
#      `verify --resume` on the same board: PASS, results byte-identical to run 2's, and fewer
#      frames sent than run 2 sent (the board kept what it had taken);
#   4. runs 1 and 2 again through libgpiod 2.3 (tests/host/libgpiod2.sh; SKIP without ../shared).
# usage: bash tests/board/gpio_cosim.sh SIM_DIR BUILD   (`make board-gpio-test`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
sim=${1:?usage: tests/board/gpio_cosim.sh SIM_DIR BUILD}
build=${2:-build}
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root" || exit 1
# shellcheck source=tests/host/waits.sh disable=SC1091
. tests/host/waits.sh
E=$build/edgeflag BS=$sim/obj/board_sim C1=$build/tests/host/gpio_cosim
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
finish() { echo "$pass passed, $fail failed"; [ "$fail" -eq 0 ]; exit $?; }
for f in "$E" "$BS" "$C1"; do
    [ -x "$f" ] || { bad "missing $f (make board-gpio-test builds it)"; finish; }
done
command -v umockdev-wrapper >/dev/null || { bad "umockdev-wrapper is missing (tools/install-deps.sh test)"; finish; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-gpiocosim.XXXXXX") || exit 1
bpid=
stop_board() {
    if [ -n "$bpid" ]; then
        kill "$bpid" 2>/dev/null
        wait "$bpid" 2>/dev/null
        bpid=
    fi
}
trap 'stop_board; rm -rf "$tmp"' EXIT
start_board() {
    stop_board
    rm -f "$tmp/gpio"
    "$BS" --dir "$sim/gateware" --gpio-listen "$tmp/gpio" --baud 0 >"$tmp/board.log" 2>&1 &
    bpid=$!
    for _ in $(seq $((EF_READY_S * 10))); do [ -S "$tmp/gpio" ] && break; sleep 0.1; done
    [ -S "$tmp/gpio" ]
}
serial=$(sed -n 's/^EF_BOARD_SERIAL ?= //p' board/firmware/firmware.mk)
lines=$("$C1" --lines)
svg=stress_pixi_fill_rule_star_nonzero.svg size=32x32
if ! "$E" vectors "tests/data/svg/$svg" -o "$tmp/v" --size $size --samples 8 >"$tmp/vec.log" 2>&1; then
    cat "$tmp/vec.log"; bad "edgeflag vectors $svg"; finish
fi
start_board || { bad "the simulated board did not come up"; cat "$tmp/board.log"; finish; }

# host NAME PROGRAM OUT [--unplug-after N] -- ARGS: edgeflag-host ARGS over the emulated chip
host() {
    local prog=$1 out=$2; shift 2
    timeout "$EF_GUARD_S" umockdev-wrapper "$prog" "$tmp/gpio" "$@" >"$out" 2>&1
}
V=(verify "$tmp/v/vectors.bin" --transport gpio --chip gpiochip0 --lines "$lines" --digest 64)

run_set() { # NAME TAG PROGRAM
    local name=$1 tag=$2 prog=$3 rc t0 ms
    host "$prog" "$tmp/self-$tag.out" --selftest "$serial"
    rc=$?
    if [ $rc = 0 ] && grep -q 'checks, 0 failed' "$tmp/self-$tag.out"; then
        ok "$name: the bus through the gateware: $(sed -n 's/^gpio-cosim: //p' "$tmp/self-$tag.out" | tr '\n' ';' | sed 's/;$//')"
    else
        bad "$name: the bus through the gateware" "exit $rc; $(tail -n 8 "$tmp/self-$tag.out")"
    fi
    t0=$(date +%s%N)
    host "$prog" "$tmp/verify-$tag.out" -- "${V[@]}" --results "$tmp/res-$tag" --timeout "$EF_LINK_MS"
    rc=$?
    ms=$((($(date +%s%N) - t0) / 1000000))
    if [ $rc = 0 ] && grep -q 'edgeflag check: PASS: 6 comparisons.*cycle-exact' "$tmp/verify-$tag.out"; then
        ok "$name: verify $svg at $size over GPIO into the gateware, digest mode: $(sed -n 's/.*check: PASS: //p' "$tmp/verify-$tag.out") ($ms ms)"
    else
        bad "$name: verify over GPIO" "exit $rc; $(tail -n 8 "$tmp/verify-$tag.out")"
    fi
}

echo "test: edgeflag-host over emulated GPIO into the simulated board's gateware"
v1=$(pkg-config --modversion libgpiod 2>/dev/null)
run_set "libgpiod ${v1:-?}" v1 "$C1"

# 3. the cable pulled mid-run, then --resume on the same (powered) board
host "$C1" "$tmp/unplug.out" --unplug-after 250 -- "${V[@]}" --results "$tmp/res-unplug" --timeout 500
rc=$?
if [ $rc = 5 ] && grep -q 'unplugged after' "$tmp/unplug.out"; then
    host "$C1" "$tmp/resume.out" -- "${V[@]}" --results "$tmp/res-unplug" --resume --timeout "$EF_LINK_MS"
    rc=$?
    first=$tmp/res-v1/vectors.actual.bin
    # the resumed run sends only what the board had not taken (the clean run sent them all)
    nall=$(sed -n 's/.* commands in \([0-9]*\) frames.*/\1/p' "$tmp/verify-v1.out")
    nres=$(sed -n 's/.* commands in \([0-9]*\) frames.*/\1/p' "$tmp/resume.out")
    if [ $rc = 0 ] && grep -q 'edgeflag check: PASS' "$tmp/resume.out" &&
       cmp -s "$tmp/res-unplug/vectors.actual.bin" "$first" && [ "${nres:-99}" -lt "${nall:-0}" ]; then
        ok "unplugged after 250 bytes to the board (exit 5), then --resume: PASS, results byte-identical, $nres of $nall frames sent"
    else
        bad "--resume after the unplug" "exit $rc, $nres of $nall frames sent, results $(cmp -s "$tmp/res-unplug/vectors.actual.bin" "$first" && echo equal || echo differ); $(tail -n 6 "$tmp/resume.out")"
    fi
else
    bad "the unplug" "exit $rc (want 5); $(tail -n 6 "$tmp/unplug.out")"
fi

# 4. libgpiod 2.3
bash tests/host/libgpiod2.sh "$build" >"$tmp/gpiod2.log" 2>&1
rc=$?
if [ $rc = 77 ]; then
    echo "SKIP - libgpiod 2.3: $(grep SKIP "$tmp/gpiod2.log") (not counted)"
elif [ $rc != 0 ]; then
    bad "building libgpiod 2.3" "$(tail -n 5 "$tmp/gpiod2.log")"
elif ! ${MAKE:-make} --no-print-directory -s gpio-cosim-v2 BUILD="$build" >"$tmp/build-v2.log" 2>&1; then
    bad "building gpio_cosim against libgpiod 2.3" "$(tail -n 5 "$tmp/build-v2.log")"
else
    run_set "libgpiod 2.3" v2 "$build/tests/host/gpio_cosim_v2"
    if cmp -s "$tmp/res-v2/vectors.actual.bin" "$tmp/res-v1/vectors.actual.bin"; then
        ok "libgpiod 2.3 and ${v1:-?} brought back the same results"
    else
        bad "libgpiod 2.3's results differ from ${v1:-?}'s"
    fi
fi
stop_board
sed 's/^/    /' "$tmp/board.log"
finish
