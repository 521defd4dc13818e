#!/usr/bin/env bash
# tests/rtl/rtl-lint.sh - `make rtl-lint`: the RTL's sources are one source
# and every Verilog file of the tree lints clean (issue 22).
#
#   1. generated files: rtl/ef_ifaces.vh and rtl/ef_ifaces_pkg.sv are what
#      `edgeflag vectors --rtl-headers` writes, rtl/ef_rooks.vh what
#      `edgeflag patterns --emit-verilog` prints, byte for byte (regenerate
#      with `make rtl-gen`);
#   2. the n-rooks tables: the RTL's rooks_k (run under Icarus through
#      dv/tb/tb_rooks.v) equals model/pattern_tables.c's k8/k16/k32 (read
#      with awk) at every N and s;
#   3. a bad NS fails elaboration: ef_raster with NS = 12 and 64 is an error
#      naming ef_error_NS_must_be_8_16_or_32 under Verilator and Icarus, and
#      NS 8/16/32 elaborate; a bad SCHEDULE (2) names
#      ef_error_SCHEDULE_must_be_0_or_1 in both;
#   4. RTL variants: every recipe of dv/faults/ applies (dv/rtl-variant.sh)
#      and its copy compiles under Icarus in both configurations (SCHEDULE
#      0 and 1); a recipe that no longer matches is
#      refused (exit 1, naming its line);
#   5. `verilator --lint-only -Wall` (with dv/lint/waivers.vlt) of every RTL
#      and bench file: ef_raster at NS 8/16/32 with the default and small
#      limits, and with SCHEDULE=1 (the overlap schedule, docs/microarch.md
#      section 6) also the tiny ones (and iverilog -g2005 -Wall), every
#      block as its own top (ef_slb_fill with SKIP 0 and 1), every bench, the DPI bench with
#      either DUT, the board's DUT wrapper, the generated package through its
#      lint wrapper (and Icarus -g2012 of the package + wrapper): no output
#      at all; and every *.v, *.vh, *.sv under rtl/ and dv/ is in some lint.
#
# usage: bash tests/rtl/rtl-lint.sh BUILD_DIR
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
build=${1:?usage: tests/rtl/rtl-lint.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
for t in iverilog vvp verilator; do
    command -v $t >/dev/null 2>&1 || { echo "rtl-lint: $t is not installed ('make deps-test')"; exit 1; }
done
[ -x "$EF" ] || { echo "rtl-lint: $EF not built (make cli)"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-rtllint.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
cd "$root" || exit 1
t0=$(date +%s)
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1"; [ -n "${2:-}" ] && printf '%s\n' "$2" | head -n 20 | sed 's/^/    /'; }

R=rtl
RTL="$R/ef_raster.v $R/ef_dec.v $R/ef_setup.v $R/ef_div.v $R/ef_etm.v $R/ef_aet.v $R/ef_plot.v $R/ef_slb_fill.v $R/ef_slb_ram.v $R/ef_cov.v"
# the overlap schedule's configuration (ef_raster SCHEDULE=1, docs/microarch.md
# section 6): the same files and the span queue
FAST="$RTL $R/ef_spanq.v"
W=dv/lint/waivers.vlt

# ---------------------------------------------------------------- 1. generated
if "$EF" vectors --rtl-headers -o "$work/hdr" >"$work/hdr.log" 2>&1; then
    for f in ef_ifaces.vh ef_ifaces_pkg.sv; do
        if cmp -s "$work/hdr/$f" "$R/$f"; then ok "rtl/$f is what edgeflag vectors --rtl-headers writes"
        else bad "rtl/$f differs from edgeflag vectors --rtl-headers (make rtl-gen)" "$(diff "$R/$f" "$work/hdr/$f" | head)"; fi
    done
else
    bad "edgeflag vectors --rtl-headers" "$(cat "$work/hdr.log")"
fi
if "$EF" patterns --emit-verilog >"$work/rooks.vh" 2>"$work/rooks.err" && cmp -s "$work/rooks.vh" "$R/ef_rooks.vh"; then
    ok "rtl/ef_rooks.vh is what edgeflag patterns --emit-verilog prints"
else
    bad "rtl/ef_rooks.vh differs from edgeflag patterns --emit-verilog (make rtl-gen)" "$(cat "$work/rooks.err"; diff "$R/ef_rooks.vh" "$work/rooks.vh" | head)"
fi

# ---------------------------------------------------------------- 2. n-rooks tables
# model/pattern_tables.c: "static const uint8_t kN[N] = { a, b, ...,\n ... };"
awk '/static const uint8_t k[0-9]+\[/ { n = $4; sub(/^k/, "", n); sub(/\[.*/, "", n); on = 1; s = 0 }
     on { line = $0; sub(/.*\{/, "", line); gsub(/[^0-9,]/, " ", line); gsub(/,/, " ", line)
          k = split(line, v, " "); for (i = 1; i <= k; i++) printf "rooks %d %d %d\n", n, s++, v[i]
          if ($0 ~ /\};/) on = 0 }' model/pattern_tables.c >"$work/rooks_c.txt"
: >"$work/rooks_v.txt"
for ns in 8 16 32; do
    iverilog -g2005 -I"$R" -Ptb_rooks.NS=$ns -o "$work/rooks$ns.vvp" dv/tb/tb_rooks.v &&
        vvp -n "$work/rooks$ns.vvp" | grep '^rooks ' >>"$work/rooks_v.txt"
done
if [ "$(wc -l <"$work/rooks_c.txt")" = 56 ] && cmp -s "$work/rooks_c.txt" "$work/rooks_v.txt"; then
    ok "the RTL's n-rooks tables (rooks_k under Icarus) equal model/pattern_tables.c at N = 8, 16, 32 (56 entries)"
else
    bad "the RTL's n-rooks tables differ from model/pattern_tables.c" "$(diff "$work/rooks_c.txt" "$work/rooks_v.txt" | head)"
fi

# ---------------------------------------------------------------- 3. NS at elaboration
ns_ok=1
for ns in 12 64; do
    # shellcheck disable=SC2086 # the file lists split on purpose
    out=$(verilator --lint-only -Wall -I"$R" -GNS=$ns --top-module ef_raster $RTL 2>&1); rc=$?
    if [ $rc = 0 ] || ! printf '%s\n' "$out" | grep -q "ef_error_NS_must_be_8_16_or_32"; then
        ns_ok=0; bad "verilator accepts ef_raster with NS = $ns (exit $rc)" "$out"
    fi
    # shellcheck disable=SC2086
    out=$(iverilog -g2005 -I"$R" -Pef_raster.NS=$ns -s ef_raster -o /dev/null $RTL 2>&1); rc=$?
    if [ $rc = 0 ] || ! printf '%s\n' "$out" | grep -q "Unknown module type: ef_error_NS_must_be_8_16_or_32"; then
        ns_ok=0; bad "iverilog accepts ef_raster with NS = $ns (exit $rc)" "$out"
    fi
done
for ns in 8 16 32; do
    # shellcheck disable=SC2086
    iverilog -g2005 -I"$R" -Pef_raster.NS=$ns -s ef_raster -o /dev/null $RTL >/dev/null 2>&1 ||
        { ns_ok=0; bad "iverilog refuses ef_raster with NS = $ns"; }
done
# shellcheck disable=SC2086
out=$(verilator --lint-only -Wall -I"$R" -GSCHEDULE=2 --top-module ef_raster $FAST 2>&1); rc=$?
if [ $rc = 0 ] || ! printf '%s\n' "$out" | grep -q "ef_error_SCHEDULE_must_be_0_or_1"; then
    ns_ok=0; bad "verilator accepts ef_raster with SCHEDULE = 2 (exit $rc)" "$out"
fi
# shellcheck disable=SC2086
out=$(iverilog -g2005 -I"$R" -Pef_raster.SCHEDULE=2 -s ef_raster -o /dev/null $FAST 2>&1); rc=$?
if [ $rc = 0 ] || ! printf '%s\n' "$out" | grep -q "Unknown module type: ef_error_SCHEDULE_must_be_0_or_1"; then
    ns_ok=0; bad "iverilog accepts ef_raster with SCHEDULE = 2 (exit $rc)" "$out"
fi
[ $ns_ok = 1 ] && ok "NS = 12 and 64 fail elaboration under Verilator and Icarus (ef_error_NS_must_be_8_16_or_32), 8/16/32 elaborate; SCHEDULE = 2 fails (ef_error_SCHEDULE_must_be_0_or_1)"

# ---------------------------------------------------------------- 4. variants
nv=0 v_ok=1
for f in dv/faults/*.sed; do
    n=$(basename "$f" .sed)
    if ! out=$(bash dv/rtl-variant.sh "$work/var_$n" "$n" 2>&1); then
        v_ok=0; bad "dv/rtl-variant.sh $n" "$out"; continue
    fi
    d=$work/var_$n
    # shellcheck disable=SC2086
    if ! out=$(iverilog -g2005 -I"$d" -s ef_raster -o /dev/null ${RTL//$R\//$d\/} 2>&1); then
        v_ok=0; bad "the variant $n does not compile" "$out"; continue
    fi
    # shellcheck disable=SC2086
    if ! out=$(iverilog -g2005 -I"$d" -Pef_raster.SCHEDULE=1 -s ef_raster -o /dev/null ${FAST//$R\//$d\/} 2>&1); then
        v_ok=0; bad "the variant $n does not compile in the fast configuration (SCHEDULE=1)" "$out"; continue
    fi
    cmp -s "$d/$(sed -n 's/^# file: *//p' "$f")" "$R/$(sed -n 's/^# file: *//p' "$f")" && { v_ok=0; bad "the variant $n equals rtl/"; }
    nv=$((nv + 1))
done
printf '# file: ef_plot.v\ns/this text is not in ef_plot.v/x/\n' >"$work/stale.sed"
out=$(bash dv/rtl-variant.sh "$work/var_stale" "$work/stale.sed" 2>&1); rc=$?
if [ $rc = 1 ] && printf '%s\n' "$out" | grep -q "stale.sed:2: the command does not change ef_plot.v"; then :; else
    v_ok=0; bad "a recipe that does not match: exit $rc, '$out'"; fi
[ $v_ok = 1 ] && ok "RTL variants: all $nv recipes of dv/faults/ apply and compile; a stale recipe is refused naming its line"

# ---------------------------------------------------------------- 5. lint
linted=()
# vl NAME ARGS...: verilator --lint-only -Wall with the waivers must print nothing
vl() {
    local name=$1 out a; shift
    out=$(verilator --lint-only -Wall --timing -I"$R" -Idv/tb "$W" "$@" 2>&1)
    for a in "$@"; do case $a in *.v | *.sv | *.vh) linted+=("$a") ;; esac; done
    if [ -n "$out" ]; then bad "verilator -Wall $name is not silent" "$out"; return 1; fi
    return 0
}
n=0 l_ok=1
for ns in 8 16 32; do
    # shellcheck disable=SC2086
    vl "ef_raster NS=$ns" -GNS=$ns --top-module ef_raster $RTL || l_ok=0
    # shellcheck disable=SC2086
    vl "ef_raster NS=$ns small" -GNS=$ns -GW_MAX=320 -GH_MAX=240 -GE_MAX=512 --top-module ef_raster $RTL || l_ok=0
    # shellcheck disable=SC2086
    vl "ef_raster SCHEDULE=1 NS=$ns" -GNS=$ns -GSCHEDULE=1 --top-module ef_raster $FAST || l_ok=0
    # shellcheck disable=SC2086
    vl "ef_raster SCHEDULE=1 NS=$ns small" -GNS=$ns -GSCHEDULE=1 -GW_MAX=320 -GH_MAX=240 -GE_MAX=512 --top-module ef_raster $FAST || l_ok=0
    # shellcheck disable=SC2086
    vl "ef_raster SCHEDULE=1 NS=$ns tiny" -GNS=$ns -GSCHEDULE=1 -GW_MAX=40 -GH_MAX=30 -GE_MAX=64 --top-module ef_raster $FAST || l_ok=0
    # shellcheck disable=SC2086
    out=$(iverilog -g2005 -Wall -I"$R" -Pef_raster.NS=$ns -Pef_raster.SCHEDULE=1 -s ef_raster -o /dev/null $FAST 2>&1)
    [ -z "$out" ] || { l_ok=0; bad "iverilog -g2005 -Wall of ef_raster SCHEDULE=1 NS=$ns is not silent" "$out"; }
    n=$((n + 5))
done
for t in ef_dec ef_setup ef_div ef_etm ef_aet ef_plot ef_slb_fill ef_slb_ram ef_cov; do
    # shellcheck disable=SC2086
    vl "$t" --top-module $t $RTL || l_ok=0; n=$((n + 1))
done
# shellcheck disable=SC2086
vl "ef_slb_fill SKIP=1" -GSKIP=1 --top-module ef_slb_fill $FAST || l_ok=0
# shellcheck disable=SC2086
vl "ef_slb_fill SKIP=1 tiny" -GSKIP=1 -GW_MAX=40 --top-module ef_slb_fill $FAST || l_ok=0
# shellcheck disable=SC2086
vl ef_spanq --top-module ef_spanq $FAST || l_ok=0
n=$((n + 3))
# the includes, as the RTL's own files (linted through every module above)
linted+=("$R/ef_ifaces.vh" "$R/ef_ns.vh" "$R/ef_rooks.vh")
# the block benches' file helpers, and the port list of the benches that instantiate the whole
# pipeline (tb_raster, tb_err, dut_rtl), linted through every bench that includes them
linted+=(dv/tb/tb_files.vh dv/tb/ef_raster_conn.vh)
TB=dv/tb
# shellcheck disable=SC2086
{
vl tb_raster --top-module tb_raster $TB/tb_raster.v $RTL || l_ok=0
vl "tb_raster (ef_raster SCHEDULE=1)" -DEF_FAST --top-module tb_raster $TB/tb_raster.v $FAST || l_ok=0
vl "tb_raster (a user DUT)" -DEF_TB_USER_DUT --top-module tb_raster $TB/tb_raster.v $RTL || l_ok=0
vl tb_dec --top-module tb_dec $TB/tb_dec.v $R/ef_dec.v || l_ok=0
vl tb_err --top-module tb_err $TB/tb_err.v $RTL || l_ok=0
vl tb_setup --top-module tb_setup $TB/tb_setup.v $R/ef_setup.v $R/ef_div.v $R/ef_slb_ram.v || l_ok=0
vl tb_etm --top-module tb_etm $TB/tb_etm.v $R/ef_etm.v $R/ef_slb_ram.v || l_ok=0
vl tb_slb_fill --top-module tb_slb_fill $TB/tb_slb_fill.v $R/ef_slb_fill.v $R/ef_slb_ram.v || l_ok=0
vl tb_backend --top-module tb_backend $TB/tb_backend.v $R/ef_etm.v $R/ef_aet.v $R/ef_plot.v $R/ef_slb_fill.v $R/ef_slb_ram.v $R/ef_cov.v || l_ok=0
vl tb_readmem --top-module tb_readmem $TB/tb_readmem.v || l_ok=0
vl tb_readmem_all --top-module tb_readmem_all $TB/tb_readmem_all.v $TB/tb_readmem.v || l_ok=0
vl tb_rooks --top-module tb_rooks $TB/tb_rooks.v || l_ok=0
vl tb_ifaces_pkg --top-module tb_ifaces_pkg $R/ef_ifaces_pkg.sv $TB/tb_ifaces_pkg.sv || l_ok=0
vl ef_rtl_dut --top-module ef_rtl_dut $TB/dut_rtl.v $RTL || l_ok=0
vl "tb_lockstep (ef_raster)" --top-module tb_lockstep $R/ef_ifaces_pkg.sv dv/dpi/ef_model_pkg.sv dv/dpi/tb_lockstep.sv $RTL || l_ok=0
vl "tb_lockstep (ef_raster SCHEDULE=1)" -DEF_FAST --top-module tb_lockstep $R/ef_ifaces_pkg.sv dv/dpi/ef_model_pkg.sv dv/dpi/tb_lockstep.sv $FAST || l_ok=0
vl "tb_lockstep (ef_slb_fill)" -DEF_TB_DUT_SLB --top-module tb_lockstep $R/ef_ifaces_pkg.sv dv/dpi/ef_model_pkg.sv dv/dpi/tb_lockstep.sv $RTL || l_ok=0
vl "ef_ifaces_pkg.sv (lint wrapper)" --top-module ef_ifaces_pkg_lint $R/ef_ifaces_pkg.sv dv/lint/ef_ifaces_pkg_lint.sv || l_ok=0
}
n=$((n + 17))
out=$(iverilog -g2012 -Wall -o /dev/null $R/ef_ifaces_pkg.sv dv/lint/ef_ifaces_pkg_lint.sv 2>&1)
[ -z "$out" ] || { l_ok=0; bad "iverilog -g2012 -Wall of ef_ifaces_pkg.sv + its lint wrapper is not silent" "$out"; }
# every Verilog file of rtl/ and dv/ is in some lint
missing=$(for f in rtl/*.v rtl/*.vh rtl/*.sv dv/*/*.v dv/*/*.sv dv/*/*.vh; do [ -e "$f" ] && echo "$f"; done | sort -u |
          comm -23 - <(printf '%s\n' "${linted[@]}" | sort -u))
[ -z "$missing" ] || { l_ok=0; bad "files no lint covers" "$missing"; }
[ $l_ok = 1 ] && ok "verilator --lint-only -Wall silent on $n configurations covering all $(printf '%s\n' "${linted[@]}" | sort -u | wc -l) Verilog files of rtl/ and dv/ (waivers: $W); iverilog -g2012 accepts the package with its wrapper"

echo "rtl-lint: $(( $(date +%s) - t0 )) s"
echo "rtl-lint: $pass passed, $fail failed"
[ $fail = 0 ]
