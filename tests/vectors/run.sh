#!/usr/bin/env bash
# tests/vectors/run.sh - `edgeflag vectors` as a verification team meets it
# (docs/vectors.md), every file read back by tools that share no code with
# the writers (check_case.sh lists what is checked per run):
#   1. every shared SVG and the bundled tiger at 8/16/32 samples x nonzero /
#      evenodd (fitted to 96x72), and `edgeflag gen` level 1: every directed
#      case at three configurations (rotating over 8/16/32 x nonzero / evenodd
#      / the scene's rules, at its own size, shrunk into 96x72 if larger) and
#      every 10th random case at two; all in all three formats,
#      each run through check_case.sh, GTKWave round trip included
#      (EF_VEC_FULL=1: every gen case at all six configurations);
#   2. determinism: the same run twice, and a clang -O0 build against this
#      one, give byte-identical directories;
#   3. `gen --shard I/3`: the vectors of the three shards are disjoint and
#      together equal the unsharded run's, case directory by case directory;
#   4. --formats / --interfaces subsets: exactly the files asked for, each
#      byte-identical to the full run's;
#   5. usage errors (exit 2) and input errors (exit 3) create nothing; help;
#   6. existing files without --force: exit 4, nothing changed; --force;
#      a DIR that is a file;
#   7. SIGTERM / SIGKILL mid-write: no manifest.json, no temporary left after
#      SIGTERM, every file present identical to an uninterrupted run's;
#      SIGTERM with --force over a complete run leaves no manifest either;
#   8. the comparators fail when they should: a VCD with one bit flipped, one
#      change dropped, one timestamp moved, truncated or garbage (through
#      vcd2fst/fst2vcd: vcd2fst alone exits 0), and a binary stream with one
#      byte flipped.
#
# usage: bash tests/vectors/run.sh BUILD_DIR   (`make test-vectors`; EF_SVG,
#        EF_VEC_JOBS (default: the number of CPUs), EF_VEC_FULL, TMPDIR (default
#        /dev/shm if writable, else /tmp))
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
# shellcheck disable=SC2012 # `ls -A` of folders this test wrote, whose names are plain
set -u
export LC_ALL=C

build=${1:?usage: tests/vectors/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
export EF=$build/edgeflag BINCHK=$build/tests/tools/vec_bin_check VCDCMP=$build/tests/tools/vcd_compare
CHECK=$root/tests/vectors/check_case.sh
svgdir=${EF_SVG:-$root/tests/data/svg}
JOBS=${EF_VEC_JOBS:-$(nproc 2>/dev/null || echo 2)}
for t in "$EF" "$BINCHK" "$VCDCMP"; do
    if [ ! -x "$t" ]; then
        echo "vectors: $t not found (make test-vectors builds it)"
        echo "0 passed, 1 failed"
        exit 1
    fi
done
for t in vcd2fst fst2vcd sha256sum; do
    command -v $t >/dev/null || { echo "vectors: $t not installed (make deps-test)"; echo "0 passed, 1 failed"; exit 1; }
done

# Some 2000 files are written, each fsync'ed by the atomic writer: on a disk
# that alone takes minutes, so the work goes to a RAM disk when there is one
# (fsync is then free; the atomic writer behaves the same).  TMPDIR overrides.
base=${TMPDIR:-/tmp}
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then base=/dev/shm; fi
tmp=$(mktemp -d "$base/edgeflag-vectors.XXXXXX") || exit 1
bgpid=
cleanup() {
    [ -n "$bgpid" ] && kill -KILL "$bgpid" 2>/dev/null
    chmod -R u+w "$tmp" 2>/dev/null
    rm -rf "$tmp"
}
trap cleanup EXIT
cd "$tmp" || exit 1

pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); echo "ok   - $1"; }
bad() {
    fail=$((fail + 1)); echo "FAIL - $1"
    shift
    for line in "$@"; do echo "       $line"; done
    if [ -s err ]; then sed 's/^/       stderr: /' err | head -n 5; fi
}
skipped() { skip=$((skip + 1)); echo "skip - $1"; }
t_stage=$SECONDS
stage() { echo "# $1 ($((SECONDS - t_stage)) s)"; t_stage=$SECONDS; }
run() { "$EF" "$@" >out 2>err; rc=$?; }
# temps DIR: the atomic writer's temporaries (".NAME.XXXXXX") left in DIR
temps() { find "$1" -maxdepth 1 -name '.*.??????' 2>/dev/null | head -n 3; }
# tree DIR: every file's name, size and hash (a snapshot to compare)
tree() { (cd "$1" 2>/dev/null && find . -type f -printf '%p %s %T@\n' | sort && find . -type f -exec sha256sum {} + | sort); }

# jobs FILE: runs check_case.sh for each line "LABEL<TAB>INPUT<TAB>DIR<TAB>OPTIONS..."
# of FILE, JOBS at a time; counts and shows the results (failures in full).
jobs_run() {
    local res=$1.results n_ok n_bad
    # shellcheck disable=SC2016
    xargs -d '\n' -P "$JOBS" -n 1 bash -c 'IFS=$'"'"'\t'"'"' read -r -a a <<<"$1"; bash "$0" "${a[@]}"' "$CHECK" <"$1" >"$res" 2>&1
    n_ok=$(grep -c '^ok ' "$res") n_bad=$(grep -vc '^ok ' "$res")
    grep -v '^ok ' "$res" | head -n 20
    pass=$((pass + n_ok)) fail=$((fail + n_bad))
    echo "     ($2: $n_ok runs passed, $n_bad failed)"
}

# ------------------------------------------------------------ 1. the matrix
# The tiger first (the determinism checks below take it as svgs[0]), then the rest.
svgs=("$root/tests/data/svg/tiger.svg")
for f in "$svgdir"/*.svg; do
    [ "$(basename "$f")" = tiger.svg ] || svgs+=("$f")
done
[ ${#svgs[@]} -gt 1 ] || bad "no SVGs in $svgdir"
: >svg.jobs
for f in "${svgs[@]}"; do
    b=$(basename "$f" .svg)
    for n in 8 16 32; do
        for r in nonzero evenodd; do
            printf '%s\t%s\t%s\t%s\n' "svg $b $n $r" "$f" "$tmp/m/svg_${b}_${n}_$r" \
                "--samples	$n	--rule	$r	--size	96x72" >>svg.jobs
        done
    done
done
mkdir -p m
jobs_run svg.jobs "${#svgs[@]} SVGs x 8/16/32 x nonzero/evenodd"

"$EF" gen -o gen >/dev/null 2>err || bad "edgeflag gen -o gen"
ndir=$(awk -F'\t' 'NR > 2 && $3 == "directed"' gen/index.tsv | wc -l)
configs=("8 nonzero" "16 evenodd" "32 scene" "16 nonzero" "32 evenodd" "8 scene")
: >gen.jobs
for f in gen/case_*.scene; do
    b=$(basename "$f" .scene) k=$((10#${b#case_}))
    read -r w h < <(sed -n 's/^scene \([0-9]*\) \([0-9]*\)$/\1 \2/p' "$f")
    # Shrunk into 96x72 when larger (never enlarged: a fit that grows a
    # scene can push its far coordinates out of range, exit 3).
    fit=""
    if [ "$w" -gt 96 ] || [ "$h" -gt 72 ]; then fit="	--size	96x72"; fi
    if [ "${EF_VEC_FULL:-0}" = 1 ]; then
        picks="0 1 2 3 4 5"
    elif [ "$k" -lt "$ndir" ]; then
        picks="$((k % 6)) $(((k + 2) % 6)) $(((k + 4) % 6))"
    elif [ $((k % 10)) = 0 ]; then
        picks="$((k % 6)) $(((k + 3) % 6))"
    else
        continue
    fi
    for p in $picks; do
        read -r n r <<<"${configs[$p]}"
        ropt="	--rule	$r"; [ "$r" = scene ] && ropt=""
        printf '%s\t%s\t%s\t%s\n' "gen $b $n $r" "$tmp/$f" "$tmp/m/gen_${b}_${n}_$r" "--samples	$n$ropt$fit" >>gen.jobs
    done
done
jobs_run gen.jobs "gen level 1: $ndir directed cases at 3 configurations, every 10th random case at 2"

# A gen case carries its seed into every header.
run vectors gen/case_000000.scene -o seeded --samples 8
if [ $rc = 0 ] && grep -q '^  "seed": 20070101,$' seeded/manifest.json &&
   grep -q '; seed 20070101$' seeded/pix.expected.hex && grep -q 'seed 20070101)' out; then
    ok "a gen scene's '# seed 20070101' is in the manifest, the hex headers and the summary"
else
    bad "seed from a gen scene" "rc=$rc"
fi

stage "matrix"
# ------------------------------------------------------------ 2. determinism
det_inputs=("$root/tests/data/svg/tiger.svg" "${svgs[@]:1:8}" gen/case_000004.scene gen/case_000016.scene gen/case_000036.scene gen/case_000100.scene)
same=1
for f in "${det_inputs[@]}"; do
    rm -rf d1 d2
    "$EF" vectors "$f" -o d1 --samples 16 --size 200x150 >/dev/null 2>&1 &&
        "$EF" vectors "$f" -o d2 --samples 16 --size 200x150 >/dev/null 2>&1 || { same=0; echo "       run failed: $f"; }
    diff -r d1 d2 >/dev/null || { same=0; echo "       differs: $f"; }
done
if [ $same = 1 ]; then ok "same input, same options, twice: byte-identical directories (${#det_inputs[@]} inputs)"
else bad "second run differs"; fi

clang_build=$root/build-vec-clang-O0
if command -v clang >/dev/null &&
   make -C "$root" --no-print-directory -s CC=clang OPT=-O0 BUILD=build-vec-clang-O0 cli >clang.log 2>&1; then
    : >det.list
    for f in "${svgs[@]}"; do echo "$f 8 evenodd --size 96x72" >>det.list; done
    for f in gen/case_0000[0-5]?.scene gen/case_000060.scene; do     # the directed cases
        read -r w h < <(sed -n 's/^scene \([0-9]*\) \([0-9]*\)$/\1 \2/p' "$f")
        fit=""
        if [ "$w" -gt 96 ] || [ "$h" -gt 72 ]; then fit="--size 96x72"; fi
        echo "$f 16 nonzero $fit" >>det.list
    done
    echo "$root/tests/data/svg/tiger.svg 16 nonzero --size 640x480" >>det.list
    differ=0 count=0
    while read -r f n r extra; do
        count=$((count + 1))
        rm -rf ca cb
        # shellcheck disable=SC2086
        "$EF" vectors "$f" -o ca --samples "$n" --rule "$r" $extra >/dev/null 2>&1
        # shellcheck disable=SC2086
        "$clang_build/edgeflag" vectors "$f" -o cb --samples "$n" --rule "$r" $extra >/dev/null 2>&1
        if ! [ -f ca/manifest.json ] || ! diff -r ca cb >/dev/null; then
            differ=$((differ + 1)); echo "       differs: $f $n $r"
        fi
    done <det.list
    if [ $differ = 0 ]; then
        ok "clang -O0 build and $(basename "$build") write byte-identical directories ($count runs)"
    else
        bad "clang -O0 against $(basename "$build"): $differ of $count runs differ"
    fi
else
    bad "clang -O0 build failed" "$(tail -n 3 clang.log 2>/dev/null)"
fi

stage "determinism"
# ------------------------------------------------------------ 3. shards
: >shard.cmds
for s in 1 2 3; do
    "$EF" gen -o "shard$s" --shard "$s/3" >/dev/null 2>&1 || bad "gen --shard $s/3"
    for f in "shard$s"/case_*.scene; do echo "$f vs/$(basename "$f" .scene)"; done >>shard.cmds
done
for f in gen/case_*.scene; do echo "$f vf/$(basename "$f" .scene)"; done >>shard.cmds
mkdir -p vs vf
# Without --force a case directory written twice (overlapping shards) fails with exit 4.
# Each run's exit status is kept: a case the fit pushes out of range (exit 3)
# must fail alike in both.
# shellcheck disable=SC2016 # sh -c's own $0, $1, $2
xargs -P "$JOBS" -L 1 sh -c '"$0" vectors "$1" -o "$2" --samples 8 --size 48x36 --formats hex,bin >/dev/null 2>&1; echo "$2 $?" >>shard.rc' "$EF" <shard.cmds
rcs() { grep "^$1/" shard.rc | sed "s|^$1/||" | sort; }
nf=$(find vf -mindepth 1 -maxdepth 1 -type d | wc -l)
ns=$(find vs -mindepth 1 -maxdepth 1 -type d | wc -l)
ncases=$(awk -F'\t' 'NR > 2' gen/index.tsv | wc -l)
nrows=$(cat shard?/index_*.tsv | awk -F'\t' '$1 ~ /^[0-9]+$/' | sort -u | wc -l)
if [ "$(rcs vf)" = "$(rcs vs)" ] && [ "$(rcs vs | wc -l)" = "$ncases" ] && [ "$nrows" = "$ncases" ] &&
   [ "$nf" -gt $((ncases * 9 / 10)) ] && diff -r vf vs >/dev/null; then
    ok "gen --shard 1/3, 2/3, 3/3: disjoint; their $ns vector directories and $ncases exit statuses equal the unsharded run's"
else
    bad "sharded vectors" "cases $ncases, index rows $nrows, directories full $nf, sharded $ns"
fi

stage "shards"
# ------------------------------------------------------------ 4. subsets
scene=gen/case_000024.scene
run vectors "$scene" -o full --samples 16
run vectors "$scene" -o sub1 --samples 16 --formats hex --interfaces span,pix
ls1=$(ls -A sub1 | tr '\n' ' ')
if [ $rc = 0 ] && [ "$ls1" = "frame.png manifest.json pix.expected.hex span.expected.hex " ] &&
   cmp -s full/span.expected.hex sub1/span.expected.hex && cmp -s full/pix.expected.hex sub1/pix.expected.hex &&
   cmp -s full/frame.png sub1/frame.png &&
   [ "$(grep '"cycles"' full/manifest.json)" = "$(grep '"cycles"' sub1/manifest.json)" ]; then
    ok "--formats hex --interfaces span,pix: exactly those files, identical to the full run's, same cycles"
else
    bad "--formats hex --interfaces span,pix" "rc=$rc files: $ls1"
fi
run vectors "$scene" -o sub2 --samples 16 --formats bin,vcd --interfaces pix,cmd
run vectors "$scene" -o sub3 --samples 16 --formats=vcd,bin --interfaces=cmd,pix
ls2=$(ls -A sub2 | tr '\n' ' ')
scopes=$(sed -n 's/^[$]scope module \([a-z_]*\) [$]end$/\1/p' sub2/vectors.vcd | tr '\n' ' ')
if [ $rc = 0 ] && [ "$ls2" = "frame.png manifest.json vectors.bin vectors.vcd " ] && [ "$scopes" = "edgeflag cmd pix " ] &&
   "$BINCHK" sub2/vectors.bin | grep -q ' mask=65 ' && diff -r sub2 sub3 >/dev/null &&
   cmp -s <(grep -v '^//' full/cmd.stim.hex; grep -v '^//' full/pix.expected.hex) <("$BINCHK" --hex 0 sub2/vectors.bin; "$BINCHK" --hex 6 sub2/vectors.bin); then
    ok "--formats bin,vcd --interfaces pix,cmd: VCD scopes cmd and pix only, mask 65, records = the full run's; list order and --name=value do not matter"
else
    bad "--formats bin,vcd --interfaces pix,cmd" "rc=$rc files: $ls2 scopes: $scopes"
fi
# `edge`, the old name of `seg` (a Verilog keyword), is read where a user
# names an interface; files carry the new name only.
run vectors "$scene" -o sub4 --samples 16 --formats hex --interfaces edge,cmd
ls4=$(ls -A sub4 | tr '\n' ' ')
rc4=$rc
cp sub4/seg.expected.hex seg.actual.hex
run check full/seg.expected.hex seg.actual.hex --interfaces pix,edge
if [ $rc4 = 0 ] && [ "$ls4" = "cmd.stim.hex frame.png manifest.json seg.expected.hex " ] && [ $rc = 0 ] &&
   cmp -s full/seg.expected.hex sub4/seg.expected.hex && grep -q '"name": "seg"' sub4/manifest.json; then
    ok "--interfaces edge,cmd: the old name reads as seg (seg.expected.hex, as in the full run); check --interfaces pix,edge too"
else
    bad "--interfaces edge,cmd (old name of seg)" "rc=$rc4/$rc files: $ls4"
fi
# and the subsets pass every per-run check
printf '%s\t%s\t%s\t%s\n' "subset hex span,pix" "$tmp/$scene" "$tmp/m/sub_a" "--samples	16	--formats	hex	--interfaces	span,pix" \
    "subset vcd,bin cmd" "$tmp/$scene" "$tmp/m/sub_b" "--samples	8	--formats	vcd,bin	--interfaces	cmd" \
    "subset hex,vcd et_wr,plot" "$tmp/$scene" "$tmp/m/sub_c" "--samples	32	--formats	hex,vcd	--interfaces	et_wr,plot" \
    "subset bin" "$tmp/$scene" "$tmp/m/sub_d" "--samples	8	--formats	bin" >sub.jobs
jobs_run sub.jobs "subsets"

# ------------------------------------------------------------ 5. usage and input errors
run vectors --help
if [ $rc = 0 ] && grep -q '^usage: edgeflag vectors INPUT -o DIR' out && [ ! -s err ]; then
    h1=$(cat out); run help vectors
    if [ $rc = 0 ] && [ "$(cat out)" = "$h1" ]; then ok "vectors --help and help vectors: usage on stdout, exit 0"
    else bad "help vectors" "rc=$rc"; fi
else
    bad "vectors --help" "rc=$rc"
fi
run --help
if grep -q '^  vectors ' out; then ok "edgeflag --help lists vectors"; else bad "edgeflag --help lists vectors"; fi
usage_cases=(
    ""
    "$scene"
    "-o u"
    "$scene -o"
    "$scene -o u --samples 12"
    "$scene -o u --samples 8x"
    "$scene -o u --samples=+8"
    "$scene -o u --samples 8 --samples 8"
    "$scene -o u --rule both"
    "$scene -o u --size 0x5"
    "$scene -o u --size 96X72"
    "$scene -o u --formats"
    "$scene -o u --formats png"
    "$scene -o u --formats hex,hex"
    "$scene -o u --formats hex,"
    "$scene -o u --formats ,hex"
    "$scene -o u --formats="
    "$scene -o u --formats HEX"
    "$scene -o u --interfaces plots"
    "$scene -o u --interfaces cmd,,pix"
    "$scene -o u --interfaces all"
    "$scene -o u --interfaces cmd --interfaces pix"
    "$scene -o u --force --force"
    "$scene -o u -o v"
    "$scene $scene -o u"
    "$scene -o u --frobnicate"
    "$scene -o u -x"
    "--rtl-headers"
    "--rtl-headers $scene -o u"
    "--rtl-headers -o u --samples 16"
    "--rtl-headers -o u --interfaces cmd"
    "--rtl-headers -o u --dump"
    "--rtl-headers --rtl-headers -o u"
)
nok=0
for args in "${usage_cases[@]}"; do
    # shellcheck disable=SC2086
    run vectors $args
    if [ $rc = 2 ] && grep -q '^edgeflag: vectors: ' err && grep -qx "Try 'edgeflag vectors --help'." err &&
       [ ! -s out ] && [ ! -e u ] && [ ! -e v ]; then
        nok=$((nok + 1))
    else
        bad "usage error: edgeflag vectors $args" "rc=$rc (want 2, message, nothing created)"
    fi
done
[ $nok = ${#usage_cases[@]} ] && ok "$nok usage errors: exit 2, 'edgeflag: vectors: ...' and the hint, nothing created"
# --rtl-headers (docs/vectors.md section 8): exactly the two files, from the
# interface table (the payload widths agree with the manifest's); an existing
# one is exit 4 without --force and left alone; --force replaces it.
run vectors --rtl-headers -o hdr
ls_h=$(ls -A hdr | tr '\n' ' ')
w_seg=$(sed -n 's/^`define EF_SEG_W \([0-9]*\)$/\1/p' hdr/ef_ifaces.vh)
w_pix=$(sed -n 's/^  localparam int PIX_W = \([0-9]*\);$/\1/p' hdr/ef_ifaces_pkg.sv)
if [ $rc = 0 ] && [ "$ls_h" = "ef_ifaces.vh ef_ifaces_pkg.sv " ] && [ -n "$w_seg" ] &&
   grep -q "\"name\": \"seg\", \"bits\": $w_seg," full/manifest.json &&
   grep -q "\"name\": \"pix\", \"bits\": $w_pix," full/manifest.json &&
   grep -q '^`define EF_OP_SHAPE_END 4$' hdr/ef_ifaces.vh && grep -q '^`define EF_ET_RD_EID_LSB 0$' hdr/ef_ifaces.vh; then
    ok "--rtl-headers: ef_ifaces.vh and ef_ifaces_pkg.sv only, widths as in the manifest (seg $w_seg, pix $w_pix)"
else
    bad "--rtl-headers" "rc=$rc files: $ls_h seg=$w_seg pix=$w_pix"
fi
echo keep >hdr/ef_ifaces_pkg.sv
run vectors --rtl-headers -o hdr
rc1=$rc; k1=$(cat hdr/ef_ifaces_pkg.sv)
run vectors --rtl-headers -o hdr --force
if [ $rc1 = 4 ] && [ "$k1" = keep ] && [ $rc = 0 ] && grep -q '^package ef_ifaces_pkg;' hdr/ef_ifaces_pkg.sv; then
    ok "--rtl-headers: an existing file is exit 4 and kept; --force replaces it"
else
    bad "--rtl-headers over existing files" "rc=$rc1 then $rc"
fi
run vectors -o u --samples 8 -- "$scene"
if [ $rc = 0 ] && [ -f u/manifest.json ]; then ok "-- ends the options"; else bad "-- ends the options" "rc=$rc"; fi
rm -rf u

run vectors missing.scene -o u
if [ $rc = 3 ] && grep -q '^edgeflag: missing.scene: ' err && [ ! -e u ]; then
    ok "missing input: exit 3, 'edgeflag: FILE: ...', DIR not created"
else
    bad "missing input" "rc=$rc (want 3)"
fi
printf 'scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 5 x 1 1\n' >broken.scene
run vectors broken.scene -o u
if [ $rc = 3 ] && grep -q '^edgeflag: broken.scene:3:[0-9]*: ' err && [ ! -e u ]; then
    ok "malformed input: exit 3 with FILE:LINE:COL, DIR not created"
else
    bad "malformed input" "rc=$rc (want 3)"
fi

stage "subsets, usage"
# ------------------------------------------------------------ 6. existing files
run vectors "$scene" -o ex --samples 8
before=$(tree ex)
sleep 0.01
run vectors "$scene" -o ex --samples 8
if [ $rc = 4 ] && grep -q "^edgeflag: 'ex/.*' exists: use --force" err && [ "$(tree ex)" = "$before" ] && [ ! -s out ]; then
    ok "existing files without --force: exit 4, every file unchanged (names, sizes, times, hashes)"
else
    bad "existing files without --force" "rc=$rc (want 4)"
fi
mkdir -p lone && echo keep >lone/vectors.vcd
run vectors "$scene" -o lone --samples 8
if [ $rc = 4 ] && [ "$(ls -A lone)" = vectors.vcd ] && [ "$(cat lone/vectors.vcd)" = keep ]; then
    ok "one existing file of the run (vectors.vcd) without --force: exit 4, nothing else written"
else
    bad "one existing file" "rc=$rc, lone holds $(ls -A lone | tr '\n' ' ')"
fi
run vectors "$scene" -o lone --samples 8 --formats hex
if [ $rc = 0 ] && [ "$(cat lone/vectors.vcd)" = keep ]; then
    ok "a file of the same name that this run does not write is no obstacle and stays untouched"
else
    bad "unrelated existing file" "rc=$rc"
fi
run vectors "$scene" -o ex --samples 32 --force
if [ $rc = 0 ] && grep -q '"samples": 32' ex/manifest.json && [ "$(tree ex)" != "$before" ] && [ -z "$(temps ex)" ]; then
    ok "--force replaces the files"
else
    bad "--force" "rc=$rc"
fi
echo notadir >afile
run vectors "$scene" -o afile --samples 8
if [ $rc = 4 ] && [ "$(cat afile)" = notadir ]; then ok "-o naming a regular file: exit 4, file untouched"
else bad "-o naming a regular file" "rc=$rc (want 4)"; fi
run vectors "$scene" -o afile/sub --samples 8
if [ $rc = 4 ] && [ "$(cat afile)" = notadir ]; then ok "-o below a regular file: exit 4"
else bad "-o below a regular file" "rc=$rc (want 4)"; fi
# The file size limit (ulimit -f, in KiB): the write fails with EFBIG, not SIGXFSZ.
( ulimit -f 2048; exec "$EF" vectors "$root/tests/data/svg/tiger.svg" --size 320x240 -o lim ) >out 2>err
rc=$?
if [ $rc = 4 ] && grep -q "^edgeflag: cannot write 'lim/.*': File too large" err && [ ! -e lim/manifest.json ] &&
   [ -z "$(temps lim)" ] && [ ! -s out ]; then
    ok "file size limit (ulimit -f 2048): exit 4, 'File too large', no manifest, no temporary ($(ls lim | wc -l) whole files before it)"
else
    bad "file size limit" "rc=$rc (want 4), left: $(temps lim) $(ls lim 2>/dev/null | tr '\n' ' ')"
fi
if [ "$(id -u)" != 0 ]; then
    mkdir ro && chmod a-w ro
    run vectors "$scene" -o ro/x --samples 8
    if [ $rc = 4 ] && [ ! -e ro/x ]; then ok "unwritable parent: exit 4"; else bad "unwritable parent" "rc=$rc (want 4)"; fi
else
    skipped "unwritable directory: running as root, permissions do not apply"
fi

stage "existing files"
# ------------------------------------------------------------ 7. interrupted runs
big=("$root/tests/data/svg/tiger.svg" --size 1280x960 --samples 16)
"$EF" vectors "${big[@]}" -o ref >/dev/null 2>&1 || bad "reference run for the interrupt tests"
"$EF" vectors "$root/tests/data/svg/tiger.svg" --size 320x240 --samples 8 -o old >/dev/null 2>&1 || bad "small run for --force"
# intact DIR: no manifest, and every file present is whole: the reference
# run's, or (--force over a complete run) the old run's
intact() {
    local f
    [ -e "$1/manifest.json" ] && return 1
    for f in "$1"/*; do
        [ -e "$f" ] || continue
        cmp -s "$f" "ref/${f##*/}" || cmp -s "$f" "old/${f##*/}" || return 1
    done
    return 0
}
# interrupt SIG STATUS WHEN [prepare]: WHEN = write (a temporary exists) or render (0.2 s in)
interrupt() {
    local sig=$1 want=$2 when=$3 prep=${4:-} st left seen n
    for _ in 1 2 3; do
        rm -rf int
        [ "$prep" = complete ] && cp -a old int
        env --default-signal=INT,TERM,HUP "$EF" vectors "${big[@]}" -o int ${prep:+--force} >/dev/null 2>err &
        bgpid=$!
        seen=0
        if [ "$when" = write ]; then
            for _ in $(seq 1 3000); do
                if [ -n "$(find int -maxdepth 1 -name '.vectors.vcd.??????' 2>/dev/null)" ]; then seen=1; break; fi
                kill -0 "$bgpid" 2>/dev/null || break
                sleep 0.005
            done
        else
            sleep 0.2
            kill -0 "$bgpid" 2>/dev/null && [ ! -e int/frame.png ] && seen=1
        fi
        if [ $seen = 0 ]; then
            wait "$bgpid"; bgpid=; continue
        fi
        kill "-$sig" "$bgpid"
        { wait "$bgpid"; } 2>/dev/null
        st=$? bgpid=
        [ $st = 0 ] && continue                    # finished between the poll and the kill
        left=$(temps int)
        [ "$sig" = KILL ] && { find int -maxdepth 1 -name '.*.??????' -delete 2>/dev/null; left=; }
        n=$(find int -maxdepth 1 -type f 2>/dev/null | wc -l)
        if [ $st = "$want" ] && [ -z "$left" ] && intact int; then
            ok "SIG$sig during the $when${prep:+ (--force over a complete run)}: status $st, no manifest.json, no temporary, the $n file(s) present whole"
        else
            bad "SIG$sig during the $when${prep:+ (--force)}" "status $st (want $want), temporaries: $left, manifest: $(ls int/manifest.json 2>/dev/null)"
        fi
        return
    done
    skipped "SIG$sig during the $when: the run finished before it could be interrupted (3 attempts)"
}
interrupt TERM 143 write
interrupt KILL 137 write
interrupt INT 130 write
interrupt TERM 143 render
interrupt TERM 143 write complete
rm -rf int ref old

stage "interrupts"
# ------------------------------------------------------------ 8. the checkers fail when they should
run vectors "$root/tests/data/svg/tiger.svg" -o cv --samples 8 --size 96x72
v=cv/vectors.vcd
if "$VCDCMP" "$v" "$v" >/dev/null; then ok "vcd_compare: a VCD equals itself"; else bad "vcd_compare on itself"; fi
# one bit of one vector value flipped (the first 'b...1 ID' after the definitions)
awk 'done || !/^b[01]*1 / || !defs { print; if (/enddefinitions/) defs = 1; next } { sub(/1 /, "0 "); print; done = 1 }' "$v" >flip.vcd
awk '!done && /^b[01]+ / && defs { done = 1; next } /enddefinitions/ { defs = 1 } 1' "$v" >drop.vcd
awk '!done && /^#[0-9]+$/ && $0 != "#0" { print "#" substr($0, 2) + 1; done = 1; next } 1' "$v" >shift.vcd
# shellcheck disable=SC2016 # a VCD's $end, not a variable
sed '0,/ valid [$]end/s// valid2 $end/' "$v" >rename.vcd
head -c $(($(wc -c <"$v") / 2)) "$v" >trunc.vcd
head -c 4000 /dev/urandom >garbage.vcd
for c in flip drop shift rename; do
    if cmp -s "$v" $c.vcd; then bad "corruption '$c' changed nothing (test bug)"; continue; fi
    "$VCDCMP" "$v" $c.vcd >cmp.out 2>&1; st=$?
    if [ $st = 1 ]; then ok "vcd_compare detects '$c': $(head -c 150 cmp.out)"
    else bad "vcd_compare misses '$c'" "status $st: $(head -n 2 cmp.out)"; fi
done
for c in trunc garbage; do
    vcd2fst $c.vcd $c.fst >/dev/null 2>&1; s1=$?
    fst2vcd $c.fst >$c.rt.vcd 2>/dev/null
    "$VCDCMP" "$v" $c.rt.vcd >cmp.out 2>&1; st=$?
    if [ $st != 0 ]; then ok "round trip of a $c VCD (vcd2fst exit $s1) fails the comparison (status $st)"
    else bad "round trip of a $c VCD passes the comparison"; fi
done
cp cv/vectors.bin flip.bin
byte=$(od -An -tu1 -j 200 -N 1 cv/vectors.bin | tr -d ' ')
printf '%b' "\\0$(printf '%03o' $((byte ^ 1)))" | dd of=flip.bin bs=1 seek=200 conv=notrunc 2>/dev/null
if ! cmp -s cv/vectors.bin flip.bin && ! "$BINCHK" flip.bin >/dev/null 2>cmp.out; then
    ok "vec_bin_check detects one flipped byte: $(head -c 100 cmp.out)"
else
    bad "vec_bin_check misses a flipped byte"
fi

stage "checkers"
echo "vectors: $pass passed, $fail failed, $skip skipped (${SECONDS} s)"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
