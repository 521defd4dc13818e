#!/usr/bin/env bash
# tests/rtl/run.sh - the vector files in a real hardware flow (issue 5): real
# simulators read them, and an RTL block written from docs/microarch.md alone
# reproduces the model's spans cycle for cycle.
#
#   1. lint: `verilator --lint-only -Wall` of rtl/ (ef_slb_fill +
#      ef_slb_ram) at NS = 8, 16, 32 and a small W_MAX must be silent, and
#      Icarus must compile it as Verilog-2005 without a warning;
#   2. $readmemh round trip: dv/tb/tb_readmem.v loads every interface's
#      hex file of a tiger vector set (160x120, 8 samples), and of gen's
#      empty-scene (every interface but cmd empty), with $readmemh,
#      checks the header's interface, word width and count against the
#      manifest, that exactly that many words were loaded, and that cycle
#      stamps strictly increase; it writes every word back with
#      $fwrite("%h\n"), and `edgeflag check` must pass on each pair:
#      under Icarus (one -P build per interface) and under Verilator (one -G
#      build of tb_readmem_all.v, seven instances); negative controls: a
#      file with one word dropped, two stamps swapped, or the wrong width
#      must FAIL the testbench;
#   3. SLB + FILL in RTL (rtl/ef_slb_fill.v) replays
#      plot.expected.hex at the stamped cycles with the canvas width and
#      rules from cmd.stim.hex, records its spans (dv/tb/tb_slb_fill.v),
#      and `edgeflag check span.expected.hex span.actual.hex --cycles` must
#      pass: the tiger at 160x120 and directed + random `edgeflag gen`
#      level-1 cases, each at 8/16/32 samples x nonzero/evenodd (and the
#      scenes' own mixed rules where they mix them), under Icarus; the tiger
#      once more under Verilator;
#   4. the bench can fail: the RTL without its write-to-read forwarding must
#      fail --cycles; a COV that takes one more cycle per span (an RTL with
#      other timing) must fail --cycles and pass --transactions;
#   5. DEC, SETUP (with its divider) and ETM, each fed from its upstream
#      interface's expected hex, reproduce seg, et_wr and et_rd cycle for
#      cycle (tests/rtl/blocks_a.sh says what runs).
#
# usage: bash tests/rtl/run.sh BUILD_DIR   (`make test-rtl`; EF_RTL_JOBS,
#        default the number of CPUs; TMPDIR; EF_RTL_KEEP=1 keeps the work
#        directory, every job's log in logs/ ending with its run time)
# Skips (exit 0, saying so) only when Icarus Verilog is not installed; the
# Verilator parts are skipped, with a message, when verilator is missing.
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
# shellcheck disable=SC2086 # the RTL file lists ($RTL, $A_*) are split into words on purpose
set -u
export LC_ALL=C

build=${1:?usage: tests/rtl/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
RTL="$root/rtl/ef_slb_fill.v $root/rtl/ef_slb_ram.v"
RI=$root/rtl      # the include folder (ef_ifaces.vh, ef_ns.vh)
TB=$root/dv/tb
jobs=${EF_RTL_JOBS:-$(nproc 2>/dev/null || echo 2)}

if ! command -v iverilog >/dev/null 2>&1 || ! command -v vvp >/dev/null 2>&1; then
    echo "test-rtl: SKIPPED: Icarus Verilog (iverilog, vvp) is not installed;" \
         "'make deps-test' (tools/install-deps.sh test) installs it"
    exit 0
fi
have_vl=0
command -v verilator >/dev/null 2>&1 && have_vl=1
[ -x "$EF" ] || { echo "test-rtl: $EF not built (make cli)"; exit 1; }

# The vectors are written atomically with fsync: a RAM disk keeps that cheap.
tmpbase=${TMPDIR:-}
if [ -z "$tmpbase" ]; then
    tmpbase=/tmp
    [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
fi
work=$(mktemp -d "$tmpbase/edgeflag-rtl.XXXXXX") || exit 1
if [ -n "${EF_RTL_KEEP:-}" ]; then
    echo "test-rtl: keeping $work (EF_RTL_KEEP)"
else
    trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work/logs" "$work/vec"

echo "test-rtl: $(iverilog -V 2>&1 | head -n 1)"
if [ $have_vl = 1 ]; then
    echo "test-rtl: $(verilator --version)"
else
    echo "test-rtl: verilator not installed: its lint and runs are SKIPPED"
fi

# ---------------------------------------------------------------- job pool
# Each job is a function run in the background with its output in
# logs/NAME.log; its verdict is the last "RESULT PASS|FAIL ..." line.
order=()
submit() {
    local name=$1; shift
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
    ( TIMEFORMAT="job time %R s real, %U s user"; time "$@" ) >"$work/logs/$name.log" 2>&1 &
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
            fail=$((fail + 1))
            echo "FAIL $n: ${v#RESULT FAIL }"
            tail -n 15 "$work/logs/$n.log" | sed 's/^/    /'
        fi
    done
    order=()
}

# count FILE: the "// count N" header line
count() { sed -n 's|^// count \([0-9]*\).*|\1|p' "$1" | head -n 1; }
# mf DIR IFACE bits|count: from manifest.json's interface table
mf() {
    local sp='[[:space:]]*'
    sed -n "s/.*{$sp\"name\":$sp\"$2\",$sp\"bits\":$sp\([0-9]*\),$sp\"count\":$sp\([0-9]*\)$sp}.*/\1 \2/p" \
        "$1/manifest.json" | head -n 1 | { read -r b c; [ "$3" = bits ] && echo "$b" || echo "$c"; }
}
expected_file() { [ "$2" = cmd ] && echo "$1/cmd.stim.hex" || echo "$1/$2.expected.hex"; }

# ---------------------------------------------------------------- 1. lint
lint() {
    local ns=$1 w=$2 out
    if [ $have_vl = 1 ]; then
        out=$(verilator --lint-only -Wall -I"$RI" -GNS="$ns" -GW_MAX="$w" --top-module ef_slb_fill $RTL 2>&1)
        [ -z "$out" ] || { echo "$out"; echo "RESULT FAIL lint NS=$ns W_MAX=$w: verilator -Wall is not silent"; return; }
    fi
    out=$(iverilog -g2005 -Wall -I"$RI" -Pef_slb_fill.NS="$ns" -Pef_slb_fill.W_MAX="$w" -s ef_slb_fill -o /dev/null $RTL 2>&1)
    [ -z "$out" ] || { echo "$out"; echo "RESULT FAIL lint NS=$ns W_MAX=$w: iverilog -g2005 -Wall is not silent"; return; }
    if [ $have_vl = 1 ]; then
        echo "RESULT PASS lint NS=$ns W_MAX=$w: verilator --lint-only -Wall and iverilog -g2005 -Wall silent"
    else
        echo "RESULT PASS lint NS=$ns W_MAX=$w: iverilog -g2005 -Wall silent (verilator SKIPPED)"
    fi
}
for ns in 8 16 32; do submit "lint_$ns" lint "$ns" 16384; done
submit lint_32_160 lint 32 160

# ---------------------------------------------------------------- vectors
tiger=$root/tests/data/svg/tiger.svg
T=$work/vec/tiger
if ! "$EF" vectors "$tiger" -o "$T" --size 160x120 --samples 8 >"$work/logs/vectors_tiger.log" 2>&1; then
    cat "$work/logs/vectors_tiger.log"; echo "test-rtl: edgeflag vectors failed on the tiger"; exit 1
fi
# a small set for the benches' exit tests (section "exits")
if ! "$EF" vectors "$tiger" -o "$work/vec/small" --size 32x24 --samples 8 >"$work/logs/vectors_small.log" 2>&1; then
    cat "$work/logs/vectors_small.log"; echo "test-rtl: edgeflag vectors failed on the tiger at 32x24"; exit 1
fi
"$EF" gen -o "$work/gen" >"$work/logs/gen.log" 2>&1 || { cat "$work/logs/gen.log"; exit 1; }

# ---------------------------------------------------------------- 2. $readmemh
ifaces="cmd seg et_wr et_rd plot span pix"

# readmem_iv DIR IFACE OUTDIR: Icarus, tb_readmem.v with -P, then edgeflag check
readmem_iv() {
    local d=$1 i=$2 o=$3 in bits n
    in=$(expected_file "$d" "$i"); bits=$(mf "$d" "$i" bits); n=$(mf "$d" "$i" count)
    [ -n "$bits" ] && [ -n "$n" ] || { echo "RESULT FAIL readmem/icarus $i: no bits/count for $i in $d/manifest.json"; return; }
    mkdir -p "$o"
    iverilog -g2005 -o "$o/$i.vvp" -Ptb_readmem.P="$bits" -Ptb_readmem.DEPTH="$n" \
        -Ptb_readmem.IFACE="\"$i\"" -Ptb_readmem.IN_FILE="\"$in\"" \
        -Ptb_readmem.OUT_FILE="\"$o/$i.actual.hex\"" "$TB/tb_readmem.v" ||
        { echo "RESULT FAIL readmem/icarus $i: compile"; return; }
    vvp -n "$o/$i.vvp" >"$o/$i.sim" 2>&1; cat "$o/$i.sim"
    grep -q "^tb_readmem $i: PASS" "$o/$i.sim" || { echo "RESULT FAIL readmem/icarus $i: testbench"; return; }
    # The guard word past DEPTH is meant to stay unread; any other $readmemh
    # complaint (excess digits, bad characters) is a format problem.
    if grep -i warning "$o/$i.sim" | grep -vq 'Not enough words'; then
        echo "RESULT FAIL readmem/icarus $i: \$readmemh warned"; return
    fi
    "$EF" check "$in" "$o/$i.actual.hex" --cycles ||
        { echo "RESULT FAIL readmem/icarus $i: edgeflag check on the \$fwrite dump"; return; }
    echo "RESULT PASS readmem/icarus $(basename "$d") $i: $n words of $((48 + bits)) bits read by \$readmemh, written back by \$fwrite, edgeflag check --cycles passes"
}
for i in $ifaces; do submit "readmem_iv_$i" readmem_iv "$T" "$i" "$work/rm_iv"; done
# A set whose interfaces are empty but for cmd (gen's empty-scene): DEPTH 0.
E=$work/vec/empty-scene
f=$(awk -F'\t' '$3 == "directed" && $5 == "empty-scene" { print $2; exit }' "$work/gen/index.tsv")
if [ -n "$f" ] && "$EF" vectors "$work/gen/$f" -o "$E" >"$work/logs/vectors_empty.log" 2>&1; then
    for i in $ifaces; do submit "readmem_iv_empty_$i" readmem_iv "$E" "$i" "$work/rm_iv_empty"; done
else
    echo "FAIL readmem/icarus empty-scene: no vectors"; fail=$((fail + 1))
fi

# Negative controls: the testbench must notice a damaged file.
readmem_neg() {
    local d=$1 kind=$2 o=$work/neg_$2 f bits n
    mkdir -p "$o"; f=$o/plot.expected.hex; bits=36; n=$(mf "$d" plot count)
    case $kind in
        drop)  awk '!/^\/\// && !done { done = 1; next } { print }' "$d/plot.expected.hex" >"$f" ;;
        swap)  awk '!/^\/\// { k++; if (k == 2) { held = $0; next } if (k == 3) { print; print held; next } } { print }' \
                   "$d/plot.expected.hex" >"$f" ;;
        width) cp "$d/plot.expected.hex" "$f"; bits=35 ;;
    esac
    iverilog -g2005 -o "$o/t.vvp" -Ptb_readmem.P="$bits" -Ptb_readmem.DEPTH="$n" -Ptb_readmem.IFACE='"plot"' \
        -Ptb_readmem.IN_FILE="\"$f\"" -Ptb_readmem.OUT_FILE="\"$o/out.hex\"" "$TB/tb_readmem.v" ||
        { echo "RESULT FAIL readmem/negative $kind: compile"; return; }
    vvp -n "$o/t.vvp" 2>&1 | head -n 5 | tee "$o/sim"
    if grep -q '^tb_readmem plot: FAIL' "$o/sim"; then
        echo "RESULT PASS readmem/negative $kind: tb_readmem fails as it should ($(grep -m1 'error:' "$o/sim" | sed 's/.*error: //'))"
    else
        echo "RESULT FAIL readmem/negative $kind: tb_readmem did not notice"
    fi
}
for k in drop swap width; do submit "readmem_neg_$k" readmem_neg "$T" "$k"; done

# Verilator: one build of the seven-instance wrapper, -G for every count.
readmem_vl() {
    local d=$1 o=$work/rm_vl i g=() in
    mkdir -p "$o"
    g+=(-GDIR="\"$d\"" -GOUT="\"$o\"")
    g+=(-GD_CMD="$(mf "$d" cmd count)" -GD_SEG="$(mf "$d" seg count)" -GD_ET_WR="$(mf "$d" et_wr count)")
    g+=(-GD_ET_RD="$(mf "$d" et_rd count)" -GD_PLOT="$(mf "$d" plot count)" -GD_SPAN="$(mf "$d" span count)")
    g+=(-GD_PIX="$(mf "$d" pix count)")
    verilator --binary --timing -Wno-fatal -Wno-WIDTH --Mdir "$o/obj" --top-module tb_readmem_all "${g[@]}" \
        "$TB/tb_readmem_all.v" "$TB/tb_readmem.v" -o tb >"$o/build.log" 2>&1 ||
        { tail -n 20 "$o/build.log"; echo "RESULT FAIL readmem/verilator: build"; return; }
    "$o/obj/tb" >"$o/sim" 2>&1; cat "$o/sim"
    for i in $ifaces; do
        in=$(expected_file "$d" "$i")
        grep -q "^tb_readmem $i: PASS" "$o/sim" || { echo "RESULT FAIL readmem/verilator $i: testbench"; return; }
        "$EF" check "$in" "$o/$i.actual.hex" --cycles ||
            { echo "RESULT FAIL readmem/verilator $i: edgeflag check on the \$fwrite dump"; return; }
    done
    echo "RESULT PASS readmem/verilator: all 7 interfaces read by \$readmemh, written back by \$fwrite, edgeflag check --cycles passes on each"
}
[ $have_vl = 1 ] && submit readmem_vl readmem_vl "$T"

# ---------------------------------------------------------------- 3. SLB+FILL
# slb NAME INPUT NS RULE [vectors options...]: make the vectors (cmd, plot,
# span), run the RTL bench under Icarus, check --cycles and --transactions.
slb() {
    local name=$1 input=$2 ns=$3 rule=$4; shift 4
    local d=$work/slb/$name np nc sim
    mkdir -p "$d"
    # rule "scene": each shape's own rule (cfg_rule then changes per shape)
    [ "$rule" = scene ] || set -- --rule "$rule" "$@"
    "$EF" vectors "$input" -o "$d" --samples "$ns" --formats hex \
        --interfaces cmd,plot,span "$@" >"$d/vectors.log" 2>&1 ||
        { cat "$d/vectors.log"; echo "RESULT FAIL slb $name: edgeflag vectors"; return; }
    np=$(count "$d/plot.expected.hex"); nc=$(count "$d/cmd.stim.hex")
    iverilog -g2005 -I"$RI" -I"$TB" -o "$d/slb.vvp" -Ptb_slb_fill.NS="$ns" -Ptb_slb_fill.NPLOT="$np" \
        -Ptb_slb_fill.NCMD="$nc" "$TB/tb_slb_fill.v" $RTL ||
        { echo "RESULT FAIL slb $name: compile"; return; }
    vvp -n "$d/slb.vvp" +plot="$d/plot.expected.hex" +cmd="$d/cmd.stim.hex" \
        +span="$d/span.actual.hex" >"$d/sim" 2>&1
    cat "$d/sim"
    sim=$(grep -E '^tb_slb_fill: (DONE|FAIL)' "$d/sim")
    [ "${sim#tb_slb_fill: DONE}" != "$sim" ] || { echo "RESULT FAIL slb $name: testbench"; return; }
    "$EF" check "$d/span.expected.hex" "$d/span.actual.hex" --cycles ||
        { "$EF" check "$d/span.expected.hex" "$d/span.actual.hex" --transactions >/dev/null 2>&1 &&
              echo "RESULT FAIL slb $name: --cycles fails but --transactions passes (timing differs)" ||
              echo "RESULT FAIL slb $name: spans differ in content"; return; }
    echo "RESULT PASS slb $name: $np plots -> $(count "$d/span.expected.hex") spans cycle-exact (edgeflag check --cycles)"
}
for ns in 8 16 32; do
    for r in nonzero evenodd; do
        submit "slb_tiger_${ns}_$r" slb "tiger-160x120/$ns/$r" "$tiger" "$ns" "$r" --size 160x120
    done
done

# Directed corner cases by name (numbers may move when the table grows),
# then the first random cases.
directed="sample-points sample-columns vertical-sample-columns slope-1-sample-per-row near-horizontal
          spike identical-evenodd bow-tie overflow-128 overflow-nested-130 overflow-staggered-128
          outside-all-sides outside-left-partial border-strips border-sample-rows right-sink
          canvas-1x1 canvas-max-wide many-shapes"
cases=()
for n in $directed; do
    f=$(awk -F'\t' -v n="$n" '$3 == "directed" && $5 == n { print $2; exit }' "$work/gen/index.tsv")
    if [ -z "$f" ]; then echo "FAIL gen: no directed case named $n in index.tsv"; fail=$((fail + 1)); continue; fi
    cases+=("$n:$f")
done
for f in $(awk -F'\t' '$3 == "random" { print $2 }' "$work/gen/index.tsv" | head -n 3); do
    cases+=("random-${f%.scene}:$f")
done
for c in "${cases[@]}"; do
    rules="nonzero evenodd"
    # Scenes mixing both rules also run with their own rules, so that the
    # rule switches between shapes of one frame.
    case ${c%%:*} in many-shapes|random-*) rules="$rules scene" ;; esac
    for ns in 8 16 32; do
        for r in $rules; do
            submit "slb_${c%%:*}_${ns}_$r" slb "${c%%:*}/$ns/$r" "$work/gen/${c#*:}" "$ns" "$r"
        done
    done
done

# The same RTL and bench under Verilator (2-state, another scheduler).
slb_vl() {
    local ns=$1 rule=$2 d=$work/slb_vl np nc
    mkdir -p "$d"
    "$EF" vectors "$tiger" -o "$d" --samples "$ns" --rule "$rule" --size 160x120 --formats hex \
        --interfaces cmd,plot,span >"$d/vectors.log" 2>&1 || { echo "RESULT FAIL slb/verilator: vectors"; return; }
    np=$(count "$d/plot.expected.hex"); nc=$(count "$d/cmd.stim.hex")
    verilator --binary --timing -Wno-fatal -Wno-WIDTH -I"$RI" -I"$TB" --Mdir "$d/obj" --top-module tb_slb_fill \
        -GNS="$ns" -GNPLOT="$np" -GNCMD="$nc" "$TB/tb_slb_fill.v" $RTL -o tb >"$d/build.log" 2>&1 ||
        { tail -n 20 "$d/build.log"; echo "RESULT FAIL slb/verilator: build"; return; }
    "$d/obj/tb" +plot="$d/plot.expected.hex" +cmd="$d/cmd.stim.hex" +span="$d/span.actual.hex" >"$d/sim" 2>&1
    cat "$d/sim"
    grep -q '^tb_slb_fill: DONE' "$d/sim" || { echo "RESULT FAIL slb/verilator: testbench"; return; }
    "$EF" check "$d/span.expected.hex" "$d/span.actual.hex" --cycles ||
        { echo "RESULT FAIL slb/verilator tiger-160x120/$ns/$rule: edgeflag check --cycles"; return; }
    echo "RESULT PASS slb/verilator tiger-160x120/$ns/$rule: $np plots -> $(count "$d/span.expected.hex") spans cycle-exact"
}
[ $have_vl = 1 ] && submit slb_vl slb_vl 16 nonzero

# ---------------------------------------------------------------- 4. mutants
mutant() {
    local kind=$1 d=$work/mut_$1 np nc rtl=$RTL inc=$RI lag=0 elastic=0 rc_c rc_t
    mkdir -p "$d"
    "$EF" vectors "$tiger" -o "$d" --samples 8 --size 160x120 --formats hex \
        --interfaces cmd,plot,span >"$d/vectors.log" 2>&1 || { echo "RESULT FAIL mutant $kind: vectors"; return; }
    np=$(count "$d/plot.expected.hex"); nc=$(count "$d/cmd.stim.hex")
    case $kind in
        no-forwarding)
            # The read-first RAM then misses the write made at the same edge
            # (the RTL variant of dv/faults/fwd.sed).
            bash "$root/dv/rtl-variant.sh" "$d/rtl" fwd || { echo "RESULT FAIL mutant $kind: the variant"; return; }
            inc=$d/rtl rtl="$d/rtl/ef_slb_fill.v $d/rtl/ef_slb_ram.v" ;;
        cov-lag) lag=1; elastic=1 ;;
    esac
    iverilog -g2005 -I"$inc" -I"$TB" -o "$d/slb.vvp" -Ptb_slb_fill.NS=8 -Ptb_slb_fill.NPLOT="$np" -Ptb_slb_fill.NCMD="$nc" \
        -Ptb_slb_fill.COV_LAG="$lag" -Ptb_slb_fill.ELASTIC="$elastic" "$TB/tb_slb_fill.v" $rtl || { echo "RESULT FAIL mutant $kind: compile"; return; }
    vvp -n "$d/slb.vvp" +plot="$d/plot.expected.hex" +cmd="$d/cmd.stim.hex" +span="$d/span.actual.hex" >"$d/sim" 2>&1
    cat "$d/sim"
    "$EF" check "$d/span.expected.hex" "$d/span.actual.hex" --cycles --errors 3; rc_c=$?
    "$EF" check "$d/span.expected.hex" "$d/span.actual.hex" --transactions --errors 3; rc_t=$?
    case $kind in
        no-forwarding)
            [ $rc_c = 1 ] && [ $rc_t = 1 ] &&
                echo "RESULT PASS mutant $kind: the RTL without forwarding fails --cycles and --transactions (exit 1)" ||
                echo "RESULT FAIL mutant $kind: check exit $rc_c (--cycles), $rc_t (--transactions); expected 1, 1" ;;
        cov-lag)
            [ $rc_c = 1 ] && [ $rc_t = 0 ] &&
                echo "RESULT PASS mutant $kind: a COV one cycle slower per span fails --cycles (exit 1), passes --transactions" ||
                echo "RESULT FAIL mutant $kind: check exit $rc_c (--cycles), $rc_t (--transactions); expected 1, 0" ;;
    esac
}
submit mutant_no_forwarding mutant no-forwarding
submit mutant_cov_lag mutant cov-lag

# ---------------------------------------------------------------- exits
# Every block bench (tb_dec, tb_setup, tb_etm, tb_slb_fill, tb_backend) and the
# $readmemh reader (tb_readmem) under each simulator: exit 0 with its DONE or
# PASS line on a good run; non-zero with its FAIL line for no plusargs at all
# (then it writes nothing in its working folder), an input that is not there,
# an output that cannot be written, and an input it refuses or that fails its
# check (two cycle stamps swapped).  Icarus builds each bench here; Verilator
# reuses the block-bench and tb_slb_fill builds of the runs above (blk_vl,
# slb_vl) and builds tb_readmem and tb_backend.  tb_backend's good run is also
# checked by `edgeflag check --cycles` on et_rd, plot, span and pix.
# swap2 IN OUT: the file with its second and third words swapped
swap2() { awk '!/^\/\// && NF { k++; if (k == 2) { held = $0; next } if (k == 3) { print; print held; next } } { print }' "$1" >"$2"; }
# exits_case SIM BIN NAME WANT ARGS...: run in an empty folder, stderr closed
# (a Verilator $fatal aborts); WANT: ok | fail; prints a line, returns 1 on a wrong exit
exits_case() {
    local sim=$1 bin=$2 name=$3 want=$4 tb=${2##*/} c out rc; shift 4
    c=$(mktemp -d "$work/exits_cwd.XXXXXX")
    if [ "$sim" = iv ]; then out=$( (cd "$c" && vvp -n "$bin" "$@" 2>&1) 2>/dev/null ); rc=$?
    else out=$( (cd "$c" && "$bin" "$@" 2>&1) 2>/dev/null ); rc=$?; fi
    tb=$(printf '%s\n' "$out" | grep -Eo '^tb_[a-z_]+' | head -n 1)
    if [ "$want" = ok ]; then
        { [ $rc = 0 ] && printf '%s\n' "$out" | grep -Eq "^$tb( [a-z_]+)?: (DONE|PASS)"; } ||
            { printf '%s\n' "$out" | tail -n 3; echo "$name: exit $rc, expected 0 with DONE/PASS"; return 1; }
    else
        { [ $rc != 0 ] && printf '%s\n' "$out" | grep -Eq '^tb_[a-z_]+( [a-z_]+)?: FAIL'; } ||
            { printf '%s\n' "$out" | tail -n 3; echo "$name: exit $rc, expected non-zero with a FAIL line"; return 1; }
        [ -z "$(ls -A "$c")" ] || { echo "$name: wrote $(ls -A "$c") in its working folder"; return 1; }
    fi
    echo "$name: exit $rc: $(printf '%s\n' "$out" | grep -E '^tb_[a-z_]+( [a-z_]+)?: (FAIL|DONE|PASS)' | head -n 1 | cut -c1-110)"
    rm -rf "$c"
}
# exits_bench SIM TB BIN VEC: the five cases of one bench, its plusargs for vector set VEC
exits_bench() {
    local sim=$1 tb=$2 bin=$3 v=$4 d=$work/exits_$1 in out io=() inp outp
    case $tb in
        tb_dec)      inp=cmd;      in=$v/cmd.stim.hex;      outp=seg
                     io=(+cmd="$v/cmd.stim.hex") ;;
        tb_setup)    inp=seg_in;   in=$v/seg.expected.hex;  outp=et_wr
                     io=(+seg_in="$v/seg.expected.hex" +cmd="$v/cmd.stim.hex") ;;
        tb_etm)      inp=et_wr_in; in=$v/et_wr.expected.hex; outp=et_rd
                     io=(+et_wr_in="$v/et_wr.expected.hex" +et_rd_exp="$v/et_rd.expected.hex" +plot="$v/plot.expected.hex") ;;
        tb_slb_fill) inp=plot;     in=$v/plot.expected.hex; outp=span
                     io=(+plot="$v/plot.expected.hex" +cmd="$v/cmd.stim.hex") ;;
        tb_readmem)  inp=in;       in=$v/plot.expected.hex; outp=out; io=() ;;
        tb_backend)  inp=etw;      in=$v/et_wr.expected.hex; outp=out
                     io=(+cmd="$v/cmd.stim.hex") ;;
    esac
    # the input that changes replaces its own plusarg
    local rest=() a
    for a in "${io[@]}"; do [ "${a%%=*}" = "+$inp" ] || rest+=("$a"); done
    mkdir -p "$d/$tb.out"; swap2 "$in" "$d/$tb.swapped"
    if [ "$tb" = tb_backend ]; then out=$d/$tb.out; else out=$d/$tb.out/$outp.actual.hex; fi
    exits_case "$sim" "$bin" "$sim $tb good" ok "${rest[@]}" +"$inp=$in" +"$outp=$out" || return 1
    if [ "$tb" = tb_backend ]; then
        "$EF" check "$v" "$out" --cycles --interfaces et_rd,plot,span,pix --errors 3 ||
            { echo "$sim tb_backend: edgeflag check --cycles on its dumps failed"; return 1; }
    fi
    exits_case "$sim" "$bin" "$sim $tb no plusargs" fail || return 1
    exits_case "$sim" "$bin" "$sim $tb missing input" fail "${rest[@]}" +"$inp=$d/no-such.hex" +"$outp=$out" || return 1
    exits_case "$sim" "$bin" "$sim $tb unwritable output" fail "${rest[@]}" +"$inp=$in" +"$outp=$d/no-such-dir/x" || return 1
    exits_case "$sim" "$bin" "$sim $tb stamps swapped" fail "${rest[@]}" +"$inp=$d/$tb.swapped" +"$outp=$out" || return 1
}
# bench_exits_iv: Icarus, one build per bench on a small set (the tiger at 32x24, 8 samples)
bench_exits_iv() {
    local d=$work/exits_iv T=$work/vec/small tb files good
    mkdir -p "$d"
    for tb in tb_dec tb_setup tb_etm tb_slb_fill tb_readmem tb_backend; do
        case $tb in
            tb_dec)   files="$root/rtl/ef_dec.v"; good="-Ptb_dec.NCMD=$(count "$T/cmd.stim.hex")" ;;
            tb_setup) files="$root/rtl/ef_setup.v $root/rtl/ef_div.v $root/rtl/ef_slb_ram.v"
                      good="-Ptb_setup.NCMD=$(count "$T/cmd.stim.hex") -Ptb_setup.NSEG=$(count "$T/seg.expected.hex")" ;;
            tb_etm)   files="$root/rtl/ef_etm.v $root/rtl/ef_slb_ram.v"
                      good="-Ptb_etm.H_MAX=256 -Ptb_etm.NWR=$(count "$T/et_wr.expected.hex") -Ptb_etm.NRD=$(count "$T/et_rd.expected.hex") -Ptb_etm.NPLOT=$(count "$T/plot.expected.hex")" ;;
            tb_slb_fill) files="$root/rtl/ef_slb_fill.v $root/rtl/ef_slb_ram.v"
                      good="-Ptb_slb_fill.NPLOT=$(count "$T/plot.expected.hex") -Ptb_slb_fill.NCMD=$(count "$T/cmd.stim.hex")" ;;
            tb_readmem) files=""
                      # shellcheck disable=SC2089 # the quotes are iverilog's: a string parameter
                      good="-Ptb_readmem.P=36 -Ptb_readmem.DEPTH=$(count "$T/plot.expected.hex") -Ptb_readmem.IFACE=\"plot\"" ;;
            tb_backend) files="$root/rtl/ef_etm.v $root/rtl/ef_aet.v $root/rtl/ef_plot.v $root/rtl/ef_slb_fill.v $root/rtl/ef_slb_ram.v $root/rtl/ef_cov.v"
                      good="-Ptb_backend.W_MAX=256 -Ptb_backend.H_MAX=256 -Ptb_backend.NCMD=$(count "$T/cmd.stim.hex") -Ptb_backend.NETW=$(count "$T/et_wr.expected.hex")" ;;
        esac
        # shellcheck disable=SC2086,SC2090 # the lists split on purpose
        iverilog -g2005 -I"$RI" -I"$TB" $good -o "$d/$tb" "$TB/$tb.v" $files >"$d/$tb.build" 2>&1 ||
            { cat "$d/$tb.build"; echo "RESULT FAIL exits icarus $tb: compile"; return; }
        exits_bench iv "$tb" "$d/$tb" "$T" || { echo "RESULT FAIL exits icarus $tb"; return; }
    done
    echo "RESULT PASS exits (Icarus): tb_dec, tb_setup, tb_etm, tb_slb_fill, tb_readmem and tb_backend exit 0 on a good run (tb_backend's dumps pass edgeflag check --cycles) and non-zero with their FAIL line for no plusargs (writing nothing), a missing input, an unwritable output, stamps swapped"
}
submit bench_exits_iv bench_exits_iv
# bench_exits_vl: Verilator, after blk_vl and slb_vl (run after the first collect)
bench_exits_vl() {
    local d=$work/exits_vl L=$work/blk/vl/lion-40x30/16/nonzero T=$work/vec/small tb bin v
    mkdir -p "$d"
    verilator --binary --timing -Wno-fatal -Wno-WIDTH --Mdir "$d/rm" --top-module tb_readmem -GP=36 \
        -GDEPTH="$(count "$T/plot.expected.hex")" -GIFACE='"plot"' "$TB/tb_readmem.v" -o tb_readmem >"$d/rm.build" 2>&1 ||
        { tail -n 20 "$d/rm.build"; echo "RESULT FAIL exits verilator tb_readmem: build"; return; }
    # shellcheck disable=SC2086 # the file list splits on purpose
    verilator --binary --timing -Wno-fatal -Wno-WIDTH -I"$RI" -I"$TB" --Mdir "$d/be" --top-module tb_backend -GW_MAX=256 \
        -GH_MAX=256 -GNCMD="$(count "$T/cmd.stim.hex")" -GNETW="$(count "$T/et_wr.expected.hex")" "$TB/tb_backend.v" \
        $root/rtl/ef_etm.v $root/rtl/ef_aet.v $root/rtl/ef_plot.v $root/rtl/ef_slb_fill.v $root/rtl/ef_slb_ram.v \
        $root/rtl/ef_cov.v -o tb_backend >"$d/be.build" 2>&1 ||
        { tail -n 20 "$d/be.build"; echo "RESULT FAIL exits verilator tb_backend: build"; return; }
    for tb in tb_dec tb_setup tb_etm tb_slb_fill tb_readmem tb_backend; do
        case $tb in
            tb_dec | tb_setup | tb_etm) bin=$L/vl-$tb/obj/tb; v=$L ;;
            tb_slb_fill) bin=$work/slb_vl/obj/tb; v=$work/slb_vl ;;
            tb_readmem) bin=$d/rm/tb_readmem; v=$T ;;
            tb_backend) bin=$d/be/tb_backend; v=$T ;;
        esac
        [ -x "$bin" ] || { echo "RESULT FAIL exits verilator $tb: no build at $bin"; return; }
        exits_bench vl "$tb" "$bin" "$v" || { echo "RESULT FAIL exits verilator $tb"; return; }
    done
    echo "RESULT PASS exits (Verilator): tb_dec, tb_setup, tb_etm, tb_slb_fill, tb_readmem and tb_backend exit 0 on a good run (tb_backend's dumps pass edgeflag check --cycles) and non-zero with their FAIL line for no plusargs (writing nothing), a missing input, an unwritable output, stamps swapped"
}

# 5. DEC, SETUP (+ divider) and ETM in RTL, block by block (tests/rtl/blocks_a.sh)
. "$root/tests/rtl/blocks_a.sh"

collect
# the Verilator exits reuse the block benches' builds made above
[ $have_vl = 1 ] && { submit bench_exits_vl bench_exits_vl; collect; }
# What the RTL runs exercised, summed over every tb_slb_fill run above.
cat "$work"/logs/slb_*.log 2>/dev/null | awk '/^tb_slb_fill: coverage:/ {
        n++; s += $3; f += $8; fl += $11 }
    END { if (n) printf "test-rtl: RTL coverage over %d runs: %d cycles of COV back-pressure, %d forwarded reads, %d spans closed by the flush step\n", n, s, f, fl }'
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
