#!/usr/bin/env bash
# tests/mutants/rtl-mutants.sh - mutation testing of the RTL (issue 27; make
# rtl-mutants, docs/testing.md "RTL mutants").
#
#   1. dv/mutants/rtl_mutate.py writes mutant schemata of rtl/*.v into the
#      work folder (rtl/ is never touched): every mutant in one design,
#      chosen at run time by +mut=K;
#   2. Verilator builds the whole-pipeline bench (dv/tb/tb_raster.v) on them
#      at NS 8/16/32, the build make rtl-test runs (W_MAX = H_MAX = 256);
#   3. mutant 0 (the design itself) must pass every case: the schemata
#      change nothing until a mutant is chosen;
#   4. stage "rtl-test": each mutant runs make rtl-test's Verilator cases
#      (every shared SVG at 24x18 and every 11th `edgeflag gen` level-1 case,
#      rotating over NS x rule, and the tiger with random back-pressure on
#      pix) and one directed case (the tiger at W_MAX x H_MAX), shortest first, each under a timeout; the mutant is killed by the
#      first case whose bench does not pass, times out, or whose dumps fail
#      `edgeflag check` (--cycles; --transactions under back-pressure);
#   5. stage "regression": the survivors run every `edgeflag gen` level-1
#      case that fits the build (NS and rule rotating per case);
#   4b/5b. the fast configuration (ef_raster SCHEDULE=1 with ef_slb_fill
#      SKIP=1 and the span queue ef_spanq, docs/microarch.md section 6) is a
#      fourth build (NS 8, tb_raster's EF_FAST): its cases (make rtl-test's
#      fast slice: every NS 8 case of stage 4 against `edgeflag vectors
#      --schedule overlap`, the tiger under back-pressure, and the tiger at
#      W_MAX x H_MAX) join stage 4, and the NS 8 level-1 cases in the overlap
#      schedule join stage 5, so a mutant of code only the overlap schedule
#      runs (the skipping scan, the queue) meets a case that runs it;
#   6. the report: per block (file), mutants, killed by each stage,
#      equivalent (dv/mutants/equivalent.tsv: key and reason, reviewed like
#      code), survivors listed with file:line, operator and text.
#
# usage: bash tests/mutants/rtl-mutants.sh BUILD_DIR
#   EF_MUT_SAMPLE=N   run N mutants drawn with EF_MUT_SEED (default 27) instead
#                     of all (the draw is deterministic: python's random.Random)
#   EF_MUT_STRAT=F,M  a stratified sample instead: per block (file) ceil(F x its
#                     mutants), at least M (all when fewer), each block drawn
#                     with its own generator seeded by EF_MUT_SEED and the file;
#                     the report adds the population estimate (combined ratio
#                     estimator, 95 % interval) and per block Wilson intervals
#   EF_MUT_KEYS=FILE  exactly the mutants of these keys (make test's slice)
#   EF_MUT_EQUIV=FILE the equivalent mutants' list (default dv/mutants/equivalent.tsv)
#   EF_MUT_REQUIRE=1  fail unless every non-equivalent mutant is killed
#   EF_MUT_OPS=LIST   only these operators (comma-separated)
#   EF_MUT_FILES=LIST only these rtl/ files (comma-separated, e.g. ef_plot.v)
#   EF_MUT_REGRESS=0  skip stage 5;  EF_MUT_JOBS (2);  EF_MUT_TIMEOUT (s, 30, plus a second per 10,000 cycles of the case)
#   EF_MUT_NS="8 16 32" the builds (cases of other NS are left out)
#   EF_MUT_FAST=0     leave the fast configuration out (default: in, when rtl/
#                     has it: ef_spanq.v and ef_raster's SCHEDULE parameter)
#   EF_MUT_GEN_SLICE (11: stage 4's gen slice);  EF_MUT_SVGS (all: a count)
#   EF_MUT_SIM=icarus Icarus instead of Verilator (the slice in make test: it
#                     compiles in seconds); EF_MUT_MAXCYC leaves out cases of
#                     more cycles (default: none; 4000 is sensible for Icarus)
#   EF_MUT_REG_MAXCYC the regression stage's cases of at most this many cycles
#                     (default 250000: a survivor runs all of them)
#   EF_MUT_REUSE=DIR  a work folder kept (EF_MUT_KEEP=1) by an earlier run of the
#                     same tree: its builds and vectors are reused
#   EF_MUT_CACHE=FILE stage-1 results of an earlier run (its stage1.txt) reused
#   EF_MUT_OUT=DIR    keep results.tsv and report.txt there
# Ends with "N passed, M failed": failed when mutant 0 fails, or a
# non-equivalent mutant survives both stages while EF_MUT_REQUIRE=1.
set -u
export LC_ALL=C
build=${1:?usage: tests/mutants/rtl-mutants.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
jobs=${EF_MUT_JOBS:-2}
tmo=${EF_MUT_TIMEOUT:-30}
nslist=${EF_MUT_NS:-8 16 32}
gslice=${EF_MUT_GEN_SLICE:-11}
WM=256 HM=256 EM=16384
sim=${EF_MUT_SIM:-verilator}
maxcyc=${EF_MUT_MAXCYC:-0}
regmax=${EF_MUT_REG_MAXCYC:-250000}
simtools="verilator"; [ "$sim" = icarus ] && simtools="iverilog vvp"
for t in $simtools python3 parallel timeout; do
    command -v "$t" >/dev/null 2>&1 || { echo "rtl-mutants: $t is not installed ('make deps-test')"; echo "0 passed, 1 failed"; exit 1; }
done
[ -x "$EF" ] || { echo "rtl-mutants: $EF not built (make cli)"; echo "0 passed, 1 failed"; exit 1; }
tmpbase=${TMPDIR:-/tmp}
[ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
if [ -n "${EF_MUT_REUSE:-}" ]; then
    work=$EF_MUT_REUSE    # a kept work folder of the same tree: its builds and vectors are reused
    EF_MUT_KEEP=1
else
    work=$(mktemp -d "$tmpbase/edgeflag-rtlmut.XXXXXX") || exit 1
fi
if [ -n "${EF_MUT_KEEP:-}" ]; then echo "rtl-mutants: keeping $work"; else trap 'rm -rf "$work"' EXIT; fi
t0=$(date +%s)
pass=0 fail=0

# ------------------------------------------------------------ 1. schemata
files=(ef_raster.v ef_dec.v ef_setup.v ef_div.v ef_etm.v ef_aet.v ef_plot.v ef_slb_fill.v ef_slb_ram.v ef_cov.v)
# the fast configuration: rtl/'s ef_raster with SCHEDULE = 1, and the span queue (only it has one)
fastf=()
if [ "${EF_MUT_FAST:-1}" = 1 ] && [ -f "$root/rtl/ef_spanq.v" ] && grep -q 'parameter *SCHEDULE' "$root/rtl/ef_raster.v"; then
    fastf=(ef_spanq.v)
fi
# an RTL variant (dv/rtl-variant.sh: a copy of rtl/ with its include files), whose .v files
# rtl_mutate.py then replaces by their schemata in place
bash "$root/dv/rtl-variant.sh" "$work/mut" >/dev/null || { echo "FAIL rtl-mutants: dv/rtl-variant.sh"; echo "0 passed, 1 failed"; exit 1; }
mkdir -p "$work/orig" && cp "$work/mut"/*.v "$work/mut"/*.vh "$work/orig/"   # the sources as mutated, for the report
# and the n-rooks table, a function included in ef_plot's body
nall=$(python3 "$root/dv/mutants/rtl_mutate.py" "$work/mut" "${files[@]/#/$work/mut/}" "${fastf[@]/#/$work/mut/}" "$work/mut/ef_rooks.vh") ||
    { echo "0 passed, 1 failed"; exit 1; }
MUTRTL=("${files[@]/#/$work/mut/}")
MUTFAST=("${MUTRTL[@]}" "${fastf[@]/#/$work/mut/}")

# ------------------------------------------------------------ 2. builds
buildone() {   # buildone KEY: NS, or fNS for the fast configuration at NS
    { [ -x "$work/vl_$1/Vtb_raster" ] || [ -f "$work/vl_$1/t.vvp" ]; } && [ -n "${EF_MUT_REUSE:-}" ] && return 0
    local ns=${1#f} def=() src=("${MUTRTL[@]}")
    [ "$1" != "$ns" ] && { def=(-DEF_FAST); src=("${MUTFAST[@]}"); }
    if [ "$sim" = icarus ]; then
        mkdir -p "$work/vl_$1"
        iverilog -g2005 -I"$work/mut" -I"$root/dv/tb" "${def[@]}" -o "$work/vl_$1/t.vvp" -Ptb_raster.NS="$ns" -Ptb_raster.W_MAX=$WM -Ptb_raster.H_MAX=$HM \
            -Ptb_raster.E_MAX=$EM -Ptb_raster.FB_BITS=16 "$root/dv/tb/tb_raster.v" "${src[@]}" >"$work/build_$1.log" 2>&1 ||
            { tail -20 "$work/build_$1.log"; return 1; }
        return
    fi
    verilator --binary --timing -O1 -Wno-fatal -Wno-WIDTH -I"$work/mut" -I"$root/dv/tb" "${def[@]}" --x-assign unique --x-initial unique --Mdir "$work/vl_$1" --top-module tb_raster \
        -GNS="$ns" -GW_MAX=$WM -GH_MAX=$HM -GE_MAX=$EM -GFB_BITS=16 "$root/dv/tb/tb_raster.v" "${src[@]}" \
        >"$work/build_$1.log" 2>&1 || { tail -20 "$work/build_$1.log"; return 1; }
}
# dv/tb/tb_err.v (make rtl-test's DUT limit checks) on the schemata, under Icarus in either mode
# (as rtl-test runs it; it compiles in a second)
builderr() {
    [ -f "$work/err.vvp" ] && [ -n "${EF_MUT_REUSE:-}" ] && return 0
    iverilog -g2005 -I"$work/mut" -I"$root/dv/tb" -o "$work/err.vvp" "$root/dv/tb/tb_err.v" "${MUTRTL[@]}" >"$work/build_err.log" 2>&1 ||
        { tail -20 "$work/build_err.log"; return 1; }
}
pids=()
builderr & pids+=($!)
fastkeys=""
[ ${#fastf[@]} -gt 0 ] && case " $nslist " in *" 8 "*) fastkeys=f8 ;; esac
for ns in $nslist $fastkeys; do buildone "$ns" & pids+=($!); done
for p in "${pids[@]}"; do wait "$p" || { echo "FAIL rtl-mutants: Verilator did not build the schemata"; echo "0 passed, 1 failed"; exit 1; }; done
echo "rtl-mutants: $nall mutants in $(( ${#files[@]} + ${#fastf[@]} + 1 )) files; schemata built ($sim) at NS $nslist${fastkeys:+ and the fast configuration at NS 8} in $(( $(date +%s) - t0 )) s"

# ------------------------------------------------------------ 3. cases
[ -f "$work/gen/index.tsv" ] || "$EF" gen -o "$work/gen" >/dev/null 2>&1 || { echo "FAIL rtl-mutants: edgeflag gen"; echo "0 passed, 1 failed"; exit 1; }
mkdir -p "$work/vec"
rules=(scene nonzero evenodd)
mkcase() {   # mkcase STAGE NAME INPUT KEY RULE SIZE [BP]  (KEY: NS, or fNS: the fast configuration)
    local d=$work/vec/$2 args=() w h me cyc ns=${4#f}
    case " $nslist $fastkeys " in *" $4 "*) ;; *) return ;; esac
    [ "$5" != scene ] && args+=(--rule "$5"); [ "$6" != - ] && args+=(--size "$6"); [ "$4" != "$ns" ] && args+=(--schedule overlap)
    [ -f "$d/manifest.json" ] || "$EF" vectors "$3" -o "$d" --samples "$ns" "${args[@]}" --formats hex >/dev/null 2>&1 || return
    read -r w h <<<"$(sed -n 's/.*; size \([0-9]*\)x\([0-9]*\);.*/\1 \2/p' "$d/cmd.stim.hex" | head -n 1)"
    if [ "$w" -gt $WM ] || [ "$h" -gt $HM ]; then rm -rf "$d"; return; fi
    me=$(awk '!/^\/\// && NF { op = substr($1, 13, 1); if (op == "2") n = 0; if (op == "3" && ++n > m) m = n } END { print m + 0 }' "$d/cmd.stim.hex")
    if [ "$me" -gt $EM ]; then rm -rf "$d"; return; fi
    cyc=$(sed -n 's/.*"cycles": \([0-9]*\).*/\1/p' "$d/manifest.json")
    if [ "$maxcyc" -gt 0 ] && [ "$cyc" -gt "$maxcyc" ]; then rm -rf "$d"; return; fi
    if [ "$1" = r ] && [ "$cyc" -gt "$regmax" ]; then rm -rf "$d"; return; fi
    echo "$1 $cyc $2 $4 ${7:--}"
}
{
    k=0 nsv=0
    for f in "$root"/tests/data/svg/*.svg; do
        [ -n "${EF_MUT_SVGS:-}" ] && [ $nsv -ge "$EF_MUT_SVGS" ] && break
        mkcase t "svg_$(basename "$f" .svg)" "$f" $((8 << (k % 3))) "${rules[$(( (k / 3) % 3 ))]}" "${EF_MUT_SVG_SIZE:-24x18}"
        [ $((k % 3)) = 0 ] && mkcase t "fast_svg_$(basename "$f" .svg)" "$f" f8 "${rules[$(( (k / 3) % 3 ))]}" "${EF_MUT_SVG_SIZE:-24x18}"
        k=$((k + 1)) nsv=$((nsv + 1))
    done
    while IFS=$'\t' read -r num file _ _ name _; do
        case $name in canvas-max*|zigzag-4096|same-cell-4096) continue ;; esac
        if [ $((num % gslice)) = 0 ]; then
            mkcase t "gen_$num" "$work/gen/$file" $((8 << (k % 3))) "${rules[$(( (k / 3) % 3 ))]}" -
            [ $((k % 3)) = 0 ] && mkcase t "fast_gen_$num" "$work/gen/$file" f8 "${rules[$(( (k / 3) % 3 ))]}" -
            k=$((k + 1))
        elif [ "${EF_MUT_REGRESS:-1}" = 1 ]; then
            mkcase r "reg_$num" "$work/gen/$file" $((8 << (num % 3))) "${rules[$(( (num / 3) % 3 ))]}" -
            [ $((num % 3)) = 0 ] && mkcase r "fast_reg_$num" "$work/gen/$file" f8 "${rules[$(( (num / 3) % 3 ))]}" -
        fi
    done < <(tail -n +3 "$work/gen/index.tsv")
    echo "t 0 tb_err 8 -"     # the DUT's limit checks (dv/tb/tb_err.v), first: it takes a second
    case " $nslist " in *" 8 "*) mkcase t bp_tiger "$root/tests/data/svg/tiger.svg" 8 scene 24x18 424242 ;; esac
    # directed (added after the first run, where it killed 3 of the 31 survivors): the tiger
    # filling the build's W_MAX x H_MAX, a FRAME of exactly the largest canvas, rows past 64
    # for AET's occupancy search and enough edges to wrap its ring
    case " $nslist " in *" 8 "*) [ "$maxcyc" = 0 ] && mkcase t max_tiger "$root/tests/data/svg/tiger.svg" 8 scene "${WM}x$HM" ;; esac
    # the fast configuration's: the tiger under back-pressure (as make rtl-test), at W_MAX x H_MAX
    if [ -n "$fastkeys" ]; then
        mkcase t fast_bp_tiger "$root/tests/data/svg/tiger.svg" f8 scene 24x18 424242
        [ "$maxcyc" = 0 ] && mkcase t fast_max_tiger "$root/tests/data/svg/tiger.svg" f8 scene "${WM}x$HM"
    fi
} >"$work/cases.all"
sort -k1,1 -k2,2n "$work/cases.all" >"$work/cases.txt"
nt=$(grep -c '^t ' "$work/cases.txt"); nr=$(grep -c '^r ' "$work/cases.txt")
echo "rtl-mutants: stage rtl-test: $nt cases ($(grep -c '^t [0-9]* fast_' "$work/cases.txt") of the fast configuration); stage regression: $nr level-1 cases ($(grep -c '^r [0-9]* fast_' "$work/cases.txt") of the fast configuration; those fitting ${WM}x$HM, $EM edges and $regmax cycles)"

# runmut K STAGE: "K killed CASE" at the first case that fails, else "K survived"
runmut() {
    local k=$1 st=$2 s cyc n ns bp a out mode ci=0
    while read -r s cyc n ns bp; do
        ci=$((ci + 1))
        [ "$s" = "$st" ] || continue
        a=$work/act/$k.$n; mkdir -p "$a"; mode=--cycles
        local t=$((tmo + cyc / 10000))   # the timeout grows with the case: ~30,000 cycles/s on a busy core
        if [ "$n" = tb_err ]; then
            rm -rf "$a"
            timeout "$t" vvp -n "$work/err.vvp" +mut="$k" 2>&1 | grep -q '^tb_err: PASS' || { echo "$k killed $n"; return; }
            continue
        fi
        local pa=(); [ "$bp" != - ] && { pa=(+bp="$bp"); mode=--transactions; }
        if [ "$sim" = icarus ]; then
            out=$(timeout "$t" vvp -n "$work/vl_$ns/t.vvp" +mut="$k" +cmd="$work/vec/$n/cmd.stim.hex" +out="$a/" "${pa[@]}" 2>&1)
        else
            out=$(timeout "$t" "$work/vl_$ns/Vtb_raster" +verilator+rand+reset+2 +verilator+seed+$((k * 1000 + ci)) +mut="$k" \
                +cmd="$work/vec/$n/cmd.stim.hex" +out="$a/" "${pa[@]}" 2>&1)
        fi
        if ! echo "$out" | grep -q '^tb_raster: DONE' || ! "$EF" check "$work/vec/$n" "$a" $mode --errors 1 >/dev/null 2>&1; then
            rm -rf "$a"; echo "$k killed $n"; return
        fi
        rm -rf "$a"
    done <"$work/cases.txt"
    echo "$k survived"
}
export -f runmut; export work EF tmo sim

# ------------------------------------------------------------ sanity: mutant 0
[ "$nt" -gt 0 ] || { echo "FAIL rtl-mutants: no case for stage rtl-test"; echo "0 passed, 1 failed"; exit 1; }
for st in t r; do
    r=$(runmut 0 $st)
    if [ "$r" != "0 survived" ]; then
        echo "FAIL rtl-mutants: the unmutated schemata (mutant 0) fail: $r"; echo "0 passed, 1 failed"; exit 1
    fi
done
pass=$((pass + 1)); echo "PASS rtl-mutants: mutant 0 (the design) passes every case of both stages"

# ------------------------------------------------------------ selection
python3 - "$work/mut/mutants.tsv" "${EF_MUT_SAMPLE:-0}" "${EF_MUT_SEED:-27}" "${EF_MUT_OPS:-}" "${EF_MUT_FILES:-}" \
    "${EF_MUT_STRAT:-}" "$work/strata.tsv" "${EF_MUT_KEYS:-}" >"$work/selected.tsv" <<'EOF' || { echo "FAIL rtl-mutants: the selection"; echo "$pass passed, $((fail + 1)) failed"; exit 1; }
import math, random, sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])][1:]
if sys.argv[8]:
    # EF_MUT_KEYS=FILE: exactly the mutants of these keys (one a line), each of which must exist
    keys = [l.strip() for l in open(sys.argv[8]) if l.strip() and not l.startswith("#")]
    have = {r[4] for r in rows}
    missing = [k for k in keys if k not in have]
    if missing:
        raise SystemExit("rtl-mutants: no mutant has the key %s (the RTL changed?)" % missing[0])
    rows = [r for r in rows if r[4] in set(keys)]
n, seed = int(sys.argv[2]), int(sys.argv[3])
ops = set(sys.argv[4].split(",")) if sys.argv[4] else None
fs = set(sys.argv[5].split(",")) if sys.argv[5] else None
rows = [r for r in rows if (not ops or r[3] in ops) and (not fs or r[1] in fs)]
pop = {}
for r in rows:
    pop[r[1]] = pop.get(r[1], 0) + 1
if sys.argv[6]:
    # stratified: per block (file) n_h = min(N_h, max(MIN, ceil(FRAC * N_h))), each stratum drawn
    # with its own generator seeded by (seed, file), so a block's draw does not depend on the others
    frac, mn = sys.argv[6].split(",")
    frac, mn = float(frac), int(mn)
    out = []
    for f in sorted(pop):
        st = [r for r in rows if r[1] == f]
        k = min(len(st), max(mn, math.ceil(frac * len(st))))
        out += random.Random("%d:%s" % (seed, f)).sample(st, k)
    rows = sorted(out, key=lambda r: int(r[0]))
elif 0 < n < len(rows):
    rows = sorted(random.Random(seed).sample(rows, n), key=lambda r: int(r[0]))
with open(sys.argv[7], "w") as st:
    for f in sorted(pop):
        st.write("%s\t%d\n" % (f, pop[f]))     # stratum sizes N_h (of the operators/files chosen)
for r in rows:
    print("\t".join(r))
EOF
nsel=$(grep -c . "$work/selected.tsv")
[ "$nsel" -gt 0 ] || { echo "FAIL rtl-mutants: no mutant selected"; echo "$pass passed, $((fail + 1)) failed"; exit 1; }
if [ -n "${EF_MUT_STRAT:-}" ]; then
    echo "rtl-mutants: $nsel of $nall mutants selected (stratified per block, EF_MUT_STRAT=$EF_MUT_STRAT, seed ${EF_MUT_SEED:-27})"
else
    echo "rtl-mutants: $nsel of $nall mutants selected${EF_MUT_SAMPLE:+ (seeded sample, seed ${EF_MUT_SEED:-27})}"
fi

# ------------------------------------------------------------ 4. + 5.
# EF_MUT_CACHE=FILE: stage-1 results ("K killed CASE" / "K survived") of an earlier run of the
# same tree and cases, taken as they are
: >"$work/stage1.txt"
if [ -n "${EF_MUT_CACHE:-}" ] && [ -f "$EF_MUT_CACHE" ]; then
    awk 'NR == FNR { c[$1] = $0; next } ($1 in c) { print c[$1] }' "$EF_MUT_CACHE" <(cut -f1 "$work/selected.tsv") >>"$work/stage1.txt"
    echo "rtl-mutants: $(grep -c . "$work/stage1.txt") stage-1 results taken from $EF_MUT_CACHE"
fi
cut -d' ' -f1 "$work/stage1.txt" >"$work/done.txt"
cut -f1 "$work/selected.tsv" | grep -vxF -f "$work/done.txt" | parallel -j "$jobs" runmut '{}' t >>"$work/stage1.txt"
# every drawn mutant has its verdict, or the run is not a measurement
nres=$(cut -d' ' -f1 "$work/stage1.txt" | sort -u | grep -c .)
if [ "$nres" != "$nsel" ]; then
    echo "FAIL rtl-mutants: $nres stage-1 verdicts for $nsel mutants"; echo "$pass passed, $((fail + 1)) failed"; exit 1
fi
if [ "${EF_MUT_REGRESS:-1}" = 1 ]; then
    awk '$2 == "survived" { print $1 }' "$work/stage1.txt" | parallel -j "$jobs" runmut '{}' r >"$work/stage2.txt"
else
    : >"$work/stage2.txt"
fi

# ------------------------------------------------------------ 6. report
python3 - "$work/selected.tsv" "$work/stage1.txt" "$work/stage2.txt" "${EF_MUT_EQUIV:-$root/dv/mutants/equivalent.tsv}" \
    "${EF_MUT_REGRESS:-1}" "$work/strata.tsv" "$work/orig" >"$work/report.txt" 2>"$work/results.tsv" <<'EOF' || { cat "$work/report.txt" "$work/results.tsv"; echo "FAIL rtl-mutants: the report"; echo "$pass passed, $((fail + 1)) failed"; exit 1; }
import sys
sel = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
def res(p):
    d = {}
    for l in open(p):
        f = l.split()
        if f:
            d[f[0]] = (f[1], f[2] if len(f) > 2 else "")
    return d
s1, s2 = res(sys.argv[2]), res(sys.argv[3])
eqv = {}
try:
    for l in open(sys.argv[4]):
        if l.startswith("#") or not l.strip() or l.startswith("key\t"):
            continue
        k, src, why = l.rstrip("\n").split("\t", 2)
        eqv[k] = (src, why)
except FileNotFoundError:
    pass
# an entry holds while the mutated line reads as it did when it was triaged (a key's occurrence
# number can move to other code when the file changes): else the mutant counts as a survivor
rtl_src = {}
def line_of(f, ln):
    if f not in rtl_src:
        rtl_src[f] = open(sys.argv[7] + "/" + f).read().split("\n")
    return " ".join(rtl_src[f][int(ln) - 1].split())
stale = []
def is_eqv(f, ln, key):
    if key not in eqv:
        return False
    if eqv[key][0] != line_of(f, ln):
        stale.append("stale equivalence (the line changed, triage it again): %s rtl/%s:%s '%s'" % (key, f, ln, line_of(f, ln)))
        return False
    return True
regress = sys.argv[5] == "1"
blocks = {}
surv = []
for mid, f, line, op, key, old, new in sel:
    b = blocks.setdefault(f, [0, 0, 0, 0, 0])
    b[0] += 1
    if mid not in s1:
        raise SystemExit("rtl-mutants: no stage-1 verdict for mutant %s" % mid)
    st1 = s1[mid][0]
    st2 = s2.get(mid, ("", ""))[0]
    if st1 == "killed":
        b[1] += 1; verdict = "killed-rtl-test " + s1[mid][1]
    elif st2 == "killed":
        b[2] += 1; verdict = "killed-regression " + s2[mid][1]
    elif is_eqv(f, line, key):
        b[3] += 1; verdict = "equivalent"
    else:
        b[4] += 1; verdict = "SURVIVED"; surv.append((f, line, op, old, new, key))
    sys.stderr.write("%s\t%s\t%s\t%s\t%s\t%s\n" % (mid, f, line, op, key, verdict))
print("%-14s %8s %10s %10s %10s %9s %12s %12s" % ("block", "mutants", "rtl-test", "regression", "equivalent",
                                                   "survived", "score(test)", "score(+reg)"))
tot = [0, 0, 0, 0, 0]
def line(name, b):
    ne = b[0] - b[3]
    sc1 = "%d.%d %%" % divmod(b[1] * 1000 // ne, 10) if ne else "-"
    sc2 = "%d.%d %%" % divmod((b[1] + b[2]) * 1000 // ne, 10) if ne else "-"
    print("%-14s %8d %10d %10d %10d %9d %12s %12s" % (name, b[0], b[1], b[2], b[3], b[4], sc1, sc2))
for f in sorted(blocks):
    line(f[:-2] if f.endswith(".v") else f, blocks[f])
    tot = [a + b for a, b in zip(tot, blocks[f])]
line("all", tot)
if not regress:
    print("(stage regression skipped: EF_MUT_REGRESS=0)")
# the population's score from the sample: the combined ratio estimator of a stratified sample
# (Cochran, Sampling Techniques, 6.11): R = sum N_h k_h/n_h / sum N_h e_h/n_h (k killed, e
# non-equivalent), its variance by linearisation with the finite-population correction; per
# block the Wilson 95 % interval of killed / non-equivalent in the sample
import math
pop = {}
for l in open(sys.argv[6]):
    f, nn = l.split("\t")
    pop[f] = int(nn)
def wilson(k, n):
    if not n:
        return "-"
    z, p = 1.96, k / n
    c = (p + z * z / (2 * n)) / (1 + z * z / n)
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return "[%.1f, %.1f] %%" % (100 * max(0, c - h), 100 * min(1, c + h))
per = {}
for mid, f, line_, op, key, old, new in sel:
    st1 = s1[mid][0]
    st2 = s2.get(mid, ("", ""))[0]
    eq = st1 != "killed" and st2 != "killed" and key in eqv and eqv[key][0] == line_of(f, line_)
    per.setdefault(f, []).append((0 if eq else 1, 1 if st1 == "killed" else 0,
                                  1 if st1 == "killed" or st2 == "killed" else 0))
for which, name in ((1, "rtl-test"), (2, "+regression")):
    if which == 2 and not regress:
        continue
    Y = sum(pop[f] * sum(r[which] for r in rs) / len(rs) for f, rs in per.items())
    X = sum(pop[f] * sum(r[0] for r in rs) / len(rs) for f, rs in per.items())
    if not X:
        continue
    R = Y / X
    v = 0.0
    for f, rs in per.items():
        nh, Nh = len(rs), pop[f]
        if nh < 2:
            continue
        d = [r[which] - R * r[0] for r in rs]
        m = sum(d) / nh
        v += Nh * Nh * (1 - nh / Nh) * sum((x - m) ** 2 for x in d) / (nh - 1) / nh
    se = math.sqrt(v) / X
    if se > 0:
        ci = "95 %% interval [%.1f, %.1f] %%" % (100 * max(0, R - 1.96 * se), 100 * min(1, R + 1.96 * se))
    else:
        # every sampled mutant killed (or none): the normal interval collapses; the Wilson interval
        # of the pooled sample stands instead
        k = sum(sum(r[which] for r in rs) for rs in per.values())
        n = sum(sum(r[0] for r in rs) for rs in per.values())
        ci = "Wilson 95 %% of the pooled sample %s" % wilson(k, n)
    print("estimate over all %d mutants (%s): %.1f %% of non-equivalent killed, %s"
          % (sum(pop.values()), name, 100 * R, ci))
for f in sorted(per):
    rs = per[f]
    print("  %-14s sample %3d of %3d; rtl-test killed %3d of %3d non-equivalent, Wilson 95 %% %s"
          % (f, len(rs), pop[f], sum(r[1] for r in rs), sum(r[0] for r in rs), wilson(sum(r[1] for r in rs), sum(r[0] for r in rs))))
for l in stale:
    print(l)
for f, ln, op, old, new, key in surv:
    print("survivor: rtl/%s:%s %s: '%s' -> '%s'  key %s" % (f, ln, op, old[:60], new[:60], key))
print("SURVIVORS %d" % len(surv))
EOF
cat "$work/report.txt"
if [ -n "${EF_MUT_OUT:-}" ]; then mkdir -p "$EF_MUT_OUT"; cp "$work/report.txt" "$work/results.tsv" "$work/selected.tsv" "$EF_MUT_OUT/"; fi
ns=$(sed -n 's/^SURVIVORS //p' "$work/report.txt")
if [ "${EF_MUT_REQUIRE:-0}" = 1 ] && [ "${ns:-1}" != 0 ]; then
    fail=$((fail + 1)); echo "FAIL rtl-mutants: $ns non-equivalent mutants survive"
else
    pass=$((pass + 1)); echo "PASS rtl-mutants: report written ($nsel mutants; ${ns:-?} non-equivalent survivors)"
fi
echo "rtl-mutants: $(( $(date +%s) - t0 )) s"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
