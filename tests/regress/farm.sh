#!/usr/bin/env bash
# tests/regress/farm.sh - `make farm-test`: the regression of docs/regress.md on a real scheduler.
# Starts a single-node Slurm (tools/slurm-local.sh), submits level 1 as a job array of 6 shards
# with tools/regress/ef-regress.sbatch, cancels shard 4 while the array runs (a shard that
# dies), waits, merges, and demands: shards 1-3 and 5-6 complete and passed, shard 4 MISSING or
# UNFINISHED, RESULT FAIL, a well-formed merged JUnit with a "missing shard" failure; then
# resubmits shard 4 alone and demands a PASS over all 261 cases.  Stops Slurm at the end.
# usage: bash tests/regress/farm.sh BUILD_DIR      (root; Debian's slurm-wlm and munge)
set -u
export LC_ALL=C
build=${1:?usage: tests/regress/farm.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
export EDGEFLAG=$build/edgeflag
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
scratch=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-farm.XXXXXX") || exit 1
cleanup() { bash "$root/tools/slurm-local.sh" stop "$scratch/slurm"; rm -rf "$scratch"; }
trap cleanup EXIT

env_line=$(bash "$root/tools/slurm-local.sh" start "$scratch/slurm") || { echo "farm: Slurm did not start"; echo "0 passed, 1 failed"; exit 1; }
eval "$env_line"
echo "farm: single-node Slurm up ($(sinfo -h -o '%n %c CPUs %t'))"
export EF_REGRESS_OUT=$scratch/out EF_REGRESS_SEED=20070101 EF_REGRESS_LEVEL=1 EF_REGRESS_HOME=$root/tools/regress
mkdir -p "$EF_REGRESS_OUT"
cd "$scratch" || exit 1

t0=$(date +%s)
jid=$(sbatch --parsable --array=1-6 "$root/tools/regress/ef-regress.sbatch") || { bad "sbatch"; exit 1; }
scancel "${jid}_4"
for _ in $(seq 600); do [ -z "$(squeue -h -j "$jid" 2>/dev/null)" ] && break; sleep 1; done
wall=$(($(date +%s) - t0))
"$root/tools/regress/ef-regress-merge" "$EF_REGRESS_OUT" >merge1.out 2>&1
mrc=$?
sum=$EF_REGRESS_OUT/merged/summary.txt
done_ok=1
for i in 1 2 3 5 6; do grep -Eq "^ +$i  complete +[0-9]+ +0 " "$sum" || done_ok=0; done
if [ $mrc = 1 ] && [ $done_ok = 1 ] && grep -Eq '^ +4  (MISSING|UNFINISHED)' "$sum" && grep -q '^RESULT: FAIL' "$sum" &&
    xmllint --noout "$EF_REGRESS_OUT/merged/junit.xml" && grep -q '<failure type="missing shard"' "$EF_REGRESS_OUT/merged/junit.xml"; then
    ok "job array of 6 shards with shard 4 cancelled: 5 complete and passed, shard 4 $(grep -Eo '^ +4  [A-Z]+' "$sum" | awk '{ print $2 }'), merge FAIL (${wall} s)"
else
    bad "job array with a cancelled shard" "merge exit $mrc"; cat "$sum" merge1.out 2>/dev/null | tail -n 20
fi

# The missing shard rerun alone (the array's size stated, as the sbatch comment says).
t1=$(date +%s)
jid2=$(EF_REGRESS_SHARDS=6 sbatch --parsable --array=4 "$root/tools/regress/ef-regress.sbatch")
for _ in $(seq 600); do [ -z "$(squeue -h -j "$jid2" 2>/dev/null)" ] && break; sleep 1; done
"$root/tools/regress/ef-regress-merge" "$EF_REGRESS_OUT" >merge2.out 2>&1
mrc=$?
runs=$(sed -n 's/^runs: \([0-9]*\) in 6 of 6 shards.*/\1/p' "$sum")
if [ $mrc = 0 ] && grep -q '^RESULT: PASS' "$sum" && [ "$runs" = "$("$EDGEFLAG" gen --list | grep -c '^[0-9]')" ]; then
    ok "shard 4 resubmitted alone: merge PASS, $runs runs in 6 of 6 shards ($(($(date +%s) - t1)) s)"
else
    bad "rerun of shard 4" "merge exit $mrc"; tail -n 20 "$sum"
fi
grep -E '^throughput' "$sum" | sed 's/^/    /'
echo "farm: $pass passed, $fail failed"
[ $fail = 0 ]
