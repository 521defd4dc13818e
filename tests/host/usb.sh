#!/usr/bin/env bash
# tests/host/usb.sh BUILD - edgeflag-host's USB transport against an emulated
# board (tests/host/usb_emu.c: umockdev + the real board engine), with the
# unmodified binary under umockdev's preload.  Every case asserts what the
# board received (the emulator's report and the DUT's input log) and what the
# user was told (exit code and message).  docs/board-usb.md, docs/board.md.
# Budget: 90 s on the 2-core CI machine (about 10 s here).
# Ends with "N passed, M failed, K skipped"; exit status 0 only if nothing failed.  A check that
# this machine cannot arrange (the permission-denied case needs root, a user nobody and a folder
# nobody can reach) is SKIPPED with the reason: never counted as passed, nor as failed.
set -u
cd "$(dirname "$0")/../.." || exit 1
# shellcheck source=tests/host/waits.sh disable=SC1091
. tests/host/waits.sh
B=${1:-build}
case $B in /*) ;; *) B=$PWD/$B ;; esac
H=$B/edgeflag-host
EMU=$B/tests/host/usb_emu
EF=$B/edgeflag
for f in "$H" "$EMU" "$EF"; do
    [ -x "$f" ] || { echo "usb: $f is missing (make test-host-usb builds it)"; exit 1; }
done
if ! "$H" --version | grep -q '^  usb   libusb'; then
    echo "usb: FAIL: edgeflag-host was built without libusb-1.0 (tools/install-deps.sh test installs it)"
    exit 1
fi
T=$(mktemp -d)
extra=()   # folders made outside $T for the run as nobody (see below)
trap 'rm -rf "$T" "${extra[@]}"' EXIT
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "usb: FAIL: $*"; }
skipped() { skip=$((skip + 1)); echo "usb: SKIPPED: $*"; }
# expect NAME WANT GOT
expect() { [ "$2" = "$3" ] && ok || bad "$1: expected '$2', got '$3'"; }
# has NAME FILE TEXT: the user was told TEXT
has() { grep -qF -- "$3" "$2" && ok || { bad "$1: '$3' not in the output:"; sed 's/^/    /' "$2"; }; }
# kv FILE KEY: a value from the emulator's report
kv() { sed -n "s/^$2=//p" "$1"; }
# crc32 FILE: CRC-32 (IEEE) by gzip, an implementation independent of ours
crc32() { gzip -c <"$1" | tail -c 8 | od -An -tx4 -N4 | tr -d ' '; }
emu() { "$EMU" "$@"; }

# The vectors: a tiger of 20584 commands (5 DATA frames) for streaming and the
# faults, and a small lion with every interface for verify.
"$EF" vectors tests/data/svg/tiger.svg -o "$T/tiger" --size 320x240 --formats bin --interfaces cmd,pix \
    --force >/dev/null 2>&1 || { echo "usb: cannot make vectors"; exit 1; }
"$EF" vectors tests/data/svg/lion.svg -o "$T/lion" --size 120x90 --formats bin --force >/dev/null 2>&1 ||
    { echo "usb: cannot make vectors"; exit 1; }
V=$T/tiger/vectors.bin
NCMD=$(sed -n 's/.*"name": "cmd", "bits": [0-9]*, "count": \([0-9]*\).*/\1/p' "$T/tiger/manifest.json")
[ -n "$NCMD" ] || { echo "usb: no cmd count in the manifest"; exit 1; }
# A generous timeout (tests/host/waits.sh) everywhere but where a stall is wanted (its short
# --timeout comes after and wins): on a loaded machine a short transfer timeout could end a
# healthy run.
L="--timeout $EF_LINK_MS"
S="--transport usb --quiet $L"

# ---- list: finds the board, prints what --device accepts and its DUT
emu --report "$T/l.rep" --run "'$H' list >'$T/l.out' 2>&1"
expect "list exit" 0 "$(kv "$T/l.rep" run1_exit)"
has "list" "$T/l.out" "usb    1:4            #0 1209:0001 serial EMU0001, protocol 1, samples 8/16/32, canvas up to 16384x16384, 4194304 edges, window 16"
expect "list identifies once" 1 "$(kv "$T/l.rep" identify)"
expect "list sends no data" 0 "$(kv "$T/l.rep" out_bytes)"
emu --bus 0 --serial A1 --serial B2 --report "$T/l2.rep" --run "'$H' list --json >'$T/l2.out' 2>&1"
has "list two boards, bus 0" "$T/l2.out" '"where": "0:4", "ours": true, "description": "#0 1209:0001 serial A1,'
has "list two boards, bus 0" "$T/l2.out" '"where": "0:5", "ours": true, "description": "#1 1209:0001 serial B2,'
emu --fault magic=XXXX --run "'$H' list >'$T/l3.out' 2>&1"
has "list foreign device" "$T/l3.out" '(not ours) 1209:0001 not an edgeflag board (identify magic 58 58 58 58, expected "EFB1")'

# ---- identify --save over usb (auto: the one board present): the record gen --dut-file reads
emu --report "$T/id.rep" --run "'$H' identify --save '$T/usb.id' >'$T/id.out' 2>&1"
expect "identify exit" 0 "$(kv "$T/id.rep" run1_exit)"
has "identify over usb" "$T/id.out" "usb: serial EMU0001, protocol 1, samples 8/16/32, canvas up to 16384x16384, 4194304 edges"
expect "identify --save: 48 bytes from EFB1" "48 EFB1" "$(wc -c <"$T/usb.id" 2>/dev/null) $(head -c 4 "$T/usb.id" 2>/dev/null)"
expect "identify sends no data" 0 "$(kv "$T/id.rep" out_bytes)"
"$EF" gen --list --dut-file "$T/usb.id" >"$T/id.tsv" 2>"$T/id.err"
expect "gen --dut-file on the saved record: exit, errors, fitted" "0  0" "$? $(cat "$T/id.err") $(grep -c 'fitted to the DUT' "$T/id.tsv")"

# ---- the reference: an uninterrupted stream
emu --report "$T/ref.rep" --dut-log "$T/ref.dut" --run "'$H' stream '$V' $S --results '$T/ref' 2>'$T/ref.err'"
expect "stream exit" 0 "$(kv "$T/ref.rep" run1_exit)"
expect "stream: commands the board took" "$NCMD" "$(kv "$T/ref.rep" cmds)"
expect "stream: DUT input bytes" $((NCMD * 13)) "$(stat -c %s "$T/ref.dut")"
expect "stream: board's input CRC = gzip's CRC of what the DUT got" "$(crc32 "$T/ref.dut")" "$(kv "$T/ref.rep" input_crc)"
expect "stream: no bad frames" 0 "$(kv "$T/ref.rep" frames_bad)"
expect "stream: window respected" 0 "$(kv "$T/ref.rep" rx_refused)"
expect "stream: board done" 2 "$(kv "$T/ref.rep" state)"
"$EF" check "$T/tiger" "$T/ref" >"$T/ref.chk" 2>&1
expect "stream: results check" 0 $?

# ---- verify, every interface the file has, JSON summary
emu --report "$T/v.rep" --run "'$H' verify '$T/lion/vectors.bin' --transport usb $L --json --results '$T/v' >'$T/v.out' 2>&1"
expect "verify exit" 0 "$(kv "$T/v.rep" run1_exit)"
has "verify" "$T/v.out" "PASS"
has "verify" "$T/v.out" '"transport": "usb", "exit": 0'

# ---- one 512-byte transfer in flight, then three of 1536: every frame split
# across transfers, the IN store wrapping around; the same results
emu --report "$T/x.rep" \
    --run "'$H' verify '$T/lion/vectors.bin' $S --in-flight 1 --transfer-size 512 --results '$T/x1'" \
    --run "'$H' verify '$T/lion/vectors.bin' $S --in-flight 3 --transfer-size 1536 --results '$T/x2'"
expect "1 x 512 B exit" 0 "$(kv "$T/x.rep" run1_exit)"
expect "3 x 1536 B exit" 0 "$(kv "$T/x.rep" run2_exit)"
cmp -s "$T/v/vectors.actual.bin" "$T/x1/vectors.actual.bin" && cmp -s "$T/v/vectors.actual.bin" "$T/x2/vectors.actual.bin" &&
    ok || bad "small transfers: results differ from the default transfers'"
[ "$(kv "$T/x.rep" urbs)" -gt 1000 ] && ok || bad "small transfers: only $(kv "$T/x.rep" urbs) URBs (not split?)"

# ---- selection among several boards: serial, BUS:DEV, #INDEX, both, none
emu --serial A1 --serial B2 --report "$T/s.rep" \
    --run "'$H' stream '$V' $S --device B2 --results '$T/s1'" \
    --run "'$H' stream '$V' $S --device 1:4 --results '$T/s2'" \
    --run "'$H' stream '$V' $S --device '#1' --results '$T/s3'" \
    --run "'$H' stream '$V' $S --device A1,1:5 --results '$T/s4' 2>'$T/s4.err'" \
    --run "'$H' stream '$V' $S --results '$T/s5' 2>'$T/s5.err'"
expect "select serial B2" 0 "$(kv "$T/s.rep" run1_exit)"
expect "select 1:4" 0 "$(kv "$T/s.rep" run2_exit)"
expect "select #1" 0 "$(kv "$T/s.rep" run3_exit)"
expect "A1 got one run" "$NCMD" "$(kv "$T/s.rep" A1.cmds)"
expect "B2 got two runs' commands (a new run resets the count)" "$NCMD" "$(kv "$T/s.rep" B2.cmds)"
expect "serial and bus:dev of two boards: no board" 7 "$(kv "$T/s.rep" run4_exit)"
has "selectors echoed" "$T/s4.err" "no edgeflag board matches --device 'A1,1:5' (VID:PID 1209:0001; boards found: 1:4 serial A1, 1:5 serial B2)"
expect "two boards, no selector" 7 "$(kv "$T/s.rep" run5_exit)"
has "ambiguity named" "$T/s5.err" "2 boards match (1:4 serial A1, 1:5 serial B2); choose one with --device SERIAL or BUS:DEV"
cmp -s "$T/ref/vectors.actual.bin" "$T/s3/vectors.actual.bin" && ok || bad "select #1: results differ"
emu --bus 0 --run "'$H' stream '$V' $S --device 0:4 --results '$T/s6'" --report "$T/s6.rep"
expect "bus 0 is a bus" 0 "$(kv "$T/s6.rep" run1_exit)"

# ---- unplug mid-stream, replug (new address), --resume: byte-identical
emu --fault unplug-at=200000 --report "$T/u.rep" --dut-log "$T/u.dut" \
    --run "'$H' stream '$V' $S --results '$T/u' 2>'$T/u1.err'" \
    --run "'$H' stream '$V' $S --results '$T/u' --resume 2>'$T/u2.err'"
expect "unplug exit" 5 "$(kv "$T/u.rep" run1_exit)"
has "unplug told" "$T/u1.err" "the board went away (unplugged?)"
has "unplug told" "$T/u1.err" "run the same command with --resume to continue"
expect "resume exit" 0 "$(kv "$T/u.rep" run2_exit)"
expect "replugged at a new address" "1:5" "$(kv "$T/u.rep" address)"
cmp -s "$T/ref/vectors.actual.bin" "$T/u/vectors.actual.bin" && ok || bad "unplug + resume: results differ"
cmp -s "$T/ref.dut" "$T/u.dut" && ok || bad "unplug + resume: the DUT's input differs (a command lost or doubled)"
expect "unplug + resume: input CRC" "$(kv "$T/ref.rep" input_crc)" "$(kv "$T/u.rep" input_crc)"

# ---- unplugged while results flow to the host, then --resume: byte-identical
emu --fault unplug-in=1000000 --report "$T/ui.rep" --dut-log "$T/ui.dut" \
    --run "'$H' stream '$V' $S --results '$T/ui' 2>'$T/ui1.err'" \
    --run "'$H' stream '$V' $S --results '$T/ui' --resume 2>'$T/ui2.err'"
expect "unplug (results) exit" 5 "$(kv "$T/ui.rep" run1_exit)"
has "unplug (results) told" "$T/ui1.err" "the board went away (unplugged?)"
expect "resume (results) exit" 0 "$(kv "$T/ui.rep" run2_exit)"
cmp -s "$T/ref/vectors.actual.bin" "$T/ui/vectors.actual.bin" && ok || bad "unplug (results) + resume: results differ"
cmp -s "$T/ref.dut" "$T/ui.dut" && ok || bad "unplug (results) + resume: the DUT's input differs"

# ---- a board that drops an ack, or gets a corrupted frame either way: recovered
emu --fault drop-ack=1 --report "$T/d.rep" --dut-log "$T/d.dut" --run "'$H' stream '$V' $S --results '$T/d'"
expect "drop-ack exit" 0 "$(kv "$T/d.rep" run1_exit)"
expect "an ack was dropped" 1 "$(kv "$T/d.rep" acks_dropped)"
cmp -s "$T/ref.dut" "$T/d.dut" && cmp -s "$T/ref/vectors.actual.bin" "$T/d/vectors.actual.bin" && ok ||
    bad "drop-ack: input or results differ"
emu --fault corrupt-out=70000 --report "$T/c.rep" --dut-log "$T/c.dut" \
    --run "'$H' stream '$V' --transport usb $L --results '$T/c' 2>'$T/c.err'"
expect "corrupt-out exit" 0 "$(kv "$T/c.rep" run1_exit)"
expect "the board saw one bad frame" 1 "$(kv "$T/c.rep" frames_bad)"
expect "and NAKed it" 1 "$(kv "$T/c.rep" naks)"
has "corrupt-out: resent" "$T/c.err" "sent again)"
grep -q "(0 sent again)" "$T/c.err" && bad "corrupt-out: nothing was sent again" || ok
cmp -s "$T/ref.dut" "$T/c.dut" && cmp -s "$T/ref/vectors.actual.bin" "$T/c/vectors.actual.bin" && ok ||
    bad "corrupt-out: input or results differ"
emu --fault corrupt-in=3 --report "$T/ci.rep" --run "'$H' stream '$V' $S --results '$T/ci'"
expect "corrupt-in exit" 0 "$(kv "$T/ci.rep" run1_exit)"
expect "a frame to the host was corrupted" 1 "$(kv "$T/ci.rep" frames_corrupted)"
cmp -s "$T/ref/vectors.actual.bin" "$T/ci/vectors.actual.bin" && ok || bad "corrupt-in: results differ"

# ---- a board that stalls past the timeout: link lost, then --resume finishes
emu --fault stall-at=150000 --report "$T/st.rep" --dut-log "$T/st.dut" \
    --run "'$H' stream '$V' $S --timeout 500 --results '$T/st' 2>'$T/st1.err'" \
    --run "'$H' stream '$V' $S --results '$T/st' --resume 2>'$T/st2.err'"
expect "stall exit" 5 "$(kv "$T/st.rep" run1_exit)"
has "stall told" "$T/st1.err" "the board stopped answering"
[ "$(kv "$T/st.rep" discards)" -gt 0 ] && ok || bad "stall: no transfer was cancelled after its timeout"
expect "stall + resume exit" 0 "$(kv "$T/st.rep" run2_exit)"
cmp -s "$T/ref.dut" "$T/st.dut" && cmp -s "$T/ref/vectors.actual.bin" "$T/st/vectors.actual.bin" && ok ||
    bad "stall + resume: input or results differ"

# ---- a board that resets itself mid-run: a board error, never wrong results
emu --fault reset-at=150000 --report "$T/r.rep" --run "'$H' stream '$V' $S --results '$T/r' 2>'$T/r.err'"
expect "reset exit" 6 "$(kv "$T/r.rep" run1_exit)"
has "reset told" "$T/r.err" "it was reset or lost its state during the run"
[ ! -e "$T/r/vectors.actual.bin" ] && ok || bad "reset: results were written"

# ---- the wrong device: another magic, another protocol version
emu --fault magic=XXXX --report "$T/m.rep" --run "'$H' stream '$V' $S --results '$T/m' 2>'$T/m.err'"
expect "wrong magic exit" 6 "$(kv "$T/m.rep" run1_exit)"
has "wrong magic told" "$T/m.err" 'device 1:4: 1209:0001 not an edgeflag board (identify magic 58 58 58 58, expected "EFB1")'
expect "wrong magic: nothing sent" 0 "$(kv "$T/m.rep" out_bytes)"
emu --fault protocol=2 --report "$T/p.rep" --run "'$H' stream '$V' $S --device EMU0001 --results '$T/p' 2>'$T/p.err'"
expect "protocol 2 exit" 6 "$(kv "$T/p.rep" run1_exit)"
has "protocol 2 told" "$T/p.err" "edgeflag board speaking protocol version 2; this host speaks version 1"
expect "protocol 2: nothing sent" 0 "$(kv "$T/p.rep" out_bytes)"

# ---- re-enumeration: identify stalls twice right after plug-in, then answers
emu --fault identify-stall=2 --report "$T/i.rep" --run "'$H' stream '$V' $S --results '$T/i'"
expect "identify retried" 0 "$(kv "$T/i.rep" run1_exit)"
[ "$(kv "$T/i.rep" identify)" -ge 3 ] && ok || bad "identify-stall: identify asked $(kv "$T/i.rep" identify) times"

# ---- permission denied: the user is pointed at the udev rule
# The emulator runs these commands as nobody (root would open any device node), and nobody must
# reach all they use.  The clone's folders may be closed to others (a clone in a mode-0700 folder,
# as root's home is), so nobody gets copies of the binary and the vectors in a folder of this
# test's own that nobody can traverse, where the emulator's testbed is made too (its TMPDIR):
# $T (mode 0711) when nobody can reach it, else a new folder in /tmp, /var/tmp or /dev/shm.  A
# probe run as nobody there decides; when none works the check is SKIPPED, saying why.
nobody_dir() {   # sets NB to a folder nobody can use, or fails with the reason in NB
    local base d why=""
    NB="not root: only root can run the commands as another user"
    [ "$(id -u)" = 0 ] || return 1
    NB="there is no user nobody on this machine"
    getent passwd nobody >/dev/null || return 1
    chmod 711 "$T"
    for base in "$T" /tmp /var/tmp /dev/shm; do
        if [ "$base" = "$T" ]; then
            d=$T/nobody
            mkdir "$d" || continue
        else
            [ -d "$base" ] && d=$(mktemp -d "$base/edgeflag-usb-nobody.XXXXXX" 2>/dev/null) || continue
            extra+=("$d")
        fi
        chmod 755 "$d" && mkdir -m 777 "$d/out" && cp "$H" "$d/edgeflag-host" && cp "$V" "$d/tiger.bin" &&
            chmod 755 "$d/edgeflag-host" && chmod 644 "$d/tiger.bin" || { why="$why; $d: cannot fill it"; continue; }
        TMPDIR=$d emu --fault eacces --run "test -x '$d/edgeflag-host' && test -r '$d/tiger.bin' && \
            test -w '$d/out' && test -d \"\$UMOCKDEV_DIR/dev\" && touch '$d/out/probe'" >"$T/probe.out" 2>&1
        if [ -e "$d/out/probe" ]; then
            NB=$d
            return 0
        fi
        if grep -q 'cannot become nobody' "$T/probe.out"; then
            NB="the emulator cannot become nobody: $(tr '\n' ' ' <"$T/probe.out")"
            return 1
        fi
        why="$why; nobody cannot reach $d"
    done
    NB="no folder that nobody can reach${why}"
    return 1
}
if nobody_dir; then
    TMPDIR=$NB emu --fault eacces --report "$T/a.rep" \
        --run "cd '$NB' && ./edgeflag-host stream tiger.bin $S --device EMU0001 --results out/r 2>out/a.err" \
        --run "cd '$NB' && ./edgeflag-host list >out/a2.out 2>&1"
    expect "eacces exit" 8 "$(kv "$T/a.rep" run1_exit)"
    has "eacces told" "$NB/out/a.err" "device 1:4 --device EMU0001: install the udev rule shipped as host/60-edgeflag.rules"
    has "eacces told" "$NB/out/a.err" "udevadm control --reload && udevadm trigger"
    has "eacces list" "$NB/out/a2.out" "permission denied (udev rule host/60-edgeflag.rules not installed?"
    expect "eacces: nothing reached the board" 0 "$(kv "$T/a.rep" identify)"
else
    skipped "permission denied (exit 8 naming the udev rule) not checked: $NB"
fi

# ---- no board at all
emu --run "'$H' stream '$V' $S --device Y --results '$T/n' 2>'$T/n.err'" --report "$T/n.rep"
expect "no match exit" 7 "$(kv "$T/n.rep" run1_exit)"
has "no match told" "$T/n.err" "no edgeflag board matches --device 'Y' (VID:PID 1209:0001; boards found: 1:4 serial EMU0001)"

echo "$pass passed, $fail failed, $skip skipped (edgeflag-host over USB to the emulated board)"
[ "$fail" -eq 0 ]
