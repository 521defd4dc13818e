#!/usr/bin/env bash
# tests/board/soc_sim.sh - the whole ULX3S board simulated (docs/board-ulx3s.md, "The board
# simulated"): the SoC's Verilog (VexRiscv running board/ef_board.c as its firmware, ef_raster,
# its frame memory, the UART) in Verilator (board/sim/board_sim.cpp), its UART behind a
# pseudo-terminal when edgeflag-host has the serial transport (else a unix socket and the socket
# transport: the same bytes), driven by the unmodified edgeflag-host:
#   1. identify: the board's true limits (W_MAX, H_MAX, E_MAX, samples, interfaces, serial;
#      capabilities results, resume, internal interfaces and digest);
#   2. verify of a bundled SVG at a small canvas in full-record mode: PASS cycle-exact on every
#      interface the board returns (seg, et_wr, et_rd, plot, span, pix);
#   3. the same in digest mode, when edgeflag-host has one (else said: SKIP, not counted);
#   3b. the UART at 3 Mbaud (serial only): the board at its own clocks (sys 30 MHz), the line paced
#      at 3 Mbaud, tests/board/sink_stream.py streaming 16 KiB of sink-mode DATA in 8 KiB frames as
#      fast as the line takes them: all acknowledged and no byte ever due while the UART's 64-byte
#      receive FIFO was full (board_sim's overrun count 0: on a real UART that byte is lost);
#   4. faults on the wire (serial only: tests/host/ptyboard as a relay in front of the board's
#      pty): a bit flipped on the way to the board, a byte to the host dropped and another
#      duplicated, in one run: recovered (exit 0), results byte-identical to run 2's;
#   5. a planted firmware fault (dut_soc.c built with EF_SOC_FAULT_PIX: one pix record's alpha
#      changed on its way to the engine), in the same simulated SoC's ROM: verify (in digest mode
#      when the host has it: the differing window fetched whole) exits 1 and names pix, nothing else;
#   6. the board's own faults of docs/board.md section 6, played by the simulated board itself
#      (board_sim --faults, serial only): the board stalls mid-commands (exit 5 "stopped
#      answering", then --resume: PASS), the line is unplugged mid-commands while the board runs on
#      (exit 5 "went away", then --resume: PASS), the SoC is reset mid-run (exit 6 "reset or lost
#      its state", then a new run: PASS); every PASS byte-identical to run 2's results;
#   7. (EF_SOCSIM_FULL=1, `make board-sim-faults`) the same faults in digest mode, a FRAME_END
#      inside an open shape refused by the firmware (exit 6), and the engine's bounded result queue
#      (docs/board.md 4.2) on the SoC: a full-record run whose results are many times the bound,
#      with firmware built with a small bound, PASS cycle-exact (the DUT back-pressured).
# usage: bash tests/board/soc_sim.sh SIM_DIR   (`make board-sim-test`: SIM_DIR is
#        build/board/sim-ns8, built by `make board-sim`; EF_SOCSIM_FULL=1 adds section 7)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
sim=${1:?usage: tests/board/soc_sim.sh SIM_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/host/waits.sh disable=SC1091
. "$root/tests/host/waits.sh"
full_set=${EF_SOCSIM_FULL:-0}
# the host's --timeout for runs that must not time out: a simulated second of the board takes
# minutes of wall time on a busy machine, and a frame's results come after its whole frame ran
LINK_MS=$((3 * EF_LINK_MS))
case $sim in /*) ;; *) sim=$root/$sim ;; esac
build=${EF_BUILD:-$root/build}
E=$build/edgeflag H=$build/edgeflag-host BS=$sim/obj/board_sim
SVG=$root/tests/data/svg
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
finish() { echo "$pass passed, $fail failed"; [ "$fail" -eq 0 ]; exit $?; }
for f in "$E" "$H" "$BS" "$sim/firmware.elf"; do
    [ -e "$f" ] || { bad "missing $f (make board-sim builds it)"; finish; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-socsim.XXXXXX") || exit 1
chmod 700 "$tmp"
bpid="" boot_ms=0
stop_board() {
    if [ -n "$bpid" ]; then
        kill "$bpid" 2>/dev/null
        wait "$bpid" 2>/dev/null
        bpid=
    fi
}
trap 'stop_board; rm -rf "$tmp"' EXIT

# The serial transport when this edgeflag-host has it (the pty), else the socket one.
if "$H" --help 2>&1 | grep -q -- '--transport.*serial\|serial.*--port'; then
    mode=serial
else
    mode=socket
fi
# start_board GATEWARE_DIR [BOARD_SIM OPTIONS]: the simulated board, its link in ${L[@]}.  The
# harness publishes the link only once the firmware has answered its own identify (a readiness
# handshake), so this waits for that, however slow the machine is, while the board process lives
# (bounded by EF_GUARD_S, tests/host/waits.sh, only for a board that hangs).
start_board() {
    local gw=$1 t0 t0ns
    shift
    stop_board
    rm -f "$tmp/tty" "$tmp/sock" "$tmp/board.out" # (the last board's line must not count)
    if [ $mode = serial ]; then
        "$BS" --dir "$gw" --link "$tmp/tty" --baud 0 "$@" >"$tmp/board.out" 2>"$tmp/board.log" &
    else
        "$BS" --dir "$gw" --listen "$tmp/sock" --baud 0 "$@" >"$tmp/board.out" 2>"$tmp/board.log" &
    fi
    bpid=$!
    t0=$(date +%s) t0ns=$(date +%s%N)
    until [ -s "$tmp/board.out" ]; do
        kill -0 "$bpid" 2>/dev/null || { bpid=; return 1; }
        [ $(($(date +%s) - t0)) -lt "$EF_GUARD_S" ] || return 1
        sleep 0.05
    done
    boot_ms=$((($(date +%s%N) - t0ns) / 1000000)) # the model's start and the firmware's boot, on this machine now
    if [ $mode = serial ]; then
        L=(--transport serial --port "$tmp/tty")
    else
        L=(--transport socket --connect "unix:$tmp/sock")
    fi
    L+=(--timeout "$LINK_MS")
}
echo "test: the simulated board over the $mode transport"
# full records: verify on a serial line defaults to digest mode once the host has it
full=()
"$H" --help 2>&1 | grep -q -- '--digest' && full=(--digest off)

# ---------------------------------------------------------------- vectors
svg=stress_pixi_fill_rule_star_nonzero.svg size=32x32
if ! "$E" vectors "$SVG/$svg" -o "$tmp/v" --size $size --samples 8 >"$tmp/vec.log" 2>&1; then
    cat "$tmp/vec.log"; bad "edgeflag vectors $svg"; finish
fi

# ---------------------------------------------------------------- 1. identify
start_board "$sim/gateware" || { bad "the simulated board did not come up"; cat "$tmp/board.log"; finish; }
if [ $mode = serial ]; then addr=$tmp/tty; else addr=unix:$tmp/sock; fi
python3 "$root/tests/board/identify.py" "$addr" >"$tmp/id.out" 2>&1
rc=$?
soc=$sim/software/include/generated/soc.h
def() { sed -n "s/^#define $1 //p" "$soc"; }
want="version 1|window 16|capabilities 15|interfaces 0x7f|samples $(def EF_NS)|width_max $(def EF_W_MAX)"
want="$want|height_max $(def EF_H_MAX)|edges_max $(def EF_E_MAX)|serial EFULX3S-0001"
got=$(tr '\n' '|' <"$tmp/id.out" | sed 's/|$//')
if [ $rc = 0 ] && [ "$got" = "$want" ]; then
    ok "identify from the simulated board's firmware: $got"
else
    bad "identify" "exit $rc: got '$got', want '$want'"
fi

# ---------------------------------------------------------------- 2. verify, full records
t0=$(date +%s%N)
"$H" verify "$tmp/v/vectors.bin" "${L[@]}" "${full[@]}" --results "$tmp/full" >"$tmp/full.out" 2>&1
rc=$?
ms=$((($(date +%s%N) - t0) / 1000000))
if [ $rc = 0 ] && grep -q 'edgeflag check: PASS: 6 comparisons.*cycle-exact' "$tmp/full.out"; then
    ok "verify $svg at $size, NS 8, full records: $(sed -n 's/.*PASS: //p' "$tmp/full.out") ($ms ms)"
else
    bad "verify $svg at $size, full records" "exit $rc; $(tail -n 12 "$tmp/full.out")"
fi
stop_board
sed 's/^/    /' "$tmp/board.log"

# ---------------------------------------------------------------- 3. digest mode
if "$H" --help 2>&1 | grep -q -- '--digest'; then
    start_board "$sim/gateware" || { bad "the simulated board did not come up"; finish; }
    t0=$(date +%s%N)
    "$H" verify "$tmp/v/vectors.bin" "${L[@]}" --digest 64 --results "$tmp/dig" >"$tmp/dig.out" 2>&1
    rc=$?
    ms=$((($(date +%s%N) - t0) / 1000000))
    if [ $rc = 0 ] && grep -q 'edgeflag check: PASS' "$tmp/dig.out"; then
        ok "verify in digest mode (a CRC-32 per 64 transactions): $(sed -n 's/.*check: PASS: //p' "$tmp/dig.out" | head -n 1) ($ms ms)"
    else
        bad "verify in digest mode" "exit $rc; $(tail -n 8 "$tmp/dig.out")"
    fi
    stop_board
else
    echo "SKIP - digest mode: this edgeflag-host has no --digest yet (not counted)"
fi

# ---------------------------------------------------------------- 3b. the UART at 3 Mbaud
if [ $mode = serial ]; then
    # (board_sim takes the last --baud: start_board's --baud 0 is overridden)
    start_board "$sim/gateware" --sys-clk 30e6 --baud 3000000 || { bad "the simulated board did not come up"; finish; }
    t0=$(date +%s%N)
    timeout "$EF_GUARD_S" python3 "$root/tests/board/sink_stream.py" "$tmp/tty" 16 8192 >"$tmp/sink.out" 2>&1
    rc=$?
    ms=$((($(date +%s%N) - t0) / 1000000))
    stop_board
    ov=$(sed -n 's/.*UART receive FIFO overruns \([0-9]*\).*/\1/p' "$tmp/board.log")
    if [ $rc = 0 ] && [ "$ov" = 0 ]; then
        ok "the UART at 3 Mbaud, sys 30 MHz: $(cat "$tmp/sink.out"), no receive FIFO overrun ($ms ms)"
    else
        bad "the UART at 3 Mbaud" "exit $rc, overruns '${ov}'; $(tail -n 2 "$tmp/sink.out") $(tail -n 1 "$tmp/board.log")"
    fi
else
    echo "SKIP - the UART at 3 Mbaud: needs the serial transport (not counted)"
fi

# ---------------------------------------------------------------- 4. faults on the wire
PB=$build/tests/host/ptyboard
if [ $mode = serial ] && [ -x "$PB" ]; then
    start_board "$sim/gateware" || { bad "the simulated board did not come up"; finish; }
    rm -f "$tmp/relay.out"
    "$PB" --to "$tmp/tty" --link "$tmp/relay" --faults flip=300,drop-down=4000,dup-down=8000 \
        >"$tmp/relay.out" 2>"$tmp/relay.err" &
    rpid=$!
    until [ -s "$tmp/relay.out" ] || ! kill -0 "$rpid" 2>/dev/null; do sleep 0.05; done
    t0=$(date +%s%N)
    "$H" verify "$tmp/v/vectors.bin" --transport serial --port "$tmp/relay" --timeout "$LINK_MS" "${full[@]}" \
        --results "$tmp/wire" >"$tmp/wire.out" 2>&1
    rc=$?
    ms=$((($(date +%s%N) - t0) / 1000000))
    kill "$rpid" 2>/dev/null
    wait "$rpid" 2>/dev/null
    if [ $rc = 0 ] && grep -q 'edgeflag check: PASS' "$tmp/wire.out" &&
       cmp -s "$tmp/wire/vectors.actual.bin" "$tmp/full/vectors.actual.bin"; then
        ok "wire faults (a bit flipped to the board, a byte to the host dropped, one duplicated): PASS, results identical ($ms ms)"
    else
        bad "wire faults" "exit $rc; $(tail -n 6 "$tmp/wire.out")"
    fi
    stop_board
else
    echo "SKIP - wire faults: need the serial transport and tests/host/ptyboard (not counted)"
fi

# ---------------------------------------------------------------- 5. a firmware fault
# the faulty firmware in a copy of the gateware folder's memory images (the ROM is $readmemh'd)
fdir=$tmp/fault-gw
mkdir -p "$fdir"
cp "$sim"/gateware/*.init "$fdir/"
if make -C "$root" --no-print-directory -f board/firmware/firmware.mk FW_SOC="$sim" FW_OUT="$tmp/fault" \
        FW_EXTRA=-DEF_SOC_FAULT_PIX EF_VENV_PY="$root/build/venv/bin/python" "$tmp/fault.bin" \
        >"$tmp/fault-build.log" 2>&1 &&
   od -An -v -tx4 -w4 "$tmp/fault.bin" | tr -d ' ' >"$fdir/sim_rom.init"; then
    start_board "$fdir" || { bad "the simulated board (faulty firmware) did not come up"; finish; }
    dig=()
    [ ${#full[@]} -gt 0 ] && dig=(--digest 64) # digest mode must find it and fetch the window
    "$H" verify "$tmp/v/vectors.bin" "${L[@]}" "${dig[@]}" --results "$tmp/fault-res" >"$tmp/fault.out" 2>&1
    rc=$?
    nm=$(sed -n 's/^edgeflag check: pix: .*, \([0-9]*\) mismatch.*/\1/p' "$tmp/fault.out" | head -n 1)
    others=$(grep -E '^edgeflag check: (seg|et_wr|et_rd|plot|span): ' "$tmp/fault.out" | grep -vc ' 0 mismatches')
    if [ $rc = 1 ] && [ "${nm:-0}" -ge 1 ] && [ "$others" = 0 ]; then
        ok "a planted firmware fault (EF_SOC_FAULT_PIX) is caught${dig:+ in digest mode}: exit 1, $nm pix mismatch(es), none elsewhere: $(grep -m1 'pix: cycle' "$tmp/fault.out" | sed 's/.*\(pix: cycle [0-9]*\).*/\1/')"
    else
        bad "the planted firmware fault" "exit $rc, pix mismatches '${nm}', other interfaces differing $others; $(tail -n 8 "$tmp/fault.out")"
    fi
    stop_board
else
    tail -n 20 "$tmp/fault-build.log"; bad "build the faulty firmware"
fi
# ---------------------------------------------------------------- 6. the board's own faults
# played by the simulated board itself (board_sim --faults): the run cut into DATA frames of 4
# commands so that the faults land mid-commands; every PASS compared with run 2's results
if [ $mode = serial ]; then
    P=(--transport serial --port "$tmp/tty" --frame-cmds 4)
    STALL_MS=$((1500 * EF_SCALE)) # the stalled run's own --timeout: 4 of them end it (what it tests)

    # hrun NAME WANT_EXIT REGEX -- COMMAND...: the exit status and what the host said
    hrun() {
        local name=$1 want=$2 re=$3 rc=0
        shift 4
        timeout "$EF_GUARD_S" "$@" >"$tmp/h.out" 2>"$tmp/h.err" || rc=$?
        if [ "$rc" = "$want" ] && { [ -z "$re" ] || grep -Eq "$re" "$tmp/h.err" "$tmp/h.out"; }; then
            ok "$name"
        else
            bad "$name" "exit $rc (want $want); $(tail -n 4 "$tmp/h.err" | tr '\n' ' ')"
        fi
    }
    # hjson KEY: the last run's --json counter KEY
    hjson() { sed -n 's/.*"'"$1"'": \([0-9]*\).*/\1/p' "$tmp/h.out" | tail -n 1; }
    same() { # NAME FILE: FILE is byte-identical to run 2's results
        if cmp -s "$2" "$tmp/full/vectors.actual.bin"; then ok "$1"; else bad "$1" "$2 differs from run 2's"; fi
    }
    # board_faults LABEL [--digest N]: the three faults, full records or digest mode
    board_faults() {
        local label=$1 r
        shift
        local dg=("${full[@]}")
        [ $# -gt 0 ] && dg=("$@")
        # the board stalls after the host's 5th frame (identify, reset, START, 2 DATA)
        r=$tmp/stall$label
        if start_board "$sim/gateware" --faults stall=5; then
            hrun "the board stalls mid-commands$label: exit 5" 5 'stopped answering.*--resume' -- \
                "$H" verify "$tmp/v/vectors.bin" "${P[@]}" "${dg[@]}" --timeout "$STALL_MS" --results "$r" --json
            if grep -q "stalled after the host's frame 5" "$tmp/board.log" && [ "$(hjson timeouts)" = 4 ] &&
               ! [ -e "$r/vectors.actual.bin" ]; then
                ok "the board stalls$label: after the host's frame 5, 4 timeouts, no results written"
            else
                bad "the board stalls$label" "timeouts $(hjson timeouts); $(cat "$tmp/board.log")"
            fi
            kill -USR1 "$bpid" # the stall ends
            hrun "the board stalls$label: --resume: PASS" 0 'check: PASS: 6 comparisons.*cycle-exact' -- \
                "$H" verify "$tmp/v/vectors.bin" "${P[@]}" "${dg[@]}" --timeout "$LINK_MS" --results "$r" --resume
            same "the board stalls$label: --resume's results byte-identical" "$r/vectors.actual.bin"
        else
            bad "the simulated board (stall) did not come up"
        fi
        # the line unplugged after the host's 5th frame; the board runs on
        r=$tmp/unplug$label
        if start_board "$sim/gateware" --faults unplug=5; then
            hrun "the line unplugged mid-commands$label: exit 5" 5 'went away.*--resume' -- \
                "$H" verify "$tmp/v/vectors.bin" "${P[@]}" "${dg[@]}" --timeout "$LINK_MS" --results "$r" --json
            if grep -q "unplugged after the host's frame 5" "$tmp/board.log" && [ "$(hjson timeouts)" = 0 ]; then
                ok "the line unplugged$label: after the host's frame 5, the hang-up seen (no timeout)"
            else
                bad "the line unplugged$label" "timeouts $(hjson timeouts); $(cat "$tmp/board.log")"
            fi
            hrun "the line unplugged$label: --resume: PASS" 0 'check: PASS: 6 comparisons.*cycle-exact' -- \
                "$H" verify "$tmp/v/vectors.bin" "${P[@]}" "${dg[@]}" --timeout "$LINK_MS" --results "$r" --resume
            same "the line unplugged$label: --resume's results byte-identical" "$r/vectors.actual.bin"
        else
            bad "the simulated board (unplug) did not come up"
        fi
        # the SoC reset (a power cycle) once its 4th frame reached the host (acknowledgements)
        r=$tmp/reset$label
        # (the frames the host sent while the SoC boots again are lost: its timeout, RESET_MS, sends
        # them again, and the rebooted firmware's NAK names frame 0, which the host had acknowledged)
        if start_board "$sim/gateware" --faults reset=4; then
            # the reset run's --timeout: twice the board's boot as measured now (at least 3 s), so
            # that its 4 timeouts outlast the reboot however loaded the machine is
            RESET_MS=$((2 * boot_ms > 3000 ? 2 * boot_ms : 3000))
            RESET_MS=$((RESET_MS * EF_SCALE))
            hrun "the SoC reset mid-run$label: exit 6" 6 'reset or lost its state.*without --resume' -- \
                "$H" verify "$tmp/v/vectors.bin" "${P[@]}" "${dg[@]}" --timeout "$RESET_MS" --results "$r" --json
            if grep -q "reset after the board's frame 4" "$tmp/board.log" && [ "$(hjson naks)" -ge 1 ] &&
               ! [ -e "$r/vectors.actual.bin" ]; then
                ok "the SoC reset$label: its NAK asked for an acknowledged frame ($(hjson timeouts) timeouts), no results written"
            else
                bad "the SoC reset$label" "naks $(hjson naks); $(cat "$tmp/board.log")"
            fi
            hrun "the SoC reset$label: the same command again: PASS" 0 'check: PASS: 6 comparisons.*cycle-exact' -- \
                "$H" verify "$tmp/v/vectors.bin" "${P[@]}" "${dg[@]}" --timeout "$LINK_MS" --results "$r"
            same "the SoC reset$label: the new run's results byte-identical" "$r/vectors.actual.bin"
        else
            bad "the simulated board (reset) did not come up"
        fi
        stop_board
    }
    board_faults ""
    if [ "$full_set" = 1 ] && [ ${#full[@]} -gt 0 ]; then
        board_faults " (digest mode)" --digest 64
    fi
else
    echo "SKIP - the board's own faults: need the serial transport (not counted)"
fi

# ---------------------------------------------------------------- 7. the full set's extras
if [ "$full_set" = 1 ]; then
    # a FRAME_END inside an open shape (the last SHAPE_END made an EDGE, the vectors' CRCs made
    # good again): the peripheral ends a frame at FRAME_END's transfer, drained only after a closed
    # shape, so the firmware refuses the stream
    python3 - "$tmp/v/vectors.bin" "$tmp/open.bin" <<'PYEOF'
import struct, sys, zlib
b = bytearray(open(sys.argv[1], 'rb').read())
o, last = 104, None
while o < len(b):
    if b[o] == 0 and b[o + 10 + 12] & 0xF == 4:
        last = o
    o += 10 + b[o + 1]
b[last + 10 + 12] = (b[last + 10 + 12] & 0xF0) | 3
struct.pack_into('<I', b, 96, zlib.crc32(bytes(b[104:])))
struct.pack_into('<I', b, 100, zlib.crc32(bytes(b[:100])))
open(sys.argv[2], 'wb').write(b)
PYEOF
    if start_board "$sim/gateware"; then
        "$H" verify "$tmp/open.bin" "${L[@]}" "${full[@]}" --results "$tmp/open" >"$tmp/open.out" 2>&1
        rc=$?
        if [ $rc = 6 ] && grep -q 'code 16: FRAME_END inside a shape' "$tmp/open.out"; then
            ok "a FRAME_END inside an open shape: refused by the firmware (exit 6, ERROR 16)"
        else
            bad "a FRAME_END inside an open shape" "exit $rc; $(tail -n 3 "$tmp/open.out")"
        fi
        stop_board
    else
        bad "the simulated board did not come up"
    fi
fi
if [ "$full_set" = 1 ] && [ $mode = serial ]; then
    # the bounded result queue on the SoC: firmware built with 1 KiB RESULT frames and a queue of 4
    # (EF_BOARD_RESULT_QUEUE) and, to show the bound is what holds it, with none (0); run 2's
    # 15 KiB of full records (16 frames) on a line of 300,000 baud in simulated time (30 kB/s:
    # slower than the firmware makes results): PASS cycle-exact, results byte-identical, and the
    # board's own status (asked by board_sim every 200,000 cycles between the host's frames) never
    # says more than 4 result frames kept; unbounded it says more
    for q in 4 0; do
        qdir=$tmp/queue$q-gw
        mkdir -p "$qdir"
        cp "$sim"/gateware/*.init "$qdir/"
        if ! make -C "$root" --no-print-directory -f board/firmware/firmware.mk FW_SOC="$sim" FW_OUT="$tmp/queue$q" \
                FW_EXTRA="-DEF_BOARD_RESULT_QUEUE=$q -DEF_BOARD_RESULT_PAYLOAD=1024" \
                EF_VENV_PY="$root/build/venv/bin/python" "$tmp/queue$q.bin" >"$tmp/queue-build.log" 2>&1; then
            tail -n 20 "$tmp/queue-build.log"; bad "build the firmware with a result queue of $q"; continue
        fi
        od -An -v -tx4 -w4 "$tmp/queue$q.bin" | tr -d ' ' >"$qdir/sim_rom.init"
        start_board "$qdir" --baud 300000 --probe-status 200000 ||
            { bad "the simulated board (result queue $q) did not come up"; continue; }
        "$H" verify "$tmp/v/vectors.bin" "${L[@]}" "${full[@]}" --results "$tmp/queue$q" >"$tmp/queue.out" 2>&1
        rc=$?
        stop_board
        most=$(sed -n 's/.*result frames kept at most \([0-9]*\) (\([0-9]*\) status probes).*/\1 \2/p' "$tmp/board.log")
        if [ $rc = 0 ] && grep -q 'check: PASS: 6 comparisons.*cycle-exact' "$tmp/queue.out" &&
            cmp -s "$tmp/queue$q/vectors.actual.bin" "$tmp/full/vectors.actual.bin" &&
            { { [ $q = 4 ] && [ "${most%% *}" -le 4 ]; } || { [ $q = 0 ] && [ "${most%% *}" -gt 4 ]; }; }; then
            ok "a result queue of $q (0: none) on the SoC, 1 KiB frames: PASS cycle-exact, identical, at most ${most%% *} result frames kept (${most#* } probes)"
        else
            bad "a result queue of $q on the SoC" "exit $rc, at most '$most' kept; $(tail -n 3 "$tmp/queue.out") $(cat "$tmp/board.log")"
        fi
    done
fi
finish
