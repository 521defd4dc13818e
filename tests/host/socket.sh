#!/usr/bin/env bash
# tests/host/socket.sh - edgeflag-host's socket transport (docs/board.md section 5.5) against
# tests/host/pyboard.py, a board written from docs/board.md alone (no code shared with host/),
# whose DUT replays the expected vectors.bin: every test runs the unmodified binary and asserts
# its exit code, what it told the user and what the board received (pyboard's counters) and
# returned (results byte for byte against the simulated board's, and `edgeflag check`).
#   1. verify over unix: and tcp:127.0.0.1:PORT, PASS, results identical to --transport sim's;
#      the board engine of board/ behind a socket (sockboard) the same way;
#   2. each pyboard fault: a host frame dropped or corrupted, a reply dropped or corrupted
#      (exit 0), the connection closed mid-commands and mid-results and a stall (exit 5,
#      then --resume: exit 0 and byte-identical results), a reset (6), another protocol
#      version and another device (6), a board that never answers identify (5);
#   3. nobody listening (exit 7 naming the address), a malformed --connect (2);
#   4. bench --transport socket against pyboard and against the engine (numbers printed).
# usage: bash tests/host/socket.sh BUILD_DIR   (`make test-host-socket`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
build=${1:?usage: tests/host/socket.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
E=$build/edgeflag H=$build/edgeflag-host SB=$build/tests/host/sockboard
PY=${PYTHON:-python3}
PYBOARD=$root/tests/host/pyboard.py
SVG=${EF_SVG:-$root/tests/data/svg}
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
for t in "$E" "$H"; do
    [ -x "$t" ] || { echo "host-socket: $t not built"; echo "0 passed, 1 failed"; exit 1; }
done
command -v "$PY" >/dev/null || { echo "host-socket: $PY not found"; echo "0 passed, 1 failed"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-sock.XXXXXX") || exit 1
bpid=
stop_board() {
    if [ -n "$bpid" ]; then
        kill "$bpid" 2>/dev/null
        wait "$bpid" 2>/dev/null
        bpid=
    fi
}
trap 'stop_board; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

# board ARGS...: pyboard on unix:$tmp/b.sock (or with --tcp 0: its port in $port); waits until it listens
board() {
    stop_board
    rm -f b.sock port stats.txt
    "$PY" "$PYBOARD" --port-file port --stats stats.txt "$@" 2>board.err &
    bpid=$!
    for _ in $(seq 100); do
        [ -s port ] && break
        sleep 0.05
    done
    port=$(cat port 2>/dev/null)
}
# bstat KEY: the board's last counter line's KEY
bstat() { tail -1 stats.txt 2>/dev/null | sed -n 's/.*"'"$1"'": \([0-9]*\).*/\1/p'; }

# run NAME EXPECTED_EXIT STDERR_REGEX -- COMMAND...
run() {
    local name=$1 want=$2 re=$3
    shift 4
    timeout 60 "$@" >out.txt 2>err.txt
    local rc=$?
    if [ "$rc" = "$want" ] && { [ -z "$re" ] || grep -Eq "$re" err.txt out.txt; }; then
        ok "$name"
    else
        bad "$name" "exit $rc (want $want); stderr: $(head -c 400 err.txt | tr '\n' ' ')"
    fi
}
same() { # NAME FILE: FILE is byte-identical to the simulated board's results
    if cmp -s "$2" sim.bin; then ok "$1"; else bad "$1" "$2 differs from the simulated board's results"; fi
}

"$E" vectors "$SVG/stress_pixi_bowtie.svg" -o small --size 64x48 --formats bin >/dev/null 2>&1
"$E" vectors "$SVG/tiger.svg" -o tiger --size 120x90 --samples 16 --formats bin >/dev/null 2>&1
[ -s tiger/vectors.bin ] || { echo "host-socket: could not make the vectors"; echo "0 passed, 1 failed"; exit 1; }
# the simulated board's results: what every socket run must give, byte for byte
"$H" verify tiger/vectors.bin --transport sim --frame-cmds 40 --quiet --results simres >/dev/null 2>&1
cp simres/vectors.actual.bin sim.bin 2>/dev/null || : >sim.bin
SOCK=unix:$tmp/b.sock
LINK=(--transport socket --frame-cmds 40 --timeout 300)

# ------------------------------------------------------------------ 1. plain runs
board --unix b.sock --vectors small/vectors.bin
run "verify over unix: against pyboard: PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify small/vectors.bin --transport socket --connect "$SOCK"
board --unix b.sock --vectors tiger/vectors.bin
run "verify the tiger over unix: (40 commands a frame): PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results r0
same "unix: results identical to the simulated board's" r0/vectors.actual.bin
[ "$(bstat dup)" = 0 ] && [ "$(bstat naks)" = 0 ] && [ "$(bstat resets)" = 1 ] && ok "the board took every frame once, no NAK, one reset" ||
    bad "clean run's board counters" "$(tail -1 stats.txt)"
board --tcp 0 --vectors tiger/vectors.bin
run "verify the tiger over tcp:127.0.0.1:PORT: PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "tcp:127.0.0.1:$port" --results r1 --json
same "tcp: results identical to the simulated board's" r1/vectors.actual.bin
run "verify over tcp:localhost:PORT (every address of the name tried): PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "tcp:localhost:$port" --results r1b
if [ -x "$SB" ]; then
    stop_board
    rm -f e.sock
    "$SB" "$tmp/e.sock" 2>sockboard.err &
    bpid=$!
    for _ in $(seq 100); do [ -S e.sock ] && break; sleep 0.05; done
    run "verify the tiger against the board engine behind a socket: PASS" 0 'check: PASS: 6 comparisons' -- \
        "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "unix:$tmp/e.sock" --results r2
    same "engine behind a socket: results identical to the simulated board's" r2/vectors.actual.bin
    run "again on the same engine: the reset control frame ends the finished run, PASS" 0 'check: PASS: 6 comparisons' -- \
        "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "unix:$tmp/e.sock" --results r3
    same "the second run's results identical to the simulated board's" r3/vectors.actual.bin
    # the link cut in the middle of a frame, 100,001 bytes in (a DATA frame of 40 commands is 540 bytes)
    stop_board
    rm -f e.sock
    "$SB" "$tmp/e.sock" 100001 2>sockboard.err &
    bpid=$!
    for _ in $(seq 100); do [ -S e.sock ] && break; sleep 0.05; done
    run "the engine's link cut mid-frame: exit 5" 5 'went away.*--resume' -- \
        "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "unix:$tmp/e.sock" --results r4
    run "the engine's link cut mid-frame: --resume: PASS" 0 'check: PASS: 6 comparisons' -- \
        "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "unix:$tmp/e.sock" --results r4 --resume
    same "the engine's link cut mid-frame: results identical to the simulated board's" r4/vectors.actual.bin
    run "bench against the engine behind a socket" 0 'sink|source|loopback' -- \
        "$H" bench --transport socket --connect "unix:$tmp/e.sock" --mib 16
    sed 's/^/# engine: /' out.txt
    stop_board
else
    bad "sockboard not built" "$SB"
fi

# ------------------------------------------------------------------ 2. faults
# fault NAME FLAG N WANT REGEX: pyboard plays FLAG N; the host exits WANT saying REGEX; a
# resumable failure is resumed; the results must equal the simulated board's either way
fault() {
    local name=$1 flag=$2 n=$3 want=$4 re=$5
    board --unix b.sock --vectors tiger/vectors.bin "$flag" "$n"
    rm -rf rf
    run "$name: exit $want" "$want" "$re" -- "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results rf
    if [ "$want" = 5 ]; then
        [ -e rf/vectors.actual.bin ] && bad "$name: a failed run left vectors.actual.bin"
        run "$name: --resume: PASS" 0 'check: PASS' -- \
            "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results rf --resume
    fi
    if [ "$want" = 0 ] || [ "$want" = 5 ]; then
        same "$name: results identical to the simulated board's" rf/vectors.actual.bin
        [ "$(bstat resets)" = 1 ] && ok "$name: the board was reset once (the first run's start only)" ||
            bad "$name: board resets" "$(tail -1 stats.txt)"
    fi
}
fault "a host frame dropped" --drop 5 0 'PASS'
[ "$(bstat gap)" -ge 1 ] && ok "the dropped frame: the board saw the gap" || bad "drop: no gap seen" "$(tail -1 stats.txt)"
fault "a host frame corrupted" --corrupt 5 0 'PASS'
[ "$(bstat bad)" -ge 1 ] && ok "the corrupted frame: the board saw damage" || bad "corrupt: no damage" "$(tail -1 stats.txt)"
fault "a reply dropped" --drop-reply 3 0 'PASS'
fault "a reply corrupted" --corrupt-reply 3 0 'PASS'
fault "the connection closed mid-commands" --disconnect 6 5 'went away.*--resume'
fault "the connection closed mid-results" --disconnect-reply 4 5 'went away.*--resume'
fault "a stall" --stall 6 5 'stopped answering.*--resume'
# (late enough that frames were acknowledged: a reset before any ACK is a legitimate fresh start)
fault "a board reset mid-run" --reset 60 6 'reset or lost its state'
fault "another protocol version" --protocol 2 6 'protocol version 2'
board --unix b.sock --vectors tiger/vectors.bin --not-ours
run "another device: exit 6" 6 'did not answer identify as an edgeflag board' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results rn
board --unix b.sock --vectors tiger/vectors.bin --mute
run "a board that never answers identify: exit 5 after four tries" 5 'no identify reply in 4 tries of 300 ms' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results rm
stop_board

# ------------------------------------------------------------------ 3. nobody there, bad address
# a port that was free a moment ago: nothing listens on it now
freeport=$("$PY" -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
run "tcp: connection refused: exit 7 naming the address" 7 "tcp:127.0.0.1:$freeport: Connection refused" -- \
    "$H" verify tiger/vectors.bin --transport socket --connect "tcp:127.0.0.1:$freeport"
run "unix: no such socket: exit 7 naming the address" 7 "unix:$tmp/none.sock: No such file" -- \
    "$H" verify tiger/vectors.bin --transport socket --connect "unix:$tmp/none.sock"
run "an unknown host: exit 7 naming the address" 7 "tcp:nosuchhost.invalid:$freeport: " -- \
    "$H" verify tiger/vectors.bin --transport socket --connect "tcp:nosuchhost.invalid:$freeport"
run "a malformed --connect: exit 2" 2 'expected unix:PATH or tcp:HOST:PORT' -- \
    "$H" verify tiger/vectors.bin --transport socket --connect "udp:1.2.3.4"
run "socket without --connect: exit 2" 2 'needs --connect' -- \
    "$H" verify tiger/vectors.bin --transport socket

# ------------------------------------------------------------------ 4. bench
board --unix b.sock
run "bench --transport socket against pyboard" 0 'sink|source|loopback' -- \
    "$H" bench --transport socket --connect "$SOCK" --mib 4
sed 's/^/# pyboard: /' out.txt
stop_board

run "--version names the socket transport" 0 '' -- "$H" --version
grep -q '^  socket .*--connect unix:PATH or tcp:HOST:PORT' out.txt && ok "--version lists socket" ||
    bad "--version" "$(cat out.txt)"

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
