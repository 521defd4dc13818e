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
#   4. bench --transport socket against pyboard and against the engine (numbers printed);
#   and identify --save from the engine and from a pyboard of small limits, whose saved record
#   `edgeflag gen --dut-file` fits and refuses by as the same limits given as flags; SIGTERM
#   to the engine spinning in its DUT and SIGINT to it idle: it dies of the signal at once.
# Recovery is asserted by how it happened (the host's NAK, retransmission and timeout counts,
# the board's gap, damage, duplicate and resend counters), never by how fast: every run that must
# not time out gets a generous --timeout (tests/host/waits.sh, EF_TEST_TIMEOUT_SCALE), and only the
# stall and the mute board, whose timeouts are what they test, get a short one.
# usage: bash tests/host/socket.sh BUILD_DIR   (`make test-host-socket`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
# shellcheck disable=SC2016 # how's conditions are single-quoted on purpose: evaluated when checked
set -u
export LC_ALL=C
build=${1:?usage: tests/host/socket.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/host/waits.sh disable=SC1091
. "$root/tests/host/waits.sh"
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

# listening FILE: waits (up to EF_READY_S) until the board process $bpid has made FILE (its
# port file or its socket), and says so; a board that died or never listens is a failure
listening() {
    local i
    for ((i = 0; i < EF_READY_S * 20; i++)); do
        [ -s "$1" ] || [ -S "$1" ] && return 0
        kill -0 "$bpid" 2>/dev/null || break
        sleep 0.05
    done
    bad "the board process is not listening ($1)" "$(head -c 400 board.err sockboard.err 2>/dev/null | tr '\n' ' ')"
    return 1
}
# board ARGS...: pyboard on unix:$tmp/b.sock (or with --tcp 0: its port in $port); waits until it listens
board() {
    stop_board
    rm -f b.sock port stats.txt
    "$PY" "$PYBOARD" --port-file port --stats stats.txt "$@" 2>board.err &
    bpid=$!
    listening port
    port=$(cat port 2>/dev/null)
}
# bstat KEY: the board's last counter line's KEY
bstat() { tail -1 stats.txt 2>/dev/null | sed -n 's/.*"'"$1"'": \([0-9]*\).*/\1/p'; }
# hstat KEY: the host's --json summary's KEY (the last run's)
hstat() { sed -n 's/.*"'"$1"'": \([0-9]*\).*/\1/p' out.txt | tail -1; }
# how NAME CONDITION: a counter check (CONDITION: shell text, e.g. '[ "$(hstat naks)" -ge 1 ] && ...',
# evaluated here), failing with both sides' counters
how() {
    if eval "$2"; then ok "$1"; else bad "$1" "host: $(grep -o '"frames_sent.*timeouts": [0-9]*' out.txt); board: $(tail -1 stats.txt)"; fi
}

# run NAME EXPECTED_EXIT STDERR_REGEX -- COMMAND...
run() {
    local name=$1 want=$2 re=$3
    shift 4
    timeout "$EF_GUARD_S" "$@" >out.txt 2>err.txt
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
# runs that must not time out: a generous --timeout; a stall and a mute board: 300 ms
LINK=(--transport socket --frame-cmds 40 --timeout "$EF_LINK_MS")
SHORT=300

# ------------------------------------------------------------------ 1. plain runs
board --unix b.sock --vectors small/vectors.bin
run "verify over unix: against pyboard: PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify small/vectors.bin --transport socket --connect "$SOCK"
board --unix b.sock --vectors tiger/vectors.bin
run "verify the tiger over unix: (40 commands a frame): PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results r0 --json
same "unix: results identical to the simulated board's" r0/vectors.actual.bin
how "clean run: the board took every frame once, no NAK, one reset; the host sent nothing again, no timeout" \
    '[ "$(bstat dup)/$(bstat gap)/$(bstat bad)/$(bstat naks)/$(bstat resets)/$(hstat retransmits)/$(hstat timeouts)" = 0/0/0/0/1/0/0 ]'
# a board that takes at most 4 KiB of DATA (identify's capabilities, docs/board.md 3.1): the host's
# frames of its default size are cut to fit, to the most whole commands that fit (315: 4,095 bytes)
board --unix b.sock --vectors tiger/vectors.bin --data-kib 4
run "verify the tiger on a board of 4 KiB DATA payloads: PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify tiger/vectors.bin --transport socket --connect "$SOCK" --timeout "$EF_LINK_MS" --results rk --json
same "4 KiB DATA payloads: results identical to the simulated board's" rk/vectors.actual.bin
how "4 KiB DATA payloads: the largest DATA the board took is 315 commands (4,095 bytes)" '[ "$(bstat data_max)" = 4095 ]'
# no --timeout: the default of 2,000 ms (docs/board.md 7, --help), against a board that answers when
# it answers (the simulated board answers inside the host's own writes, so only here do reads come back
# empty): the run passes with the same results
board --unix b.sock --vectors tiger/vectors.bin
run "verify with the default --timeout: PASS" 0 'check: PASS: 6 comparisons' -- \
    "$H" verify tiger/vectors.bin --transport socket --connect "$SOCK" --results rd
same "the default --timeout: results identical to the simulated board's" rd/vectors.actual.bin
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
    listening e.sock
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
    listening e.sock
    run "the engine's link cut mid-frame: exit 5" 5 'went away.*--resume' -- \
        "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "unix:$tmp/e.sock" --results r4
    run "the engine's link cut mid-frame: --resume: PASS" 0 'check: PASS: 6 comparisons' -- \
        "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "unix:$tmp/e.sock" --results r4 --resume
    same "the engine's link cut mid-frame: results identical to the simulated board's" r4/vectors.actual.bin
    run "bench against the engine behind a socket" 0 'sink|source|loopback' -- \
        "$H" bench --transport socket --connect "unix:$tmp/e.sock" --mib 16 --timeout "$EF_LINK_MS"
    sed 's/^/# engine: /' out.txt
    # what no correct host sends (issue 27: the engine's mutants that the host's runs cannot
    # reach): tests/board/probe.py, written from docs/board.md alone, checks the engine's ERROR
    # codes for refused STARTs, DATA and END, its single NAK per gap, status and ACKR
    if "$PY" "$root/tests/board/probe.py" "unix:$tmp/e.sock" >probe.txt 2>&1 && tail -n 1 probe.txt | grep -q ' 0 failed$'; then
        ok "the engine answers tests/board/probe.py's $(tail -n 1 probe.txt | cut -d' ' -f1) protocol checks"
    else
        bad "tests/board/probe.py against the engine" "$(grep -v '^ok - ' probe.txt | head -n 5 | tr '\n' ' ')"
    fi
    run "identify --save over a socket, from the engine: exit 0" 0 '' -- \
        "$H" identify --transport socket --connect "unix:$tmp/e.sock" --save eng.bin --timeout "$EF_LINK_MS"
    if grep -q '^socket: serial EFSOCK0001, protocol 1, samples 8/16/32, canvas up to 16384x16384' out.txt &&
       [ "$(wc -c <eng.bin)" = 48 ] && [ "$(head -c 10 eng.bin | tail -c 6 | od -An -tx1 | tr -d ' ')" = 010010000f00 ]; then
        ok "the engine's identify over the socket's control frame: decoded, saved whole (48 bytes)"
    else
        bad "identify from the engine" "$(cat out.txt)"
    fi
    stop_board
    # SIGTERM while the engine spins (sockboard --hang-dut: its DUT never returns from the first
    # command, as a mutant of the engine that loops forever; c-mutants.sh runs those): the board
    # must die of the signal at once and leave no socket file; SIGINT when idle the same.
    # died PID: waits up to 5 s for PID to end; its exit status in $drc ("" if it did not end)
    died() { local i; drc=; for ((i = 0; i < 50; i++)); do kill -0 "$1" 2>/dev/null || { wait "$1"; drc=$?; return 0; }; sleep 0.1; done; return 1; }
    rm -f h.sock
    "$SB" --hang-dut "$tmp/h.sock" 2>hang.err &
    bpid=$!
    listening h.sock
    "$H" stream small/vectors.bin --transport socket --connect "unix:$tmp/h.sock" --timeout 300 --results rh >hang.out 2>&1
    hrc=$?
    spin=$(ps -o stat= -p "$bpid" | cut -c1)
    kill -TERM "$bpid"
    if died "$bpid" && [ "$hrc" = 5 ] && [ "$spin" = R ] && [ "$drc" = 143 ] && [ ! -e h.sock ]; then
        ok "SIGTERM while the engine spins in its DUT (the host gave up: exit 5): the board died of it (143) at once, its socket file removed"
    else
        bad "SIGTERM to a spinning board" "host exit $hrc, board state '$spin', board exit '${drc}' ($(kill -0 "$bpid" 2>/dev/null && echo still running)), socket $(ls h.sock 2>/dev/null || echo gone)"
        kill -9 "$bpid" 2>/dev/null
    fi
    bpid=
    rm -f h.sock
    "$SB" "$tmp/h.sock" 2>hang.err &
    bpid=$!
    listening h.sock
    kill -INT "$bpid"
    if died "$bpid" && [ "$drc" = 130 ] && [ ! -e h.sock ]; then
        ok "SIGINT to an idle board: died of it (130), its socket file removed"
    else
        bad "SIGINT to an idle board" "exit '${drc}', socket $(ls h.sock 2>/dev/null || echo gone)"
        kill -9 "$bpid" 2>/dev/null
    fi
    bpid=
else
    bad "sockboard not built" "$SB"
fi
# A board with small limits (pyboard, written from docs/board.md alone: 64x64, 200 edges, and the
# one sample count of its vectors, 16): identify --save, then gen --dut-file on the saved record
# fits and refuses exactly as the same limits given as flags do, neither nothing nor everything.
board --unix b.sock --vectors small/vectors.bin --limits 64,64,200
run "identify --save from a board of 64x64, 200 edges, 16 samples" 0 '' -- \
    "$H" identify --transport socket --connect "$SOCK" --save small_board.bin --timeout "$EF_LINK_MS"
"$E" gen --list --dut-file small_board.bin >gf.tsv 2>gf.err
"$E" gen --list --dut-limits 64x64 --dut-edges 200 --dut-samples 16 >gl.tsv 2>gl.err
nfit=$(grep -c 'fitted to the DUT' gf.tsv) nref=$(grep -c "refused by the DUT's limits" gf.err)
if grep -q 'samples 16, canvas up to 64x64, 200 edges' out.txt && cmp -s gf.tsv gl.tsv && cmp -s gf.err gl.err &&
   [ "$nfit" -gt 0 ] && [ "$nref" -gt 0 ]; then
    ok "gen --dut-file on that board's saved identify: $nfit cases fitted and $nref refused, exactly as --dut-limits 64x64 --dut-edges 200 --dut-samples 16"
else
    bad "gen --dut-file on pyboard's identify" "fitted $nfit, refused $nref; $(cat out.txt; head -n 2 gf.err)"
fi

# ------------------------------------------------------------------ 2. faults
# fault NAME FLAG N WANT REGEX [TIMEOUT_MS]: pyboard plays FLAG N; the host exits WANT saying REGEX
# (its --json summary in out.txt, the board's counters in stats.txt, for the caller to ask how);
# a resumable failure is resumed; the results must equal the simulated board's either way
fault() {
    local name=$1 flag=$2 n=$3 want=$4 re=$5 ms=${6:-$EF_LINK_MS}
    board --unix b.sock --vectors tiger/vectors.bin "$flag" "$n"
    rm -rf rf
    run "$name: exit $want" "$want" "$re" -- "$H" verify tiger/vectors.bin "${LINK[@]}" --timeout "$ms" \
        --connect "$SOCK" --results rf --json
    cp out.txt fault.json
    if [ "$want" = 5 ]; then
        [ -e rf/vectors.actual.bin ] && bad "$name: a failed run left vectors.actual.bin"
        run "$name: --resume: PASS" 0 'check: PASS' -- \
            "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results rf --resume --json
        how "$name: --resume went on from where the board was (frame > 0), with no timeout" \
            '[ "$(hstat resumed_from_frame)" -gt 0 ] && [ "$(hstat timeouts)" = 0 ]'
    fi
    if [ "$want" = 0 ] || [ "$want" = 5 ]; then
        same "$name: results identical to the simulated board's" rf/vectors.actual.bin
        [ "$(bstat resets)" = 1 ] && ok "$name: the board was reset once (the first run's start only)" ||
            bad "$name: board resets" "$(tail -1 stats.txt)"
    fi
    cp fault.json out.txt
}
# a frame to the board lost or damaged: the board NAKs the frame it expects, the host goes back to
# it (retransmits), no timeout (docs/board.md 4.1)
fault "a host frame dropped" --drop 5 0 'PASS'
how "the dropped frame: the board saw the gap and NAKed it, the host sent again from there, no timeout" \
    '[ "$(bstat gap)" -ge 1 ] && [ "$(bstat naks)" -ge 1 ] && [ "$(bstat bad)" = 0 ] &&
     [ "$(hstat naks)" -ge 1 ] && [ "$(hstat retransmits)" -ge 1 ] && [ "$(hstat timeouts)" = 0 ]'
fault "a host frame corrupted" --corrupt 5 0 'PASS'
how "the corrupted frame: the board saw damage and NAKed it, the host sent again from there, no timeout" \
    '[ "$(bstat bad)" -ge 1 ] && [ "$(bstat naks)" -ge 1 ] &&
     [ "$(hstat naks)" -ge 1 ] && [ "$(hstat retransmits)" -ge 1 ] && [ "$(hstat timeouts)" = 0 ]'
# a frame to the host lost or damaged: the host sees the next one's gap and asks for every result
# again (ACKR with RESEND): the board sends copies, the board's frames were all taken once
fault "a reply dropped" --drop-reply 3 0 'PASS'
how "the dropped reply: asked again, the board sent copies (board frames > results), nothing resent to it, no timeout" \
    '[ "$(bstat board_frames)" -gt "$(bstat results_made)" ] && [ "$(bstat dup)/$(bstat naks)" = 0/0 ] &&
     [ "$(hstat retransmits)/$(hstat timeouts)" = 0/0 ]'
fault "a reply corrupted" --corrupt-reply 3 0 'PASS'
how "the corrupted reply: asked again, the board sent copies, nothing resent to it, no timeout" \
    '[ "$(bstat board_frames)" -gt "$(bstat results_made)" ] && [ "$(bstat dup)/$(bstat naks)" = 0/0 ] &&
     [ "$(hstat retransmits)/$(hstat timeouts)" = 0/0 ]'
fault "the connection closed mid-commands" --disconnect 6 5 'went away.*--resume'
how "closed mid-commands: the host saw the link go, no timeout" \
    '[ "$(hstat timeouts)" = 0 ]'
fault "the connection closed mid-results" --disconnect-reply 4 5 'went away.*--resume'
how "closed mid-results: the host saw the link go, no timeout" \
    '[ "$(hstat timeouts)" = 0 ]'
# the stall's timeout is what it tests: a short one, four of them in a row end the run
fault "a stall" --stall 6 5 'stopped answering.*--resume' "$SHORT"
how "the stall: the run ended after 4 timeouts in a row" \
    '[ "$(hstat timeouts)" = 4 ]'
# (late enough that frames were acknowledged: a reset before any ACK is a legitimate fresh start)
fault "a board reset mid-run" --reset 60 6 'reset or lost its state'
how "the reset: the board's NAK asked for a frame it had acknowledged, no timeout" \
    '[ "$(hstat naks)" -ge 1 ] && [ "$(hstat timeouts)" = 0 ]'
fault "another protocol version" --protocol 2 6 'protocol version 2'
board --unix b.sock --vectors tiger/vectors.bin --not-ours
run "another device: exit 6" 6 'did not answer identify as an edgeflag board' -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --connect "$SOCK" --results rn
board --unix b.sock --vectors tiger/vectors.bin --mute
run "a board that never answers identify: exit 5 after four tries" 5 "no identify reply in 4 tries of $SHORT ms" -- \
    "$H" verify tiger/vectors.bin "${LINK[@]}" --timeout "$SHORT" --connect "$SOCK" --results rm
# lost at identify, before any resume state exists: the host must not send the user to --resume
if grep -q 'nothing to resume: run the same command again' err.txt && ! grep -q -- '--resume' err.txt; then
    ok "lost before the run started: told to run again, not to --resume"
else
    bad "lost before the run started" "$(head -c 400 err.txt | tr '\n' ' ')"
fi
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
    "$H" bench --transport socket --connect "$SOCK" --mib 4 --timeout "$EF_LINK_MS"
sed 's/^/# pyboard: /' out.txt
stop_board

run "--version names the socket transport" 0 '' -- "$H" --version
grep -q '^  socket .*--connect unix:PATH or tcp:HOST:PORT' out.txt && ok "--version lists socket" ||
    bad "--version" "$(cat out.txt)"

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
