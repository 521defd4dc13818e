#!/usr/bin/env bash
# tests/host/serial.sh - edgeflag-host's serial transport (docs/board-serial.md) through a
# pseudo-terminal: the unmodified binary with --transport serial --port PTY against a board, with
# tests/host/ptyboard as a relay in front of it that limits the rate and plays the wire's faults.
#   1. verify at small canvases over every interface: PASS, results byte-identical to the
#      simulated board's; --baud through termios2; the engine's result queue bound (4 frames
#      kept at most, the DUT back-pressured); the wire at 3 Mbaud's 300 kB/s (measured);
#   2. the fault matrix of docs/board.md section 6 on the wire: a flipped bit, a dropped and a
#      duplicated byte each way (recovered: exit 0), a stalled board and the line unplugged
#      (exit 5, then --resume: exit 0 and byte-identical results), the board reset (exit 6);
#   3. list and auto find an FT231X by sysfs (a stand-in tree) and ask identify; permission
#      denied names the udev rule (exit 8); no such port (exit 7); --port missing (exit 2).
# usage: bash tests/host/serial.sh BUILD_DIR [BOARD_CMD]   (`make test-host-serial`)
#   BOARD_CMD: a command that starts a board behind a pty and prints the pty's path on the first
#   line of its standard output, then keeps running until SIGTERM (default: BUILD_DIR's
#   tests/host/ptyboard, the board engine with the C model; a Verilated SoC's harness fits too).
# Ends with "N passed, M failed, K skipped"; exit status 0 only if nothing failed (a check this
# machine cannot arrange is SKIPPED with the reason: docs/testing.md, "What the tests assume").
# Recovery is asserted by how it happened (the host's --json counts); runs that must not time out
# get a generous --timeout (tests/host/waits.sh, EF_TEST_TIMEOUT_SCALE).
# shellcheck disable=SC2016 # how's conditions are single-quoted on purpose: evaluated when checked
set -u
export LC_ALL=C
build=${1:?usage: tests/host/serial.sh BUILD_DIR [BOARD_CMD]}
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/host/waits.sh disable=SC1091
. "$root/tests/host/waits.sh"
case $build in /*) ;; *) build=$PWD/$build ;; esac
E=$build/edgeflag H=$build/edgeflag-host PB=$build/tests/host/ptyboard
PY=${PYTHON:-python3}
BOARD_CMD=${2:-$PB}
SVG=${EF_SVG:-$root/tests/data/svg}
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
skipped() { skip=$((skip + 1)); echo "SKIPPED - $1"; }
for t in "$E" "$H" "$PB"; do
    [ -x "$t" ] || { echo "host-serial: $t not built"; echo "0 passed, 1 failed"; exit 1; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-serial.XXXXXX") || exit 1
bpid='' rpid='' extra=()
stop_pid() { [ -n "$1" ] && kill "$1" 2>/dev/null && wait "$1" 2>/dev/null; }
trap 'stop_pid "$rpid"; stop_pid "$bpid"; rm -rf "$tmp" "${extra[@]}"' EXIT
cd "$tmp" || exit 1

# wait_line FILE: waits up to EF_READY_S (30 s) for FILE's first line, prints it
wait_line() {
    for _ in $(seq $((EF_READY_S * 20))); do
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
    timeout "$EF_GUARD_S" "$@" >out.txt 2>err.txt || rc=$?
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
# hstat KEY: the host's --json summary's KEY (the last run's)
hstat() { sed -n 's/.*"'"$1"'": \([0-9]*\).*/\1/p' out.txt | tail -1; }
how() { # NAME CONDITION: how a run went, by the host's counters (CONDITION: shell text, evaluated here)
    if eval "$2"; then ok "$1"; else bad "$1" "$(grep -o '"frames_sent.*timeouts": [0-9]*' out.txt)"; fi
}
# runs that must not time out: a generous --timeout; the stall's is short (what it tests), and a
# frame to the host damaged on the wire is recovered by the host's timeout (docs/board.md 4.2):
# there 1 s times EF_TEST_TIMEOUT_SCALE, which a busy machine does not reach between two frames
LINK=(--transport serial --port "$tmp/tty" --frame-cmds 40 --timeout "$EF_LINK_MS")
SHORT=300 DOWN=$((1000 * EF_SCALE))

# ------------------------------------------------------------------ 1. plain runs
relay
for v in small tiger lion; do
    run "verify $v over the pty (every interface, full records): PASS" 0 'check: PASS: 6 comparisons' -- \
        "$H" verify $v/vectors.bin "${LINK[@]}" --digest off --results r-$v
    same "$v: results identical to the simulated board's" r-$v/vectors.actual.bin sim-$v/vectors.actual.bin
    run "verify $v in digest mode (the serial default): PASS" 0 'digest: pix: [0-9]+ windows of 1024 transactions: all equal' -- \
        "$H" verify $v/vectors.bin "${LINK[@]}" --results d-$v
    grep -q 'check: PASS: 6 comparisons' err.txt || bad "$v in digest mode: check did not pass" "$(tail -3 err.txt)"
    same "$v in digest mode: rebuilt results identical to the simulated board's" d-$v/vectors.actual.bin sim-$v/vectors.actual.bin
done
run "digest mode with 7-transaction windows: PASS" 0 'digest: pix: [0-9]+ windows of 7 transactions: all equal' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --digest 7 --results d7
same "7-transaction windows: results identical" d7/vectors.actual.bin sim-tiger/vectors.actual.bin
run "verify --save-frame: PASS" 0 'check: PASS' -- "$H" verify tiger/vectors.bin "${LINK[@]}" --results sf --save-frame sf.png
same "--save-frame: the board's frame, byte-identical to edgeflag vectors' frame.png" sf.png tiger/frame.png
# a board whose pix differs from the expected in one transaction (the expected vectors changed,
# their CRCs made good again): digest mode fetches the window and names the same mismatch as full records
"$PY" - tiger/vectors.bin bad.bin 6 1500 <<'PYEOF'
import sys, zlib, struct
src, dst, iface, nth = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
b = bytearray(open(src, 'rb').read())
o = 104
while o < len(b):
    if b[o] == iface:
        if nth == 0:
            b[o + 10] ^= 0x01  # the payload's lowest bit (pix: the colour's alpha)
            break
        nth -= 1
    o += 10 + b[o + 1]
else:
    sys.exit('no such record')
struct.pack_into('<I', b, 96, zlib.crc32(bytes(b[104:])))
struct.pack_into('<I', b, 100, zlib.crc32(bytes(b[:100])))
open(dst, 'wb').write(b)
PYEOF
mkdir -p bad && mv bad.bin bad/vectors.bin
run "one pix transaction differs, full records: exit 1" 1 'pix: .* 1 mismatch' -- \
    "$H" verify bad/vectors.bin "${LINK[@]}" --digest off --results bf --errors 5
sed 's|^bf/|R/|' out.txt >full-report.txt
run "one pix transaction differs, digest mode: exit 1, one window fetched" 1 'digest: pix: 1 of [0-9]+ windows differ.*fetching 1' -- \
    "$H" verify bad/vectors.bin "${LINK[@]}" --results bd --errors 5
sed 's|^bd/|R/|' out.txt >digest-report.txt
if [ -s full-report.txt ] && cmp -s full-report.txt digest-report.txt; then
    ok "digest mode names the same transaction, cycle and fields as full records: $(cut -c1-90 digest-report.txt)"
else
    bad "digest and full reports differ" "$(cat full-report.txt digest-report.txt)"
fi
same "digest mode's rebuilt results identical to full records'" bd/vectors.actual.bin bf/vectors.actual.bin
# more differing windows than --digest-fetch's default (docs/board.md 4.5: 16 of each interface): 20 pix
# windows of 7 transactions differ (each window's first transaction changed): the first 16 are fetched,
# the report says so, and the run fails (exit 1)
"$PY" - tiger/vectors.bin many.bin 6 7 20 <<'PYEOF'
import sys, zlib, struct
src, dst, iface, win, n = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
b = bytearray(open(src, 'rb').read())
o, k = 104, 0
while o < len(b) and k < win * n:
    if b[o] == iface:
        if k % win == 0:
            b[o + 10] ^= 0x01
        k += 1
    o += 10 + b[o + 1]
if k < win * n:
    sys.exit('too few records')
struct.pack_into('<I', b, 96, zlib.crc32(bytes(b[104:])))
struct.pack_into('<I', b, 100, zlib.crc32(bytes(b[:100])))
open(dst, 'wb').write(b)
PYEOF
mkdir -p many && mv many.bin many/vectors.bin
run "20 pix windows differ, digest mode: exit 1, the default 16 fetched" 1 \
    'digest: pix: 20 of [0-9]+ windows differ, the first at window 0 .*fetching 16 of them whole' -- \
    "$H" verify many/vectors.bin "${LINK[@]}" --digest 7 --results dm --errors 5
run "verify at --baud 115200 (the standard code) : PASS" 0 'check: PASS' -- \
    "$H" verify small/vectors.bin "${LINK[@]}" --baud 115200 --results rb1
run "verify at --baud 1234567 (termios2 BOTHER): PASS" 0 'check: PASS' -- \
    "$H" verify small/vectors.bin "${LINK[@]}" --baud 1234567 --results rb2
# the engine's result queue bound (docs/board.md 4.2): the tiger's full records (61 frames of
# 32 KiB) through an engine that keeps at most 4 result frames (the DUT held back while the host
# has not acknowledged them) pass with the same results and never keep more than 4; the same run
# unbounded keeps more (so the bound is what held it)
for q in 4 0; do
    rm -f qtty q.port
    "$PB" --link "$tmp/qtty" --result-queue $q >q.port 2>q.err &
    qpid=$!
    wait_line q.port >/dev/null || bad "the ptyboard with --result-queue $q started" "$(cat q.err)"
    run "full records through a result queue of $q frames (0: none): PASS" 0 '"check": "pass"' -- \
        "$H" verify tiger/vectors.bin --transport serial --port "$tmp/qtty" --timeout "$EF_LINK_MS" --digest off \
        --results rq$q --json --quiet
    tq=$(hstat timeouts)
    stop_pid "$qpid"
    peak=$(sed -n 's/.*kept at most \([0-9]*\) at once.*/\1/p' q.err)
    same "a result queue of $q: results identical to the simulated board's" rq$q/vectors.actual.bin sim-tiger/vectors.actual.bin
    if [ $q = 4 ] && [ "${peak:-99}" -le 4 ] && [ "$tq" = 0 ]; then
        ok "a result queue of 4: at most $peak result frames kept at once, no timeout"
    elif [ $q = 0 ] && [ "${peak:-0}" -gt 4 ]; then
        ok "no bound: $peak result frames kept at once (more than the bound of 4)"
    else
        bad "the result queue of $q" "at most '${peak}' frames kept, $tq timeouts"
    fi
done
# the wire of a 3 Mbaud 8N1 line: 300,000 bytes a second each way
relay --rate 300000
for mode in off 1024; do
    t0=$(date +%s.%N)
    run "verify the tiger on a 300 kB/s wire (--digest $mode): PASS" 0 '"check": "pass"' -- \
        "$H" verify tiger/vectors.bin "${LINK[@]}" --digest $mode --frame-cmds 400 --results rw$mode --json --quiet
    t1=$(date +%s.%N)
    same "300 kB/s (--digest $mode): results identical to the simulated board's" rw$mode/vectors.actual.bin sim-tiger/vectors.actual.bin
    n=$(sed -n 's/.*"result_records": \([0-9]*\), "result_bytes": \([0-9]*\).*/\1 \2/p' out.txt)
    echo "$n $t0 $t1" | awk -v m=$mode '{ s = $4 - $3; printf "# --digest %s at 300 kB/s: %d transactions checked, %d result bytes on the wire, %.2f s in all: %.0f transactions/s\n", m, $1, $2, s, $1 / s }'
done
# the progress bar on a terminal (util-linux's script gives the run a pty) over the same wire: the tiger
# at 640x480 (28,613 commands, 372 kB: over 1.2 s at 300 kB/s) is redrawn every 0.2 s while its commands
# flow; every redraw's bar agrees with its percentage (floor(P * 30 / 100) .. floor((P + 1) * 30 / 100)
# '#'), and one between 1 % and 75 % (0.2 s or more after the start) shows an ETA above 0.0 s
if command -v script >/dev/null; then
    "$E" vectors "$SVG/tiger.svg" -o big --size 640x480 --formats bin >/dev/null 2>&1
    timeout "$EF_GUARD_S" script -qfec "'$H' verify big/vectors.bin ${LINK[*]} --results pbar" /dev/null </dev/null >tty.txt 2>&1
    prc=$?
    tr '\r' '\n' <tty.txt | awk -v rc=$prc '
        /^\[[#.]+\] +[0-9]+%/ { n++; bar = substr($0, 2, 30); h = gsub(/#/, "", bar); p = $2 + 0
            if (h < int(p * 30 / 100) || h > int((p + 1) * 30 / 100)) bad = bad " " p "%:" h "#"
            if (p >= 1 && p <= 75 && $6 + 0 > 0) eta++; lp = p }
        END { if (rc == 0 && n >= 3 && bad == "" && eta > 0 && lp == 100) {
                  printf "ok - the progress bar on a terminal at 300 kB/s: %d redraws agree with their percentage, %d show an ETA\n", n, eta; exit 0 }
              printf "FAIL - the progress bar on a terminal at 300 kB/s: exit %d, %d redraws, %d with an ETA between 1 %% and 75 %%, last %s%%, disagreeing:%s\n", rc, n, eta, lp, bad; exit 1 }' &&
        pass=$((pass + 1)) || fail=$((fail + 1))
else
    bad "the progress bar on a terminal at 300 kB/s" "util-linux's script is not installed"
fi

# ------------------------------------------------------------------ 2. faults on the wire
# fault NAME FAULTS WANT REGEX [HOST OPTIONS...]: the relay plays FAULTS; the host exits WANT saying
# REGEX; a resumable failure is resumed; the results equal the simulated board's either way.  The
# first run's --json summary is left in out.txt for the caller's counter checks.
fault() {
    local name=$1 faults=$2 want=$3 re=$4
    shift 4
    [ "${1:-}" = --digest ] && name="$name (digest mode)"
    relay --faults "$faults" --stall-ms 5000
    rm -rf rf
    run "$name: exit $want" "$want" "$re" -- "$H" verify tiger/vectors.bin "${LINK[@]}" --digest off --results rf --json "$@"
    cp out.txt fault.json
    if [ "$want" = 5 ]; then
        [ -e rf/vectors.actual.bin ] && bad "$name: a failed run left vectors.actual.bin"
        sleep 1.5 # an unplugged line is back; a stall (5 s) ends while the resume waits for identify
        run "$name: --resume: PASS" 0 'check: PASS' -- \
            "$H" verify tiger/vectors.bin "${LINK[@]}" --results rf --resume
    fi
    if [ "$want" = 0 ] || [ "$want" = 5 ]; then
        same "$name: results identical to the simulated board's" rf/vectors.actual.bin sim-tiger/vectors.actual.bin
    fi
    cp fault.json out.txt
}
# to the board: its NAK names the frame, the host goes back to it, no timeout
for f in "a bit flipped on the way to the board:flip=3000" "a byte to the board dropped:drop=5000" \
    "a byte to the board duplicated:dup=7000"; do
    fault "${f%%:*}" "${f#*:}" 0 'PASS'
    how "${f%%:*}: NAKed, sent again, no timeout" \
        '[ "$(hstat naks)" -ge 1 ] && [ "$(hstat retransmits)" -ge 1 ] && [ "$(hstat timeouts)" = 0 ]'
done
# to the host: nothing resent to the board
for f in "a bit flipped on the way to the host:flip-down=20000" "a byte to the host dropped:drop-down=40000" \
    "a byte to the host duplicated:dup-down=60000"; do
    fault "${f%%:*}" "${f#*:}" 0 'PASS' --timeout "$DOWN"
    how "${f%%:*}: no NAK (recovered with $(hstat timeouts) timeouts of $DOWN ms)" \
        '[ "$(hstat naks)" = 0 ]'
done
# (the stalled relay reads nothing: the host's writes can time out before its 4 reads do)
fault "the board stalls" stall=60 5 'stopped answering.*--resume' --timeout "$SHORT"
fault "the line unplugged" unplug=60 5 'went away.*--resume'
how "the line unplugged: the host saw the hang-up, no timeout" \
    '[ "$(hstat timeouts)" = 0 ]'
fault "the board reset mid-run" reset=60 6 'reset or lost its state'
how "the board reset: its NAK asked for an acknowledged frame, no timeout" \
    '[ "$(hstat naks)" -ge 1 ] && [ "$(hstat timeouts)" = 0 ]'
# the same on a digest run (frames counted as above: a digest run's START is the 4th frame; the
# resume takes the digest run from the resume state)
fault "a bit flipped on the way to the board" flip=3000 0 'PASS' --digest 64
fault "a byte to the host dropped" drop-down=300 0 'PASS' --digest 64 --timeout "$DOWN"
fault "a byte to the host duplicated" dup-down=500 0 'PASS' --digest 64 --timeout "$DOWN"
fault "the board stalls" stall=60 5 'stopped answering.*--resume' --digest 64 --timeout "$SHORT"
fault "the line unplugged" unplug=60 5 'went away.*--resume' --digest 64
fault "the board reset mid-run" reset=60 6 'reset or lost its state' --digest 64
# the fetch run (a select run for the differing window of section 1's altered vectors) unplugged
# 100 frames in (the digest run is about 300), then resumed: the same report, the same results
relay --faults unplug=400
rm -rf rs
run "the fetch run unplugged: exit 5" 5 'went away.*--resume' -- \
    "$H" verify bad/vectors.bin "${LINK[@]}" --results rs --errors 5
if grep -q '^digest 1024 phase 2 nsel 1 ' rs/.resume 2>/dev/null; then
    ok "the fetch run unplugged: .resume says the select run and its window"
else
    bad "the fetch run unplugged: .resume" "$(tail -n 2 rs/.resume 2>&1)"
fi
run "the fetch run resumed: exit 1" 1 'pix: .* 1 mismatch' -- \
    "$H" verify bad/vectors.bin "${LINK[@]}" --results rs --errors 5 --resume
sed 's|^rs/|R/|' out.txt >resumed-report.txt
if [ -s resumed-report.txt ] && cmp -s full-report.txt resumed-report.txt; then
    ok "the fetch run resumed: the same report as full records"
else
    bad "the fetch run resumed: the report" "$(cat resumed-report.txt)"
fi
same "the fetch run resumed: results identical to full records'" rs/vectors.actual.bin bf/vectors.actual.bin

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
    "$H" verify small/vectors.bin --frame-cmds 40 --timeout "$EF_LINK_MS" --results ra
unset EF_SERIAL_SYSFS EF_SERIAL_DEV
stop_pid "$mute"
# As root: the command runs as nobody (root opens any tty), from copies of the binary and the
# vectors in a folder nobody can reach (the clone's folders may be closed to others: a clone in a
# mode-0700 folder), after a probe as nobody shows it can use them; else SKIPPED, saying why.
as_nobody=(setpriv --reuid nobody --regid "$(id -g nobody 2>/dev/null)" --clear-groups)
nobody_dir() { # sets NB to a folder nobody can use, or fails with the reason in NB
    local base d why=""
    NB="setpriv (util-linux) is not installed"
    command -v setpriv >/dev/null || return 1
    NB="there is no user nobody on this machine"
    getent passwd nobody >/dev/null || return 1
    chmod 711 "$tmp"
    for base in "$tmp" /tmp /var/tmp /dev/shm; do
        if [ "$base" = "$tmp" ]; then
            d=$tmp/nobody
            mkdir "$d" || continue
        else
            [ -d "$base" ] && d=$(mktemp -d "$base/edgeflag-serial-nobody.XXXXXX" 2>/dev/null) || continue
            extra+=("$d")
        fi
        if ! { chmod 755 "$d" && mkdir -m 777 "$d/out" && cp "$H" "$d/edgeflag-host" && cp small/vectors.bin "$d/small.bin" &&
            chmod 755 "$d/edgeflag-host" && chmod 644 "$d/small.bin"; }; then
            why="$why; $d: cannot fill it"
            continue
        fi
        if "${as_nobody[@]}" sh -c "test -x '$d/edgeflag-host' && test -r '$d/small.bin' && touch '$d/out/probe'" \
            >probe.out 2>&1 && [ -e "$d/out/probe" ]; then
            NB=$d
            return 0
        fi
        if ! "${as_nobody[@]}" true >probe.out 2>&1; then
            NB="root cannot become nobody here: $(tr '\n' ' ' <probe.out)"
            return 1
        fi
        why="$why; nobody cannot reach $d"
    done
    NB="no folder that nobody can reach$why"
    return 1
}
if [ "$(id -u)" = 0 ]; then
    slave=$(readlink "$tmp/tty")
    if nobody_dir; then
        run "permission denied on the tty: exit 8 naming the udev rule" 8 'permission denied.*60-edgeflag-serial.rules.*udevadm' -- \
            "${as_nobody[@]}" "$NB/edgeflag-host" verify "$NB/small.bin" --transport serial --port "$slave" \
            --results "$NB/out/r"
    else
        skipped "permission denied on the tty (exit 8 naming the udev rule) not checked: $NB"
    fi
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

echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" = 0 ]
