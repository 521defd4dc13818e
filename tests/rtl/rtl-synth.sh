#!/usr/bin/env bash
# tests/rtl/rtl-synth.sh - synthesis figures of ef_raster (make rtl-synth,
# not in make test): Yosys synth_ice40 and nextpnr-ice40 for a configuration
# that fits a small FPGA (default W_MAX 320, H_MAX 240, E_MAX 255, NS 8 and
# 16, on an iCE40 HX8K); prints LUTs, FFs, block RAMs and Fmax per
# configuration, and fails on a latch or on Yosys warnings.
#   EF_SYNTH_NS="8 16" EF_SYNTH_E=255 EF_SYNTH_DEVICE=hx8k EF_SYNTH_PKG=ct256
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
R=$root/rtl_vectors/rtl
RTL="$R/ef_raster.v $R/ef_dec.v $R/ef_setup.v $R/ef_div.v $R/ef_etm.v $R/ef_aet.v $R/ef_plot.v $R/ef_slb_fill.v $R/ef_slb_ram.v $R/ef_cov.v"
dev=${EF_SYNTH_DEVICE:-hx8k} pkg=${EF_SYNTH_PKG:-ct256} E=${EF_SYNTH_E:-255}
out=${EF_SYNTH_OUT:-$root/build/synth}
mkdir -p "$out"
rc=0
for ns in ${EF_SYNTH_NS:-8 16}; do
    tag=ns${ns}_w320_h240_e$E
    cat >"$out/$tag.ys" <<YS
read_verilog -defer $RTL
chparam -set NS $ns -set W_MAX 320 -set H_MAX 240 -set E_MAX $E ef_raster
hierarchy -top ef_raster
synth_ice40 -top ef_raster -json $out/$tag.json
tee -o $out/$tag.stat stat
YS
    yosys -l "$out/$tag.yosys.log" -q "$out/$tag.ys" >/dev/null 2>&1 || { echo "rtl-synth: $tag: yosys failed ($out/$tag.yosys.log)"; rc=1; continue; }
    if grep -qi 'latch' "$out/$tag.stat" || grep -qE '^Warning' "$out/$tag.yosys.log"; then
        grep -iE '^Warning|latch' "$out/$tag.yosys.log" "$out/$tag.stat" | head; echo "rtl-synth: $tag: a latch or a warning"; rc=1
    fi
    nextpnr-ice40 --$dev --package "$pkg" --json "$out/$tag.json" --freq 12 >"$out/$tag.pnr.log" 2>&1 ||
        { tail -5 "$out/$tag.pnr.log"; echo "rtl-synth: $tag: nextpnr-ice40 failed (does not fit the $dev?)"; rc=1; continue; }
    lut=$(grep -E 'ICESTORM_LC:' "$out/$tag.pnr.log" | tail -n 1 | sed 's/^Info: *//')
    ram=$(grep -E 'ICESTORM_RAM:' "$out/$tag.pnr.log" | tail -n 1 | sed 's/^Info: *//')
    ff=$(grep -cE 'SB_DFF' "$out/$tag.stat"; grep -E '^ +SB_DFF' "$out/$tag.stat" | awk '{ s += $2 } END { print s }')
    fmax=$(grep -E 'Max frequency for clock' "$out/$tag.pnr.log" | tail -n 1 | sed 's/^Info: *//')
    echo "rtl-synth: $tag on iCE40 $dev: $lut; $ram; flip-flops $(echo "$ff" | tail -n 1); $fmax"
done
exit $rc
