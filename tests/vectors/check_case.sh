#!/usr/bin/env bash
# tests/vectors/check_case.sh LABEL INPUT DIR [VECTORS OPTIONS...] - one run of
# `edgeflag vectors INPUT -o DIR OPTIONS` checked the way a user's tools would
# read its files (docs/vectors.md), by tools that share no code with the
# writers: sha256sum, wc, grep, python3's json module, tests/tools/vec_bin_check
# (the binary stream), tests/tools/vcd_compare --words (a VCD "testbench"),
# GTKWave's vcd2fst/fst2vcd.  Prints exactly one line, "ok   - LABEL: ..." or
# "FAIL - LABEL: reason", for tests/vectors/run.sh to count.
#   - exit 0, the documented summary line, nothing on stderr but notes/warnings;
#   - manifest.json: valid JSON; lists exactly the files in DIR (no temporary
#     left), each with its size and the SHA-256 that sha256sum computes;
#     transactions = the sum of the interface counts = the summary's;
#   - hex: "// count" = data lines = manifest count, every word exactly
#     ceil(bits / 4) lower-case digits, header line naming the same run;
#   - bin: header fields and both CRCs, framing and order (vec_bin_check),
#     against the manifest;
#   - the three formats hold the same transactions: each hex file's words equal
#     the binary stream's records of that interface and the words a testbench
#     samples from the VCD at every rising clk edge with valid high;
#   - VCD: last timestamp 10 * cycles; survives vcd2fst + fst2vcd with every
#     signal and value change intact (ROUNDTRIP=0 skips it);
#   - frame.png is byte for byte what `edgeflag render` writes with the same
#     options; the seed is the scene's `# seed N` (else 0).
# Environment: EF (edgeflag), BINCHK, VCDCMP (the tools), KEEP=1 keeps DIR.
set -u
export LC_ALL=C
label=$1 in=$2 dir=$3
shift 3
t0=${EPOCHREALTIME/./}
fail() { echo "FAIL - $label: $*"; exit 1; }

"$EF" vectors "$in" -o "$dir" "$@" >"$dir.out" 2>"$dir.err"
rc=$?
[ $rc = 0 ] || fail "exit $rc: $(head -n 2 "$dir.err" | tr '\n' ' ')"
if grep -v -e ': note: ' -e '^edgeflag: warning: ' "$dir.err" | grep -q .; then
    fail "unexpected stderr: $(head -n 2 "$dir.err" | tr '\n' ' ')"
fi
re='^edgeflag vectors: wrote ([0-9]+) files \(([0-9]+) transactions, ([0-9]+) cycles; ([0-9]+)x([0-9]+), ([0-9]+) samples, rule ([a-z]+), seed ([0-9]+)\) to (.*)$'
summary=$(cat "$dir.out")
[[ $summary =~ $re ]] || fail "summary line: $summary"
nfiles=${BASH_REMATCH[1]} ntx=${BASH_REMATCH[2]} cycles=${BASH_REMATCH[3]}
width=${BASH_REMATCH[4]} height=${BASH_REMATCH[5]} samples=${BASH_REMATCH[6]} rule=${BASH_REMATCH[7]}
seed=${BASH_REMATCH[8]}
[ "${BASH_REMATCH[9]}" = "$dir" ] || fail "summary names ${BASH_REMATCH[9]}, not $dir"

m=$dir/manifest.json
[ -f "$m" ] || fail "no manifest.json"
version=$(sed -n 's/^  "generator": "edgeflag \(.*\)",$/\1/p' "$m")
[ "$version" = "${EF_VERSION:-$version}" ] || fail "manifest generator $version"
# A real JSON parser: jq (fast), else python3.
if command -v jq >/dev/null; then
    jq empty "$m" 2>/dev/null || fail "manifest.json is not valid JSON (jq)"
elif command -v python3 >/dev/null; then
    python3 -c 'import json, sys; json.load(open(sys.argv[1], encoding="utf-8"))' "$m" 2>/dev/null ||
        fail "manifest.json is not valid JSON (python3)"
fi
# The manifest's top-level numbers (one key per line by design).
key() { sed -n "s/^  \"$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}\$/\1/p" "$m"; }
[ "$(key cycles)" = "$cycles" ] && [ "$(key transactions)" = "$ntx" ] && [ "$(key width)" = "$width" ] &&
    [ "$(key height)" = "$height" ] && [ "$(key samples)" = "$samples" ] && [ "$(key rule)" = "$rule" ] &&
    [ "$(key seed)" = "$seed" ] && [ "$(key input)" = "$(basename "$in")" ] ||
    fail "manifest header disagrees with the summary"
want_seed=0
case $in in
*.scene | *.txt)
    s=$(sed -n '/^[^#]/q; s/^# seed \([0-9][0-9]*\)\([, \t].*\)\{0,1\}$/\1/p' "$in" | head -n 1)
    [ -n "$s" ] && want_seed=$s ;;
esac
[ "$seed" = "$want_seed" ] || fail "seed $seed, the input says $want_seed"

# Interfaces: name bits count.
declare -A icount ibits
while read -r n b c; do icount[$n]=$c ibits[$n]=$b; done < <(
    sed -n 's/^    { "name": "\([a-z_]*\)", "bits": \([0-9]*\), "count": \([0-9]*\) },\{0,1\}$/\1 \2 \3/p' "$m")
sum=0
for n in "${!icount[@]}"; do sum=$((sum + icount[$n])); done
[ "$sum" = "$ntx" ] || fail "interface counts add up to $sum, not $ntx"

# Sizes and hashes of everything in DIR, each tool run once.
declare -A size hash
while read -r sz f; do size[${f##*/}]=$sz; done < <(stat -c '%s %n' "$dir"/*)
while read -r h f; do hash[${f##*/}]=$h; done < <(sha256sum "$dir"/*)
# Every hex file in one pass: data lines, "// count", word bits, malformed
# words, whether line 2 names this run; and all words as "IFACE WORD" lines in
# interface order (the order of the arguments) for the cross-format check.
hexfiles=()
for n in cmd seg et_wr et_rd plot span pix; do
    for f in "$dir/$n".*.hex; do [ -f "$f" ] && hexfiles+=("$f"); done
done
declare -A hdata hcount hbits hbad hrun
if [ ${#hexfiles[@]} -gt 0 ]; then
    runline="// generator edgeflag $version; input $(basename "$in"); size ${width}x$height; samples $samples; rule $rule; seed $seed"
    while read -r f d c b bad r; do
        hdata[$f]=$d hcount[$f]=$c hbits[$f]=$b hbad[$f]=$bad hrun[$f]=$r
    done < <(awk -v run="$runline" -v words="$dir.hexwords" '
        FNR == 1 { f = FILENAME; sub(/.*\//, "", f); files[++nf] = f; n = f; sub(/\..*/, "", n); data[f] = 0; bad[f] = 0 }
        FNR == 2 { runok[f] = ($0 == run) }
        /^\/\/ count / { cnt[f] = $3 }
        /^\/\/ word / { bits[f] = $3; digits = int((bits[f] + 3) / 4) }
        /^\/\// { next }
        { data[f]++; if (length($0) != digits || $0 !~ /^[0-9a-f]+$/) bad[f]++; print n, $0 > words }
        END { for (i = 1; i <= nf; i++) { f = files[i]; print f, data[f], cnt[f] "", bits[f] "", bad[f], runok[f] + 0 } }
    ' "${hexfiles[@]}")
fi

# Files: name format interface role count bytes sha256, against the directory.
listed=()
while read -r name fmt iface role count bytes sha; do
    f=$dir/$name
    [ -f "$f" ] || fail "$name listed but missing"
    [ "${size[$name]}" = "$bytes" ] || fail "$name: size ${size[$name]}, manifest $bytes"
    [ "${hash[$name]}" = "$sha" ] || fail "$name: sha256sum disagrees with the manifest"
    listed+=("$name")
    case $fmt:$name:$role in
    hex:cmd.stim.hex:stim | hex:*.expected.hex:expected | vcd:vectors.vcd:all | bin:vectors.bin:all) ;;
    png:frame.png:expected | pam:frame.pam:expected) ;;
    *) fail "$name: format $fmt, role $role" ;;
    esac
    case $fmt in
    hex)
        iface=${iface//\"/}
        [ "$count" = "${icount[$iface]:-x}" ] || fail "$name: count $count, interface table ${icount[$iface]:-none}"
        [ "${hdata[$name]}" = "$count" ] || fail "$name: ${hdata[$name]} data lines, manifest count $count"
        [ "${hcount[$name]}" = "$count" ] || fail "$name: '// count ${hcount[$name]}' line"
        [ "${hbits[$name]}" = $((48 + ibits[$iface])) ] || fail "$name: word of ${hbits[$name]} bits"
        [ "${hbad[$name]}" = 0 ] || fail "$name: ${hbad[$name]} words not of exactly ceil(bits/4) lower-case hex digits"
        [ "${hrun[$name]}" = 1 ] || fail "$name: line 2 does not name this run"
        ;;
    bin)
        hdr=$("$BINCHK" "$f" 2>&1) || fail "vec_bin_check: $hdr"
        r=2; [ "$rule" = nonzero ] && r=0; [ "$rule" = evenodd ] && r=1
        counts=
        mask=0 i=0
        for n in cmd seg et_wr et_rd plot span pix; do
            counts=$counts${counts:+,}${icount[$n]:-0}
            [ -n "${icount[$n]:-}" ] && mask=$((mask | 1 << i))
            i=$((i + 1))
        done
        want="version=1 header=104 samples=$samples rule=$r width=$width height=$height seed=$seed mask=$mask counts=$counts records=$ntx bytes=$bytes"
        [ "$hdr" = "$want" ] || fail "bin header: $hdr, want $want"
        ;;
    vcd)
        [ "$(tac "$f" | grep -m 1 '^#')" = "#$((10 * cycles))" ] || fail "vcd: last timestamp is not #$((10 * cycles))"
        grep -qx '[$]timescale 1ns [$]end' "$f" || fail "vcd: timescale"
        if [ "${ROUNDTRIP:-1}" = 1 ]; then
            vcd2fst "$f" "$dir.fst" >/dev/null 2>&1 && fst2vcd "$dir.fst" >"$dir.rt.vcd" 2>/dev/null ||
                fail "vcd2fst/fst2vcd failed"
            out=$("$VCDCMP" "$f" "$dir.rt.vcd" 2>&1) || fail "GTKWave round trip: $out"
            rm -f "$dir.fst" "$dir.rt.vcd"
        fi
        ;;
    png | pam) ;;
    *) fail "$name: unknown format $fmt" ;;
    esac
done < <(sed -n 's/^    { "name": "\([^"]*\)", "format": "\([a-z]*\)", "interface": \([a-z_"]*\), "role": "\([a-z]*\)", "count": \([0-9]*\), "bytes": \([0-9]*\), "sha256": "\([0-9a-f]\{64\}\)" },\{0,1\}$/\1 \2 \3 \4 \5 \6 \7/p' "$m")
[ $((${#listed[@]} + 1)) = "$nfiles" ] || fail "manifest lists ${#listed[@]} files, summary says $nfiles with the manifest"
have=$(find "$dir" -mindepth 1 -maxdepth 1 ! -name manifest.json -printf '%f\n' | sort | tr '\n' ' ')
[ "$have" = "$(printf '%s\n' "${listed[@]}" | sort | tr '\n' ' ')" ] || fail "directory holds '$have', manifest lists '${listed[*]}'"

# The same transactions in every format: hex words = binary records = what a
# testbench samples from the VCD.
if [ ${#hexfiles[@]} -gt 0 ]; then
    touch "$dir.hexwords"
    if [ -f "$dir/vectors.bin" ]; then
        cmp -s "$dir.hexwords" <("$BINCHK" --hex all "$dir/vectors.bin") || fail "hex words and binary records differ"
    fi
    if [ -f "$dir/vectors.vcd" ]; then
        cmp -s "$dir.hexwords" <("$VCDCMP" --words all "$dir/vectors.vcd") || fail "hex words and the VCD's transfers differ"
    fi
fi
rm -f "$dir.hexwords"

# The frame is what `render` writes with the same options.
ropt=()
while [ $# -gt 0 ]; do
    case $1 in
    --formats | --interfaces) shift 2 ;;
    --force) shift ;;
    *) ropt+=("$1"); shift ;;
    esac
done
frame=$(ls "$dir"/frame.* 2>/dev/null)
"$EF" render "$in" -o "$dir.render.${frame##*.}" "${ropt[@]}" 2>/dev/null || fail "render failed"
cmp -s "$frame" "$dir.render.${frame##*.}" || fail "frame differs from edgeflag render's"
rm -f "$dir.render.${frame##*.}" "$dir.out" "$dir.err"
[ "${KEEP:-0}" = 1 ] || rm -rf "$dir"
echo "ok   - $label: $nfiles files, $ntx transactions, $cycles cycles ($(((${EPOCHREALTIME/./} - t0) / 1000)) ms)"
