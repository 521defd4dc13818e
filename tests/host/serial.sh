#!/usr/bin/env bash
# tests/host/serial.sh - edgeflag-host's serial transport (docs/board-serial.md) through a
# pseudo-terminal: the unmodified binary with --transport serial --port PTY against a board, with
# tests/host/ptyboard as a relay in front of it that limits the rate and plays the wire's faults.
#   1. verify at small canvases over every interface: PASS, results byte-identical to the
#      simulated board's; --baud through termios2; the wire at 3 Mbaud's 300 kB/s (measured);
#   2. the fault matrix of docs/board.md section 6 on the wire: a flipped bit, a dropped and a
#      duplicated byte each way (recovered: exit 0), a stalled board and the line unplugged
#      (exit 5, then --resume: exit 0 and byte-identical results), the board reset (exit 6);
#   3. list and auto find an FT231X by sysfs (a stand-in tree) and ask identify; permission
#      denied names the udev rule (exit 8); no such port (exit 7); --port missing (exit 2).
# usage: bash tests/host/serial.sh BUILD_DIR [BOARD_CMD]   (`make test-host-serial`)
#   BOARD_CMD: a command that starts a board behind a pty and prints the pty's path on the first
#   line of its standard output, then keeps running until SIGTERM (default: BUILD_DIR's
#   tests/host/ptyboard, the board engine with the C model; a Verilated SoC's harness fits too).
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
build=${1:?usage: tests/host/serial.sh BUILD_DIR [BOARD_CMD]}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
E=$build/edgeflag H=$build/edgeflag-host PB=$build/tests/host/ptyboard
BOARD_CMD=${2:-$PB}
SVG=${EF_SVG:-$root/tests/data/svg}
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
for t in "$E" "$H" "$PB"; do
    [ -x "$t" ] || { echo "host-serial: $t not built"; echo "0 passed, 1 failed"; exit 1; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-serial.XXXXXX") || exit 1
bpid='' rpid=''
stop_pid() { [ -n "$1" ] && kill "$1" 2>/dev/null && wait "$1" 2>/dev/null; }
trap 'stop_pid "$rpid"; stop_pid "$bpid"; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

# wait_line FILE: waits up to 30 s for FILE's first line, prints it
wait_line() {
    for _ in $(seq 600); do
        [ -s "$1" ] && head -1 "$1" | grep -q . && { head -1 "$1"; return 0; }
        sleep 0.05
    done
    return 1
}
# the board under test, running for the whole script
bash -c "$BOARD_CMD" >board.port 2>board.err &
bpid=$!
BPTY=$(wait_line board.port) || { echo "host-serial: the board ($BOARD_CMD) printed no pty"; cat board.err; echo "0 passed, 1 failed"; exit 1; }
echo "# board: $BOARD_CMD on $BPTY"
# relay ARGS...: a fresh relay in front of the board, the host's port at $tmp/tty
relay() {
    stop_pid "$rpid"
    rm -f tty relay.port
    "$PB" --to "$BPTY" --link "$tmp/tty" "$@" >relay.port 2>relay.err &
    rpid=$!
    wait_line relay.port >/dev/null || bad "the relay started" "$(cat relay.err)"
}

# run NAME EXPECTED_EXIT STDERR_REGEX -- COMMAND...: the command's exit status and what it said
run() {
    local name=$1 want=$2 re=$3 rc=0
    shift 4
    timeout 60 "$@" >out.txt 2>err.txt || rc=$?
    if [ "$rc" != "$want" ]; then
        bad "$name" "exit $rc (want $want); stderr: $(head -c 400 err.txt | tr '\n' ' ')"
    elif [ -n "$re" ] && ! grep -Eq "$re" err.txt out.txt; then
        bad "$name" "no /$re/ in what it said: $(head -c 400 err.txt | tr '\n' ' ')"
    else
        ok "$name"
    fi
}
same() { # NAME FILE REF: FILE is byte-identical to REF
    if cmp -s "$2" "$3"; then ok "$1"; else bad "$1" "$2 differs from $3"; fi
}

"$E" vectors "$SVG/stress_pixi_bowtie.svg" -o small --size 64x48 --formats bin >/dev/null 2>&1
"$E" vectors "$SVG/tiger.svg" -o tiger --size 96x72 --samples 16 --formats bin >/dev/null 2>&1
"$E" vectors "$SVG/lion.svg" -o lion --size 64x48 --samples 32 --rule evenodd --formats bin >/dev/null 2>&1
if ! [ -s tiger/vectors.bin ] || ! [ -s lion/vectors.bin ]; then
    echo "host-serial: could not make the vectors"; echo "0 passed, 1 failed"; exit 1
fi
for v in small tiger lion; do # the simulated board's results: what every serial run must give
    "$H" verify $v/vectors.bin --transport sim --frame-cmds 40 --quiet --results sim-$v >/dev/null 2>&1
done
LINK=(--transport serial --port "$tmp/tty" --frame-cmds 40 --timeout 300)

# ------------------------------------------------------------------ 1. plain runs
relay
for v in small tiger lion; do
    run "verify $v over the pty (every interface): PASS" 0 'check: PASS: 6 comparisons' -- \
        "$H" verify $v/vectors.bin "${LINK[@]}" --results r-$v
    same "$v: results identical to the simulated board's" r-$v/vectors.actual.bin sim-$v/vectors.actual.bin
done
run "verify at --baud 115200 (the standard code) : PASS" 0 'check: PASS' -- \
    "$H" verify small/vectors.bin "${LINK[@]}" --baud 115200 --results rb1
run "verify at --baud 1234567 (termios2 BOTHER): PASS" 0 'check: PASS' -- \
    "$H" verify small/vectors.bin "${LINK[@]}" --baud 1234567 --results rb2
# the wire of a 3 Mbaud 8N1 line: 300,000 bytes a second each way
relay --rate 300000
run "verify the tiger on a 300 kB/s wire: PASS" 0 '"check": "pass"' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --frame-cmds 400 --timeout 2000 --results rw --json --quiet
same "300 kB/s: results identical to the simulated board's" rw/vectors.actual.bin sim-tiger/vectors.actual.bin
sed -n 's/.*"result_records": \([0-9]*\), "result_bytes": \([0-9]*\), "seconds": \([0-9.]*\).*/\1 \2 \3/p' out.txt |
    awk '{ printf "# full records at 300 kB/s: %d records, %d bytes in %.2f s: %.0f records/s, %.0f kB/s of results\n", $1, $2, $3, $1 / $3, $2 / $3 / 1000 }'

# ------------------------------------------------------------------ 2. faults on the wire
# fault NAME FAULTS WANT REGEX [HOST OPTIONS...]: the relay plays FAULTS; the host exits WANT saying
# REGEX; a resumable failure is resumed; the results equal the simulated board's either way
fault() {
    local name=$1 faults=$2 want=$3 re=$4
    shift 4
    relay --faults "$faults" --stall-ms 2500
    rm -rf rf
    run "$name: exit $want" "$want" "$re" -- "$H" verify tiger/vectors.bin "${LINK[@]}" --results rf "$@"
    if [ "$want" = 5 ]; then
        [ -e rf/vectors.actual.bin ] && bad "$name: a failed run left vectors.actual.bin"
        sleep 1.5 # a stall ends (2.5 s after it began), an unplugged line is back
        run "$name: --resume: PASS" 0 'check: PASS' -- \
            "$H" verify tiger/vectors.bin "${LINK[@]}" --results rf --resume "$@"
    fi
    if [ "$want" = 0 ] || [ "$want" = 5 ]; then
        same "$name: results identical to the simulated board's" rf/vectors.actual.bin sim-tiger/vectors.actual.bin
    fi
}
fault "a bit flipped on the way to the board" flip=3000 0 'PASS'
fault "a byte to the board dropped" drop=5000 0 'PASS'
fault "a byte to the board duplicated" dup=7000 0 'PASS'
fault "a bit flipped on the way to the host" flip-down=20000 0 'PASS'
fault "a byte to the host dropped" drop-down=40000 0 'PASS'
fault "a byte to the host duplicated" dup-down=60000 0 'PASS'
fault "the board stalls" stall=60 5 'stopped answering.*--resume'
fault "the line unplugged" unplug=60 5 'went away.*--resume'
fault "the board reset mid-run" reset=60 6 'reset or lost its state'

# ------------------------------------------------------------------ 3. finding boards, errors
relay
mkdir -p sys/class/tty sys/devices/usb1/1-1/1-1:1.0/ttyUSB0 sys/devices/usb1/1-2/1-2:1.0/ttyUSB1 dev
printf '0403\n' >sys/devices/usb1/1-1/idVendor
printf '6015\n' >sys/devices/usb1/1-1/idProduct
printf 'EFTEST42\n' >sys/devices/usb1/1-1/serial
printf '00\n' >sys/devices/usb1/1-1/1-1:1.0/bInterfaceNumber
printf '0403\n' >sys/devices/usb1/1-2/idVendor
printf '6010\n' >sys/devices/usb1/1-2/idProduct
ln -s ../../devices/usb1/1-1/1-1:1.0/ttyUSB0 sys/class/tty/ttyUSB0
ln -s ../../devices/usb1/1-2/1-2:1.0/ttyUSB1 sys/class/tty/ttyUSB1
ln -s .. sys/devices/usb1/1-1/1-1:1.0/ttyUSB0/device
ln -s .. sys/devices/usb1/1-2/1-2:1.0/ttyUSB1/device
ln -s "$tmp/tty" dev/ttyUSB0
# ttyUSB1: an FT2232 whose port has nothing behind it (a pty nobody answers on)
"$PB" --to /dev/null --link "$tmp/dev/ttyUSB1" >/dev/null 2>&1 &
mute=$!
sleep 0.3
export EF_SERIAL_SYSFS=$tmp/sys EF_SERIAL_DEV=$tmp/dev
run "list finds the FT231X by sysfs and it answers identify" 0 'serial +.*/dev/ttyUSB0 +0403:6015 FT231X interface 00, USB serial EFTEST42; serial EFPTY0001' -- \
    "$H" list
if grep -q 'ttyUSB1.*(not ours) 0403:6010 FT2232.*does not answer identify' out.txt; then
    ok "list shows the silent FT2232 as not ours"
else
    bad "list: the FT2232" "$(cat out.txt)"
fi
run "verify --transport auto picks the serial board that answers: PASS" 0 'check: PASS' -- \
    "$H" verify small/vectors.bin --frame-cmds 40 --timeout 300 --results ra
unset EF_SERIAL_SYSFS EF_SERIAL_DEV
stop_pid "$mute"
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null; then
    slave=$(readlink "$tmp/tty")
    run "permission denied on the tty: exit 8 naming the udev rule" 8 'permission denied.*60-edgeflag-serial.rules.*udevadm' -- \
        setpriv --reuid 65534 --regid 65534 --clear-groups "$H" verify small/vectors.bin --transport serial --port "$slave"
else
    chmod 000 "$(readlink "$tmp/tty")" 2>/dev/null
    run "permission denied on the tty: exit 8 naming the udev rule" 8 'permission denied.*60-edgeflag-serial.rules.*udevadm' -- \
        "$H" verify small/vectors.bin --transport serial --port "$tmp/tty"
fi
run "no such port: exit 7" 7 'ttyNONE: No such file' -- \
    "$H" verify small/vectors.bin --transport serial --port "$tmp/ttyNONE"
run "serial without --port: exit 2" 2 'needs --port' -- "$H" verify small/vectors.bin --transport serial
run "not a tty: exit 2" 2 'not a terminal' -- "$H" verify small/vectors.bin --transport serial --port small/vectors.bin
run "--version names the serial transport" 0 '' -- "$H" --version
if grep -q '^  serial .*termios2' out.txt; then ok "--version lists serial"; else bad "--version" "$(cat out.txt)"; fi

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
