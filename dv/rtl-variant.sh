#!/usr/bin/env bash
# dv/rtl-variant.sh - an RTL variant: a copy of rtl/ with recipes applied.
# The one way the tree makes RTL that differs from rtl/ (the planted faults
# of dv/faults/, a mutation run's mutants): rtl/ itself holds no test-only
# code, and a bench builds a variant exactly as it builds rtl/, from the
# copy's folder (with -I on it for the `include files).  docs/testing.md,
# "RTL variants".
#
# usage: dv/rtl-variant.sh OUTDIR [RECIPE...]
#   OUTDIR   made (or emptied of *.v, *.vh, *.sv) and filled with rtl/'s
#            *.v, *.vh and *.sv, then each RECIPE applied in order
#   RECIPE   a file, or a NAME for dv/faults/NAME.sed
#
# A recipe is a sed script with one header line "# file: NAME" (the file of
# rtl/ it edits) and one sed command per line (no multi-line commands; other
# "#" lines and blank lines are comments).  Each command is applied alone,
# in order, and must change the file: a command that no longer matches (the
# RTL moved on under it) is an error naming the recipe's line, never a
# variant that silently equals rtl/.
# Exit: 0 made; 1 a recipe did not apply; 2 usage or a missing file.
set -u
export LC_ALL=C
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: dv/rtl-variant.sh OUTDIR [RECIPE...]" >&2; exit 2; }
out=$1; shift
mkdir -p "$out" || exit 2
rm -f "$out"/*.v "$out"/*.vh "$out"/*.sv
cp "$root"/rtl/*.v "$root"/rtl/*.vh "$root"/rtl/*.sv "$out"/ || exit 2
applied=()
for r in "$@"; do
    f=$r
    [ -f "$f" ] || f=$root/dv/faults/$r.sed
    [ -f "$f" ] || { echo "rtl-variant: no recipe '$r' (a file, or dv/faults/$r.sed)" >&2; exit 2; }
    target=$(sed -n 's/^# file: *//p' "$f")
    [ "$(printf '%s\n' "$target" | grep -c .)" = 1 ] ||
        { echo "rtl-variant: $f: needs exactly one '# file: NAME' line" >&2; exit 2; }
    [ -f "$out/$target" ] || { echo "rtl-variant: $f: no file $target in rtl/" >&2; exit 2; }
    n=0 k=0
    while IFS= read -r line || [ -n "$line" ]; do
        n=$((n + 1))
        case $line in '' | '#'*) continue ;; esac
        sed -e "$line" "$out/$target" >"$out/$target.new" ||
            { echo "rtl-variant: $f:$n: sed refused the command" >&2; rm -f "$out/$target.new"; exit 1; }
        if cmp -s "$out/$target.new" "$out/$target"; then
            echo "rtl-variant: $f:$n: the command does not change $target (the RTL moved on under it?)" >&2
            rm -f "$out/$target.new"; exit 1
        fi
        mv "$out/$target.new" "$out/$target"; k=$((k + 1))
    done <"$f"
    [ $k -gt 0 ] || { echo "rtl-variant: $f: no command" >&2; exit 2; }
    applied+=("$(basename "$f") ($k on $target)")
done
{ echo "RTL variant of $root/rtl, made by dv/rtl-variant.sh"; for a in "${applied[@]}"; do echo "applied: $a"; done; } \
    >"$out/VARIANT"
exit 0
