#!/usr/bin/env bash
# tests/rtl/rtl-test.sh - the whole pipeline in RTL (issue 18): ef_raster
# (rtl/) turns cmd.stim.hex into pix cycle for cycle, and every
# internal interface with it, under Icarus and Verilator.
#
#   1. lint: verilator --lint-only -Wall of ef_raster at NS 8/16/32 and
#      iverilog -g2005 -Wall: silent;
#   2. cases: every shared SVG (tests/data/svg) at 32x24 and a slice of the
#      `edgeflag gen` level-1 set (EF_RTL_SLICE: every Nth case, default 11),
#      rotating over NS 8/16/32 x the rule settings (scene, nonzero,
#      evenodd), each in Icarus and in Verilator; `edgeflag check --cycles`
#      must pass on seg, et_wr, et_rd, plot, span and pix;
#   3. random back-pressure on pix (seeded): --transactions must pass, in
#      both simulators;
#   4. refusals: a canvas over W_MAX, a shape over E_MAX edges and a stamp
#      going backwards are refused by tb_raster naming the file and line,
#      which the script finds independently (the line of the offending word);
#   5. faults: each planted fault (dv/faults/NAME.sed, an RTL variant made by
#      dv/rtl-variant.sh) runs a case that exercises it; `edgeflag
#      check` must fail (exit 1) and its earliest reported mismatch must be on
#      the fault's interface, at the cycle where a plain in-order comparison
#      of the two hex files (awk, independent of edgeflag check) first
#      differs (on that interface, or on it among others at that cycle),
#      with a field the fault changes marked.
#   6. the fast configuration (ef_raster SCHEDULE=1, the overlap schedule of
#      docs/microarch.md section 6), a slice: the NS 8 cases of stage 2
#      against `edgeflag vectors --schedule overlap`, `--cycles`, in Verilator
#      and (those of at most EF_RTL_IV_CYCLES cycles) Icarus; back-pressure
#      (--transactions) in both; the faults of stage 5 in the fast
#      configuration and two of its own (skipstart, spanq), each caught as
#      in stage 5.  The fast configuration's lint is rtl-lint's.
#
# usage: bash tests/rtl/rtl-test.sh BUILD_DIR   (make rtl-test; EF_RTL_JOBS
#        (default 2), EF_RTL_SLICE, EF_RTL_KEEP=1 keeps the work directory)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
# Needs iverilog and verilator (tools/install-deps.sh test installs them).
# shellcheck disable=SC2086 # the RTL file lists ($RTL, $A_*) are split into words on purpose
set -u
export LC_ALL=C

build=${1:?usage: tests/rtl/rtl-test.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
TB=$root/dv/tb
R=$root/rtl
# rtl_files DIR: the whole pipeline's files in DIR (rtl/ or a variant's copy)
rtl_files() {
    local d=$1
    echo "$d/ef_raster.v $d/ef_dec.v $d/ef_setup.v $d/ef_div.v $d/ef_etm.v $d/ef_aet.v $d/ef_plot.v $d/ef_slb_fill.v $d/ef_slb_ram.v $d/ef_cov.v"
}
RTL=$(rtl_files "$R")
# rtl_files_fast DIR: the fast configuration's (SCHEDULE=1, docs/microarch.md
# section 6): the same files and the span queue
rtl_files_fast() {
    echo "$(rtl_files "$1") $1/ef_spanq.v"
}
jobs=${EF_RTL_JOBS:-2}
slice=${EF_RTL_SLICE:-11}
# the hardware the cases run on (small: the gen slice's canvases fit)
WM=256 HM=256 EM=16384

for t in iverilog vvp verilator; do
    command -v $t >/dev/null 2>&1 || { echo "rtl-test: $t is not installed ('make deps-test')"; exit 1; }
done
[ -x "$EF" ] || { echo "rtl-test: $EF not built (make cli)"; exit 1; }

tmpbase=${TMPDIR:-/tmp}
[ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
work=$(mktemp -d "$tmpbase/edgeflag-rtltest.XXXXXX") || exit 1
if [ -n "${EF_RTL_KEEP:-}" ]; then echo "rtl-test: keeping $work"; else trap 'rm -rf "$work"' EXIT; fi
mkdir -p "$work/logs"
t_start=$(date +%s)

order=()
submit() {
    local name=$1; shift
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
    ( "$@" ) >"$work/logs/$name.log" 2>&1 &
    order+=("$name")
}
pass=0 fail=0
collect() {
    wait
    local n v
    for n in "${order[@]}"; do
        v=$(grep -E '^RESULT (PASS|FAIL)' "$work/logs/$n.log" | tail -n 1)
        if [ "${v#RESULT PASS}" != "$v" ]; then
            pass=$((pass + 1)); echo "PASS ${v#RESULT PASS }"
        else
            fail=$((fail + 1)); echo "FAIL $n: ${v#RESULT FAIL }"
            tail -n 12 "$work/logs/$n.log" | sed 's/^/    /'
        fi
    done
    order=()
}

# ---------------------------------------------------------------- 1. lint
lint() {
    local ns=$1 out
    out=$(verilator --lint-only -Wall -I"$R" -GNS="$ns" -GW_MAX=320 -GH_MAX=240 -GE_MAX=512 --top-module ef_raster $RTL 2>&1)
    [ -z "$out" ] || { echo "$out" | head -20; echo "RESULT FAIL lint ef_raster NS=$ns: verilator -Wall is not silent"; return; }
    out=$(iverilog -g2005 -Wall -I"$R" -Pef_raster.NS="$ns" -s ef_raster -o /dev/null $RTL 2>&1)
    [ -z "$out" ] || { echo "$out" | head -20; echo "RESULT FAIL lint ef_raster NS=$ns: iverilog -Wall is not silent"; return; }
    echo "RESULT PASS lint ef_raster NS=$ns: verilator --lint-only -Wall and iverilog -g2005 -Wall silent"
}
for ns in 8 16 32; do submit "lint_$ns" lint $ns; done

# ---------------------------------------------------------------- builds
# build_iv KEY [FAULT]: one Icarus build per sample count (KEY = NS; fN: the
# fast configuration at N) and planted fault (the RTL variant dv/rtl-variant.sh makes
# from dv/faults/FAULT.sed)
build_iv() {
    local key=$1 ns=${1#f} fault=${2:-} o=$work/iv_$1${2:+_$2} src=$R files=rtl_files def=() top=
    [ "$key" != "$ns" ] && { files=rtl_files_fast; def=(-DEF_FAST); top="fast "; }
    mkdir -p "$o"
    if [ -n "$fault" ]; then
        src=$o/rtl
        bash "$root/dv/rtl-variant.sh" "$src" "$fault" || { echo "RESULT FAIL build icarus ${top}NS=$ns $fault: the variant"; return; }
    fi
    # shellcheck disable=SC2046 # the file list splits on purpose
    iverilog -g2005 -I"$src" -I"$TB" "${def[@]}" -o "$o/t.vvp" -Ptb_raster.NS="$ns" -Ptb_raster.W_MAX=$WM -Ptb_raster.H_MAX=$HM \
        -Ptb_raster.E_MAX=$EM -Ptb_raster.FB_BITS=16 "$TB/tb_raster.v" $($files "$src") &&
        echo "RESULT PASS build icarus ${top}NS=$ns ${fault}" || echo "RESULT FAIL build icarus ${top}NS=$ns $fault"
}
build_vl() {
    local key=$1 ns=${1#f} o=$work/vl_$1 files=$RTL def=() top=
    [ "$key" != "$ns" ] && { files=$(rtl_files_fast "$R"); def=(-DEF_FAST); top="fast "; }
    mkdir -p "$o"
    # random initial state (run with +verilator+rand+reset+2, a seed per case): a register the
    # reset forgets, or a wrong reset value, shows instead of hiding behind zeroes (issue 27)
    verilator --binary --timing -O1 -Wno-fatal -Wno-WIDTH -I"$R" -I"$TB" "${def[@]}" --x-assign unique --x-initial unique --Mdir "$o/obj" --top-module tb_raster \
        -GNS="$ns" -GW_MAX=$WM -GH_MAX=$HM -GE_MAX=$EM -GFB_BITS=16 "$TB/tb_raster.v" $files >"$o/build.log" 2>&1 &&
        echo "RESULT PASS build verilator ${top}NS=$ns" || { tail -20 "$o/build.log"; echo "RESULT FAIL build verilator ${top}NS=$ns"; }
}
faults="rooks pad topclip lastedge div_floor sb_ring fwd span"
for ns in 8 16 32; do submit "build_vl_$ns" build_vl $ns; done
for ns in 8 16 32; do submit "build_iv_$ns" build_iv $ns; done
for f in $faults; do submit "build_iv_$f" build_iv 8 "$f"; done
# the fast configuration: the same faults, and its own two
faults_fast="rooks pad topclip lastedge div_floor sb_ring fwd span skipstart spanq"
submit build_vl_f8 build_vl f8
submit build_iv_f8 build_iv f8
for f in $faults_fast; do submit "build_iv_f8_$f" build_iv f8 "$f"; done

# ---------------------------------------------------------------- vectors
"$EF" gen -o "$work/gen" >"$work/logs/gen.log" 2>&1 || { cat "$work/logs/gen.log"; exit 1; }
cases=()      # NAME|INPUT|NS|RULE|SIZE
k=0
for f in "$root"/tests/data/svg/*.svg; do
    ns=$((8 << (k % 3))); rule=$(echo scene nonzero evenodd | cut -d' ' -f$(( (k / 3) % 3 + 1 )))
    cases+=("svg_$(basename "$f" .svg)_${ns}_$rule|$f|$ns|$rule|24x18"); k=$((k + 1))
done
while IFS=$'\t' read -r num file kind _ name _; do
    [ "$kind" = directed ] || [ "$kind" = random ] || continue
    case $name in canvas-max*|zigzag-4096|same-cell-4096) continue ;; esac   # over the bench's W_MAX/H_MAX, or slow
    [ $((num % slice)) = 0 ] || continue
    ns=$((8 << (k % 3))); rule=$(echo scene nonzero evenodd | cut -d' ' -f$(( (k / 3) % 3 + 1 )))
    cases+=("gen_${num}_${name}_${ns}_$rule|$work/gen/$file|$ns|$rule|-"); k=$((k + 1))
done < <(tail -n +3 "$work/gen/index.tsv")
# directed (issue 27, a mutant survivor): the tiger filling the build's W_MAX x H_MAX (a FRAME
# of exactly the largest canvas, rows past 64 for AET's occupancy search, enough edges to wrap
# AET's ring); Verilator only (445,000 cycles)
cases+=("max_tiger_8_scene|$root/tests/data/svg/tiger.svg|8|scene|${WM}x$HM")

vectors() {      # vectors NAME INPUT NS RULE SIZE [SCHEDULE]
    local d=$work/vec/$1 args=()
    [ "$4" != scene ] && args+=(--rule "$4"); [ "$5" != - ] && args+=(--size "$5"); [ -n "${6:-}" ] && args+=(--schedule "$6")
    "$EF" vectors "$2" -o "$d" --samples "$3" "${args[@]}" --formats hex >"$work/logs/vec_$1.log" 2>&1
}
mkdir -p "$work/vec"
# A case whose canvas is over the bench's W_MAX x H_MAX is left out (the
# refusal itself is tested below); Icarus runs the cases of at most
# EF_RTL_IV_CYCLES cycles (default 4000: it simulates this design at a few
# thousand cycles per second), Verilator all.
ivmax=${EF_RTL_IV_CYCLES:-4000}
kept=() nskip=0 fast=()
for c in "${cases[@]}"; do
    IFS='|' read -r n i ns rule size <<<"$c"
    vectors "$n" "$i" "$ns" "$rule" "$size" || { echo "FAIL vectors $n"; fail=$((fail + 1)); continue; }
    read -r w h <<<"$(sed -n 's/.*; size \([0-9]*\)x\([0-9]*\);.*/\1 \2/p' "$work/vec/$n/cmd.stim.hex" | head -n 1)"
    if [ "$w" -gt $WM ] || [ "$h" -gt $HM ]; then nskip=$((nskip + 1)); continue; fi
    # a shape of more EDGE commands than E_MAX (lorem_ipsum_compound: one shape
    # of the whole paragraph) is refused by the bench by design: left out
    me=$(awk '!/^\/\// && NF { op = substr($1, 13, 1); if (op == "2") n = 0; if (op == "3" && ++n > m) m = n } END { print m + 0 }' "$work/vec/$n/cmd.stim.hex")
    if [ "$me" -gt $EM ]; then nskip=$((nskip + 1)); continue; fi
    cyc=$(sed -n 's/.*"cycles": \([0-9]*\).*/\1/p' "$work/vec/$n/manifest.json")
    kept+=("$c|$cyc")
    # the fast configuration's slice (stage 6): the NS 8 cases, in the overlap schedule
    if [ "$ns" = 8 ]; then
        vectors "fast_$n" "$i" 8 "$rule" "$size" overlap || { echo "FAIL vectors fast_$n"; fail=$((fail + 1)); continue; }
        fast+=("fast_$n|$(sed -n 's/.*"cycles": \([0-9]*\).*/\1/p' "$work/vec/fast_$n/manifest.json")")
    fi
done
echo "rtl-test: ${#kept[@]} cases ($nskip left out: a canvas over ${WM}x$HM or a shape over $EM edges)"
cases=("${kept[@]}")
collect

# ---------------------------------------------------------------- 2. cases
# run SIM NAME NS [bp SEED]
# sim_run SIM NS PLUSARGS...: the NS build of SIM; its output, its exit status
# (in a subshell with stderr closed: a Verilator $fatal aborts, and the shell
# would say so)
sim_run() {
    local sim=$1 ns=$2; shift 2
    if [ "$sim" = icarus ]; then ( vvp -n "$work/iv_$ns/t.vvp" "$@" 2>&1 ) 2>/dev/null
    else ( "$work/vl_$ns/obj/Vtb_raster" +verilator+rand+reset+2 +verilator+seed+$(( $(printf '%s' "$*" | cksum | cut -d' ' -f1) % 2000000000 + 1 )) "$@" 2>&1 ) 2>/dev/null; fi
}
run() {
    local sim=$1 n=$2 ns=$3 bp=${4:-} v=$work/vec/$2 a=$work/act_$1_$2 mode=--cycles pa=() t0 t1 out rc
    mkdir -p "$a"
    [ -n "$bp" ] && { pa+=(+bp="$bp"); mode=--transactions; }
    t0=$(date +%s.%N)
    out=$(sim_run "$sim" "$ns" +cmd="$v/cmd.stim.hex" +out="$a" "${pa[@]}"); rc=$?
    t1=$(date +%s.%N)
    echo "$out"
    { [ "$rc" = 0 ] && echo "$out" | grep -q '^tb_raster: DONE'; } ||
        { echo "RESULT FAIL $sim $n${bp:+ bp}: the bench did not finish (exit $rc)"; return; }
    "$EF" check "$v" "$a" $mode --errors 5 || { echo "RESULT FAIL $sim $n${bp:+ bp}: edgeflag check $mode"; return; }
    cyc=$(echo "$out" | sed -n 's/.* \([0-9]*\) cycles.*/\1/p' | head -n 1)
    echo "RESULT PASS $sim $n${bp:+ (back-pressure seed $bp)}: edgeflag check $mode passes on seg, et_wr, et_rd, plot, span, pix ($cyc cycles, $(awk -v a="$t0" -v b="$t1" -v c="$cyc" 'BEGIN { printf "%.0f", c / (b - a) }') cycles/s)"
}
niv=0
for c in "${cases[@]}"; do
    IFS='|' read -r n i ns rule size cyc <<<"$c"
    [ "$cyc" -le "$ivmax" ] && { submit "icarus_$n" run icarus "$n" "$ns"; niv=$((niv + 1)); }
    submit "verilator_$n" run verilator "$n" "$ns"
done
bpcase=$(printf '%s\n' "${cases[@]}" | grep '^svg_tiger' | head -n 1 | cut -d'|' -f1)
bpns=$(printf '%s\n' "${cases[@]}" | grep '^svg_tiger' | head -n 1 | cut -d'|' -f3)
submit icarus_bp run icarus "$bpcase" "$bpns" 20070101
submit verilator_bp run verilator "$bpcase" "$bpns" 424242
# 6. the fast configuration's slice
nivf=0
for c in "${fast[@]}"; do
    IFS='|' read -r n cyc <<<"$c"
    [ "$cyc" -le "$ivmax" ] && { submit "icarus_$n" run icarus "$n" f8; nivf=$((nivf + 1)); }
    submit "verilator_$n" run verilator "$n" f8
done
fbp=$(printf '%s\n' "${fast[@]}" | cut -d'|' -f1 | grep tiger | head -n 1); [ -n "$fbp" ] || fbp=${fast[0]%%|*}
submit icarus_fast_bp run icarus "$fbp" f8 20070101
submit verilator_fast_bp run verilator "$fbp" f8 424242

# ---------------------------------------------------------------- 4. refusals
refusal() {      # refusal KIND SIM
    local kind=$1 sim=$2 d=$work/ref_$1_$2 src f line want out rc
    mkdir -p "$d"; src=$work/vec/$bpcase/cmd.stim.hex; f=$d/cmd.stim.hex
    case $kind in
        canvas)   # the FRAME word (the first word) gets a width of W_MAX + 1
            awk -v w=$((WM + 1)) '!/^\/\// && !done { printf "%012x1%06x%s\n", 0, w, substr($0, 20); done = 1; next } { print }' "$src" >"$f" ;;
        edges)    # a shape of E_MAX + 1 EDGE commands
            awk -v n=$((EM + 1)) '/^\/\// { print; next } { c++; if (c == 1) { print; printf "%012x2000000000000000000000000\n", 1; for (i = 0; i < n; i++) printf "%012x3%06x%06x%06x%06x\n", 2 + i, 0, 0, 256, 256; printf "%012x4000000000000000000000000\n", n + 2; exit } }' "$src" >"$f" ;;
        backwards) # the third word's stamp set to 0
            awk '!/^\/\// { c++; if (c == 3) { printf "%012x%s\n", 0, substr($0, 13); next } } { print }' "$src" >"$f" ;;
    esac
    case $kind in
        canvas)    line=$(grep -vn '^//' "$f" | head -n 1 | cut -d: -f1); want="FRAME canvas over" ;;
        edges)     line=$(grep -vn '^//' "$f" | sed -n "$((EM + 3))p" | cut -d: -f1); want="a shape of more EDGE commands than" ;;
        backwards) line=$(grep -vn '^//' "$f" | sed -n 3p | cut -d: -f1); want="cycle stamp does not increase" ;;
    esac
    out=$(sim_run "$sim" 8 +cmd="$f" +out="$d"); rc=$?; echo "$out"
    [ "$rc" != 0 ] && echo "$out" | grep -qF "tb_raster: REFUSED $f:$line: $want" &&
        echo "RESULT PASS refusal $kind ($sim): tb_raster refuses it at $(basename "$f"):$line ($want ...), exit $rc" ||
        echo "RESULT FAIL refusal $kind ($sim): expected 'REFUSED $f:$line: $want' and a non-zero exit (exit $rc)"
}
for k in canvas edges backwards; do
    for sim in icarus verilator; do submit "refusal_${k}_$sim" refusal $k $sim; done
done

# The DUT's own limit checks, which tb_raster's refusals keep from it (issue 27: mutants of
# DEC's and ETM's error paths survived every case): dv/tb/tb_err.v drives ef_raster (W_MAX =
# H_MAX = 16, E_MAX = 8) with FRAMEs of size 0 and over the limits, exactly at them, and shapes
# of E_MAX and E_MAX + 1 edges; err must rise, stick and clear exactly as docs/microarch.md says.
dut_err() {
    local d=$work/err out rc
    mkdir -p "$d"
    iverilog -g2005 -I"$R" -I"$TB" -o "$d/t.vvp" "$TB/tb_err.v" $RTL >"$d/build.log" 2>&1 ||
        { cat "$d/build.log"; echo "RESULT FAIL dut-err (icarus): the build"; return; }
    out=$( (vvp -n "$d/t.vvp" 2>&1) 2>/dev/null); rc=$?
    echo "$out"
    { [ "$rc" = 0 ] && echo "$out" | grep -q '^tb_err: PASS'; } &&
        echo "RESULT PASS dut-err (icarus): $(echo "$out" | sed -n 's/^tb_err: PASS //p'): a FRAME of size 0 or over W_MAX x H_MAX and a shape over E_MAX raise the sticky err (the canvas clamped to 1 x 1), reset clears it" ||
        echo "RESULT FAIL dut-err (icarus): tb_err did not pass (exit $rc)"
}
submit dut_err dut_err

# Every other exit of the bench (docs/testing.md): non-zero with its FAIL
# line for no +cmd, no +out, a command file that is missing or holds no
# command, an output folder that cannot be written, a DUT not ready for a
# command at its stamp; exit 0 with DONE on a good run, which writes exactly
# the six dumps in +out and nothing in the working folder.
exits() {        # exits SIM
    local sim=$1 d=$work/exits_$1 src=$work/vec/$bpcase/cmd.stim.hex out rc k want args files
    mkdir -p "$d/out" "$d/cwd" "$d/ro"; chmod 0555 "$d/ro"
    printf '// no command here\n\n' >"$d/empty.hex"
    # the first command after the first SHAPE_END stamped one cycle after
    # it: the DUT is draining the shape then, so it is not ready
    awk 'function hex(h,   k, v) { v = 0; for (k = 1; k <= length(h); k++) v = v * 16 + index("0123456789abcdef", tolower(substr(h, k, 1))) - 1; return v }
         !/^\/\// && NF { if (late) { printf "%012x%s\n", stamp + 1, substr($0, 13); late = 0; next }
                           if (substr($0, 13, 1) == "4" && !done) { stamp = hex(substr($0, 1, 12)); late = 1; done = 1 } }
         { print }' "$src" >"$d/notready.hex"
    cmp -s "$src" "$d/notready.hex" && { echo "RESULT FAIL exits ($sim): could not make the not-ready stream"; return; }
    for k in nocmd noout missing empty unwritable notready good; do
        case $k in
            nocmd)      args=(+out="$d/out"); want="tb_raster: FAIL no +cmd=FILE" ;;
            noout)      args=(+cmd="$src"); want="tb_raster: FAIL no +out=DIR" ;;
            missing)    args=(+cmd="$d/no-such.hex" +out="$d/out"); want="tb_raster: FAIL cannot open $d/no-such.hex" ;;
            empty)      args=(+cmd="$d/empty.hex" +out="$d/out"); want="tb_raster: FAIL $d/empty.hex holds no command" ;;
            unwritable) args=(+cmd="$src" +out="$d/ro/no-such-dir"); want="tb_raster: FAIL cannot open $d/ro/no-such-dir/seg.actual.hex for writing" ;;
            notready)   args=(+cmd="$d/notready.hex" +out="$d/out"); want="tb_raster: FAIL NS=8: " ;;
            good)       args=(+cmd="$src" +out="$d/out"); want="tb_raster: DONE NS=8: " ;;
        esac
        rm -f "$d"/out/*
        out=$(cd "$d/cwd" && sim_run "$sim" 8 "${args[@]}"); rc=$?
        if ! printf '%s\n' "$out" | grep -qF "$want"; then
            echo "$out" | tail -n 5; echo "RESULT FAIL exits ($sim) $k: no line '$want' (exit $rc)"; return
        fi
        if [ $k = good ]; then
            files=$(cd "$d/out" && for f in *; do printf '%s ' "$f"; done)
            [ "$rc" = 0 ] && [ "$files" = "et_rd.actual.hex et_wr.actual.hex pix.actual.hex plot.actual.hex seg.actual.hex span.actual.hex " ] &&
                [ -z "$(ls -A "$d/cwd")" ] ||
                { echo "RESULT FAIL exits ($sim) good: exit $rc, wrote '$files' and '$(ls -A "$d/cwd")' in the working folder"; return; }
        elif [ "$rc" = 0 ]; then
            echo "RESULT FAIL exits ($sim) $k: '$want' but exit 0"; return
        fi
        echo "$k: exit $rc: $(printf '%s\n' "$out" | grep -F "$want" | head -n 1)"
    done
    echo "RESULT PASS exits ($sim): no +cmd, no +out, a missing or empty command file, an unwritable folder and a DUT not ready at a stamp exit non-zero with their FAIL line; a good run exits 0 (DONE) and writes only the six dumps in +out"
}
for sim in icarus verilator; do submit "exits_$sim" exits $sim; done

# ---------------------------------------------------------------- 5. faults
# first_diff DIR_EXPECTED DIR_ACTUAL: "IFACE CYCLE" of the earliest first
# difference over the interfaces, by plain in-order comparison of the words
# (one line per interface when several first differ at that cycle).
first_diff() {
    local i
    # payload widths P of docs/microarch.md 3: the cycle is the word's bits above P
    for i in seg:97 et_wr:181 et_rd:36 plot:36 span:75 pix:68; do
        awk -v i=${i%:*} -v p=${i#*:} '
            function cycle(w,   b, k, d, c) {
                b = ""
                for (k = 1; k <= length(w); k++) {
                    d = index("0123456789abcdef", tolower(substr(w, k, 1))) - 1
                    b = b (int(d / 8) % 2) (int(d / 4) % 2) (int(d / 2) % 2) (d % 2)
                }
                b = substr(b, 1, length(b) - p); c = 0
                for (k = 1; k <= length(b); k++) c = c * 2 + substr(b, k, 1)
                return c
            }
            FNR == 1 { f++ } /^\/\// || /^$/ { next } f == 1 { e[++ne] = $1 } f == 2 { a[++na] = $1 }
            END { n = ne > na ? ne : na
                  for (k = 1; k <= n; k++) if (e[k] != a[k]) {
                      c = (k <= ne) ? cycle(e[k]) : cycle(a[k])
                      if (k <= na && k <= ne && cycle(a[k]) < c) c = cycle(a[k])
                      printf "%s %.0f\n", i, c; exit } }' \
            "$1/${i%:*}.expected.hex" "$2/${i%:*}.actual.hex"
    done | sort -k2,2n -k1,1 | awk 'NR == 1 { c = $2 } $2 == c'
}
fault() {        # fault NAME CASE IFACE FIELDS [KEY: 8, or f8 for the fast configuration]
    local label=$1 n=$2 want_if=$3 fields=$4 key=${5:-8} v=$work/vec/$2 a=$work/fault_${5:-8}_$1 rc rep got_if got_cyc ind
    [ "$key" = 8 ] || label="$1 (fast configuration)"
    mkdir -p "$a"
    ( vvp -n "$work/iv_${key}_$1/t.vvp" +cmd="$v/cmd.stim.hex" +out="$a" 2>&1 | tail -n 2 ) 2>/dev/null
    "$EF" check "$v" "$a" --cycles --errors 100000 >"$a/check.out" 2>"$a/check.err"; rc=$?
    [ $rc = 1 ] || { echo "RESULT FAIL fault $label: edgeflag check exit $rc, expected 1"; return; }
    # the earliest reported mismatch
    rep=$(grep -E '^[^ ]+: [a-z_]+: cycle [0-9]+' "$a/check.out" | sed -E 's/^[^ ]+: ([a-z_]+): cycle ([0-9]+)(.*)$/\2 \1 \3/' | sort -n -k1,1 | head -n 1)
    got_cyc=${rep%% *}; rep=${rep#* }; got_if=${rep%% *}
    ind=$(first_diff "$v" "$a"); local ind1
    ind1=$(printf '%s\n' "$ind" | paste -sd, -)
    echo "earliest reported: $got_if cycle $got_cyc: ${rep#* }"; echo "independent first difference: $ind1"
    [ "$got_if" = "$want_if" ] || { echo "RESULT FAIL fault $label: first mismatch on $got_if, expected $want_if"; return; }
    # check places a pair at its expected cycle and names the actual one too
    # ("and the cycle: expected C1, actual C2"); an extra one at its actual cycle
    local alt
    alt=$(echo "$rep" | sed -n 's/.*and the cycle: expected [0-9]*, actual \([0-9]*\).*/\1/p')
    if ! printf '%s\n' "$ind" | grep -qx "$got_if $got_cyc" && { [ -z "$alt" ] || ! printf '%s\n' "$ind" | grep -qx "$got_if $alt"; }; then
        echo "RESULT FAIL fault $label: reported at $got_if $got_cyc${alt:+ (actual $alt)}, the files first differ at $ind1"; return
    fi
    local ok=0 fld
    # a field marked as differing; "extra": a whole extra transaction (a span
    # that should not exist: the pad fault makes a zero winding look covered)
    for fld in ${fields//,/ }; do
        [ "$fld" = extra ] && { echo "$rep" | grep -q 'extra transaction: actual' && ok=1; continue; }
        echo "$rep" | grep -qE "actual .*\b$fld=[^ ;]*\*" && ok=1
    done
    [ "$fields" = "-" ] && echo "$rep" | grep -qE 'missing transaction|extra transaction|fields differ|cycle differs' && ok=1
    [ $ok = 1 ] || { echo "RESULT FAIL fault $label: none of the fields $fields is marked as differing"; return; }
    echo "RESULT PASS fault $label: edgeflag check fails; first mismatch on $got_if at cycle $got_cyc (the files' first difference): $(echo "${rep#* }" | cut -c1-160) ($n)"
}
collect
# The fault cases need vectors at 8 samples: the tiger for most, gen's directed cases for the rest.
for x in "tiger|$root/tests/data/svg/tiger.svg|scene|32x24" "tiger_nz|$root/tests/data/svg/tiger.svg|nonzero|32x24"; do
    IFS='|' read -r n i rule size <<<"$x"; vectors "f_$n" "$i" 8 "$rule" "$size"
done
for nm in outside-crossing slope-1-sample-per-row; do
    f=$(awk -F'\t' -v n=$nm '$5 == n { print $2 }' "$work/gen/index.tsv"); vectors "f_$nm" "$work/gen/$f" 8 scene -
    vectors "ff_$nm" "$work/gen/$f" 8 scene - overlap
done
for x in "tiger|$root/tests/data/svg/tiger.svg|scene|32x24" "tiger_nz|$root/tests/data/svg/tiger.svg|nonzero|32x24" \
         "tiger64|$root/tests/data/svg/tiger.svg|scene|64x48"; do
    IFS='|' read -r n i rule size <<<"$x"; vectors "ff_$n" "$i" 8 "$rule" "$size" overlap
done
submit fault_rooks     fault rooks     f_tiger plot q
submit fault_pad       fault pad       f_tiger_nz span mask,x,len,extra
submit fault_topclip   fault topclip   f_outside-crossing et_wr r0,x,e,slot
submit fault_lastedge  fault lastedge  f_tiger plot -
submit fault_divfloor  fault div_floor f_tiger et_wr x,e,qs,rs
submit fault_sbring    fault sb_ring   f_tiger et_wr x,e,qs,rs,dy
submit fault_fwd       fault fwd       f_tiger span -
submit fault_span      fault span      f_tiger span len
submit fault_f_rooks     fault rooks     ff_tiger plot q f8
submit fault_f_pad       fault pad       ff_tiger_nz span mask,x,len,extra f8
submit fault_f_topclip   fault topclip   ff_outside-crossing et_wr r0,x,e,slot f8
submit fault_f_lastedge  fault lastedge  ff_tiger plot - f8
submit fault_f_divfloor  fault div_floor ff_tiger et_wr x,e,qs,rs f8
submit fault_f_sbring    fault sb_ring   ff_tiger et_wr x,e,qs,rs,dy f8
submit fault_f_fwd       fault fwd       ff_tiger span - f8
submit fault_f_span      fault span      ff_tiger span len f8
submit fault_f_skipstart fault skipstart ff_tiger span x f8
submit fault_f_spanq     fault spanq     ff_tiger64 span - f8
collect

echo "rtl-test: ${#cases[@]} cases in Verilator, $niv of them in Icarus; the fast configuration ${#fast[@]} in Verilator, $nivf in Icarus; $(( $(date +%s) - t_start )) s"
echo "rtl-test: $pass passed, $fail failed"
[ $fail = 0 ]
