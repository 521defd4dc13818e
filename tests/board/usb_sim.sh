#!/usr/bin/env bash
# tests/board/usb_sim.sh - the simulated ULX3S board over USB (docs/board-ulx3s.md, "USB"): the
# unmodified edgeflag-host and the real libusb, under umockdev's usbdevfs emulation
# (tests/host/usb_emu --soc), against the Verilated SoC's USB device (LUNA's core in gateware,
# board/soc/usb_core.py), whose UTMI side the simulated board's host controller drives
# (board/sim/usb_link.cpp: SOF, tokens, DATA0/1, handshakes, CRCs):
#   1. enumeration and list: the descriptors the gateware returned (docs/board-usb.md section 2 at
#      full speed), its serial string equal to identify's, identify's limits;
#   2. verify of a bundled SVG at 16 x 16, full records: PASS cycle-exact on every interface;
#   3. unplugged mid-commands, replugged at a new address, --resume: results byte-identical to 2's;
#   4. unplugged while results flow, --resume: byte-identical;
#   5. the board's CPU stops (a stall: the core NAKs): "stopped answering" (exit 5), then --resume:
#      byte-identical;
#   6. permission denied (the node root-only, the host run as nobody): exit 8 naming the udev rule;
#   7. the IN bursts ended with short and with zero-length packets (the host controller's count).
# One simulated board serves every case (its state carries over, as a powered board's does).
# usage: bash tests/board/usb_sim.sh SIM_DIR   (`make board-sim-usb-test`; SIM_DIR is
#        build/board/sim-ns8, built by `make board-sim`)
# Budget: 75 s on 2 cores.  Ends with "N passed, M failed, K skipped"; exit 0 only if none failed.
set -u
export LC_ALL=C
sim=${1:?usage: tests/board/usb_sim.sh SIM_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $sim in /*) ;; *) sim=$root/$sim ;; esac
# shellcheck source=tests/host/waits.sh disable=SC1091
. "$root/tests/host/waits.sh"
build=${EF_BUILD:-$root/build}
E=$build/edgeflag H=$build/edgeflag-host BS=$sim/obj/board_sim EMU=$build/tests/host/usb_emu
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
skipped() { skip=$((skip + 1)); echo "SKIP - $1"; }
finish() { echo "$pass passed, $fail failed, $skip skipped"; [ "$fail" -eq 0 ]; exit $?; }
for f in "$E" "$H" "$BS" "$EMU"; do
    [ -e "$f" ] || { bad "missing $f (make board-sim host-usb-emu builds it)"; finish; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-usbsim.XXXXXX") || exit 1
chmod 711 "$tmp"
bpid=
stop_board() {
    if [ -n "$bpid" ]; then
        kill "$bpid" 2>/dev/null
        wait "$bpid" 2>/dev/null
        bpid=
    fi
}
trap 'stop_board; rm -rf "$tmp"' EXIT
kv() { sed -n "s/^$2=//p" "$1"; }
sock=$tmp/usb.sock
emu() { timeout "$EF_GUARD_S" "$EMU" --soc "$sock" "$@"; }

svg=stress_pixi_fill_rule_star_nonzero.svg size=16x16
if ! "$E" vectors "$root/tests/data/svg/$svg" -o "$tmp/v" --size $size --samples 8 --formats bin >"$tmp/vec.log" 2>&1; then
    cat "$tmp/vec.log"; bad "edgeflag vectors $svg"; finish
fi
V=$tmp/v/vectors.bin
L="--transport usb --timeout $((3 * EF_LINK_MS))"

"$BS" --dir "$sim/gateware" --usb "$sock" --baud 0 >"$tmp/board.log" 2>&1 &
bpid=$!
for _ in $(seq $((10 * EF_READY_S))); do [ -S "$sock" ] && break; sleep 0.1; done
[ -S "$sock" ] || { bad "the simulated board did not come up"; cat "$tmp/board.log"; finish; }
t00=$(date +%s)

# ---------------------------------------------------------------- 1. enumeration, list
emu --report "$tmp/l.rep" --run "'$H' list >'$tmp/l.out' 2>&1"
soc=$sim/software/include/generated/soc.h
def() { sed -n "s/^#define $1 //p" "$soc"; }
want="usb    1:4            #0 1209:0001 serial EFULX3S-0001, protocol 1, samples $(def EF_NS), canvas up to $(def EF_W_MAX)x$(def EF_H_MAX), $(def EF_E_MAX) edges, window 16"
if [ "$(kv "$tmp/l.rep" run1_exit)" = 0 ] && grep -qF "$want" "$tmp/l.out"; then
    ok "list through libusb and the gateware: $(sed -n 's/^usb *//p' "$tmp/l.out")"
else
    bad "list" "exit $(kv "$tmp/l.rep" run1_exit), want '$want', got: $(cat "$tmp/l.out")"
fi
# the device descriptor byte for byte as docs/board-usb.md's, and the configuration's at full
# speed: 64-byte bulk packets, bus-powered at 500 mA
dev=120100020000004009120100000101020301
cfg=0902200001010080fa0904000002ff0000000705010240000007058102400000
if [ "$(kv "$tmp/l.rep" usb_descriptors)" = "$dev$cfg" ]; then
    ok "the gateware's descriptors: device as docs/board-usb.md section 2, bulk 0x01/0x81 of 64 bytes"
else
    bad "descriptors" "got $(kv "$tmp/l.rep" usb_descriptors)"
fi
if [ "$(kv "$tmp/l.rep" usb_serial)" = EFULX3S-0001 ] && [ "$(kv "$tmp/l.rep" identify)" = 1 ]; then
    ok "the serial string is identify's: $(kv "$tmp/l.rep" usb_serial) ($(kv "$tmp/l.rep" usb_manufacturer), $(kv "$tmp/l.rep" usb_product))"
else
    bad "serial string" "'$(kv "$tmp/l.rep" usb_serial)', identify asked $(kv "$tmp/l.rep" identify) times"
fi

# ---------------------------------------------------------------- 2. verify, full records
t0=$(date +%s%N)
emu --report "$tmp/ref.rep" --run "'$H' verify '$V' $L --results '$tmp/ref' >'$tmp/ref.out' 2>&1"
ms=$((($(date +%s%N) - t0) / 1000000))
if [ "$(kv "$tmp/ref.rep" run1_exit)" = 0 ] && grep -q 'edgeflag check: PASS: 6 comparisons.*cycle-exact' "$tmp/ref.out" &&
   [ "$(kv "$tmp/ref.rep" state)" = 2 ]; then
    ok "verify $svg at $size over USB: $(sed -n 's/.*check: PASS: //p' "$tmp/ref.out") ($ms ms, $(kv "$tmp/ref.rep" in_bytes) bytes in, $(kv "$tmp/ref.rep" out_bytes) out)"
else
    bad "verify over USB" "exit $(kv "$tmp/ref.rep" run1_exit); $(tail -n 8 "$tmp/ref.out")"
fi
crc=$(kv "$tmp/ref.rep" input_crc)

# resumed_case NAME FAULT REPORT_PREFIX MESSAGE [OPTIONS OF THE FIRST RUN]
resumed_case() {
    local name=$1 fault=$2 r=$tmp/$3 msg=$4
    shift 4
    t0=$(date +%s%N)
    emu --fault "$fault" --report "$r.rep" \
        --run "'$H' verify '$V' $L $* --results '$r' >'$r.1' 2>&1" \
        --run "'$H' verify '$V' $L --results '$r' --resume >'$r.2' 2>&1"
    ms=$((($(date +%s%N) - t0) / 1000000))
    if [ "$(kv "$r.rep" run1_exit)" = 5 ] && grep -qF "$msg" "$r.1" && [ "$(kv "$r.rep" run2_exit)" = 0 ] &&
       grep -q 'edgeflag check: PASS' "$r.2" && cmp -s "$tmp/ref/vectors.actual.bin" "$r/vectors.actual.bin" &&
       [ "$(kv "$r.rep" input_crc)" = "$crc" ]; then
        ok "$name: exit 5 ('$msg'), --resume: PASS, results byte-identical, input CRC $crc ($ms ms)"
        return 0
    fi
    bad "$name" "exits $(kv "$r.rep" run1_exit)/$(kv "$r.rep" run2_exit), input CRC $(kv "$r.rep" input_crc) (want $crc); $(tail -n 3 "$r.1"); $(tail -n 3 "$r.2")"
    return 1
}

# ---------------------------------------------------------------- 3-5. unplug, stall: --resume
resumed_case "unplugged mid-commands" unplug-at=150 u "the board went away (unplugged?)" &&
    { [ "$(kv "$tmp/u.rep" address)" = 1:5 ] && ok "replugged at a new address: 1:5" ||
        bad "replug address" "$(kv "$tmp/u.rep" address)"; }
resumed_case "unplugged while results flow" unplug-in=2000 ui "the board went away (unplugged?)"
resumed_case "the board's CPU stops (stall)" stall-at=150 st "the board stopped answering" --timeout 500

# ---------------------------------------------------------------- 6. permission denied
if [ "$(id -u)" = 0 ] && getent passwd nobody >/dev/null; then
    d=$tmp/nobody
    mkdir -m 755 "$d" && mkdir -m 777 "$d/out" && cp "$H" "$d/edgeflag-host" && chmod 755 "$d/edgeflag-host"
    TMPDIR=$d emu --fault eacces --report "$tmp/a.rep" \
        --run "cd '$d' && ./edgeflag-host list >out/a.out 2>&1" >"$tmp/a.log" 2>&1
    if grep -qF "permission denied (udev rule host/60-edgeflag.rules not installed?" "$d/out/a.out" 2>/dev/null &&
       [ "$(kv "$tmp/a.rep" identify)" = 0 ]; then
        ok "permission denied: the udev rule named, nothing reached the board"
    elif [ ! -e "$d/out/a.out" ]; then
        skipped "permission denied: nobody cannot reach $d ($(head -c 200 "$tmp/a.log"))"
    else
        bad "permission denied" "$(cat "$d/out/a.out")"
    fi
else
    skipped "permission denied: needs root and a user nobody"
fi

stop_board
# docs/board-usb.md section 4: every burst ends with a short packet, or a zero-length one after a
# full packet; the host controller counted both kinds (the bursts of 1 KiB end with the latter)
zs=$(sed -n 's/.*IN bursts ended by \([0-9]*\) short and \([0-9]*\) zero-length.*/\1 \2/p' "$tmp/board.log")
if [ -n "$zs" ] && [ "${zs% *}" -gt 0 ] && [ "${zs#* }" -gt 0 ]; then
    ok "IN bursts ended by ${zs% *} short and ${zs#* } zero-length packets"
else
    bad "short and zero-length packets" "'$zs'"
fi
echo "usb_sim: $(($(date +%s) - t00)) s; $(grep 'usb:' "$tmp/board.log" | sed 's/^board_sim: //')"
grep 'sys cycles' "$tmp/board.log" | sed 's/^/    /'
finish
