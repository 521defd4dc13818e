#!/usr/bin/env bash
# dv/cocotb/measure.sh BUILD_DIR [SVG] [WxH]: the cocotb bench's simulated cycles per second against
# the C++ Verilator bench (dv/tb/tb_raster.v, --binary) on the same scene (default: the tiger at
# 64x48, 8 samples, W_MAX/H_MAX 256), both cycle-exact on every interface, both Verilator builds at
# -O2 (README, "From Python").  Prints one line per bench and the ratio.
set -eu
build=${1:?usage: dv/cocotb/measure.sh BUILD_DIR [SVG] [WxH]}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$root/$build ;; esac
svg=$(realpath "${2:-$root/tests/data/svg/tiger.svg}")
size=${3:-64x48}
work=$build/cocotb/measure
rm -rf "$work" && mkdir -p "$work/vl" "$work/dump"
"$build/edgeflag" vectors "$svg" -o "$work/vec" --size "$size" --samples 8 --formats hex >/dev/null 2>&1
R=$root/rtl
verilator --binary -O2 -Wno-fatal -Wno-WIDTH -I"$R" -I"$root/dv/tb" --Mdir "$work/vl" --top-module tb_raster -GNS=8 -GW_MAX=256 \
    -GH_MAX=256 -GE_MAX=16384 -GFB_BITS=16 "$root/dv/tb/tb_raster.v" "$R"/ef_raster.v "$R"/ef_dec.v "$R"/ef_setup.v \
    "$R"/ef_div.v "$R"/ef_etm.v "$R"/ef_aet.v "$R"/ef_plot.v "$R"/ef_slb_fill.v "$R"/ef_slb_ram.v "$R"/ef_cov.v \
    >"$work/vl/build.log" 2>&1
t0=$(date +%s.%N)
"$work/vl/Vtb_raster" +cmd="$work/vec/cmd.stim.hex" +out="$work/dump" >"$work/cxx.log" 2>&1
t1=$(date +%s.%N)
"$build/edgeflag" check "$work/vec" "$work/dump" --cycles --allow-missing cmd >/dev/null
cycles=$(grep -o 'cycles": [0-9]*' "$work/vec/manifest.json" | grep -o '[0-9]*$')
cxx=$(echo "$cycles / ($t1 - $t0)" | bc -l)
printf 'C++ Verilator bench (dv/tb/tb_raster.v): %d cycles in %.3f s: %.0f cycles/s (edgeflag check --cycles passed)\n' \
    "$cycles" "$(echo "$t1 - $t0" | bc -l)" "$cxx"
cd "$root/dv/cocotb"
PATH=$root/build/venv/bin:$PATH EF_BUILD=$build EF_COCOTB_SET=measure EF_MEASURE_SVG=$svg EF_MEASURE_SIZE=$size \
    EDGEFLAG_LIBDIR=$build MAKEFLAGS=-j2 PYTHONPATH=$root/dv/cocotb:$root/python \
    "$root/build/venv/bin/python" -m pytest -p no:cacheprovider -q test_runner.py -k test_measure >"$work/cocotb.log" 2>&1
python3 - "$build/cocotb/measure/measure.summary.json" "$cxx" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
(c,) = s["cases"]
rate = c["cycles"] / c["wall"]
print(f"cocotb bench (dv/cocotb, Verilator): {c['cycles']} cycles in {c['wall']:.3f} s: {rate:.0f} cycles/s, "
      f"{c['total']} transactions checked")
print(f"the C++ bench is {float(sys.argv[2]) / rate:.0f}x faster")
PY
