#!/usr/bin/env bash
# dv/rtl-sim.sh - one command from vectors to a verdict (issue 27; `make
# rtl-sim`, docs/vectors.md section 9): builds the whole-pipeline bench
# dv/tb/tb_raster.v around rtl/'s ef_raster (or a user's own top with
# ef_raster's ports), warning-clean and cached per configuration, runs it on
# VECTORS_DIR/cmd.stim.hex, dumps every interface and runs `edgeflag check`
# on the dumps against VECTORS_DIR.
#
# usage: dv/rtl-sim.sh VECTORS_DIR [--sim verilator|icarus] [--ns N]
#            [--top FILE]... [--fast] [--out DIR] [--w-max W] [--h-max H] [--e-max E]
#            [--transactions] [--edgeflag PATH] [--cache DIR]
#   --sim       the simulator (default verilator)
#   --ns        the build's samples per pixel (default: the vectors' own, from
#               cmd.stim.hex's header)
#   --top FILE  the DUT's Verilog instead of rtl/ (repeat for every file; one
#               of them defines module ef_raster with ef_raster's ports and
#               parameters NS, W_MAX, H_MAX, E_MAX; `include files are looked
#               up beside each file and in rtl/)
#   --fast      rtl/'s ef_raster with SCHEDULE=1 (the overlap schedule,
#               docs/microarch.md section 6): give it vectors written with
#               `edgeflag vectors --schedule overlap` (or --transactions)
#   --out DIR   where the dumps go (default CACHE/out/NAME, NAME the vectors'
#               folder name); emptied of *.actual.hex first
#   --w-max, --h-max, --e-max   the build's limits (default 2048, 2048, 8192:
#               the DUT refuses a canvas or a shape beyond them)
#   --transactions  compare in order only (a DUT with other timing)
#   --edgeflag  the edgeflag command (default: build/edgeflag beside this
#               tree, else edgeflag on the PATH)
#   --cache     the build cache (default build/rtl-sim in this tree)
# Exit: edgeflag check's status when the bench ran (0 PASS, 1 mismatches, 2
# its input errors); 2 usage; 3 the DUT refused the case (its reason
# printed: a canvas, a shape or a command count beyond this build's
# limits); 4 the bench failed (its FAIL line printed); 5 the build failed or a
# tool is missing.
set -u
export LC_ALL=C
root=$(cd "$(dirname "$0")/.." && pwd)
usage() {
    sed -n 's/^# \{0,1\}//; /^usage:/,/^Exit:/p' "$0" | sed '$d' >&2
    exit 2
}
die() { echo "rtl-sim: $1" >&2; exit "${2:-2}"; }

fast=0 vec='' sim=verilator ns='' out='' wmax=2048 hmax=2048 emax=8192 mode=--cycles ef='' cache=$root/build/rtl-sim
tops=()
while [ $# -gt 0 ]; do
    case $1 in
        --sim) sim=${2:-}; shift 2 || usage ;;
        --ns) ns=${2:-}; shift 2 || usage ;;
        --top) [ -n "${2:-}" ] || usage; tops+=("$2"); shift 2 ;;
        --fast) fast=1; shift ;;
        --out) out=${2:-}; shift 2 || usage ;;
        --w-max) wmax=${2:-}; shift 2 || usage ;;
        --h-max) hmax=${2:-}; shift 2 || usage ;;
        --e-max) emax=${2:-}; shift 2 || usage ;;
        --transactions) mode=--transactions; shift ;;
        --edgeflag) ef=${2:-}; shift 2 || usage ;;
        --cache) cache=${2:-}; shift 2 || usage ;;
        -h | --help) usage ;;
        -*) echo "rtl-sim: unknown option '$1'" >&2; usage ;;
        *) [ -z "$vec" ] || { echo "rtl-sim: one VECTORS_DIR only ('$1')" >&2; usage; }; vec=$1; shift ;;
    esac
done
[ -n "$vec" ] || { echo "rtl-sim: no VECTORS_DIR" >&2; usage; }
[ $fast = 0 ] || [ ${#tops[@]} = 0 ] || die "--fast and --top exclude each other"
case $sim in verilator | icarus) ;; *) die "--sim is verilator or icarus, not '$sim'" ;; esac
for v in "$wmax" "$hmax" "$emax" ${ns:+"$ns"}; do
    case $v in '' | *[!0-9]*) die "a limit or --ns is a number ('$v')" ;; esac
done
[ -d "$vec" ] || die "no vectors folder $vec"
[ -r "$vec/cmd.stim.hex" ] || die "no $vec/cmd.stim.hex (edgeflag vectors writes it; --formats hex)"
vec=$(cd "$vec" && pwd)
if [ -z "$ns" ]; then
    ns=$(sed -n 's/^\/\/ .*; samples \([0-9]*\);.*/\1/p' "$vec/cmd.stim.hex" | head -n 1)
    [ -n "$ns" ] || die "$vec/cmd.stim.hex names no sample count: give --ns"
fi
case $ns in 8 | 16 | 32) ;; *) die "--ns is 8, 16 or 32, not $ns" ;; esac
if [ -z "$ef" ]; then
    if [ -x "$root/build/edgeflag" ]; then ef=$root/build/edgeflag; else ef=$(command -v edgeflag) || die "no edgeflag: build it (make cli) or give --edgeflag" 5; fi
fi
[ -x "$ef" ] || die "--edgeflag $ef is not executable" 5
if [ "$sim" = verilator ]; then
    command -v verilator >/dev/null 2>&1 || die "verilator is not installed (tools/install-deps.sh test)" 5
else
    { command -v iverilog && command -v vvp; } >/dev/null 2>&1 || die "iverilog/vvp are not installed (tools/install-deps.sh test)" 5
fi

# --------------------------------------------------------------- the build
R=$root/rtl
incs=(-I"$R" -I"$root/dv/tb")   # dv/tb: ef_raster_conn.vh, the bench's port list
defs=()
if [ ${#tops[@]} -gt 0 ]; then
    src=()
    for f in "${tops[@]}"; do
        [ -r "$f" ] || die "--top $f: no such file"
        f=$(cd "$(dirname "$f")" && pwd)/$(basename "$f")
        src+=("$f"); incs=(-I"$(dirname "$f")" "${incs[@]}")
    done
    defs=(-DEF_TB_USER_DUT)
elif [ $fast = 1 ]; then
    src=("$R"/ef_raster.v "$R"/ef_dec.v "$R"/ef_setup.v "$R"/ef_div.v "$R"/ef_etm.v "$R"/ef_aet.v "$R"/ef_plot.v
         "$R"/ef_slb_fill.v "$R"/ef_slb_ram.v "$R"/ef_spanq.v "$R"/ef_cov.v)
    defs=(-DEF_FAST)
else
    src=("$R"/ef_raster.v "$R"/ef_dec.v "$R"/ef_setup.v "$R"/ef_div.v "$R"/ef_etm.v "$R"/ef_aet.v "$R"/ef_plot.v
         "$R"/ef_slb_fill.v "$R"/ef_slb_ram.v "$R"/ef_cov.v)
fi
tb=$root/dv/tb/tb_raster.v
params=(NS="$ns" W_MAX="$wmax" H_MAX="$hmax" E_MAX="$emax" FB_BITS=21 CMD_MAX=1048576)
# The configuration's key: the simulator, its version, the parameters and
# every source's content (so an edit rebuilds, and nothing else does).
key=$( { echo "$sim ${params[*]} ${defs[*]}"; if [ "$sim" = verilator ]; then verilator --version; else iverilog -V 2>&1 | head -n 1; fi
         cat "$tb" "${src[@]}" "$R"/*.vh "$root/dv/lint/waivers.vlt"; for d in "${incs[@]}"; do cat "${d#-I}"/*.vh 2>/dev/null; done; } |
       sha256sum | cut -c1-16)
cfg=$sim-ns$ns-w$wmax-h$hmax-e$emax${defs:+-user}-$key
[ $fast = 0 ] || cfg=$sim-ns$ns-w$wmax-h$hmax-e$emax-fast-$key
bdir=$cache/$cfg
mkdir -p "$cache" || die "cannot make $cache" 5
if [ -e "$bdir/ok" ]; then
    echo "rtl-sim: bench $cfg (cached in $bdir)"
else
    tmp=$(mktemp -d "$cache/.build.XXXXXX") || die "cannot make a build folder in $cache" 5
    t0=$(date +%s)
    if [ "$sim" = verilator ]; then
        g=(); for p in "${params[@]}"; do g+=(-G"$p"); done
        # Warning-clean: -Wall with the tree's waivers and warnings fatal for
        # rtl/ and the bench; a user's top is linted too, its warnings shown.
        wf=(); [ ${#tops[@]} -gt 0 ] && wf=(-Wno-fatal)
        if ! verilator --binary --timing -Wall "${wf[@]}" "$root/dv/lint/waivers.vlt" "${incs[@]}" "${defs[@]}" -j 2 \
                --Mdir "$tmp/obj" --top-module tb_raster "${g[@]}" "$tb" "${src[@]}" -o tb_raster >"$tmp/build.log" 2>&1; then
            tail -n 30 "$tmp/build.log" >&2; rm -rf "$tmp"; die "the Verilator build of $cfg failed" 5
        fi
        bin=(obj/tb_raster)
    else
        p=(); for q in "${params[@]}"; do p+=(-Ptb_raster."$q"); done
        if ! iverilog -g2005 -Wall "${incs[@]}" "${defs[@]}" "${p[@]}" -s tb_raster -o "$tmp/tb_raster.vvp" "$tb" "${src[@]}" \
                >"$tmp/build.log" 2>&1; then
            cat "$tmp/build.log" >&2; rm -rf "$tmp"; die "the Icarus build of $cfg failed" 5
        fi
        if [ ${#tops[@]} -eq 0 ] && [ -s "$tmp/build.log" ]; then
            cat "$tmp/build.log" >&2; rm -rf "$tmp"; die "the Icarus build of $cfg is not warning-clean" 5
        fi
        bin=(tb_raster.vvp)
    fi
    grep -q '%Warning' "$tmp/build.log" 2>/dev/null && grep '%Warning' "$tmp/build.log" | head -n 20 >&2
    echo "${bin[0]}" >"$tmp/ok"
    # publish atomically; a concurrent build of the same configuration wins
    mv -T "$tmp" "$bdir" 2>/dev/null || rm -rf "$tmp"
    echo "rtl-sim: built $cfg in $(( $(date +%s) - t0 )) s ($bdir)"
fi

# --------------------------------------------------------------- the run
[ -n "$out" ] || out=$cache/out/$(basename "$vec")
mkdir -p "$out" || die "cannot make $out" 5
rm -f "$out"/*.actual.hex
if [ "$sim" = verilator ]; then
    run=("$bdir/$(cat "$bdir/ok")")
else
    run=(vvp -n "$bdir/$(cat "$bdir/ok")")
fi
# (stderr closed around it: a Verilator $fatal aborts, and the shell would say so)
( "${run[@]}" +cmd="$vec/cmd.stim.hex" +out="$out" >"$out/sim.log" 2>&1 ) 2>/dev/null
rc=$?
if grep -q '^tb_raster: REFUSED' "$out/sim.log"; then
    grep '^tb_raster: REFUSED' "$out/sim.log" >&2
    echo "rtl-sim: REFUSED: the case does not fit this build (NS $ns, W_MAX $wmax, H_MAX $hmax, E_MAX $emax): nothing simulated" >&2
    exit 3
fi
if [ $rc != 0 ] || ! grep -q '^tb_raster: DONE' "$out/sim.log"; then
    grep -E '^tb_raster: ' "$out/sim.log" | tail -n 12 >&2
    echo "rtl-sim: the bench failed (exit $rc; its log: $out/sim.log)" >&2
    exit 4
fi
grep '^tb_raster: DONE' "$out/sim.log"
"$ef" check "$vec" "$out" $mode
