#!/usr/bin/env bash
# tests/host/run.sh - edgeflag-host as a user runs it, against the simulated board
# (docs/board.md): every test runs the binary and asserts its exit code, what it told the
# user, and what the board received and returned (the board's DONE carries the CRC of the
# input it took, which the host compares; results are compared byte for byte with a clean
# run's and checked by `edgeflag check`).
#   1. verify of small scenes and the tiger (every interface), stream, --json, --quiet;
#   2. the fault matrix: dropped, corrupted, dropped-reply and corrupted-reply frames,
#      unplug mid-stream and mid-results then --resume, a board that stalls past the timeout
#      then --resume, a board reset mid-run, another device, another protocol version;
#   3. wrong use: --resume with nothing to resume or another file's state, auto with no
#      board, bad vector files (missing, truncated, bad CRC, other format version, hex,
#      no cmd), a results folder that cannot be made, a mismatching board result;
#   4. bench over the null and sim transports, list, --version;
#   5. identify and identify --save (the record `edgeflag gen --dut-file` reads): decoded, saved
#      whole and atomically, refused from another device or protocol (nothing saved), exit 4.
# usage: bash tests/host/run.sh BUILD_DIR   (`make test-host`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
build=${1:?usage: tests/host/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/host/waits.sh disable=SC1091
. "$root/tests/host/waits.sh"
case $build in /*) ;; *) build=$PWD/$build ;; esac
E=$build/edgeflag H=$build/edgeflag-host
SVG=${EF_SVG:-$root/tests/data/svg}
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
for t in "$E" "$H"; do
    [ -x "$t" ] || { echo "host: $t not built"; echo "0 passed, 1 failed"; exit 1; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-host.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
# The simulated board works inside the host's reads and writes (a whole frame of the model at a
# FRAME_END), so a busy machine stretches the time between two ACKs: every run gets a generous
# --timeout (tests/host/waits.sh); only the stall, whose timeout is what it tests, a short one
# after it (the last --timeout given wins).
SIM=(--transport sim --timeout "$EF_LINK_MS")

# run NAME EXPECTED_EXIT STDERR_REGEX -- COMMAND...: the exit code and a line of the message
run() {
    local name=$1 want=$2 re=$3
    shift 4
    timeout "$EF_GUARD_S" "$@" >out.txt 2>err.txt
    local rc=$?
    if [ "$rc" = "$want" ] && { [ -z "$re" ] || grep -Eq "$re" err.txt; }; then
        ok "$name"
    else
        bad "$name" "exit $rc (want $want); stderr: $(head -c 400 err.txt | tr '\n' ' ')"
    fi
}
json() { sed -n 's/.*"'"$1"'": \([0-9]*\).*/\1/p' out.txt | tail -1; }

# ------------------------------------------------------------------ 1. the plain runs
"$E" vectors "$SVG/stress_pixi_bowtie.svg" -o small --size 64x48 --formats bin >/dev/null 2>&1
"$E" vectors "$SVG/stress_pixi_fill_rule_multiple_holes.svg" -o holes --size 80x60 --samples 16 --formats bin \
    >/dev/null 2>&1
"$E" vectors "$SVG/tiger.svg" -o tiger --size 200x150 --samples 32 --formats bin >/dev/null 2>&1
for v in small holes tiger; do
    run "verify $v over sim: PASS on every interface" 0 'check: PASS: 6 comparisons' -- \
        "$H" verify $v/vectors.bin "${SIM[@]}"
done
cp tiger/board/vectors.actual.bin clean.bin
run "stream: results in the default folder, summary line" 0 'commands in .* frames .* result records \(pix\)' -- \
    "$H" stream small/vectors.bin "${SIM[@]}"
[ -s small/board/vectors.actual.bin ] && [ ! -e small/board/.resume ] && [ ! -e small/board/.results.part ] &&
    ok "stream leaves vectors.actual.bin and no resume state" || bad "stream's results folder"
run "--json summary with --quiet: nothing on stderr" 0 '' -- \
    "$H" verify holes/vectors.bin "${SIM[@]}" --quiet --json --results J
grep -q '"check": "pass"' out.txt && [ "$(grep -c . err.txt)" = 0 ] && ok "--json says pass, --quiet is quiet" ||
    bad "--json/--quiet" "$(cat out.txt err.txt | head -c 300)"
grep -q $'\r' err.txt && bad "progress bar drawn when stderr is not a terminal" || ok "no progress bar on a pipe"

# --------------------------------------------------------------- 2. the fault matrix
# faulty link or board, the run still completes with every frame taken once
for f in drop=3 corrupt=4 drop=2,drop=3,corrupt=5 drop-reply=20 corrupt-reply=25 "drop-reply=7,corrupt-reply=9"; do
    run "fault $f: recovered, PASS" 0 'check: PASS' -- "$H" verify tiger/vectors.bin "${SIM[@]}" \
        --frame-cmds 40 --sim-faults "$f" --results F --json
    case $f in drop=*|corrupt=*)
        [ "$(json retransmits)" -gt 0 ] 2>/dev/null && ok "fault $f: frames were sent again" ||
            bad "fault $f: no retransmission counted" "$(cat out.txt)"
        # the board's NAK names the missing frame: recovery without waiting for a timeout
        [ "$(json timeouts)" = 0 ] && ok "fault $f: recovered by NAK, no timeout" ||
            bad "fault $f: needed a timeout to recover" "$(cat out.txt)" ;;
    esac
    cmp -s F/vectors.actual.bin clean.bin && ok "fault $f: results byte-identical to a clean run" ||
        bad "fault $f: results differ from a clean run"
done
# unplug while commands flow, and while results flow; then --resume on the same board
for at in 5 60; do
    rm -rf S R
    run "unplug at host frame $at: exit 5, says --resume" 5 'went away.*--resume' -- "$H" verify tiger/vectors.bin \
        "${SIM[@]}" --frame-cmds 40 --sim-state S --results R --sim-faults unplug=$at
    [ -s R/.resume ] && [ ! -e R/vectors.actual.bin ] && ok "unplug at $at: resume state kept, no results file" ||
        bad "unplug at $at: results folder" "$(ls -a R)"
    run "resume after unplug at $at: PASS" 0 'check: PASS: 6 comparisons' -- "$H" verify tiger/vectors.bin \
        "${SIM[@]}" --frame-cmds 40 --sim-state S --results R --resume --json
    [ "$(json resumed_from_frame)" -gt 0 ] 2>/dev/null && ok "resume at $at continued mid-stream" ||
        bad "resume at $at started over" "$(cat out.txt)"
    cmp -s R/vectors.actual.bin clean.bin && ok "resume at $at: results byte-identical to a clean run" ||
        bad "resume at $at: results differ"
done
# unplugged at the first frame (START): the host kept a resume state with nothing in it and the board has
# no run; --resume, as the host's message says, starts over (a host killed between its reset and START, as
# below, leaves the same state)
rm -rf S R
run "unplug at host frame 1: exit 5, says --resume" 5 'after 0 of .*--resume' -- "$H" verify tiger/vectors.bin \
    "${SIM[@]}" --frame-cmds 40 --sim-state S --results R --sim-faults unplug=1
run "resume with nothing begun: starts from frame 0, PASS" 0 'no result was kept: starting the run from frame 0' -- "$H" verify \
    tiger/vectors.bin "${SIM[@]}" --frame-cmds 40 --sim-state S --results R --resume --json
cmp -s R/vectors.actual.bin clean.bin && [ "$(json resumed_from_frame)" = 0 ] &&
    ok "resume with nothing begun: results byte-identical to a clean run" ||
    bad "resume with nothing begun: results differ or resumed_from_frame $(json resumed_from_frame)"
# the host killed (SIGKILL) at some moment of a long run; the board (its state in S) lives on
"$E" vectors "$SVG/tiger.svg" -o big --size 640x480 --formats bin >/dev/null 2>&1
"$H" stream big/vectors.bin "${SIM[@]}" --interfaces pix,span --results BC --quiet
for delay in 0.15 0.3 0.45; do
    rm -rf S R
    timeout -s KILL $delay "$H" stream big/vectors.bin "${SIM[@]}" --interfaces pix,span --frame-cmds 100 \
        --sim-state S --results R --quiet >/dev/null 2>&1
    krc=$?
    if [ -e R/.resume ]; then
        "$H" stream big/vectors.bin "${SIM[@]}" --interfaces pix,span --frame-cmds 100 --sim-state S \
            --results R --resume --quiet --json >out.txt 2>err.txt
    else
        "$H" stream big/vectors.bin "${SIM[@]}" --interfaces pix,span --frame-cmds 100 --sim-state S \
            --results R --quiet --json >out.txt 2>err.txt
    fi
    rrc=$?
    [ $rrc = 0 ] && cmp -s R/vectors.actual.bin BC/vectors.actual.bin &&
        ok "host killed after ${delay}s (status $krc), resumed from frame $(json resumed_from_frame): byte-identical" ||
        bad "host killed after ${delay}s: resume exit $rrc" "$(head -c 300 err.txt)"
done

# the progress bar, drawn only when standard error is a terminal (docs/board.md: util-linux's script gives
# the run a pty): every redraw's bar agrees with its percentage (floor(P * 30 / 100) .. floor((P + 1) * 30 /
# 100) '#'), the first (at most the window of 16 of 2,864 frames acknowledged) is at 0 % with no '#', the
# last at 100 % with all 30
if command -v script >/dev/null; then
    timeout "$EF_GUARD_S" script -qfec "'$H' verify big/vectors.bin --transport sim --timeout $EF_LINK_MS --frame-cmds 10 --interfaces pix --results pb" \
        /dev/null </dev/null >tty.txt 2>&1
    prc=$?
    tr '\r' '\n' <tty.txt | awk -v rc=$prc '
        /^\[[#.]+\] +[0-9]+%/ { n++; bar = substr($0, 2, 30); h = gsub(/#/, "", bar); p = $2 + 0
            if (h < int(p * 30 / 100) || h > int((p + 1) * 30 / 100)) bad = bad " " p "%:" h "#"
            if (n == 1) { fp = p; fh = h } lp = p; lh = h }
        END { if (rc == 0 && n >= 2 && bad == "" && fp == 0 && fh == 0 && lp == 100 && lh == 30) {
                  printf "ok - the progress bar on a terminal: %d redraws, each bar agrees with its percentage, 0 %% to 100 %%\n", n; exit 0 }
              printf "FAIL - the progress bar on a terminal: exit %d, %d redraws, first %s%% %s#, last %s%% %s#, disagreeing:%s\n", rc, n, fp, fh, lp, lh, bad; exit 1 }' &&
        pass=$((pass + 1)) || fail=$((fail + 1))
else
    bad "the progress bar on a terminal" "util-linux's script is not installed"
fi

rm -rf S R
run "stall past the timeout: exit 5 after 4 tries" 5 'stopped answering.*--resume' -- "$H" verify \
    tiger/vectors.bin "${SIM[@]}" --frame-cmds 40 --timeout 50 --sim-state S --results R --sim-faults stall=8 --json
if [ "$(json timeouts)" = 4 ]; then ok "the stall: the run ended after 4 timeouts in a row"; else
    bad "the stall: not 4 timeouts" "$(cat out.txt)"; fi
run "resume after the stall: PASS" 0 'check: PASS' -- "$H" verify tiger/vectors.bin "${SIM[@]}" \
    --frame-cmds 40 --sim-state S --results R --resume
cmp -s R/vectors.actual.bin clean.bin && ok "resume after stall: byte-identical" || bad "resume after stall: differs"
run "board reset mid-run: exit 6" 6 'reset or lost its state' -- "$H" verify tiger/vectors.bin "${SIM[@]}" \
    --frame-cmds 40 --sim-faults reset=30 --results R2
rm -rf S R
"$H" stream tiger/vectors.bin "${SIM[@]}" --frame-cmds 40 --sim-state S --results R --sim-faults unplug=420 \
    >/dev/null 2>&1
printf '\377\377\377\377' >>S/board.log    # the simulated board is power-cycled (docs/board.md 5.3)
[ "$(sed -n 's/^res_next //p' R/.resume)" -gt 0 ] 2>/dev/null && ok "unplug at 420 (results flowing): result frames kept" ||
    bad "unplug at 420: no result frame kept, the power-cycle case below would start over" "$(cat R/.resume)"
run "power-cycled board then --resume (results kept): exit 6, nothing to resume" 6 'no run to resume' -- "$H" verify \
    tiger/vectors.bin "${SIM[@]}" --frame-cmds 40 --sim-state S --results R --resume
run "another device (no magic): exit 6" 6 'did not answer identify as an edgeflag board' -- \
    "$H" stream small/vectors.bin "${SIM[@]}" --sim-faults not-ours=1
run "another protocol version: exit 6" 6 'protocol version 2' -- \
    "$H" stream small/vectors.bin "${SIM[@]}" --sim-faults protocol=2
[ ! -e small/board/vectors.actual.bin ] && ok "a failed run leaves no earlier run's results looking complete" ||
    bad "an earlier run's vectors.actual.bin survived a failed run"
run "bad --sim-faults: exit 2" 2 'is not KIND=N' -- "$H" stream small/vectors.bin "${SIM[@]}" --sim-faults jam=1

# --------------------------------------------------------------------- 3. wrong use
rm -rf N
run "--resume with nothing interrupted: exit 2" 2 'no resume state' -- \
    "$H" stream small/vectors.bin "${SIM[@]}" --results N --resume
rm -rf S R
"$H" stream tiger/vectors.bin "${SIM[@]}" --frame-cmds 40 --sim-state S --results R --sim-faults unplug=5 \
    >/dev/null 2>&1
run "--resume with another vectors file's state: exit 2" 2 'another vectors file' -- \
    "$H" stream small/vectors.bin "${SIM[@]}" --sim-state S --results R --resume
run "auto with no board: exit 7, never the sim" 7 'no board found' -- "$H" stream small/vectors.bin
run "missing vectors file: exit 3" 3 'nope.bin: No such file' -- "$H" stream nope.bin "${SIM[@]}"
head -c 300 small/vectors.bin >trunc.bin
run "truncated vectors.bin: exit 3, names the place" 3 'trunc.bin' -- "$H" stream trunc.bin "${SIM[@]}"
cp small/vectors.bin badcrc.bin
printf '\x55' | dd of=badcrc.bin bs=1 seek=200 conv=notrunc 2>/dev/null
run "vectors.bin with a bad record CRC: exit 3" 3 'badcrc.bin.*CRC' -- "$H" stream badcrc.bin "${SIM[@]}"
cp small/vectors.bin v2.bin
printf '\x02' | dd of=v2.bin bs=1 seek=8 conv=notrunc 2>/dev/null
run "vectors.bin of another format version: exit 3" 3 'v2.bin' -- "$H" stream v2.bin "${SIM[@]}"
"$E" vectors "$SVG/stress_pixi_bowtie.svg" -o hex --size 32x24 --formats hex >/dev/null 2>&1
run "a hex file: exit 3, asks for vectors.bin" 3 'not a binary vector stream' -- \
    "$H" stream hex/cmd.stim.hex "${SIM[@]}"
# the .bin test at its boundary: a file named just ".bin" (4 characters) is a vector stream too
cp small/vectors.bin .bin
run "a vectors file named .bin: taken, PASS" 0 'check: PASS: 6 comparisons' -- "$H" verify .bin "${SIM[@]}" --results dotbin
"$E" vectors "$SVG/stress_pixi_bowtie.svg" -o nocmd --size 32x24 --formats bin --interfaces pix >/dev/null 2>&1
run "vectors.bin without cmd: exit 3" 3 'records no cmd' -- "$H" stream nocmd/vectors.bin "${SIM[@]}"
: >blocker
run "results folder blocked by a file: exit 4" 4 'cannot create the results folder' -- \
    "$H" stream small/vectors.bin "${SIM[@]}" --results blocker/sub
run "--interfaces without pix: exit 2" 2 'including pix' -- \
    "$H" verify small/vectors.bin "${SIM[@]}" --interfaces span
run "unknown transport: exit 2" 2 'must be usb, gpio, serial, sim' -- "$H" stream small/vectors.bin --transport tcp
# a board whose result differs: one pix payload bit changed in the expected file (CRCs
# made right again by Python's zlib, an implementation of CRC-32 independent of ours)
python3 - small/vectors.bin wrong.bin <<'EOF'
import struct, sys, zlib
b = bytearray(open(sys.argv[1], 'rb').read())
pos, last_pix = 104, None
while pos < len(b):
    if b[pos] == 6:
        last_pix = pos
    pos += 10 + b[pos + 1]
b[last_pix + 10] ^= 1
struct.pack_into('<I', b, 96, zlib.crc32(bytes(b[104:])))
struct.pack_into('<I', b, 100, zlib.crc32(bytes(b[:100])))
open(sys.argv[2], 'wb').write(b)
EOF
run "board result differs from the vectors: exit 1, named" 1 'check: pix: FAIL|FAIL' -- \
    "$H" verify wrong.bin "${SIM[@]}" --junit wrong.xml
grep -q '<failure' wrong.xml 2>/dev/null && ok "verify --junit records the failure" || bad "verify --junit"

# ---------------------------------------------------------------- 4. bench, list, version
run "bench over null" 0 '' -- "$H" bench --transport null --mib 64
grep -Eq '^null +sink +[0-9.]+ MB/s' out.txt && grep -q 'latency' out.txt && ok "bench null: sink MB/s and latency" ||
    bad "bench null output" "$(cat out.txt)"
run "bench over sim" 0 '' -- "$H" bench "${SIM[@]}" --mib 16 --json
grep -q '"sink": {"ran": true' out.txt && grep -q '"source": {"ran": true' out.txt &&
    grep -q '"loopback": {"ran": true' out.txt && ok "bench sim: sink, source, loopback ran" ||
    bad "bench sim output" "$(cat out.txt)"
run "list with no board: exit 0" 0 '' -- "$H" list --transport usb
grep -Eq 'no board found|^usb ' out.txt && ok "list says what it found" || bad "list output" "$(cat out.txt)"
run "--version names every transport" 0 '' -- "$H" --version
grep -q '^  usb ' out.txt && grep -q '^  gpio ' out.txt && grep -q '^  sim ' out.txt && ok "--version lists transports" ||
    bad "--version" "$(cat out.txt)"

# ------------------------------------------------------ 5. identify, and --save for gen --dut-file
# le32 FILE OFFSET: a little-endian 32-bit field of a file, read by od (not the host's code)
le32() { od -An -tu4 -j "$2" -N4 --endian=little "$1" | tr -d ' '; }
run "identify over sim --save: exit 0" 0 'wrote id.bin .*edgeflag gen --dut-file id.bin' -- \
    "$H" identify "${SIM[@]}" --save id.bin
if grep -q '^sim: serial EFSIM0001, protocol 1, samples 8/16/32, canvas up to 16384x16384, 4194304 edges' out.txt &&
   [ "$(wc -c <id.bin)" = 48 ] && [ "$(head -c 4 id.bin)" = EFB1 ] &&
   [ "$(le32 id.bin 16)/$(le32 id.bin 20)/$(le32 id.bin 24)/$(le32 id.bin 28)" = 56/16384/16384/4194304 ]; then
    ok "identify prints the record decoded; id.bin is its 48 bytes (od: samples 0x38, 16384x16384, 4194304 edges)"
else
    bad "identify --save" "$(cat out.txt) / $(od -An -tx1 id.bin | head -n 3 | tr '\n' ' ')"
fi
"$E" gen --list >gen_plain.tsv 2>&1
"$E" gen --list --dut-file id.bin >gen_sim.tsv 2>gen_sim.err
if [ -s gen_sim.tsv ] && [ ! -s gen_sim.err ] && ! grep -q 'fitted to the DUT' gen_sim.tsv && cmp -s gen_plain.tsv gen_sim.tsv; then
    ok "edgeflag gen --dut-file on the simulated board's saved identify: its limits read, every case fits as it is"
else
    bad "gen --dut-file id.bin" "$(head -n 2 gen_sim.err)"
fi
run "identify --json" 0 '' -- "$H" identify "${SIM[@]}" --json --save id2.bin --quiet
python3 - out.txt <<'PY' && cmp -s id.bin id2.bin && ok "identify --json: the fields as JSON, the file named; the same record saved again" || bad "identify --json" "$(cat out.txt)"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["transport"] == "sim" and j["serial"] == "EFSIM0001" and j["samples"] == [8, 16, 32], j
assert (j["width_max"], j["height_max"], j["edges_max"], j["saved"]) == (16384, 16384, 4194304, "id2.bin"), j
PY
printf 'an older file\n' >kept.bin
run "identify from another device (no magic): exit 6, nothing saved" 6 'did not answer identify as an edgeflag board.*nothing saved' -- \
    "$H" identify "${SIM[@]}" --sim-faults not-ours=1 --save kept.bin
run "identify from another protocol version: exit 6, nothing saved" 6 'protocol version 2.*nothing saved' -- \
    "$H" identify "${SIM[@]}" --sim-faults protocol=2 --save kept.bin
[ "$(cat kept.bin)" = "an older file" ] && ok "a refused identify leaves an existing --save file as it was" ||
    bad "identify refused: the existing file was changed"
: >notdir
run "identify --save into a path that cannot be written: exit 4" 4 "cannot write 'notdir/id.bin'" -- \
    "$H" identify "${SIM[@]}" --save notdir/id.bin
run "identify --save replaces an existing file" 0 '' -- "$H" identify "${SIM[@]}" --save kept.bin --quiet
cmp -s kept.bin id.bin && [ -z "$(find . -maxdepth 1 -name '.kept.bin.*')" ] && ok "replaced whole, no temporary left" ||
    bad "identify --save over an existing file"
run "--save with another command: usage error" 2 "save is identify's" -- "$H" stream small/vectors.bin "${SIM[@]}" --save x.bin
run "identify takes no file: usage error" 2 'identify takes no file' -- "$H" identify small/vectors.bin "${SIM[@]}"

echo "$pass passed, $fail failed"
[ $fail = 0 ]
