#!/usr/bin/env bash
# syn/scenes.sh - a schedule's frame length, pixels and pixels per clock
# for the scenes issue 25 reports (docs/synthesis.md): the tiger, the
# lion and the text scene of the shared illustrations (lorem_ipsum_compound:
# a paragraph of glyph outlines) at 640x480, and the paper's ten synthetic
# tests under both rules (bench/paper_scenes.py) at 640x480; at 8 samples
# unless EF_SCENES_NS says otherwise; the reference schedule, or the one
# EF_SCENES_SCHEDULE names (overlap: the fast configuration's, docs/microarch.md
# section 6; passed as --schedule, so an edgeflag built before the option
# existed runs with it unset).  Every number comes from `edgeflag
# vectors` (its manifest: cycles, the pix count) run here; with MHZ, the
# frame time at that clock too.  Not in make test.
#
# usage: syn/scenes.sh BUILD_DIR [MHZ]
# Exit 0 after printing every scene; 1 if a scene could not be run.
set -u
export LC_ALL=C
build=${1:?usage: syn/scenes.sh BUILD_DIR [MHZ]}
mhz=${2:-}
root=$(cd "$(dirname "$0")/.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
ns=${EF_SCENES_NS:-8}
sched=()
[ -n "${EF_SCENES_SCHEDULE:-}" ] && sched=(--schedule "$EF_SCENES_SCHEDULE")
[ -x "$EF" ] || { echo "scenes: $EF not built (make cli)"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-scenes.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
python3 "$root/bench/paper_scenes.py" "$work/paper" || { echo "scenes: bench/paper_scenes.py failed"; exit 1; }
scenes=("$root/tests/data/svg/tiger.svg" "$root/tests/data/svg/lion.svg" "$root/tests/data/svg/lorem_ipsum_compound.svg")
for f in "$work"/paper/paper_*.txt; do scenes+=("$f"); done
rc=0 tc=0 tp=0 n=0
printf '%-40s %10s %9s %8s%s\n' scene cycles pixels pix/clk "${mhz:+ ms@${mhz}MHz}"
for s in "${scenes[@]}"; do
    name=$(basename "$s")
    if ! "$EF" vectors "$s" --samples "$ns" --size 640x480 "${sched[@]}" -o "$work/v" --force --formats hex --interfaces pix \
        >"$work/log" 2>&1; then
        echo "scenes: edgeflag vectors failed on $name: $(tail -n 1 "$work/log")"; rc=1; continue
    fi
    read -r cyc pix < <(python3 -c 'import json,sys
m = json.load(open(sys.argv[1]))
print(m["cycles"], sum(i["count"] for i in m["interfaces"] if i["name"] == "pix"))' "$work/v/manifest.json")
    ms=""
    [ -n "$mhz" ] && ms=$(awk -v c="$cyc" -v f="$mhz" 'BEGIN { printf " %9.3f", c / (f * 1000) }')
    printf '%-40s %10d %9d %8.3f%s\n' "$name" "$cyc" "$pix" "$(awk -v p="$pix" -v c="$cyc" 'BEGIN { print p / c }')" "$ms"
    case $name in paper_*) tc=$((tc + cyc)) tp=$((tp + pix)) n=$((n + 1)) ;; esac
done
[ $n -gt 0 ] && printf '%-40s %10d %9d %8.3f\n' "paper's synthetic set ($n scenes), sum" "$tc" "$tp" \
    "$(awk -v p="$tp" -v c="$tc" 'BEGIN { print p / c }')"
exit $rc
