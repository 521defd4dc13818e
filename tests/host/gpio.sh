#!/usr/bin/env bash
# test-host-gpio: the GPIO transport through libgpiod against an emulated chip
# with the real board engine on its lines (docs/board-gpio.md section 8), once
# with the system's libgpiod (1.6.3 on Debian 12) and once with libgpiod 2.3
# built into BUILD/libgpiod2 (skipped, saying why, without ../shared).
#   tests/host/gpio.sh BUILD
set -u
cd "$(dirname "$0")/../.." || exit 1
# shellcheck source=tests/host/waits.sh disable=SC1091
. tests/host/waits.sh
build=${1:-build}
make=${MAKE:-make}
out=$build/test-host-gpio
rm -rf "$out" && mkdir -p "$out"
fail=0

# A small scene's vectors: a bowtie at 16x16, 8 samples (a few hundred bytes each way).
if ! "$build/edgeflag" vectors tests/data/svg/stress_pixi_bowtie.svg -o "$out/vec" --samples 8 --size 16x16 \
        --force >"$out/vectors.log" 2>&1; then
    cat "$out/vectors.log"; echo "gpio: cannot make the test vectors"; exit 1
fi

# The command as a user meets it, no chip needed: a bad line map is a usage
# error (exit 2) naming the item; a chip that is not there is "no board" (exit 7).
H=$build/edgeflag-host
user_error() {   # EXIT REGEX ARGS...
    local want=$1 re=$2; shift 2
    "$H" stream "$out/vec/vectors.bin" --transport gpio "$@" >"$out/cli.out" 2>"$out/cli.err"
    local rc=$?
    if [ $rc -ne "$want" ] || ! grep -Eq "$re" "$out/cli.err"; then
        echo "gpio (command): FAIL: $* gave exit $rc (want $want), told: $(cat "$out/cli.err")"; fail=1
    else
        echo "gpio (command): ok: $* -> exit $rc: $(cat "$out/cli.err")"
    fi
}
if [ -x "$H" ]; then
    user_error 2 "'bogus=1': unknown signal" --lines bogus=1
    user_error 2 "line 30 is mapped to both clk and valid" --lines clk=30,valid=30
    user_error 2 "'d=1-4': a range must span exactly 8 lines" --lines d=1-4
    user_error 7 "/dev/gpiochip-absent: cannot open GPIO chip" --chip /dev/gpiochip-absent
else
    echo "gpio (command): FAIL: $H not built"; fail=1
fi

run_one() {   # NAME PROGRAM
    local name=$1 prog=$2 res=$out/res-${1//[^a-z0-9.]/_}
    echo "== gpio ($name): $prog"
    if ! command -v umockdev-wrapper >/dev/null; then
        echo "gpio ($name): FAIL: umockdev-wrapper is missing (tools/install-deps.sh test installs umockdev)"
        fail=1; return
    fi
    if ! timeout "$EF_GUARD_S" umockdev-wrapper "$prog" "$out/vec/vectors.bin" "$res"; then
        echo "gpio ($name): FAIL: the emulator test failed"; fail=1; return
    fi
    # The board's results against the expected records, by the project's own checker.
    if ! "$build/edgeflag" check "$out/vec/vectors.bin" "$res/vectors.actual.bin" --interfaces pix; then
        echo "gpio ($name): FAIL: the results streamed over GPIO differ from the vectors"; fail=1; return
    fi
    echo "gpio ($name): PASS"
}

if pkg-config --exists libgpiod; then
    run_one "libgpiod $(pkg-config --modversion libgpiod)" "$build/tests/host/gpio_emu"
else
    echo "gpio (system libgpiod): SKIP: no libgpiod installed (tools/install-deps.sh test installs libgpiod-dev)"
fi

bash tests/host/libgpiod2.sh "$build"
rc=$?
if [ $rc -eq 77 ]; then
    echo "gpio (libgpiod 2.3): SKIP: see the line above; the v2 backend was not tested"
elif [ $rc -ne 0 ]; then
    echo "gpio (libgpiod 2.3): FAIL: building libgpiod 2.3 failed"; fail=1
elif ! $make --no-print-directory -s gpio-emu-v2 BUILD="$build" >"$out/build-v2.log" 2>&1; then
    cat "$out/build-v2.log"; echo "gpio (libgpiod 2.3): FAIL: the v2 test did not build"; fail=1
else
    run_one "libgpiod 2.3" "$build/tests/host/gpio_emu_v2"
fi
[ $fail -eq 0 ] && echo "gpio: all passed" 
exit $fail
