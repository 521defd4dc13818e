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
#   4. faults on the wire (serial only: tests/host/ptyboard as a relay in front of the board's
#      pty): a bit flipped on the way to the board, a byte to the host dropped and another
#      duplicated, in one run: recovered (exit 0), results byte-identical to run 2's;
#   5. a planted firmware fault (dut_soc.c built with EF_SOC_FAULT_PIX: one pix record's alpha
#      changed on its way to the engine), in the same simulated SoC's ROM: verify (in digest mode
#      when the host has it: the differing window fetched whole) exits 1 and names pix, nothing else.
# usage: bash tests/board/soc_sim.sh SIM_DIR   (`make board-sim-test`: SIM_DIR is
#        build/board/sim-ns8, built by `make board-sim`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
sim=${1:?usage: tests/board/soc_sim.sh SIM_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
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
bpid=
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
# start_board GATEWARE_DIR: the simulated board, its link in $link (LINK OPTIONS in ${L[@]})
start_board() {
    stop_board
    rm -f "$tmp/pty" "$tmp/sock"
    if [ $mode = serial ]; then
        "$BS" --dir "$1" --pty-link "$tmp/pty" --baud 0 >"$tmp/board.log" 2>&1 &
        bpid=$!
        for _ in $(seq 100); do [ -s "$tmp/pty" ] && break; sleep 0.1; done
        [ -s "$tmp/pty" ] || return 1
        L=(--transport serial --port "$(cat "$tmp/pty")")
    else
        "$BS" --dir "$1" --listen "$tmp/sock" --baud 0 >"$tmp/board.log" 2>&1 &
        bpid=$!
        for _ in $(seq 100); do [ -S "$tmp/sock" ] && break; sleep 0.1; done
        [ -S "$tmp/sock" ] || return 1
        L=(--transport socket --connect "unix:$tmp/sock")
    fi
    L+=(--timeout 30000)
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
if [ $mode = serial ]; then addr=$(cat "$tmp/pty"); else addr=unix:$tmp/sock; fi
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

# ---------------------------------------------------------------- 4. faults on the wire
PB=$build/tests/host/ptyboard
if [ $mode = serial ] && [ -x "$PB" ]; then
    start_board "$sim/gateware" || { bad "the simulated board did not come up"; finish; }
    "$PB" --to "$(cat "$tmp/pty")" --link "$tmp/tty" --faults flip=300,drop-down=4000,dup-down=8000 \
        >"$tmp/relay.out" 2>"$tmp/relay.err" &
    rpid=$!
    for _ in $(seq 100); do [ -s "$tmp/relay.out" ] && break; sleep 0.1; done
    t0=$(date +%s%N)
    "$H" verify "$tmp/v/vectors.bin" --transport serial --port "$tmp/tty" --timeout 30000 "${full[@]}" \
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
finish
