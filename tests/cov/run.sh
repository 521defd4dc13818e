#!/usr/bin/env bash
# tests/cov/run.sh - `edgeflag coverage` (issue 27, make test-coverage;
# docs/cli.md): the functional cover points of dv/coverage/points.tsv.
#   1. --list gives exactly the names of points.tsv, in its order (read here
#      with awk, not through the tool);
#   2. a hand-made scene whose counts are worked out in the comments below
#      (spec 5, 6.1, 7.2 by hand): each listed point has exactly that count;
#   3. the same set written as vectors.bin only gives the same report;
#   4. --require: exit 1 naming the missed points of a small set, 0 when the
#      required ones are hit; usage errors (no DIR, a --require name that is
#      no point) exit 2, a directory that is not vectors exits 3;
#   5. tests/cov/func-coverage.sh: the shared SVGs and `edgeflag gen` level 1
#      hit every point (--require all).
# usage: bash tests/cov/run.sh BUILD_DIR.  Ends with "N passed, M failed".
set -u
export LC_ALL=C
build=${1:?usage: tests/cov/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "PASS $*"; }
ko() { fail=$((fail + 1)); echo "FAIL $*"; }
[ -x "$EF" ] || { echo "coverage: $EF not built (make cli)"; echo "0 passed, 1 failed"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-cov.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT

# 1. the table is the file
awk -F'\t' '/^#/ || $1 == "name" || NF < 3 { next } { print $1 }' "$root/dv/coverage/points.tsv" >"$work/want.txt"
"$EF" coverage --list | cut -f1 >"$work/got.txt"
if cmp -s "$work/want.txt" "$work/got.txt" && [ -s "$work/got.txt" ]; then
    ok "edgeflag coverage --list: the $(grep -c . "$work/got.txt") points of dv/coverage/points.tsv, in order"
else ko "edgeflag coverage --list differs from dv/coverage/points.tsv"; diff "$work/want.txt" "$work/got.txt" | head; fi

# 2. A 4x4 canvas at 8 samples (h = 32, c = 16, N*H = 32 sample rows), two shapes:
#    A: the rectangle x 1..3, y -1..2 (nonzero): top and bottom edges horizontal (2), the right
#       edge down, the left up (one each); both start above the canvas: r0 = ceil((-256-16)/32)
#       = -8 < 0, clipped (clip.top 2); r1 = ceil((512-16)/32) - 1 = 15 <= 31 (no bottom clip).
#       Rows 0 and 1 get one span each, x = 1, len 2, full mask (solid 2); 4 pixels.
#    B: the rectangle x 2..4, y 3..4: r0 = 24, r1 = ceil((1024-16)/32) - 1 = 31 = N*H - 1
#       exactly (no clip); its right edge at x = 4.0 holds x = 1023 in the DDA, q = (1023 + off)
#       >> 8 = 4 = W on its 8 sample rows (plot.sink 8, clamp.right 0); one span x = 2, len 2,
#       x + len = W (span.right 1, solid 1), all in row 3 (shape.one_row 1: A has two rows).
cat >"$work/hand.scene" <<'SCENE'
scene 4 4
shape nonzero 255 255 255 255
contour 1 -1 3 -1 3 2 1 2
shape nonzero 255 255 255 255
contour 2 3 4 3 4 4 2 4
SCENE
"$EF" vectors "$work/hand.scene" -o "$work/hand" --samples 8 >/dev/null 2>&1 || ko "edgeflag vectors of the hand-made scene"
"$EF" coverage "$work/hand" >"$work/hand.txt" 2>&1
bad=""
for pc in setup.horizontal:4 clip.top:2 clip.bottom:0 setup.dir_down:2 setup.dir_up:2 span.solid:3 span.partial:0 \
          span.right:1 span.x0:0 plot.sink:8 clamp.right:0 clamp.left:0 plot.cell0:0 pix.alpha_full:6 \
          pix.overdraw:0 shape.one_row:1 edge.longest:0 mode.nonzero.ns8.box.none:2; do
    got=$(awk -v p="${pc%:*}" '$2 == p { print $3 }' "$work/hand.txt")
    [ "$got" = "${pc#*:}" ] || bad="$bad ${pc%:*}=${got:-none}(want ${pc#*:})"
done
if [ -z "$bad" ]; then ok "edgeflag coverage on a hand-worked scene: 18 points with exactly the counts worked out by hand"
else ko "edgeflag coverage on the hand-worked scene:$bad"; fi

# 3. binary stream only
mkdir -p "$work/bin" && cp "$work/hand/vectors.bin" "$work/bin/"
"$EF" coverage "$work/bin" >"$work/bin.txt" 2>&1
if diff <(grep -v '^coverage:' "$work/hand.txt") <(grep -v '^coverage:' "$work/bin.txt") >/dev/null; then
    ok "edgeflag coverage reads vectors.bin alone to the same report as the hex files"
else ko "edgeflag coverage: vectors.bin and hex reports differ"; fi

# 4. exit codes
"$EF" coverage "$work/hand" --require all >"$work/req.txt" 2>&1; rc=$?
if [ $rc = 1 ] && grep -q '^MISS  *clip.bottom ' "$work/req.txt" && grep -q 'required points missed' "$work/req.txt"; then
    ok "--require all on a small set: exit 1, the misses listed (clip.bottom among them)"
else ko "--require all on a small set: exit $rc"; fi
"$EF" coverage "$work/hand" --require 'clip.top,setup.dir*' >/dev/null 2>&1; rc=$?
[ $rc = 0 ] && ok "--require 'clip.top,setup.dir*' (all hit by the hand-made set): exit 0" || ko "--require 'clip.top,setup.dir*': exit $rc, expected 0"
"$EF" coverage >/dev/null 2>&1; r1=$?
"$EF" coverage "$work/hand" --require no.such.point >/dev/null 2>"$work/e.txt"; r2=$?
"$EF" coverage "$work" >/dev/null 2>"$work/e3.txt"; r3=$?
if [ $r1 = 2 ] && [ $r2 = 2 ] && grep -q 'no.such.point' "$work/e.txt" && [ $r3 = 3 ] && grep -q 'not a vectors directory' "$work/e3.txt"; then
    ok "usage errors exit 2 (no DIR; --require naming no point, named), a folder that is not vectors exits 3"
else ko "exit codes: no DIR $r1, bad --require $r2, not vectors $r3 (want 2, 2, 3)"; fi

# 5. the project's own sets
if bash "$root/tests/cov/func-coverage.sh" "$build" "$work/func.txt" >"$work/func.log" 2>&1; then
    ok "shared SVGs + gen level 1: $(grep '^coverage: .* points hit' "$work/func.txt")"
else tail -20 "$work/func.log"; ko "tests/cov/func-coverage.sh: not every point hit"; fi

echo "$pass passed, $fail failed"
[ $fail = 0 ]
