#!/usr/bin/env bash
# board/soc/bitstream.sh BOARD NS DIR SEED - `make bitstream`'s gateware step: the SoC of
# board/soc/soc.py with DIR/firmware.bin in its ROM, through the packaged Yosys, nextpnr-ecp5 and
# ecppack (build/fpga-bin's shims of the yowasp tools), then the figures: utilisation (LUT4 from
# Yosys, nextpnr's placed cells, flip-flops, DP16KD, MULT18X18D against the device's) and each
# clock's Fmax against its constraint.  Exit 0 only with the .bit written and every clock met
# (nextpnr runs without --timing-allow-fail, so a missed constraint already fails it).
set -euo pipefail
board=$1 ns=$2 dir=$3 seed=$4
cd "$(dirname "$0")/../.."
export PATH=$PWD/build/fpga-bin:$PATH
py=${EF_VENV:-build/venv}/bin/python
log=$dir/bitstream.log
start=$(date +%s)
echo "bitstream: $board, ef_raster NS $ns, seed $seed (Yosys, nextpnr-ecp5 and ecppack from PyPI: slow on a busy machine)"
# EF_SOC_FLAGS: more soc.py options (`make bitstream BOARD_GPIO=0` gives --no-gpio)
# shellcheck disable=SC2086
if ! "$py" board/soc/soc.py --target "$board" --ns "$ns" --out "$dir" --rom "$dir/firmware.bin" --seed "$seed" \
        ${EF_SOC_FLAGS:-} >"$log" 2>&1; then
    grep -E "ERROR|Error|error:|FAIL" "$log" | tail -n 20
    tail -n 20 "$log"
    echo "bitstream: FAILED (log: $log)" >&2
    exit 1
fi
secs=$(($(date +%s) - start))
bit=$dir/gateware/radiona_ulx3s.bit
[ -s "$bit" ] || { echo "bitstream: no $bit" >&2; exit 1; }
# nextpnr's last utilisation table and its last Fmax lines (after routing)
util=$(awk '/Device utilisation:/{buf=""; on=1; next} on && /^Info:[ \t]*[A-Z_0-9]+: /{buf=buf $0 "\n"; next} on{on=0} END{printf "%s", buf}' "$log")
cell() { printf '%s\n' "$util" | awk -v c="$1" '$2 == c":" {print $3 $4}'; }
lut4=$(awk '$2 == "LUT4" {v=$1} END{print v}' "$dir/gateware/radiona_ulx3s.rpt" 2>/dev/null)
# (nextpnr prints them after placement and after routing: the last line of each clock)
nclk=$(grep -E "Max frequency for clock" "$log" | sed "s/.*for clock *'\{0,1\}//; s/'\{0,1\}: .*//" | sort -u | wc -l)
fmax=$(grep -E "Max frequency for clock" "$log" | tail -n "$nclk")
if [ -z "$util" ] || [ -z "$fmax" ]; then
    echo "bitstream: no utilisation or Fmax in $log" >&2
    exit 1
fi
if printf '%s\n' "$fmax" | grep -q FAIL; then
    printf '%s\n' "$fmax"
    echo "bitstream: timing FAILED" >&2
    exit 1
fi
echo "bitstream: $bit ($(stat -c %s "$bit") bytes) in ${secs} s"
echo "bitstream: Yosys LUT4 ${lut4:-?}; placed (used/available): TRELLIS_COMB $(cell TRELLIS_COMB), TRELLIS_FF $(cell TRELLIS_FF), DP16KD $(cell DP16KD), MULT18X18D $(cell MULT18X18D)"
printf '%s\n' "$fmax" | sed 's/^Info: */bitstream: /'
echo "bitstream: firmware $(riscv64-unknown-elf-size "$dir/firmware.elf" | awk 'NR==2{print $1 " bytes text, " $2 " data, " $3 " bss"}')"
