#!/usr/bin/env bash
# tests/regress/run.sh - the farm flow of docs/regress.md as a user runs it, with GNU parallel:
#   1. the whole level-1 set in 4 shards (parallel -j2), merged: PASS, every case of
#      `edgeflag gen` run exactly once, one well-formed JUnit (xmllint) and a summary;
#   2. a shard killed mid-run and a shard never started show as missing, never as passed;
#   3. a DUT that gets one pixel wrong, one that never writes pix.actual.hex, and one that hangs
#      past --timeout fail, with the case's seed and first mismatch line in the summary;
#   4. shards of another seed (or level) are refused by the merge;
#   5. the DUT's limits: runs over --dut-limits/--dut-edges are refused by name before any
#      simulation, and a DUT's own REFUSED is quoted; both counted apart from failures; with
#      --fit, gen's refusals reach the merged report with each case's real configuration
#      (sample count, rule, its own seed) and gen's reason, counted by who refused.
# usage: bash tests/regress/run.sh BUILD_DIR   (`make test-regress`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C
build=${1:?usage: tests/regress/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
export EDGEFLAG=$build/edgeflag
SHARD=$root/tools/regress/ef-regress-shard
MERGE=$root/tools/regress/ef-regress-merge
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1${2:+: $2}"; }
for t in "$EDGEFLAG" parallel xmllint; do
    command -v "$t" >/dev/null || { echo "regress: $t not found (make test installs it)"; echo "0 passed, 1 failed"; exit 1; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-regress.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

# ------------------------------------------------------------ 1. level 1 under GNU parallel
t0=$(date +%s)
parallel --halt never -j2 "$SHARD" --out R --shard {}/4 ::: 1 2 3 4 >par.log 2>&1
prc=$?
"$MERGE" R >merge.out 2>&1
mrc=$?
ncases=$("$EDGEFLAG" gen --list | grep -c '^[0-9]')
nruns=$(cat R/shard_*_of_4/cases.tsv | grep -c '^[0-9]')
nuniq=$(cat R/shard_*_of_4/cases.tsv | grep '^[0-9]' | cut -f1 | sort -u | wc -l)
if [ $prc = 0 ] && [ $mrc = 0 ] && grep -q '^RESULT: PASS' R/merged/summary.txt && [ "$nruns" = "$ncases" ] &&
    [ "$nuniq" = "$ncases" ] && xmllint --noout R/merged/junit.xml &&
    grep -q "<testsuites name=\"edgeflag regress seed 20070101 level 1\" tests=\"$ncases\" failures=\"0\"" R/merged/junit.xml; then
    ok "level 1 in 4 shards under GNU parallel: $nruns runs, each of the $ncases cases once, merged PASS ($(($(date +%s) - t0)) s)"
else
    bad "level 1 under GNU parallel" "parallel $prc, merge $mrc, $nruns runs of $ncases cases ($nuniq distinct)"
    tail -n 20 merge.out par.log
fi
grep -E '^throughput' R/merged/summary.txt | sed 's/^/    /'

# ------------------------------------------------------------ 2. a killed shard, a missing shard
# 40 shards of a DUT that takes a second a case: shards 1 and 2 run to the end, shard 3 is
# killed after 3 s (of its 7 cases), shards 4..40 never start.
# shellcheck disable=SC2016 # expanded by the shard, for each case
slow='sleep 1; "$EDGEFLAG" vectors "$EF_CASE_FILE" -o "$EF_DUMPS" --samples "$EF_SAMPLES" $EF_RULE_OPT --dump --force --formats hex'
parallel -j2 "$SHARD" --out K --shard {}/40 --run "'$slow'" ::: 1 2 >/dev/null 2>&1
( timeout -s KILL 3 "$SHARD" --out K --shard 3/40 --run "$slow" >/dev/null 2>&1 ) 2>/dev/null
"$MERGE" K >kmerge.out 2>&1
krc=$?
if [ $krc = 1 ] && grep -q '^    1  complete' K/merged/summary.txt && grep -q '^    3  UNFINISHED' K/merged/summary.txt &&
    grep -q '^    4  MISSING' K/merged/summary.txt && grep -q '^RESULT: FAIL' K/merged/summary.txt &&
    xmllint --noout K/merged/junit.xml && [ "$(grep -c '<failure type="missing shard"' K/merged/junit.xml)" = 38 ]; then
    ok "a shard killed mid-run is UNFINISHED and an absent one MISSING: both JUnit failures, merge exit 1"
else
    bad "killed and missing shards" "merge exit $krc"; cat kmerge.out
fi

# ------------------------------------------------------------ 3. DUTs that are wrong
# One pixel wrong: the model's dumps with the first pix word's rgba flipped in bit 0.
cat >dut_flip.sh <<'EOF'
#!/usr/bin/env bash
# A DUT that renders like the model but gets the last pixel of the frame wrong (rgba bit 0).
set -e
"$EDGEFLAG" vectors "$EF_CASE_FILE" -o "$EF_DUMPS" --samples "$EF_SAMPLES" $EF_RULE_OPT --dump --force --formats hex >/dev/null
f=$EF_DUMPS/pix.actual.hex
last=$(grep -v '^//' "$f" | tail -n 1)
[ -n "$last" ] || exit 0
new=${last%?}$(printf '%x' $(( 16#${last: -1} ^ 1 )))
sed -i "\$s/.*/$new/" "$f"
EOF
chmod +x dut_flip.sh
"$SHARD" --out F --shard 5/40 --run "bash $tmp/dut_flip.sh" >flip.log 2>&1
frc=$?
"$MERGE" F >fmerge.out 2>&1
fmrc=$?
nf=$(grep -c '	fail	' F/shard_5_of_40/cases.tsv)
if [ $frc = 1 ] && [ $fmrc = 1 ] && [ "$nf" -ge 1 ] &&
    grep -Eq '^  case [0-9]+ \([0-9]+ samples, rule scene, seed [0-9a-fx]+\) fail in shard 5: .*pix: cycle [0-9]+, y [0-9]+, x [0-9]+: fields differ' F/merged/summary.txt &&
    ls F/shard_5_of_40/fail/case_*/dumps/pix.actual.hex >/dev/null 2>&1; then
    ok "a DUT with one wrong pixel: $nf failing runs, each with its seed and first mismatch line in the summary, files kept"
else
    bad "one wrong pixel" "shard exit $frc, merge exit $fmrc, $nf failing runs"; tail -5 flip.log; grep -A3 FAILED F/merged/summary.txt
fi
# shellcheck disable=SC2016 # expanded by the shard, for each case
"$SHARD" --out P --shard 7/40 --run 'cd "$EF_DUMPS" && for f in "$EF_VECTORS"/*.expected.hex; do
    b=$(basename "$f" .expected.hex); [ "$b" = pix ] || grep -v "^//" "$f" >"$b.actual.hex"; done' >p.log 2>&1
prc=$?
np=$(grep -c '	fail	.*pix: FAIL: dumps holds no dump of it' P/shard_7_of_40/cases.tsv)
nr=$(grep -c '^[0-9]' P/shard_7_of_40/cases.tsv)
[ $prc = 1 ] && [ "$np" = "$nr" ] && [ "$nr" -gt 0 ] && ok "a DUT that never writes pix.actual.hex fails every run ($np of $nr)" ||
    bad "DUT without pix" "exit $prc, $np of $nr failed for the missing pix"
"$SHARD" --out T --shard 9/130 --run 'sleep 30' --timeout 1 >t.log 2>&1
trc=$?
nt=$(grep -c '	timeout	' T/shard_9_of_130/cases.tsv)
nr=$(grep -c '^[0-9]' T/shard_9_of_130/cases.tsv)
[ $trc = 1 ] && [ "$nt" = "$nr" ] && [ "$nr" -gt 0 ] && grep -q '<error type="timeout"' T/shard_9_of_130/junit.xml &&
    ok "a DUT that hangs: every run a timeout after --timeout 1 ($nt runs), JUnit errors" || bad "timeout" "exit $trc, $nt of $nr"

# ------------------------------------------------------------ 5. the DUT's limits
# Level 1 in 4 shards for a DUT of 64x64 pixels, 200 edges a shape, 8 and 16 samples: the runs
# over it are refused by name before any simulation, counted apart, and the merge passes.
parallel --halt never -j2 "$SHARD" --out L --shard {}/4 --dut-limits 64x64 --dut-edges 200 --dut-samples 8,16 ::: 1 2 3 4 \
    >lpar.log 2>&1
lprc=$?
"$MERGE" L >lmerge.out 2>&1
lmrc=$?
# cases.tsv: case samples rule seed verdict seconds first
refs() { cat L/shard_*_of_4/cases.tsv | awk -F'\t' -v re="$1" '$5 == "refused" && $7 ~ re { n++ } END { print n + 0 }'; }
nref=$(refs '^refused before simulation: ')
ncanvas=$(refs "^refused before simulation: canvas [0-9]+x[0-9]+ over the DUT's 64x64 [(]--dut-limits[)]: refused\$")
nedges=$(refs "^refused before simulation: shape [0-9]+ has [0-9]+ edges, over the DUT's 200 [(]--dut-edges[)]: refused\$")
nsamp=$(refs "^refused before simulation: 32 samples per pixel, the DUT takes 8,16\$")
if [ $lprc = 0 ] && [ $lmrc = 0 ] && [ "$ncanvas" -gt 0 ] && [ "$nedges" -gt 0 ] && [ "$nsamp" -gt 0 ] &&
    [ "$nref" = $((ncanvas + nedges + nsamp)) ] &&
    grep -q "^runs: $ncases in 4 of 4 shards; failed: 0; refused (do not fit the DUT, not failures): $nref;" L/merged/summary.txt &&
    grep -q "^refused by: edgeflag gen (fitting the cases to the DUT) 0; the DUT's limits before simulation $nref; the DUT itself 0$" L/merged/summary.txt &&
    grep -q '^REFUSED runs' L/merged/summary.txt && grep -q '^RESULT: PASS' L/merged/summary.txt &&
    xmllint --noout L/merged/junit.xml && [ "$(grep -c '<skipped message="refused before simulation' L/merged/junit.xml)" = "$nref" ]; then
    ok "the DUT's limits (64x64, 200 edges, 8 and 16 samples): $nref of $ncases runs refused by name before simulation ($ncanvas canvas, $nedges edges, $nsamp sample count), counted apart, JUnit skipped, merge PASS"
else
    bad "DUT limits" "parallel $lprc, merge $lmrc, $nref refused ($ncanvas canvas, $nedges edges, $nsamp samples); $(grep -E '^runs|^RESULT' L/merged/summary.txt)"
fi
# --fit: the same limits go to edgeflag gen, which fits what it can (canvases scaled, shapes
# split where the picture stays) and refuses the rest by name; nothing over the limits reaches
# vectors or the DUT.  Shard 2/26 holds zigzag-4096 (case 53: one contour of 4096 edges, over 200).
"$EDGEFLAG" gen -o Fgen --shard 2/26 >/dev/null 2>&1
nbig=$(cd Fgen && awk '/^scene/ && ($2 > 64 || $3 > 64) { n++ } END { print n + 0 }' case_*.scene)
"$SHARD" --out FIT --shard 2/26 --fit --dut-limits 64x64 --dut-edges 200 --dut-samples 8,16 --rules scene,evenodd >f.log 2>&1
frc=$?
F=FIT/shard_2_of_26/cases.tsv
fgen=$(awk -F'\t' '$5 == "refused" && $7 ~ /^refused before simulation: edgeflag gen: / { n++ } END { print n + 0 }' "$F")
fother=$(awk -F'\t' '$5 == "refused" && $7 !~ /^refused before simulation: edgeflag gen: / { n++ } END { print n + 0 }' "$F")
fpass=$(awk -F'\t' '$5 == "pass" { n++ } END { print n + 0 }' "$F")
fs=$(awk -F'\t' 'NR > 1 && $2 != 8 && $2 != 16 { n++ } END { print n + 0 }' "$F")
if [ $frc = 0 ] && [ "$nbig" -gt 0 ] && [ "$fother" = 0 ] && [ "$fs" = 0 ] && [ "$fpass" -gt 0 ] &&
   grep -q "^53	16	scene	20070101	refused	.*edgeflag gen: shape 0 has 4096 edges, over the DUT's 200, and its contour 0 alone has 4096" "$F" &&
   [ "$(grep -c '<skipped message="refused before simulation: edgeflag gen: ' FIT/shard_2_of_26/junit.xml)" = "$fgen" ]; then
    ok "--fit (64x64, 200 edges, 8 and 16 samples, 2 rules): gen fits the shard's $nbig canvases over 64x64 ($fpass runs pass), refuses $((fgen / 2)) case(s) ($fgen runs) by name (zigzag-4096: a contour of 4096 edges), nothing refused later, every run at 8 or 16 samples"
else
    bad "--fit" "exit $frc, big $nbig, pass $fpass, gen-refused $fgen, other refusals $fother, other sample counts $fs; $(tail -n 3 "$F")"
fi
# The merged report of the --fit shard (two rules, so two runs a case): gen's refusals counted
# apart from failures and by who refused, each with the configuration the case would have run in
# (sample count and rule) and its own seed (a random case's, from the unfitted index), gen's
# reason quoted; the runs add up to the shard's cases times its rules, as without limits.
"$MERGE" FIT >f2merge.out 2>&1
F2=FIT/merged/summary.txt
ncase2=$("$EDGEFLAG" gen --list --shard 2/26 | grep -c '^[0-9]')
seed105=$("$EDGEFLAG" gen --list --shard 2/26 | awk -F'\t' '$1 == 105 { print $7 }')
fg2=$(grep -c '^  case [0-9]* ([0-9]* samples, rule [a-z]*, seed [0-9a-fx]*) in shard 2: refused before simulation: edgeflag gen: ' "$F2")
if grep -q "^runs: $((2 * ncase2)) in 1 of 26 shards; failed: 0; refused (do not fit the DUT, not failures): $fgen;" "$F2" &&
   grep -q "^refused by: edgeflag gen (fitting the cases to the DUT) $fgen; the DUT's limits before simulation 0; the DUT itself 0$" "$F2" &&
   grep -q "^    2  complete *$((2 * ncase2)) *0 *$fgen " "$F2" && [ "$fg2" = "$fgen" ] &&
   grep -q "^  case 53 (16 samples, rule evenodd, seed 20070101) in shard 2: refused before simulation: edgeflag gen: shape 0 has 4096 edges, over the DUT's 200" "$F2" &&
   [ -n "$seed105" ] && grep -q "^  case 105 (16 samples, rule scene, seed $seed105) in shard 2: refused before simulation: edgeflag gen: shape 2 has" "$F2" &&
   ! grep -q -- '(- samples' "$F2"; then
    ok "merged report of a --fit shard: $fgen runs refused by edgeflag gen counted apart (by who refused, per shard), each with its sample count, rule and own seed (case 105: $seed105) and gen's reason; $((2 * ncase2)) runs = the shard's $ncase2 cases x 2 rules"
else
    bad "merged report of a --fit shard" "cases $ncase2, gen-refused $fgen, seed105 '$seed105'; $(grep -E '^(runs|refused by|    2 )|case (53|105) ' "$F2" | head -n 6)"
fi
# A DUT that refuses a case itself (exit non-zero with its REFUSED line): refused, its own words quoted.
"$SHARD" --out D --shard 9/130 --run 'echo "tb_raster: REFUSED cmd.stim.hex:5: FRAME canvas over the hardware W_MAX x H_MAX"; exit 1' >d.log 2>&1
drc=$?
nd=$(awk -F'\t' '$5 == "refused" && index($7, "the DUT refused it: tb_raster: REFUSED cmd.stim.hex:5: FRAME canvas over") == 1 { n++ }
              END { print n + 0 }' D/shard_9_of_130/cases.tsv)
nr=$(grep -c '^[0-9]' D/shard_9_of_130/cases.tsv)
"$MERGE" D >/dev/null 2>&1
if [ $drc = 0 ] && [ "$nd" = "$nr" ] && [ "$nr" -gt 0 ] && grep -q "^refused	$nr$" D/shard_9_of_130/shard.meta &&
   grep -q "^refused by: edgeflag gen (fitting the cases to the DUT) 0; the DUT's limits before simulation 0; the DUT itself $nr$" D/merged/summary.txt &&
   grep -q "^  case [0-9]* ([0-9]* samples, rule scene, seed [0-9a-fx]*) in shard 9: the DUT refused it: tb_raster: REFUSED cmd.stim.hex:5: " D/merged/summary.txt; then
    ok "a DUT that refuses a case itself: refused ($nd runs), quoting its REFUSED line, not a failure (exit 0); the merge counts it as the DUT's"
else
    bad "a refusing DUT" "exit $drc, $nd of $nr refused: $(tail -n 2 D/shard_9_of_130/cases.tsv)"
fi

# ------------------------------------------------------------ 4. shards that do not belong together
mkdir -p X && cp -R R/shard_1_of_4 R/shard_2_of_4 R/shard_3_of_4 X/
"$SHARD" --out X --shard 4/4 --seed 7 >/dev/null 2>&1
"$MERGE" X >x.out 2>&1
xrc=$?
[ $xrc = 2 ] && grep -q 'shards do not belong together: .*seed 20070101.*seed 7' x.out && [ ! -e X/merged/junit.xml ] &&
    ok "a shard of another seed: merge refused (exit 2), no report written" || bad "mixed seeds" "exit $xrc: $(cat x.out)"
rm -rf X/shard_4_of_4 && cp -R R/shard_4_of_4 X/ && sed -i 's/^level\t1$/level\t2/' X/shard_4_of_4/shard.meta
"$MERGE" X >x2.out 2>&1
[ $? = 2 ] && grep -q 'level 1.*level 2\|level 2.*level 1' x2.out && ok "a shard of another level: merge refused" ||
    bad "mixed levels" "$(cat x2.out)"
"$MERGE" R --shards 8 >s.out 2>&1
[ $? = 2 ] && grep -q -- '--shards 8, but the shards were run as 4' s.out && ok "--shards 8 against a 4-shard run: refused" ||
    bad "--shards" "$(cat s.out)"
"$SHARD" --out Z --shard 5/4 >z.out 2>&1
[ $? = 2 ] && grep -q 'I must be 1..N' z.out && ok "--shard 5/4: usage error, exit 2" || bad "bad --shard" "$(cat z.out)"

echo "regress: $pass passed, $fail failed"
[ $fail = 0 ]
