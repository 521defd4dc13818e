#!/usr/bin/env bash
# tests/mutants/rtl-mutants-slice.sh - make test-rtl-mutants, the slice of make rtl-mutants in
# make test (issue 27): tests/mutants/rtl-mutants.sh under Icarus at NS 8 (the reference and the fast
# configuration) on its small cases (<= 4,000 cycles) and dv/tb/tb_err.v, over the mutants named in
# tests/mutants/slice_keys.tsv.
#   1. with EF_MUT_REQUIRE=1 the run must pass, and each mutant get the verdict the file names:
#      killed by a case (the plain dumps, tb_err's limit checks, tb_raster's pulse check), or
#      equivalent (listed in dv/mutants/equivalent.tsv);
#   2. the score check must bite: the same verdicts (reused, EF_MUT_CACHE) against
#      dv/mutants/equivalent.tsv without the equivalent mutant's line must FAIL the run, naming
#      it as the one survivor.
# usage: bash tests/mutants/rtl-mutants-slice.sh BUILD_DIR.  Ends with "N passed, M failed".
set -u
export LC_ALL=C
build=${1:?usage: tests/mutants/rtl-mutants-slice.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
keys=$root/tests/mutants/slice_keys.tsv
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-mutslice.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1${2:+: $2}"; }
grep -v '^#' "$keys" | tail -n +2 | cut -f1 >"$tmp/keys.txt"
export EF_MUT_SIM=icarus EF_MUT_NS=8 EF_MUT_SVGS=6 EF_MUT_GEN_SLICE=40 EF_MUT_REGRESS=0 EF_MUT_MAXCYC=4000 \
    EF_MUT_SVG_SIZE=16x12 EF_MUT_KEYS=$tmp/keys.txt EF_MUT_REQUIRE=1
mkdir -p "$tmp/w"
EF_MUT_REUSE=$tmp/w EF_MUT_OUT=$tmp/o1 bash "$root/tests/mutants/rtl-mutants.sh" "$build" >"$tmp/run1.log" 2>&1; rc=$?
if [ $rc = 0 ] && [ -f "$tmp/o1/results.tsv" ]; then
    ok "rtl-mutants over $(grep -c . "$tmp/keys.txt") mutants of slice_keys.tsv: $(grep -m1 '^all ' "$tmp/run1.log" | tr -s ' ')"
else
    tail -n 20 "$tmp/run1.log"; bad "rtl-mutants over slice_keys.tsv (exit $rc)"
fi
# each verdict as slice_keys.tsv says (results.tsv: id file line op key verdict...)
nv=0
while IFS=$'\t' read -r key want; do
    got=$(awk -F'\t' -v k="$key" '$5 == k { print $6 }' "$tmp/o1/results.tsv" 2>/dev/null)
    case $want:$got in
        killed:killed-rtl-test*|equivalent:equivalent) nv=$((nv + 1)) ;;
        *) bad "mutant $key" "want $want, got '${got:-no verdict}'" ;;
    esac
done < <(grep -v '^#' "$keys" | tail -n +2)
[ "$nv" = "$(grep -c . "$tmp/keys.txt")" ] && ok "each of the $nv mutants has the verdict slice_keys.tsv names ($(cut -f6 "$tmp/o1/results.tsv" | cut -d' ' -f1,2 | sort | uniq -c | tr -s ' ' | paste -sd, -))"

# 2. the score check fails when a survivor is not in the equivalent list
eq=$(grep -v '^#' "$keys" | awk -F'\t' '$2 == "equivalent" { print $1; exit }')
grep -vF "$eq	" "$root/dv/mutants/equivalent.tsv" >"$tmp/equiv.tsv"
if [ "$(wc -l <"$tmp/equiv.tsv")" = "$(($(wc -l <"$root/dv/mutants/equivalent.tsv") - 1))" ] && [ -f "$tmp/w/stage1.txt" ]; then
    cp "$tmp/w/stage1.txt" "$tmp/stage1.txt"
    EF_MUT_REUSE=$tmp/w EF_MUT_CACHE=$tmp/stage1.txt EF_MUT_EQUIV=$tmp/equiv.tsv \
        bash "$root/tests/mutants/rtl-mutants.sh" "$build" >"$tmp/run2.log" 2>&1; rc=$?
    if [ $rc != 0 ] && grep -q '^FAIL rtl-mutants: 1 non-equivalent mutants survive' "$tmp/run2.log" &&
        grep -qF "key $eq" "$tmp/run2.log"; then
        ok "without its equivalent.tsv line the run fails (exit $rc): 1 non-equivalent survivor, $eq"
    else
        tail -n 20 "$tmp/run2.log"; bad "the score check did not bite without the equivalent line (exit $rc)"
    fi
else
    bad "could not drop '$eq' from dv/mutants/equivalent.tsv, or no stage-1 verdicts kept"
fi
echo "$pass passed, $fail failed"
[ $fail = 0 ]
