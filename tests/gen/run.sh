#!/usr/bin/env bash
# tests/gen/run.sh - `edgeflag gen` as a regression farm meets it (docs/gen.md):
# a level-1 run, every generated case rendered at 8, 16 and 32 samples, the
# same bytes twice, shards 1/3 2/3 3/3 written into one directory equal to
# the unsharded run file for file and byte for byte, -n that raises and never
# lowers, bad options (exit 2, nothing created), existing files (exit 4
# unless --force), --list, help.  Needs only bash and coreutils.
#
# usage: bash tests/gen/run.sh BUILD_DIR      (from anywhere; `make test-gen`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
# 10-25 s on 2 cores (bound by fsync): the 16384 x 16384 canvas is rendered once (8 samples,
# .pgm: a 1 GiB image in memory), every other case at all three counts.
set -u
export LC_ALL=C   # sort order and messages

build=${1:?usage: tests/gen/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
JOBS=${EF_GEN_JOBS:-4}
if [ ! -x "$EF" ]; then
    echo "gen: $EF not found (make cli first)"
    echo "0 passed, 1 failed"
    exit 1
fi

# Every file is written atomically with fsync: a RAM disk keeps that cheap.
tmpbase=${TMPDIR:-}
if [ -z "$tmpbase" ]; then
    tmpbase=/tmp
    [ -d /dev/shm ] && [ -w /dev/shm ] && tmpbase=/dev/shm
fi
tmp=$(mktemp -d "$tmpbase/edgeflag-gen.XXXXXX") || exit 1
cleanup() { chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
cd "$tmp" || exit 1

pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok   - $1"; }
bad() {
    fail=$((fail + 1)); echo "FAIL - $1"
    shift
    for line in "$@"; do echo "       $line"; done
    if [ -s err ]; then sed 's/^/       stderr: /' err | head -n 5; fi
}
run() { "$EF" "$@" >out 2>err; rc=$?; }
# rows FILE: the index's case rows (after its two header lines)
rows() { tail -n +3 "$1"; }
# drawings DIR: one line per case file, "NAME<TAB>its non-comment lines joined by |"
drawings() {
    (cd "$1" && awk '!/^#/ { d[FILENAME] = d[FILENAME] $0 "|" } END { for (f in d) print f "\t" d[f] }' case_*.scene) | sort
}

# ------------------------------------------------------------ level 1
run gen -o l1
total=$(sed -n 's/.* \([0-9][0-9]*\) cases (.*/\1/p' l1/index.tsv 2>/dev/null)
nfiles=$(find l1 -name 'case_*.scene' | wc -l)
if [ $rc -eq 0 ] && [ -n "$total" ] && [ "$nfiles" -eq "$total" ] && [ "$(rows l1/index.tsv | wc -l)" -eq "$total" ] &&
   grep -q "^edgeflag gen: wrote $total of $total cases .*seed 20070101, level 1, shard 1/1" out && [ ! -s err ]; then
    ok "gen -o l1: $total cases, index rows, summary"
else
    bad "gen -o l1" "rc=$rc total=$total files=$nfiles"
fi
ndir=$(rows l1/index.tsv | awk -F'\t' '$3 == "directed"' | wc -l)
nrand=$(rows l1/index.tsv | awk -F'\t' '$3 == "random"' | wc -l)
if [ "$nrand" -eq 200 ] && [ "$ndir" -gt 0 ] && [ $((ndir + nrand)) -eq "$total" ]; then
    ok "level 1: $ndir directed then 200 random"
else
    bad "level 1 counts" "directed=$ndir random=$nrand"
fi
cats=$(rows l1/index.tsv | awk -F'\t' '$3 == "directed" { print $4 }' | sort -u | tr '\n' ' ')
want="cancel canvas clip-border coincident compositing coord-limits degenerate edges-per-row horizontal outside sample-grid slope vertical winding-overflow zero-length "
if [ "$cats" = "$want" ]; then ok "every directed category present"; else bad "categories" "got: $cats" "want: $want"; fi
badhdr=$(awk 'FNR == 1 && !/^# edgeflag gen: generator [0-9]+, edgeflag / { n++ }
              FNR == 2 && !/^# seed 20070101, level 1, case [0-9]+ of / { n++ } END { print n + 0 }' l1/case_*.scene)
if [ "$badhdr" -eq 0 ]; then ok "every file starts with the generator, seed, level and case"; else bad "headers" "$badhdr files"; fi

# ------------------------------------------- render every case at 8/16/32
# A case whose canvas exceeds 2^24 pixels is rendered once (8 samples, .pgm).
mkdir -p img
for f in l1/case_*.scene; do
    read -r _ w h < <(grep -m1 '^scene ' "$f")
    if [ $((w * h)) -gt 16777216 ]; then
        echo "$f 8 pgm"
    else
        for n in 8 16 32; do echo "$f $n pam"; done
    fi
done >jobs.txt
njobs=$(wc -l <jobs.txt)
t0=$(date +%s)
# each job prints "FAIL ..." or the stderr lines it produced
# shellcheck disable=SC2016  # $0..$3 belong to the inner sh
xargs -P "$JOBS" -L 1 sh -c '
    b=$(basename "$1" .scene)
    o=img/$b.$2.$3
    if "$0" render "$1" -o "$o" --samples "$2" 2>"$o.err"; then :; else echo "FAIL $1 --samples $2 rc=$?"; fi
    cat "$o.err"; rm -f "$o" "$o.err"' "$EF" <jobs.txt >render.log 2>&1
t1=$(date +%s)
nfail=$(grep -c '^FAIL' render.log)
other=$(grep -v '^FAIL' render.log | grep -vc 'winding counter overflow')
if [ "$nfail" -eq 0 ] && [ "$other" -eq 0 ]; then
    ok "rendered $njobs case x sample-count runs, all exit 0 ($((t1 - t0)) s; $(grep -c 'winding counter overflow' render.log) overflow warnings)"
else
    bad "render every case" "$nfail failed, $other unexpected stderr lines" "$(grep -v 'winding counter overflow' render.log | head -n 5)"
fi
ov=$(rows l1/index.tsv | awk -F'\t' '$5 == "overflow-128" { print $2 }')
"$EF" render "l1/$ov" -o ov.pam --samples 16 >out 2>err
if [ -n "$ov" ] && grep -q 'winding counter overflow' err; then ok "overflow-128 warns"; else bad "overflow-128 warning" "file=$ov"; fi
rm -f ov.pam

# ---------------------------------------------------------- determinism
run gen -o l1b
if [ $rc -eq 0 ] && diff -r l1 l1b >/dev/null; then ok "a second run writes the same bytes"; else bad "determinism" "rc=$rc"; fi
run gen --list --seed 20070101 --level 1 -n 200 --shard 1/1 --samples 16
if [ $rc -eq 0 ] && cmp -s out l1/index.tsv; then ok "the defaults spelled out give the same index"; else bad "explicit defaults" "rc=$rc"; fi

# --------------------------------------------------------------- shards
# three shards into one directory, as array jobs sharing an output folder
src=0
for i in 1 2 3; do
    "$EF" gen -o sh --shard "$i/3" >"out$i" 2>err || src=1
done
nsh=$(find sh -name 'case_*.scene' | wc -l)
if [ $src -eq 0 ] && [ "$nsh" -eq "$total" ] && diff -r -x 'index*.tsv' l1 sh >/dev/null; then
    ok "shards 1/3 2/3 3/3 == unsharded: same $nsh files, same bytes"
else
    bad "shard union" "rc=$src files=$nsh"
fi
for i in 1 2 3; do rows "sh/index_${i}_of_3.tsv"; done | sort -n >union.tsv
rows l1/index.tsv >whole.tsv
if cmp -s union.tsv whole.tsv && [ "$(cat sh/index_*_of_3.tsv | wc -l)" -eq $((total + 6)) ]; then
    ok "shard indexes: rows disjoint, union == index.tsv"
else
    bad "shard index union"
fi
over=0
for i in 1 2 3; do
    while IFS=$'\t' read -r k _; do
        [ $((k % 3)) -eq $((i - 1)) ] || over=$((over + 1))
    done < <(rows "sh/index_${i}_of_3.tsv")
done
if [ $over -eq 0 ]; then ok "shard I/3 holds exactly the cases k mod 3 = I-1"; else bad "shard rule" "$over misplaced"; fi
run gen -o sh7 --shard 7/7
n7=$(find sh7 -name 'case_*.scene' | wc -l)
if [ $rc -eq 0 ] && [ "$n7" -eq $(((total - 7) / 7 + 1)) ] && [ -e sh7/case_000006.scene ] && [ ! -e sh7/case_000000.scene ]; then
    ok "--shard 7/7: $n7 cases starting at case 6"
else
    bad "--shard 7/7" "rc=$rc files=$n7"
fi

# ----------------------------------------------------------------- -n
run gen -o n201 -n 201
drawings l1 >d_l1
same=0
drawings n201 | grep -v "^case_$(printf '%06d' "$total")" | cmp -s - d_l1 && same=1
if [ $rc -eq 0 ] && [ "$(find n201 -name 'case_*.scene' | wc -l)" -eq $((total + 1)) ] && [ $same -eq 1 ]; then
    ok "-n 201 adds one case; the other drawings are unchanged"
else
    bad "-n 201" "rc=$rc same=$same"
fi

# --------------------------------------------------------- bad options
while IFS= read -r args; do
    [ -z "$args" ] && continue
    rm -rf bad
    # shellcheck disable=SC2086
    run gen $args
    if [ $rc -eq 2 ] && grep -q '^edgeflag: gen: ' err && [ ! -e bad ] && [ ! -s out ]; then
        ok "bad option: gen $args -> 2, nothing created"
    else
        bad "bad option: gen $args" "rc=$rc (want 2, a message, no directory)"
    fi
done <<'EOF'
-o bad -n 199
-o bad -n 0
-o bad --level 2 -n 19999
-o bad -n 2000000
-o bad -n 12x
-o bad --level 3
-o bad --level 0
-o bad --level 1x
-o bad --level
-o bad --seed -1
-o bad --seed 18446744073709551616
-o bad --seed 0x10
-o bad --seed 12abc
-o bad --seed=
-o bad --shard 0/3
-o bad --shard 4/3
-o bad --shard 1/0
-o bad --shard 1
-o bad --shard 1/3/4
-o bad --shard /3
-o bad --shard -1/3
-o bad --samples 12
-o bad --samples 8x
-o bad --frob
-o bad extra
-o bad -o bad2
-o bad --level 1 --level 1
-o bad --force --force
-o bad --list
--list --force
--seed 5
EOF
run gen --seed 18446744073709551615 --list
if [ $rc -eq 0 ] && head -n 1 out | grep -q 'seed 18446744073709551615,'; then ok "--seed 2^64-1 accepted"; else bad "--seed max" "rc=$rc"; fi

# ------------------------------------------------- existing files, --force
before=$(cat l1/index.tsv l1/case_000000.scene | cksum)
run gen -o l1
if [ $rc -eq 4 ] && grep -q 'exists' err && [ "$(cat l1/index.tsv l1/case_000000.scene | cksum)" = "$before" ] &&
   [ -z "$(find l1 -name '.case_*')" ]; then
    ok "existing files: exit 4, nothing changed"
else
    bad "existing files" "rc=$rc (want 4)"
fi
run gen -o l1 --seed 7
if [ $rc -eq 4 ] && diff -r l1 l1b >/dev/null; then ok "another seed into a used directory: refused, untouched"; else bad "refuse other seed" "rc=$rc"; fi
run gen -o l1 --force
if [ $rc -eq 0 ] && diff -r l1 l1b >/dev/null; then ok "--force rewrites the same bytes"; else bad "--force" "rc=$rc"; fi
: >afile
run gen -o afile/sub
if [ $rc -eq 4 ] && [ ! -s out ]; then ok "a file in the way of DIR: exit 4"; else bad "file in the way" "rc=$rc"; fi
run gen -o deep/er/dir --shard 2/500
if [ $rc -eq 0 ] && [ -f deep/er/dir/index_2_of_500.tsv ] && [ -f deep/er/dir/case_000001.scene ]; then
    ok "missing parents created; shard index name"
else
    bad "mkdir -p / shard index" "rc=$rc"
fi

# --------------------------------------------------------- seeds, grids
run gen -o s2 --seed 2
dsame=0
rows l1/index.tsv | awk -F'\t' '$3 == "directed" { print $2 }' >dfiles
mapfile -t dlist <dfiles
(cd l1 && awk 'FNR != 2' "${dlist[@]}") >d1
(cd s2 && awk 'FNR != 2' "${dlist[@]}") >d2
cmp -s d1 d2 && dsame=1
rdiff=$(drawings s2 | join -t "$(printf '\t')" d_l1 - | awk -F'\t' '$2 != $3' | wc -l)
if [ $rc -eq 0 ] && [ $dsame -eq 1 ] && [ "$rdiff" -ge 195 ]; then
    ok "--seed 2: directed cases unchanged but for the seed line, $rdiff of 200 random drawings differ"
else
    bad "--seed 2" "rc=$rc directed-same=$dsame random-differ=$rdiff"
fi
run gen -o g8 --samples 8 --shard 1/2
if [ $rc -eq 0 ] && grep -q 'built for the 8-sample grid' g8/case_000000.scene && ! grep -q 'built for the 16-sample grid' g8/case_0000*.scene; then
    ok "--samples 8: grid-dependent cases on the 8-sample grid"
else
    bad "--samples 8" "rc=$rc"
fi
run gen --list --level 2
l2total=$(head -n 1 out | sed -n 's/.* \([0-9][0-9]*\) cases (.*/\1/p')
if [ $rc -eq 0 ] && [ -n "$l2total" ] && [ "$(tail -n +3 out | wc -l)" -eq "$l2total" ] &&
   [ "$(tail -n +3 out | awk -F'\t' '$3 == "random"' | wc -l)" -eq 20000 ] &&
   tail -n +3 out | awk -F'\t' '$3 == "directed" { print $6 }' | sort -u | tr '\n' ' ' | grep -q '^0 16 32 8 $'; then
    ok "--list --level 2: $l2total cases, 20000 random, grids 8 16 32"
else
    bad "--list --level 2" "rc=$rc total=$l2total"
fi
run gen --list
if [ $rc -eq 0 ] && cmp -s out l1/index.tsv; then ok "--list prints exactly index.tsv"; else bad "--list" "rc=$rc"; fi

# ------------------------------------------------------ the DUT's limits (docs/gen.md 11)
# scenedims DIR: "FILE W H" per case file; maxedges FILE: the most points of one shape
scenedims() { (cd "$1" && awk '/^scene / { print FILENAME, $2, $3 }' case_*.scene); }
maxedges() { awk '/^shape/ { s++ } /^contour/ { n[s] += (NF - 1) / 2 } END { m = 0; for (i in n) if (n[i] > m) m = n[i]; print m }' "$1"; }
# 1. canvas: every case over 2048x2048 is scaled by the smallest 1/2^k, every vertex as the rule says
run gen -o dl1 --dut-limits 2048x2048 --dut-edges 8192
want=$(scenedims l1 | awk '$2 > 2048 || $3 > 2048' | wc -l)
nfit=$(sed -n 's/.*: \([0-9]*\) fitted, \([0-9]*\) refused.*/\1 \2/p' out)
scaled_ok=1 nsc=0 same_ok=1
while read -r f w h; do
    if [ "$w" -le 2048 ] && [ "$h" -le 2048 ]; then cmp -s "l1/$f" "dl1/$f" || same_ok=0; continue; fi
    nsc=$((nsc + 1))
    # independent: the smallest k, the canvas, and every vertex floor((256 v + 2^(k-1)) / 2^k)
    awk -v w="$w" -v h="$h" 'function fl(x) { return x >= 0 ? int(x) : (int(x) == x ? x : int(x) - 1) }
        BEGIN { k = 0; W = w; H = h; while (W > 2048 || H > 2048) { k++; d = 2 ^ k; W = int((w + d - 1) / d); H = int((h + d - 1) / d) } }
        FNR == 1 { f++ } /^#/ { next }
        f == 1 && /^contour/ { for (i = 2; i <= NF; i++) want[++n] = fl((256 * $i + d / 2) / d) }
        f == 2 && /^scene/ { if ($2 != W || $3 != H) bad = "canvas " $2 "x" $3 ", want " W "x" H }
        f == 2 && /^contour/ { for (i = 2; i <= NF; i++) if (256 * $i != want[++m]) bad = bad " vertex " m }
        END { if (m != n) bad = bad " counts " m "/" n; if (bad != "") { print FILENAME ": " bad; exit 1 } }' \
        "l1/$f" "dl1/$f" || scaled_ok=0
    grep -q "^# Fitted to the DUT's limits: canvas ${w}x$h scaled by 1/" "dl1/$f" || scaled_ok=0
done < <(scenedims l1)
if [ $rc -eq 0 ] && [ "$nfit" = "$want 0" ] && [ "$nsc" = "$want" ] && [ "$want" -gt 0 ] && [ $scaled_ok = 1 ] &&
   [ $same_ok = 1 ] && [ "$(rows dl1/refused.tsv | wc -l)" = 0 ]; then
    ok "--dut-limits 2048x2048: the $want canvases over it scaled by 1/2^k (canvas and every vertex as an awk computation says), every other case byte-identical, none refused"
else
    bad "--dut-limits 2048x2048 fitting" "rc=$rc fitted/refused='$nfit' want $want scaled=$nsc ok=$scaled_ok same=$same_ok"
fi
run gen -o dl0 --dut-limits 16384x16384 --dut-edges 8192 --dut-samples 8,16,32
if [ $rc -eq 0 ] && grep -q ': 0 fitted, 0 refused' out && diff -r -x refused.tsv l1 dl0 >/dev/null; then
    ok "the regression's build (16384x16384, 8192 edges, 8/16/32 samples): level 1 fits as it is, the same bytes"
else bad "level 1 against 16384x16384/8192" "rc=$rc $(cat out)"; fi
# 2. edges: shapes split only where the picture stays; the rest refused, listed, not written
run gen -o dl2 --dut-limits 64x64 --dut-edges 40
lim_ok=1 split_ok=1 nsplit=0
for f in dl2/case_*.scene; do
    [ "$(maxedges "$f")" -le 40 ] || lim_ok=0
    awk '/^scene/ { exit !($2 <= 64 && $3 <= 64) }' "$f" || lim_ok=0
done
for f in $(rows dl2/index.tsv | awk -F'\t' '$8 ~ /split into/ && $8 !~ /scaled/ { print $2 }'); do
    nsplit=$((nsplit + 1))
    for ns in 8 16 32; do
        for r in "" "--rule nonzero" "--rule evenodd"; do
            # shellcheck disable=SC2086 # the rule option splits on purpose
            "$EF" render "l1/$f" -o a.pam --samples $ns $r 2>/dev/null && "$EF" render "dl2/$f" -o b.pam --samples $ns $r 2>/dev/null &&
                cmp -s a.pam b.pam || { split_ok=0; echo "       $f at $ns $r: not the same picture"; }
        done
    done
    [ "$(maxedges "l1/$f")" -gt 40 ] || split_ok=0
done
nref=$(rows dl2/refused.tsv | wc -l); nlines=$(grep -c 'refused by the DUT.s limits: ' out)
ref_ok=1
# refused.tsv: case kind category name grid seed reason; the first six as the unfitted index says
while IFS=$'\t' read -r k kind cat name grid seed why; do
    f=$(printf 'case_%06d.scene' "$k")
    [ ! -e "dl2/$f" ] && [ "$(maxedges "l1/$f")" -gt 40 ] && [ -n "$why" ] || ref_ok=0
    [ "$(rows l1/index.tsv | awk -F'\t' -v k="$k" '$1 == k { print $3, $4, $5, $6, $7 }')" = "$kind $cat $name $grid $seed" ] ||
        { ref_ok=0; echo "       refused.tsv's row of case $k: $kind $cat $name $grid $seed, not the index's"; }
done < <(rows dl2/refused.tsv)
nw=$(find dl2 -name 'case_*.scene' | wc -l)
if [ $rc -eq 0 ] && [ $lim_ok = 1 ] && [ $split_ok = 1 ] && [ $nsplit -gt 0 ] && [ $ref_ok = 1 ] && [ "$nref" -gt 0 ] &&
   [ "$nref" = "$nlines" ] && [ $((nw + nref)) = "$total" ] && grep -q "zigzag-4096.*contour 0 alone has 4096" dl2/refused.tsv &&
   grep -q "changes the picture" dl2/refused.tsv; then
    ok "--dut-limits 64x64 --dut-edges 40: every written case within them; $nsplit split cases render the same bytes as unsplit (8/16/32 x 3 rule settings, edgeflag render); $nref refused (over 40 edges by an awk count, not written, one line each, refused.tsv)"
else
    bad "--dut-edges 40 fit/refuse" "rc=$rc lim=$lim_ok split=$split_ok ($nsplit) ref=$ref_ok nref=$nref lines=$nlines written=$nw total=$total"
fi
# 3. sample counts: level 1's grid follows the DUT; level 2's other grids are refused
run gen --list --dut-samples 8
g_ok=$(tail -n +3 out | awk -F'\t' '$6 != 0 && $6 != 8 { n++ } $6 == 8 { m++ } END { print (n == 0 && m > 0) }')
run gen --list --level 2 --dut-samples 8,32
g2=$(grep -c 'built for the 16-sample grid, the DUT takes 8,32 samples per pixel' err)
if [ "$g_ok" = 1 ] && [ "$g2" -gt 0 ] && [ "$(tail -n +3 out | awk -F'\t' '$6 == 16' | wc -l)" = 0 ]; then
    ok "--dut-samples: level 1's grid cases built on the DUT's 8 grid; level 2's 16-grid cases refused ($g2, on stderr under --list)"
else bad "--dut-samples" "g_ok=$g_ok g2=$g2"; fi
# 4. --dut-file: an identify record (docs/board.md 3.1), a C header, the RTL's own parameters
le32() { printf '%b' "\\x$(printf %02x $(($1 & 255)))\\x$(printf %02x $((($1 >> 8) & 255)))\\x$(printf %02x $((($1 >> 16) & 255)))\\x$(printf %02x $((($1 >> 24) & 255)))"; }
{ printf 'EFB1\001\000\004\000'; le32 15; le32 127; le32 $((8 | 16)); le32 100; le32 50; le32 64; printf 'serial-0123456789' | head -c 16; } >ident.bin
printf '#define MY_W_MAX 100\n#define MY_H_MAX 50\n#define MY_E_MAX 64\n#define MY_NS 16\n' >dut.h
run gen --list --dut-file ident.bin; a1=$(tail -n +3 out | md5sum); e1=$(md5sum <err)
run gen --list --dut-limits 100x50 --dut-edges 64 --dut-samples 8,16; a2=$(tail -n +3 out | md5sum); e2=$(md5sum <err)
run gen --list --dut-file dut.h --dut-samples 8,16; a3=$(tail -n +3 out | md5sum)
run gen -o dl4 --dut-file "$root/rtl/ef_raster.v"; r4=$rc; o4=$(cat out)
rtl_params=$(sed -n 's/^ *parameter \(NS\|W_MAX\|H_MAX\|E_MAX\) *= *\([0-9]*\).*/\1=\2/p' "$root/rtl/ef_raster.v" | tr '\n' ' ')
want4=$(echo "$rtl_params" | awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } printf "W_MAX %s, H_MAX %s, E_MAX %s, samples %s", v["W_MAX"], v["H_MAX"], v["E_MAX"], v["NS"] }')
if [ "$a1" = "$a2" ] && [ "$e1" = "$e2" ] && [ "$a1" = "$a3" ] && [ "$(wc -c <ident.bin)" = 48 ] && [ $r4 = 0 ] &&
   printf '%s\n' "$o4" | grep -qF "the DUT's limits ($want4)"; then
    ok "--dut-file: a 48-byte identify record and a C header give what the flags give; rtl/ef_raster.v's parameters read ($want4)"
else bad "--dut-file" "a1=$a1 a2=$a2 a3=$a3 r4=$r4 want '$want4': $o4"; fi
du_ok=1
printf 'nothing here\n' >none.h
# shellcheck disable=SC2016 # the backquotes are Verilog's `define
printf '`define W_MAX 10\n`define W_MAX 20\n`define H_MAX 5\n' >twice.vh
for args in "--dut-limits 0x5" "--dut-limits 5" "--dut-edges 0" "--dut-samples 12" "--dut-file none.h" "--dut-file twice.vh" \
            "--dut-file no-such.h" "--samples 16 --dut-samples 8"; do
    # shellcheck disable=SC2086
    run gen -o du $args
    [ $rc -eq 2 ] && [ ! -e du ] || { du_ok=0; bad "gen $args: rc=$rc, expected 2 and nothing created"; }
done
[ $du_ok = 1 ] && ok "DUT-limit usage errors (bad sizes, 0 edges, 12 samples, a file defining nothing or W_MAX twice, a missing file, --samples the DUT does not take): exit 2, nothing created"

# ----------------------------------------------------------------- help
for args in "gen --help" "gen -h" "help gen" "gen -o x --level 9 --help"; do
    # shellcheck disable=SC2086
    run $args
    if [ $rc -eq 0 ] && grep -q '^usage: edgeflag gen' out && [ ! -s err ] && [ ! -e x ]; then
        ok "help: edgeflag $args"
    else
        bad "help: edgeflag $args" "rc=$rc"
    fi
done
run --help
if grep -q '^  gen ' out; then ok "gen listed in edgeflag --help"; else bad "gen in --help"; fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
