#!/usr/bin/env bash
# tests/dpi/run.sh - `make test-dpi`: the reference model as a command stream
# (dv/dpi/ef_model_stream.h) and its DPI-C lockstep bench (docs/dpi.md).
#
#   1. the stream against the files `edgeflag vectors` wrote for the same
#      scenes (tests/dpi/test_model_stream.c, cmocka): the tiger at 160x120
#      (8 samples, each shape's rule; 16 samples with the rule override
#      against a --rule evenodd run) and an `edgeflag gen` random case of
#      several shapes at 32 samples;
#   2. Verilator (--binary --timing) builds dv/dpi/tb_lockstep.sv:
#      ef_slb_fill fed the model's plots, its spans checked by the model
#      through DPI-C, in lockstep, cycle for cycle; it must PASS on the tiger
#      (each shape's rule, and +rule=evenodd) and on the gen case, with as
#      many spans checked as span.expected.hex holds (NS = 8 and 32); the
#      package's structs are checked against the model's interface table at
#      start-up; the gen case once more under valgrind's memcheck (when
#      installed) with no error;
#   3. the loop can fail: built from the RTL variant with the planted fault span (every span of
#      two or more pixels one short) it must stop at the first such span, naming
#      the simulation time, interface span, that span's cycle, and `len` as
#      the one differing field (expected len = actual + 1); with +cov_lag=1
#      (COV one cycle slower per span) it must stop at a span reported late
#      by 1 cycle; a command stream over the DUT's W_MAX is refused naming
#      the file, line and the limit, and one whose stamps go backwards naming
#      the file and line.
# The three Verilator builds run side by side at -O0 (the C++ compile is
# most of this stage's time; the simulations take well under a second).
#
# usage: bash tests/dpi/run.sh BUILD_DIR   (EF_DPI_KEEP=1 keeps the work dir;
#        EF_DPI_RTL=DIR takes the RTL from DIR instead of rtl)
# Skips part 2 and 3, saying so, without verilator.  Ends with "N passed,
# M failed"; exit 0 only if nothing failed.
# shellcheck disable=SC2086 # the RTL file lists ($RTL, $A_*) are split into words on purpose
set -u
export LC_ALL=C
ulimit -c 0                       # $fatal aborts the simulation: no core files

build=${1:?usage: tests/dpi/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
DPI=$root/dv/dpi
R=${EF_DPI_RTL:-$root/rtl}     # EF_DPI_RTL: another RTL folder (the same file names)
# rtl_slb DIR, rtl_raster DIR: the DUT's files in an RTL folder
rtl_slb() { echo "$1/ef_slb_fill.v $1/ef_slb_ram.v"; }
rtl_raster() { echo "$1/ef_raster.v $1/ef_dec.v $1/ef_setup.v $1/ef_div.v $1/ef_etm.v $1/ef_aet.v $1/ef_plot.v $(rtl_slb "$1") $1/ef_cov.v"; }
# the fast configuration (ef_raster SCHEDULE=1, docs/microarch.md section 6): the
# same files and the span queue, checked in transaction order
rtl_fast() { echo "$(rtl_raster "$1") $1/ef_spanq.v"; }
for f in "$EF" "$build/tests/test_model_stream"; do
    [ -e "$f" ] || { echo "test-dpi: $f not built (make test-dpi builds it)"; exit 1; }
done

tmpbase=${TMPDIR:-/tmp}
[ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
work=$(mktemp -d "$tmpbase/edgeflag-dpi.XXXXXX") || exit 1
if [ -n "${EF_DPI_KEEP:-}" ]; then echo "test-dpi: keeping $work"; else trap 'rm -rf "$work"' EXIT; fi

pass=0 fail=0
ok()  { pass=$((pass + 1)); echo "PASS $*"; }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
t0=$(date +%s)

# --------------------------------------------------------------- vectors
tiger=$root/tests/data/svg/tiger.svg
vec() {   # vec NAME INPUT OPTIONS...: hex files only
    local name=$1 in=$2; shift 2
    "$EF" vectors "$in" -o "$work/$name" --formats hex "$@" >"$work/$name.log" 2>&1 ||
        { cat "$work/$name.log"; echo "test-dpi: edgeflag vectors $name failed"; exit 1; }
}
vec t8 "$tiger" --size 160x120 --samples 8
vec t16 "$tiger" --size 160x120 --samples 16
vec t16e "$tiger" --size 160x120 --samples 16 --rule evenodd
vec t8e "$tiger" --size 160x120 --samples 8 --rule evenodd
"$EF" gen -o "$work/gen" -n 200 >"$work/gen.log" 2>&1 || { cat "$work/gen.log"; exit 1; }
# The first random case that fits the benches' 160x120 and mixes both rules
# over several shapes (the rule and the colour change from shape to shape).
g=
while read -r f; do
    if awk '$1 == "scene" && ($2 > 160 || $3 > 120) { big = 1 } $1 == "shape" { r[$2]++ }
            END { exit !(!big && r["nonzero"] && r["evenodd"]) }' "$work/gen/$f"; then
        g=$f; break
    fi
done < <(awk -F'\t' '$3 == "random" { print $2 }' "$work/gen/index.tsv")
[ -n "$g" ] || { echo "test-dpi: no random gen case of both rules within 160x120"; exit 1; }
vec g32 "$work/gen/$g" --samples 32
vec g8 "$work/gen/$g" --samples 8
count() { sed -n 's|^// count \([0-9]*\).*|\1|p' "$1" | head -n 1; }

# --------------------------------------------------------------- 1. cmocka
if "$build/tests/test_model_stream" "$work/t8,$work/t8,8,scene" "$work/t16,$work/t16e,16,evenodd" \
        "$work/g32,$work/g32,32,scene" >"$work/cmocka.log" 2>&1; then
    ok "model stream: $(grep -c '^model stream:' "$work/cmocka.log") vector sets equal, transaction for transaction" \
       "($(grep -o '[0-9]* test(s)' "$work/cmocka.log" | tail -n 1) of tests/dpi/test_model_stream.c; gen case $g)"
else
    cat "$work/cmocka.log"; bad "model stream (tests/dpi/test_model_stream.c)"
fi

# --------------------------------------------------------------- 2. Verilator
if ! command -v verilator >/dev/null 2>&1; then
    echo "test-dpi: verilator not installed: the lockstep bench is SKIPPED ('make deps-test' installs it)"
    echo "$pass passed, $fail failed"
    [ "$fail" -eq 0 ]; exit
fi
echo "test-dpi: $(verilator --version)"
# The interface package the bench and ef_model_pkg import (docs/vectors.md section 8).
"$EF" vectors --rtl-headers -o "$work/hdr" >"$work/hdr.log" 2>&1 || { cat "$work/hdr.log"; exit 1; }
[ -e "$build/libef_dpi.a" ] || { echo "test-dpi: $build/libef_dpi.a not built (make test-dpi builds it)"; exit 1; }

# vl_build NAME DUT NS W_MAX H_MAX [RTL_DIR]: builds tb_lockstep with DUT
# (raster: ef_raster, the whole pipeline; slb: ef_slb_fill) from RTL_DIR
# (default $R; a planted fault's RTL variant) into $work/vl_NAME/obj/tb;
# "ok" or the reason in $work/vl_NAME/status.
vl_build() {
    local name=$1 dut=$2 ns=$3 w=$4 h=$5 src=${6:-$R}; shift 5; [ $# -gt 0 ] && shift
    local d=$work/vl_$name s rtl
    s=$(date +%s)
    rtl=$(rtl_raster "$src")
    [ "$dut" = slb ] && { rtl=$(rtl_slb "$src"); set -- -DEF_TB_DUT_SLB "$@"; }
    [ "$dut" = fast ] && { rtl=$(rtl_fast "$src"); set -- -DEF_FAST "$@"; }
    mkdir -p "$d"
    if ! verilator --binary --timing --timescale 1ns/1ns -j 1 --Mdir "$d/obj" --top-module tb_lockstep \
            -MAKEFLAGS "OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0" \
            -GNS="$ns" -GW_MAX="$w" -GH_MAX="$h" -I"$src" "$@" "$work/hdr/ef_ifaces_pkg.sv" "$DPI/ef_model_pkg.sv" \
            "$DPI/tb_lockstep.sv" $rtl "$build/libef_dpi.a" -o tb >"$d/build.log" 2>&1; then
        echo "verilator build failed" >"$d/status"; return
    fi
    # Warnings do not stop the build; the bench is meant to have none.
    if grep -q '^%Warning' "$d/build.log"; then echo "verilator warned" >"$d/status"; return; fi
    echo "ok $(( $(date +%s) - s ))" >"$d/status"
}
# vl NAME ...: whether the build went well (its log when not)
vl() {
    local d=$work/vl_$1 st
    st=$(cat "$d/status" 2>/dev/null)
    if [ "${st%% *}" = ok ]; then
        echo "test-dpi: built $1 in ${st#ok } s"; return 0
    fi
    tail -n 30 "$d/build.log"; bad "verilator build $1: ${st:-no status}"; return 1
}
# The whole pipeline when the tree has it (every interface checked), and the
# SLB + FILL block, which also has the bench's COV model (+cov_lag).
if [ -e "$R/ef_raster.v" ]; then
    DUT=raster; CHECKS="cmd seg et_wr et_rd plot span pix"
else
    DUT=slb; CHECKS="span"
    echo "test-dpi: no rtl/ef_raster.v: the lockstep DUT is ef_slb_fill alone"
fi
echo "test-dpi: DUT $DUT, checked in lockstep: $CHECKS"
vl_build ns8 $DUT 8 160 120 & vl_build ns32 $DUT 32 160 120 &
wait
# the planted fault dv/faults/span.sed: an RTL variant
bash "$root/dv/rtl-variant.sh" "$work/rtl_span" span || bad "dv/rtl-variant.sh span"
vl_build short $DUT 8 160 120 "$work/rtl_span" &
[ $DUT = raster ] && vl_build slb8 slb 8 160 120 &
wait
# the fast configuration in transaction order, and with the span fault
FAST=0
if [ -e "$R/ef_spanq.v" ]; then
    FAST=1
    vl_build fast8 fast 8 160 120 & vl_build fastshort fast 8 160 120 "$work/rtl_span" &
    wait
fi

# run NAME VECDIR [plusargs]: the bench on VECDIR/cmd.stim.hex; output in $work/NAME.sim
run() {
    local bin=$work/vl_$1/obj/tb name=$2 dir=$3; shift 3
    # (in a subshell with its stderr closed: the simulation aborts on a
    # mismatch, and the shell that waits for it prints "Aborted")
    ( "$bin" +cmd="$dir/cmd.stim.hex" "$@" >"$work/$name.sim" 2>&1; echo $? >"$work/$name.rc" ) 2>/dev/null
}

# pass_run NAME VECDIR [IFACES]: PASS, exit 0, and as many transactions
# checked on each interface as VECDIR's file of it holds
pass_run() {
    local name=$1 dir=$2 ifs=${3:-$CHECKS} line i n f miss=
    line=$(grep '^tb_lockstep: ' "$work/$name.sim" | head -n 1)
    for i in $ifs; do
        f=$dir/$i.expected.hex; [ "$i" = cmd ] && f=$dir/cmd.stim.hex
        n=$(count "$f")
        printf '%s\n' "$line" | grep -Eq "[:,] $n ${i}[,;]" || miss="$miss $i($n)"
    done
    # one frame length (docs/microarch.md 4, item 7): the bench's, the manifest's and edgeflag vectors'
    # own line (not for the fast configuration, whose frame is its own, shorter: the line says so)
    local mc
    mc=$(sed -n 's/.*"cycles": \([0-9]*\).*/\1/p' "$dir/manifest.json")
    case $line in *"(the DUT's, ef_raster SCHEDULE=1"*) mc=fast ;; esac
    [ "$mc" = fast ] || { [ -n "$mc" ] && printf '%s\n' "$line" | grep -q "; a frame of $mc cycles" && grep -q ", $mc cycles; " "$dir.log"; } ||
        miss="$miss frame($mc: the manifest's; the vectors line: $(grep -o ', [0-9]* cycles; ' "$dir.log"))"
    if [ "$(cat "$work/$name.rc")" = 0 ] && [ "${line#tb_lockstep: PASS}" != "$line" ] && [ -z "$miss" ]; then
        ok "lockstep $name: ${line#tb_lockstep: PASS }"
    else
        cat "$work/$name.sim"
        bad "lockstep $name: want PASS with every transaction of the files checked and the manifest's frame length (exit $(cat "$work/$name.rc"); counts differ:$miss)"
    fi
}

if vl ns8; then
    run ns8 tiger8 "$work/t8";              pass_run tiger8 "$work/t8"
    run ns8 tiger8e "$work/t8" +rule=evenodd; pass_run tiger8e "$work/t8e"
    run ns8 gen8 "$work/g8";                pass_run gen8 "$work/g8"

    # Under valgrind (when installed): no invalid access between the bench and
    # the C side (a bench that used the model after destroying it crashed
    # only now and then; memcheck sees it every time).
    if command -v valgrind >/dev/null 2>&1; then
        if ( valgrind -q --error-exitcode=99 "$work/vl_ns8/obj/tb" +cmd="$work/g8/cmd.stim.hex" \
                 >"$work/vg.sim" 2>&1 ) 2>/dev/null && grep -q '^tb_lockstep: PASS' "$work/vg.sim"; then
            ok "lockstep gen8 under valgrind memcheck: no errors"
        else
            cat "$work/vg.sim"; bad "lockstep gen8 under valgrind memcheck"
        fi
    else
        echo "test-dpi: valgrind not installed: the memcheck run is SKIPPED"
    fi

    # COV one cycle slower per span (+cov_lag=1, the SLB + FILL bench's COV
    # model): the DUT's spans come late.
    cov_bin=ns8; [ $DUT = raster ] && cov_bin=slb8
    if [ $DUT = slb ] || vl slb8; then
        [ $DUT = raster ] && { run slb8 slb_tiger8 "$work/t8"; pass_run slb_tiger8 "$work/t8" span; }
        run $cov_bin slow "$work/t8" +cov_lag=1
        line=$(grep -m1 '^tb_lockstep: FAIL' "$work/slow.sim")
        if [ "$(cat "$work/slow.rc")" != 0 ] &&
           printf '%s\n' "$line" | grep -Eq "^tb_lockstep: FAIL at time [0-9]+ ns, cycle ([0-9]+): span: cycle [0-9]+, y [0-9]+, x [0-9]+: cycle differs: expected ([0-9]+), actual [0-9]+ \(late by 1\): y=[0-9]+ x=[0-9]+ len=[0-9]+ mask=0x[0-9a-f]{8}$"; then
            ok "COV one cycle slower caught: ${line#tb_lockstep: FAIL }"
        else
            cat "$work/slow.sim"; bad "cov_lag=1: want a span reported late by 1, exit != 0"
        fi
    fi

    # A stream over W_MAX: the FRAME of a 200-wide canvas into a W_MAX=160 bench.
    mkdir -p "$work/wide"
    awk '!/^\/\// && !done { printf "%012x%s\n", 0, "1" sprintf("%06x", 200) substr($0, 20); done = 1; next } { print }' \
        "$work/t8/cmd.stim.hex" >"$work/wide/cmd.stim.hex"
    run ns8 wide "$work/wide"
    line=$(grep -m1 '^tb_lockstep: FAIL' "$work/wide.sim")
    if [ "$(cat "$work/wide.rc")" != 0 ] &&
       printf '%s\n' "$line" | grep -q "cmd.stim.hex:5: the model refused the command: command 1 (FRAME, op 1): canvas 200x120 over width_max x height_max 160x120"; then
        ok "lockstep refuses a canvas over W_MAX: ${line#tb_lockstep: FAIL }"
    else
        cat "$work/wide.sim"; bad "lockstep wide: want the FRAME refused at cmd.stim.hex:5"
    fi

    # Stamps that go backwards (words 2 and 3 swapped: line 7 is earlier than line 6).
    mkdir -p "$work/back"
    awk 'NR == 6 { held = $0; next } NR == 7 { print; print held; next } { print }' \
        "$work/t8/cmd.stim.hex" >"$work/back/cmd.stim.hex"
    run ns8 back "$work/back"
    line=$(grep -m1 '^tb_lockstep: FAIL' "$work/back.sim")
    if [ "$(cat "$work/back.rc")" != 0 ] &&
       printf '%s\n' "$line" | grep -Eq "back/cmd.stim.hex:7: cycle stamp [0-9]+ does not follow the previous one, [0-9]+$"; then
        ok "lockstep refuses stamps that go backwards: ${line#tb_lockstep: FAIL }"
    else
        cat "$work/back.sim"; bad "lockstep back: want cmd.stim.hex:7 refused"
    fi
    # No input: no +cmd, a missing file, a file without a command: each a FAIL line and a
    # non-zero exit, nothing simulated.
    mkdir -p "$work/noin"; printf '// no command\n' >"$work/noin/cmd.stim.hex"
    x_ok=1 x_msg=
    for k in nocmd missing empty; do
        case $k in
            nocmd)   a=(); want="tb_lockstep: FAIL no +cmd=FILE" ;;
            missing) a=(+cmd="$work/noin/no-such.hex"); want="tb_lockstep: FAIL cannot open $work/noin/no-such.hex" ;;
            empty)   a=(+cmd="$work/noin/cmd.stim.hex"); want="tb_lockstep: FAIL $work/noin/cmd.stim.hex holds no command" ;;
        esac
        ( "$work/vl_ns8/obj/tb" "${a[@]}" >"$work/noin/$k.sim" 2>&1; echo $? >"$work/noin/$k.rc" ) 2>/dev/null
        if [ "$(cat "$work/noin/$k.rc")" = 0 ] || ! grep -qF "$want" "$work/noin/$k.sim"; then
            x_ok=0; cat "$work/noin/$k.sim"; bad "lockstep $k: want '$want' and a non-zero exit (exit $(cat "$work/noin/$k.rc"))"
        fi
        x_msg="$x_msg $k exit $(cat "$work/noin/$k.rc");"
    done
    [ $x_ok = 1 ] && ok "lockstep without input (no +cmd, a missing file, no command in it) fails with its line:$x_msg"
fi
if vl ns32; then
    run ns32 gen32 "$work/g32";             pass_run gen32 "$work/g32"
fi

# --------------------------------------------------------------- 3. faults
# The first expected span: its cycle (the word's top 48 bits) and fields.
# The RTL's planted fault span (dv/faults/span.sed) cuts every
# span of two or more pixels one short: the first such span of the files is
# where the bench must stop.  A span word is 123 bits in 31 digits: its first
# 13 digits are bits 123..72 and the cycle, bits 122..75, is their value
# shifted right by 3; len is bits 46..32, within the last 16 digits.
c1=
while read -r w; do
    case $w in ''|//*) continue ;; esac
    if [ $(( (16#${w: -16} >> 32) & 0x7fff )) -ge 2 ]; then c1=$(( 16#${w:0:13} >> 3 )); break; fi
done <"$work/t8/span.expected.hex"
if vl short; then
    run short short "$work/t8"
    line=$(grep -m1 '^tb_lockstep: FAIL' "$work/short.sim")
    # Exactly one field marked, len, one less than expected; at the first span's cycle.
    el=$(printf '%s\n' "$line" | sed -n 's/.*fields differ: expected .* len=\([0-9]*\) .*; actual .*/\1/p')
    al=$(printf '%s\n' "$line" | sed -n 's/.*; actual .* len=\([0-9]*\)\* .*/\1/p')
    stars=$(printf '%s\n' "${line#*; actual }" | tr -cd '*' | wc -c)
    if [ "$(cat "$work/short.rc")" != 0 ] &&
       printf '%s\n' "$line" | grep -Eq "^tb_lockstep: FAIL at time [0-9]+ ns, cycle $c1: span: cycle $c1, y [0-9]+, x [0-9]+: fields differ: expected y=[0-9]+ x=[0-9]+ len=[0-9]+ mask=0x[0-9a-f]{8}; actual " &&
       [ -n "$el" ] && [ -n "$al" ] && [ "$el" = $((al + 1)) ] && [ "$stars" = 1 ]; then
        ok "RTL fault span (dv/faults/span.sed: a span one pixel short) caught: ${line#tb_lockstep: FAIL }"
    else
        cat "$work/short.sim"; bad "fault span: want the first span of 2+ pixels (cycle $c1) reported with len one short, exit != 0"
    fi
fi

# The fast configuration (ef_raster SCHEDULE=1) against the model in
# transaction order (docs/dpi.md): every transaction of the files checked,
# and the span fault stopping at the first span of 2+ pixels, len one short.
if [ $FAST = 1 ] && vl fast8; then
    run fast8 fast_tiger8 "$work/t8";  pass_run fast_tiger8 "$work/t8"
    run fast8 fast_gen8 "$work/g8";    pass_run fast_gen8 "$work/g8"
fi
if [ $FAST = 1 ] && vl fastshort; then
    run fastshort fastshort "$work/t8"
    line=$(grep -m1 '^tb_lockstep: FAIL' "$work/fastshort.sim")
    el=$(printf '%s\n' "$line" | sed -n 's/.*fields differ: expected .* len=\([0-9]*\) .*; actual .*/\1/p')
    al=$(printf '%s\n' "$line" | sed -n 's/.*; actual .* len=\([0-9]*\)\* .*/\1/p')
    stars=$(printf '%s\n' "${line#*; actual }" | tr -cd '*' | wc -c)
    if [ "$(cat "$work/fastshort.rc")" != 0 ] &&
       printf '%s\n' "$line" | grep -Eq "^tb_lockstep: FAIL at time [0-9]+ ns, cycle [0-9]+: span: cycle [0-9]+, y [0-9]+, x [0-9]+: fields differ: " &&
       [ -n "$el" ] && [ -n "$al" ] && [ "$el" = $((al + 1)) ] && [ "$stars" = 1 ]; then
        ok "fast configuration, RTL fault span (transaction order) caught: ${line#tb_lockstep: FAIL }"
    else
        cat "$work/fastshort.sim"; bad "fault span in the fast configuration: want a span reported with len one short, exit != 0"
    fi
fi
echo "test-dpi: $(( $(date +%s) - t0 )) s"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
