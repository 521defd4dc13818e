#!/usr/bin/env bash
# tests/host/rtl.sh - the Verilated reference RTL as the simulated board's DUT
# (`edgeflag-host "${SIM[@]}" --sim-dut rtl`, docs/board.md 5.3): the unmodified
# edgeflag-host, built with the RTL DUT (make host-rtl), against the model's own vectors.
#   1. verify of two shared SVGs at 64x48, 8 and 16 samples: PASS cycle-exact on pix and
#      every internal interface (seg, et_wr, et_rd, plot, span), and the RTL's results
#      byte-identical to the model DUT's;
#   2. a link fault (--sim-faults drop=2): still PASS, the frame sent again; unplugged
#      mid-commands (exit 5), then --resume with --sim-state: byte-identical results;
#   3. a planted RTL fault (an edgeflag-host built with the RTL variant dv/faults/rooks.sed: one wrong
#      n-rooks offset in PLOT): verify exits 1, the earliest mismatch (by cycle) on plot, none
#      on seg or et_wr (et_rd, span and pix follow: PLOT's back-pressure and its wrong samples);
#   4. a canvas over the RTL's W_MAX: exit 3, the host refusing it from identify's limits; a
#      shape of 34,000 edges (over E_MAX): exit 6, the board's ERROR naming E_MAX; `--sim-dut` misspelt: exit 2; an
#      edgeflag-host built without the RTL DUT: `--sim-dut rtl` exit 7 naming make host-rtl,
#      and --version says whether it is built in.
# usage: bash tests/host/rtl.sh BUILD_DIR   (`make test-host-rtl`; EF_RTL_DUT_SRC: another
#        RTL folder than rtl).  Builds what it needs (about 30 s on two cores).
# Skips (exit 0, saying so) only when verilator is not installed.
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
build=${1:?usage: tests/host/rtl.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/host/waits.sh disable=SC1091
. "$root/tests/host/waits.sh"
case $build in /*) ;; *) build=$PWD/$build ;; esac
MAKE=${MAKE:-make}
if ! command -v verilator >/dev/null 2>&1; then
    echo "test-host-rtl: SKIPPED: verilator is not installed ('make deps-test' installs it)"
    exit 0
fi
E=$build/edgeflag H=$build/edgeflag-host HF=$build/edgeflag-host-rtlfault HN=$build/edgeflag-host-nortl
SVG=$root/tests/data/svg
# The RTL DUT runs inside the host's reads and writes (a whole frame at a FRAME_END, slower than
# the model's), so a busy machine stretches the time between two ACKs: a generous --timeout
# (tests/host/waits.sh); no case here tests a timeout.
SIM=(--transport sim --timeout "$EF_LINK_MS")
src=()
[ -n "${EF_RTL_DUT_SRC:-}" ] && src=(RTL_DUT_SRC="$EF_RTL_DUT_SRC")
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-hrtl.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT

# ---------------------------------------------------------------- builds
t0=$(date +%s)
if ! $MAKE -C "$root" --no-print-directory -j2 BUILD="$build" WITH_RTL_DUT=1 "${src[@]}" "$H" "$E" \
        >"$tmp/build.log" 2>&1; then
    tail -n 30 "$tmp/build.log"; bad "build edgeflag-host with the RTL DUT"; echo "$pass passed, $fail failed"; exit 1
fi
# the planted fault: NS 8 only, its own objects and binary, built from the
# RTL variant of dv/faults/rooks.sed
if ! bash "$root/dv/rtl-variant.sh" "$build/host/rtl-fault-src" rooks >"$tmp/build_fault.log" 2>&1 ||
   ! $MAKE -C "$root" --no-print-directory -j2 BUILD="$build" WITH_RTL_DUT=1 RTL_DUT_SRC="$build/host/rtl-fault-src" RTL_DUT_NS=8 \
        RTL_DUT_FAULT=rooks RTL_DUT_OPT=-O0 RTL_DUT_DIR="$build/host/rtl-fault" EDGEFLAG_HOST="$HF" "$HF" \
        >"$tmp/build_fault.log" 2>&1; then
    tail -n 30 "$tmp/build_fault.log"; bad "build edgeflag-host with the RTL DUT and the planted fault rooks"
fi
# without the RTL DUT (a relink: the stub)
if ! $MAKE -C "$root" --no-print-directory -j2 BUILD="$build" WITH_RTL_DUT=0 RTL_DUT_DIR="$build/host/rtl-none" \
        EDGEFLAG_HOST="$HN" "$HN" >"$tmp/build_none.log" 2>&1; then
    tail -n 30 "$tmp/build_none.log"; bad "build edgeflag-host without the RTL DUT"
fi
echo "test-host-rtl: builds took $(($(date +%s) - t0)) s"
cd "$tmp" || exit 1

# vec NAME SVG NS [SIZE]: vectors in $tmp/NAME
vec() { "$E" vectors "$SVG/$2" -o "$1" --size "${4:-64x48}" --samples "$3" >"$1.log" 2>&1 ||
            { cat "$1.log"; bad "edgeflag vectors $2 at $3"; return 1; }; }
# nmis FILE IFACE: the mismatch count check printed for IFACE ("" when it printed none)
nmis() { sed -n "s/^edgeflag check: $2: .*, \([0-9]*\) mismatches.*/\1/p" "$1" | head -n 1; }

# ---------------------------------------------------------------- 1. verify
"$H" --version >version.txt
if grep -q 'sim-dut rtl: built in (Verilated ef_raster: NS 8 16 32' version.txt; then
    ok "--version says the RTL DUT is built in ($(sed -n 's/.*sim-dut rtl: //p' version.txt))"
else
    bad "--version does not say the RTL DUT is built in" "$(grep sim version.txt)"
fi
for svg in stress_pixi_figure8.svg stress_pixi_fill_rule_multiple_holes.svg; do
    for ns in 8 16; do
        n=${svg%.svg}_$ns
        vec "$n" "$svg" "$ns" || continue
        start=$(date +%s%N)
        "$H" verify "$n/vectors.bin" "${SIM[@]}" --sim-dut rtl --results "$n.rtl" >"$n.out" 2>&1
        rc=$?
        ms=$((($(date +%s%N) - start) / 1000000))
        allzero=1 want="seg et_wr et_rd plot span pix"
        for i in $want; do [ "$(nmis "$n.out" "$i")" = 0 ] || allzero=0; done
        if [ $rc = 0 ] && [ $allzero = 1 ] && grep -q 'edgeflag check: PASS: 6 comparisons.*cycle-exact' "$n.out"; then
            ok "verify $svg at $ns samples with the RTL DUT: PASS cycle-exact on $want ($(sed -n 's/.*PASS: //p' "$n.out"), ${ms} ms)"
        else
            bad "verify $svg at $ns samples with the RTL DUT" "exit $rc; $(tail -n 12 "$n.out")"
            continue
        fi
        # the model DUT's results: the RTL's must be the same bytes
        "$H" verify "$n/vectors.bin" "${SIM[@]}" --results "$n.model" >/dev/null 2>&1
        if cmp -s "$n.model/vectors.actual.bin" "$n.rtl/vectors.actual.bin"; then
            ok "$svg at $ns: the RTL DUT's vectors.actual.bin is byte-identical to the model DUT's"
        else
            bad "$svg at $ns: the RTL DUT's results differ from the model DUT's"
        fi
    done
done

# ---------------------------------------------------------------- 2. a link fault
n=stress_pixi_figure8_8
"$H" verify "$n/vectors.bin" "${SIM[@]}" --sim-dut rtl --sim-faults drop=2 --results drop >drop.out 2>&1
rc=$?
again=$(sed -n 's/.*(\([0-9]*\) sent again).*/\1/p' drop.out | head -n 1)
if [ $rc = 0 ] && grep -q 'edgeflag check: PASS' drop.out && [ "${again:-0}" -ge 1 ] &&
   cmp -s drop/vectors.actual.bin "$n.rtl/vectors.actual.bin"; then
    ok "--sim-faults drop=2 with the RTL DUT: PASS, $again frame(s) sent again, results identical"
else
    bad "--sim-faults drop=2 with the RTL DUT" "exit $rc, sent again '${again}'; $(tail -n 5 drop.out)"
fi

# unplugged mid-commands, then --resume: the board's state (--sim-state) is replayed into a
# fresh RTL, and the results are the same bytes as an uninterrupted run
"$H" verify "$n/vectors.bin" "${SIM[@]}" --sim-dut rtl --sim-state st --sim-faults unplug=4 --frame-cmds 20 \
    --results res >unplug.out 2>&1
rc1=$?
"$H" verify "$n/vectors.bin" "${SIM[@]}" --sim-dut rtl --sim-state st --resume --frame-cmds 20 \
    --results res >resume.out 2>&1
rc2=$?
if [ $rc1 = 5 ] && grep -q 'went away' unplug.out && [ $rc2 = 0 ] && grep -q 'edgeflag check: PASS' resume.out &&
   cmp -s res/vectors.actual.bin "$n.rtl/vectors.actual.bin"; then
    ok "unplug=4 with the RTL DUT: exit 5, then --resume exit 0 with results byte-identical to an uninterrupted run"
else
    bad "unplug + --resume with the RTL DUT" "exit $rc1 then $rc2; $(tail -n 2 unplug.out resume.out)"
fi

# ---------------------------------------------------------------- 3. a planted RTL fault
if [ -x "$HF" ]; then
    "$HF" verify "$n/vectors.bin" "${SIM[@]}" --sim-dut rtl --results fault --errors 100000 >fault.out 2>&1
    rc=$?
    p=$(grep -c "^fault/vectors.actual.bin: record [0-9]* (byte offset [0-9]*): plot: cycle" fault.out)
    up="$(nmis fault.out seg)$(nmis fault.out et_wr)"
    # the earliest mismatch (by cycle) of every one check printed: the fault's own interface
    first=$(sed -n 's/^fault\/vectors.actual.bin: record [0-9]* (byte offset [0-9]*): \([a-z_]*\): cycle \([0-9]*\).*/\2 \1/p' \
                fault.out | sort -n | head -n 1)
    if [ $rc = 1 ] && [ -n "$p" ] && [ "$p" -gt 0 ] && [ "$up" = 00 ] && [ "${first#* }" = plot ] &&
       grep -q 'edgeflag check: FAIL' fault.out; then
        ok "the planted RTL fault rooks (dv/faults/rooks.sed): verify exit 1, $p mismatches on plot, the earliest at cycle ${first% *} on plot, none on seg or et_wr ($(grep -m1 ": plot: cycle ${first% *}" fault.out | cut -d: -f3- | cut -c1-160))"
    else
        bad "the planted RTL fault rooks (dv/faults/rooks.sed) was not caught on plot" "exit $rc, plot '$p', seg+et_wr '$up', first '$first'; $(head -n 20 fault.out)"
    fi
fi

# ---------------------------------------------------------------- 4. errors
vec wide stress_pixi_figure8.svg 8 1100x40 &&
{
    "$H" verify wide/vectors.bin "${SIM[@]}" --sim-dut rtl --results wide.r >wide.out 2>wide.err
    rc=$?
    if [ $rc = 3 ] && grep -q 'does not fit this board.*canvas up to 1024x1024' wide.err && [ ! -e wide.r/vectors.actual.bin ]; then
        ok "a 1100x40 canvas with the RTL DUT: exit 3, $(head -n 1 wide.err | cut -c1-200)"
    else
        bad "a canvas over W_MAX with the RTL DUT" "exit $rc; $(tail -n 3 wide.err)"
    fi
}
# one shape of 34,000 edges: over the RTL's E_MAX (32,768); the DUT refuses it (ERROR code 16)
awk 'BEGIN { printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"48\"><path d=\"M"
             for (i = 0; i < 34000; i++) printf "%s%d %d", (i ? " L" : ""), 32 + (i % 2 ? 20 : 10) * cos(6.2831853 * i / 34000),
                                             24 + (i % 2 ? 20 : 10) * sin(6.2831853 * i / 34000)
             print " Z\" fill=\"red\"/></svg>" }' >many.svg
if "$E" vectors many.svg -o many --samples 8 >many.log 2>&1; then
    "$H" verify many/vectors.bin "${SIM[@]}" --sim-dut rtl --results many.r >many.out 2>many.err
    rc=$?
    if [ $rc = 6 ] && grep -q "code 16: a shape of more EDGE commands than the RTL's E_MAX (32768)" many.err &&
       [ ! -e many.r/vectors.actual.bin ]; then
        ok "a shape of 34000 edges with the RTL DUT: exit 6, $(head -n 1 many.err)"
    else
        bad "a shape over E_MAX with the RTL DUT" "exit $rc; $(tail -n 3 many.err)"
    fi
else
    cat many.log; bad "edgeflag vectors of a 34000-edge shape"
fi
"$H" verify "$n/vectors.bin" "${SIM[@]}" --sim-dut verilog >usage.out 2>usage.err
rc=$?
if [ $rc = 2 ] && grep -q -- '--sim-dut must be model or rtl' usage.err; then
    ok "--sim-dut verilog: exit 2, $(head -n 1 usage.err)"
else
    bad "--sim-dut verilog" "exit $rc; $(cat usage.err)"
fi
if [ -x "$HN" ]; then
    "$HN" verify "$n/vectors.bin" "${SIM[@]}" --sim-dut rtl --results none >none.out 2>none.err
    rc=$?
    if [ $rc = 7 ] && grep -q 'make host-rtl' none.err && "$HN" --version | grep -q 'sim-dut rtl: not built in'; then
        ok "built without the RTL DUT: --sim-dut rtl exit 7, $(head -n 1 none.err | cut -c1-160); --version says not built in"
    else
        bad "built without the RTL DUT, --sim-dut rtl" "exit $rc; $(cat none.err)"
    fi
fi

# ---------------------------------------------------------------- 5. the RTL's limits, saved
# identify --save of the board with the Verilated RTL (its W_MAX, H_MAX, E_MAX and sample counts,
# board/rtl_dut.mk), then gen --dut-file on that record: the same fits as the RTL's parameters
# given as flags (read here from board/rtl_dut.mk's defaults), and the canvases over them fitted
"$H" identify "${SIM[@]}" --sim-dut rtl --save rtl_ident.bin >ident.out 2>ident.err
rc=$?
lim=$(sed -n 's/.*canvas up to \([0-9]*x[0-9]*\), \([0-9]*\) edges.*/\1 \2/p' ident.out)
want=$(awk '$2 == "?=" { v[$1] = $3 } END { print v["RTL_DUT_W_MAX"] "x" v["RTL_DUT_H_MAX"], v["RTL_DUT_E_MAX"] }' "$root/board/rtl_dut.mk")
"$E" gen --list --dut-file rtl_ident.bin >rf.tsv 2>rf.err
"$E" gen --list --dut-limits "${want% *}" --dut-edges "${want#* }" --dut-samples 8,16,32 >rl.tsv 2>rl.err
nfit=$(grep -c 'fitted to the DUT' rf.tsv)
if [ $rc = 0 ] && [ "$lim" = "$want" ] && cmp -s rf.tsv rl.tsv && cmp -s rf.err rl.err && [ "$nfit" -gt 0 ]; then
    ok "identify --save with the RTL DUT ($want edges): gen --dut-file on it fits $nfit cases, as the RTL's parameters given as flags do"
else
    bad "identify --save with the RTL DUT" "exit $rc, identify says '$lim', the build '$want', $nfit fitted; $(cat ident.err)"
fi

echo "test-host-rtl: $(($(date +%s) - t0)) s in all"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
