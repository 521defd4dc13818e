#!/usr/bin/env bash
# tests/check/run.sh - `edgeflag check` as a verification engineer meets it
# (docs/vectors.md section 7), on real `edgeflag vectors` output of the tiger
# (160x120) and of an `edgeflag gen` case:
#   - identical data passes (exit 0, nothing on stdout): directories, each hex
#     file, vectors.bin, RTL-style dumps (IFACE.actual.hex without a header),
#     hex against binary;
#   - mutations fail (exit 1) with one line at the right place: one flipped
#     bit (pix, span, plot word; a pix record of vectors.bin), one dropped
#     transaction, one transaction delayed by a cycle.  The expected file,
#     line (or record and offset), interface, cycle, scanline and pixel are
#     decoded here from the words themselves, with the layout the hex header
#     states, independently of the checker's decoding;
#   - --transactions passes the delay and fails the flip and the drop;
#     --errors caps the lines and keeps the count exact; --junit is valid XML
#     (xmllint) with one case per interface; --diff-image is a PNG of the
#     frame's size and (as PAM) has exactly the mutated pixel in magenta;
#   - it cannot pass by accident: a dump folder of copies of the expected
#     files, EXPECTED given as ACTUAL, an expected file as the dump (exit 2);
#     a missing pix or internal dump (exit 1, named, a JUnit failure) unless
#     --allow-missing/--interfaces excuse it (JUnit <skipped/>, never pix);
#   - usage errors (exit 2), unwritable outputs (exit 4, nothing left).
# Malformed dumps are in the bad-input catalogue (tests/bad/CATALOGUE.tsv).
#
# usage: bash tests/check/run.sh BUILD_DIR      (`make test-check`)
# Ends with "N passed, M failed"; exit status 0 only if nothing failed.
set -u
export LC_ALL=C

build=${1:?usage: tests/check/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
MUT=$build/tests/check/vec_mutate
LIB=$build/tests/check/check_lib
# EF_CHECK_WRITER=PATH: write the vectors with another build's edgeflag (e.g.
# to run the checker under a sanitizer the model's tracing does not pass).
EFW=${EF_CHECK_WRITER:-$EF}
for b in "$EF" "$MUT"; do
    [ -x "$b" ] || { echo "check: $b not built"; echo "0 passed, 1 failed"; exit 1; }
done

tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-check.XXXXXX") || exit 1
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok   - $1"; }
bad() {
    fail=$((fail + 1)); echo "FAIL - $1"
    shift
    for line in "$@"; do echo "       $line"; done
    [ -s out ] && sed 's/^/       stdout: /' out | head -n 4
    [ -s err ] && sed 's/^/       stderr: /' err | head -n 4
}
# run ARGS...: edgeflag with stdout in ./out, stderr in ./err; sets rc.
run() { "$EF" "$@" >out 2>err; rc=$?; }
# expect_rc WHAT WANT: rc is WANT.
expect_rc() { if [ "$rc" = "$2" ]; then ok "$1 (exit $2)"; else bad "$1" "exit $rc, want $2"; fi; }

# ------------------------------------------------------------ word decoding
# A hex word's bits, from the digits alone (no edgeflag code involved).
declare -A H2B=([0]=0000 [1]=0001 [2]=0010 [3]=0011 [4]=0100 [5]=0101 [6]=0110 [7]=0111
                [8]=1000 [9]=1001 [a]=1010 [b]=1011 [c]=1100 [d]=1101 [e]=1110 [f]=1111)
hex2bin() { local h=$1 o='' i; for ((i = 0; i < ${#h}; i++)); do o+=${H2B[${h:i:1}]}; done; echo "$o"; }
bin2hex() {
    local b=$1 o='' i
    while [ $((${#b} % 4)) -ne 0 ]; do b=0$b; done
    for ((i = 0; i < ${#b}; i += 4)); do o+=$(printf %x $((2#${b:i:4}))); done
    echo "$o"
}
# bits HEX HI LO: bits HI..LO of the number HEX, in decimal (HI - LO < 63).
bits() { local b; b=$(hex2bin "$1"); echo $((2#${b:${#b}-1-$2:$2-$3+1})); }
# layout FILE: FH[name], FL[name] from its "// word N bits: cycle[a:b] f[c:d] ..." line.
declare -A FH FL
layout() {
    FH=() FL=()
    local f
    # shellcheck disable=SC2013 # the field list is one line of words
    for f in $(sed -n 's|^// word [0-9]* bits: ||p' "$1"); do
        local n=${f%%\[*} r=${f#*\[}
        r=${r%\]}
        FH[$n]=${r%%:*} FL[$n]=${r##*:}
    done
}
field() { bits "$1" "${FH[$2]}" "${FL[$2]}"; }
# nth_data FILE K: "LINE WORD" of the K-th data line (not a comment).
nth_data() { grep -n -v '^//' "$1" | sed -n "${2}p" | tr ':' ' '; }
# flip_word WORD BIT: WORD with payload bit BIT flipped.
flip_word() {
    local w=$1 p=$((${#1} - 1 - $2 / 4))
    echo "${w:0:p}$(printf %x $((16#${w:p:1} ^ (1 << ($2 % 4)))))${w:p+1}"
}
# delay_word WORD D: WORD with its cycle (the field "cycle") plus D.
delay_word() {
    local b c n
    b=$(hex2bin "$1")
    n=${#b}
    c=$(($(field "$1" cycle) + $2))
    local cb=
    for ((k = FH[cycle] - FL[cycle]; k >= 0; k--)); do cb+=$(((c >> k) & 1)); done
    b=${b:0:n-1-FH[cycle]}$cb${b:n-FL[cycle]}
    local h
    h=$(bin2hex "$b")
    while [ ${#h} -lt ${#1} ]; do h=0$h; done
    echo "$h"
}
# set_line FILE LINE TEXT / del_line FILE LINE: in place.
set_line() { sed -i "${2}s/.*/$3/" "$1"; }
del_line() { sed -i "${2}d" "$1"; }
# where IFACE WORD: ", y Y, x X" etc. as check prints it, from the layout.
where() {
    local s='' f
    for f in y row; do [ -n "${FH[$f]:-}" ] && { s+=", $f $(field "$2" $f)"; break; }; done
    for f in x q; do [ -n "${FH[$f]:-}" ] && { s+=", $f $(field "$2" $f)"; break; }; done
    echo "$1: cycle $(field "$2" cycle)$s"
}

# ------------------------------------------------------------ the vectors
"$EFW" vectors "$root/tests/data/svg/tiger.svg" -o V --size 160x120 >/dev/null 2>err ||
    { bad "edgeflag vectors tiger.svg failed"; echo "$pass passed, $fail failed"; exit 1; }
"$EFW" gen -o G >/dev/null 2>err ||
    { bad "edgeflag gen failed"; echo "$pass passed, $fail failed"; exit 1; }
gcases=(G/case_*.scene)
gcase=${gcases[39]}
"$EFW" vectors "$gcase" -o VG --samples 16 --rule evenodd >/dev/null 2>err ||
    { bad "edgeflag vectors $gcase failed"; echo "$pass passed, $fail failed"; exit 1; }

# RTL-style dumps: IFACE.actual.hex without the header, in a directory of their own.
rtl_dir() {
    mkdir -p "$2"
    local f
    for f in "$1"/*.expected.hex; do
        grep -v '^//' "$f" >"$2/$(basename "$f" .expected.hex).actual.hex"
    done
}
rtl_dir V A
rtl_dir VG AG

# ------------------------------------------------------------ identical data
for pair in "V A" "VG AG"; do
    read -r e a <<<"$pair"
    set -- "$e" "$a"
    run check "$1" "$2"
    if [ $rc = 0 ] && [ ! -s out ] && grep -q '^edgeflag check: PASS' err; then
        ok "identical directories $1 vs $2 pass"
    else
        bad "identical directories $1 vs $2" "exit $rc, want 0, empty stdout and a PASS line"
    fi
done
n=0 good=0
for f in V/*.expected.hex VG/*.expected.hex; do
    n=$((n + 1))
    d=${f%%/*}
    a=A${d#V}/$(basename "$f" .expected.hex).actual.hex     # V -> A, VG -> AG
    "$EF" check "$f" "$a" >out 2>err && [ ! -s out ] && good=$((good + 1))
done
[ $good = $n ] && ok "each hex file passes against its header-less dump ($n files)" ||
    bad "hex files against their dumps" "$good of $n passed"
for b in V VG; do
    mkdir -p "B$b" && cp "$b/vectors.bin" "B$b/vectors.actual.bin"
    run check $b/vectors.bin "B$b/vectors.actual.bin"
    [ $rc = 0 ] && [ ! -s out ] && ok "$b/vectors.bin passes against a copy of it" || bad "$b/vectors.bin against a copy" "exit $rc"
done
run check V/vectors.bin A/pix.actual.hex --interfaces pix
[ $rc = 0 ] && grep -q '^edgeflag check: pix: ' err && grep -q '^edgeflag check: span: skipped (not in --interfaces)' err &&
    ok "vectors.bin against a pix hex dump with --interfaces pix: pix compared, the rest skipped, pass" ||
    bad "bin vs hex --interfaces pix" "exit $rc"

# The model standing in for the DUT: `vectors --dump` names its files as dumps.
"$EFW" vectors "$root/tests/data/svg/tiger.svg" -o MD --size 160x120 --dump >/dev/null 2>err || bad "vectors --dump" "$(head -c 300 err)"
run check V MD
[ $rc = 0 ] && [ ! -e MD/manifest.json ] && [ -s MD/vectors.actual.bin ] && [ "$(grep -c ' 0 mismatches$' err)" = 13 ] &&
    head -n 1 MD/pix.actual.hex | grep -q 'role actual$' &&
    ok "vectors --dump: IFACE.actual.hex and vectors.actual.bin, no manifest; check passes on all 13 comparisons" ||
    bad "vectors --dump" "exit $rc"

# ------------------------------------------------------------ cannot pass by accident
# Each of these once passed: a dump folder holding copies of the expected files, the
# expected folder or file given twice, a bench that never wrote pix.actual.hex.
rm -rf C && cp -R V C
run check V C
[ $rc = 2 ] && grep -q 'nothing to compare.*it holds expected files' err && ! grep -q PASS err &&
    ok "a dump folder of copies of the expected files: exit 2, never taken for dumps" || bad "copies of expected" "exit $rc"
run check V V
[ $rc = 2 ] && grep -q '^edgeflag: V and V are the same directory' err && ok "EXPECTED given as ACTUAL: exit 2" ||
    bad "V V" "exit $rc"
run check V/pix.expected.hex V/pix.expected.hex
[ $rc = 2 ] && grep -q 'are the same file' err && ok "an expected file against itself: exit 2" || bad "file against itself" "exit $rc"
run check V/pix.expected.hex C/pix.expected.hex
[ $rc = 2 ] && grep -q 'is an expected file (\*.expected.hex), never a dump' err &&
    ok "an expected file given as the dump: exit 2" || bad "expected file as dump" "exit $rc"
rm -rf NP && cp -R A NP && rm NP/pix.actual.hex
run check V NP --junit jnp.xml
if [ $rc = 1 ] && grep -q '^edgeflag check: pix: FAIL: NP holds no dump of it' err && grep -q 'FAIL: .*1 interface without a dump' err &&
    xmllint --noout jnp.xml && grep -q '<failure type="missing dump" message="no dump of pix' jnp.xml &&
    grep -q 'failures="1"' jnp.xml; then
    ok "a bench that never wrote pix.actual.hex fails (exit 1, a JUnit failure)"
else
    bad "missing pix dump" "exit $rc"
fi
rm -rf NQ && cp -R A NQ && rm NQ/plot.actual.hex NQ/et_rd.actual.hex
run check V NQ
[ $rc = 1 ] && [ "$(grep -c ': FAIL: NQ holds no dump of it' err)" = 2 ] && ok "two internal dumps missing: both named, exit 1" ||
    bad "missing internal dumps" "exit $rc"
run check V NQ --allow-missing plot,et_rd --junit jnq.xml --name "case 7 seed 42"
if [ $rc = 0 ] && grep -q '^edgeflag check: plot: skipped' err && xmllint --noout jnq.xml &&
    grep -q '<testsuite name="case 7 seed 42" tests="6" failures="0" errors="0" skipped="2"' jnq.xml &&
    [ "$(grep -c '<skipped ' jnq.xml)" = 2 ] && grep -q 'classname="case 7 seed 42" name="pix: ' jnq.xml; then
    ok "--allow-missing plot,et_rd: pass, both listed as skipped in JUnit under --name"
else
    bad "--allow-missing" "exit $rc"
fi
run check V A --interfaces pix,span --junit jif.xml
[ $rc = 0 ] && [ "$(grep -c '<skipped ' jif.xml)" = 4 ] && grep -q '<testsuite name="V"' jif.xml &&
    ok "--interfaces pix,span: two compared, four skipped; the suite named after EXPECTED" || bad "--interfaces" "exit $rc"
run check V/span.expected.hex V/vectors.bin
[ $rc = 0 ] && ok "a span hex file against vectors.bin passes" || bad "hex vs bin" "exit $rc"

# ------------------------------------------------------------ the manifest
rm -rf N && cp -R V N && rm N/manifest.json
run check N A
[ $rc = 0 ] && grep -q '^edgeflag: warning: N has no manifest.json' err && [ "$(grep -c ' 0 mismatches$' err)" = 6 ] &&
    ok "no manifest: a warning, then every *.expected.hex compared" || bad "EXPECTED without a manifest" "exit $rc"
rm -rf N && cp -R V N
ml=$(grep -n '"name": "span.expected.hex"' N/manifest.json | cut -d: -f1)
fl=$(grep -n '"files": \[' N/manifest.json | cut -d: -f1)
sed -i "${ml}s/\"count\": [0-9]*/\"count\": 1/" N/manifest.json
run check N A
[ $rc = 2 ] && grep -Eq "^edgeflag: N/manifest.json: files\[$((ml - fl - 1))\]\.count: the manifest counts 1 transactions in 'span.expected.hex', the file holds" err &&
    ok "a manifest count that disagrees with its file: exit 2 naming the entry's key" || bad "manifest count" "exit $rc"
rm -rf N && cp -R V N && rm N/plot.expected.hex
run check N A
[ $rc = 2 ] && grep -Eq "^edgeflag: N/manifest.json: files\[[0-9]+\]\.name: the manifest names 'plot.expected.hex', which is not in N$" err &&
    ok "a manifest naming a missing file: exit 2" || bad "manifest naming a missing file" "exit $rc"

# ------------------------------------------------------------ hex mutations
# mutate_hex IFACE K BIT: flips payload bit BIT of the K-th word of IFACE in a
# copy M of V; the single report must name M's line, the cycle and place.
mutate_hex() {
    local iface=$1 k=$2 bit=$3 ln w nw want
    rm -rf M && cp -R A M
    layout "V/$iface.expected.hex"
    read -r ln w < <(nth_data "V/$iface.expected.hex" "$k")
    nw=$(flip_word "$w" "$bit")
    set_line "M/$iface.actual.hex" "$k" "$nw"
    want="M/$iface.actual.hex:$k: $(where "$iface" "$w"): fields differ: "
    run check V M
    if [ $rc = 1 ] && [ "$(wc -l <out)" = 1 ] && [[ "$(cat out)" == "$want"* ]] && grep -q '\*' out &&
        grep -q "(expected at V/$iface.expected.hex:$ln)" out; then
        ok "flipped bit $bit of $iface word $k: one report at line $k, ${want#*: }"
    else
        bad "flipped bit $bit of $iface word $k" "exit $rc, want 1 and one line starting '$want'"
    fi
    run check --transactions V M
    [ $rc = 1 ] && [ "$(wc -l <out)" = 1 ] && ok "--transactions fails the flipped $iface bit too" ||
        bad "--transactions and a flipped $iface bit" "exit $rc, want 1"
}
mutate_hex pix 1000 0       # rgba bit 0
mutate_hex span 500 0       # mask bit 0
mutate_hex plot 2000 1      # q bit 0 (bit 0 is dir)

# Drop the 777th pix from a header-less dump: reported missing at the expected line.
rm -rf D && cp -R A D
layout V/pix.expected.hex
read -r ln w < <(nth_data V/pix.expected.hex 777)
del_line D/pix.actual.hex 777
run check V D
want="V/pix.expected.hex:$ln: $(where pix "$w"): missing transaction: "
if [ $rc = 1 ] && [ "$(wc -l <out)" = 1 ] && [[ "$(cat out)" == "$want"* ]] && grep -q '(before D/pix.actual.hex:777)' out; then
    ok "dropped pix 777: one 'missing' report at V/pix.expected.hex:$ln, ${want#*: }"
else
    bad "dropped pix 777" "exit $rc, want 1 and one line starting '$want'"
fi
run check --transactions V D
[ $rc = 1 ] && grep -q 'missing transaction' out && ok "--transactions fails the dropped pix too" ||
    bad "--transactions and a dropped pix" "exit $rc"

# Delay one pix by one cycle (and one span): a single 'late by 1' report; --transactions passes.
delay_test() {
    local iface=$1 k=$2 ln w nw
    rm -rf L && cp -R A L
    layout "V/$iface.expected.hex"
    read -r ln w < <(nth_data "V/$iface.expected.hex" "$k")
    nw=$(delay_word "$w" 1)
    set_line "L/$iface.actual.hex" "$k" "$nw"
    local c
    c=$(field "$w" cycle)
    local want
    want="L/$iface.actual.hex:$k: $(where "$iface" "$w"): cycle differs: expected $c, actual $((c + 1)) (late by 1): "
    run check V L
    if [ $rc = 1 ] && [ "$(wc -l <out)" = 1 ] && [[ "$(cat out)" == "$want"* ]]; then
        ok "$iface $k delayed by a cycle: one report, ${want#*: }"
    else
        bad "$iface $k delayed by a cycle" "exit $rc, want 1 and one line starting '$want'"
    fi
    run check V L --transactions
    [ $rc = 0 ] && [ ! -s out ] && ok "--transactions passes the delayed $iface" || bad "--transactions, delayed $iface" "exit $rc, want 0"
}
delay_test pix 1500
delay_test span 300

# ------------------------------------------------------------ binary mutations
bin_where() {   # IFACE "record R offset O cycle C payload HEX" -> the report's prefix after the file name
    local iface=$1 r o c p
    read -r _ r _ o _ c _ p <<<"$2"
    layout "V/$iface.expected.hex"
    local s=
    for f in y row; do [ -n "${FH[$f]:-}" ] && { s+=", $f $(bits "$p" "${FH[$f]}" "${FL[$f]}")"; break; }; done
    for f in x q; do [ -n "${FH[$f]:-}" ] && { s+=", $f $(bits "$p" "${FH[$f]}" "${FL[$f]}")"; break; }; done
    echo "record $r (byte offset $o): $iface: cycle $c$s"
}
mkdir -p B
info=$("$MUT" V/vectors.bin B/vectors.bin flip pix 2000 8 2>&1)   # alpha bit 0... or rgba bit 8
run check V/vectors.bin B/vectors.bin
want="B/vectors.bin: $(bin_where pix "$info"): fields differ: "
[ $rc = 1 ] && [ "$(wc -l <out)" = 1 ] && [[ "$(cat out)" == "$want"* ]] && ok "vectors.bin, flipped pix bit: ${want}..." ||
    bad "vectors.bin flipped pix bit" "exit $rc, want 1 and '$want'"
info=$("$MUT" V/vectors.bin B/vectors.bin drop span 100 2>&1)
run check V/vectors.bin B/vectors.bin
want="V/vectors.bin: $(bin_where span "$info"): missing transaction: "
[ $rc = 1 ] && [ "$(wc -l <out)" = 1 ] && [[ "$(cat out)" == "$want"* ]] && ok "vectors.bin, dropped span: ${want}..." ||
    bad "vectors.bin dropped span" "exit $rc, want 1 and '$want'"
info=$("$MUT" V/vectors.bin B/vectors.bin delay plot 300 1 2>&1)
run check V/vectors.bin B/vectors.bin
want="B/vectors.bin: $(bin_where plot "$info" | sed 's/cycle \([0-9]*\)/cycle X/'): cycle differs: "
got=$(sed 's/cycle \([0-9]*\),/cycle X,/' out)
c=$(awk '{ print $6 }' <<<"$info")
[ $rc = 1 ] && [ "$(wc -l <out)" = 1 ] && [[ "$got" == "$want"* ]] && grep -q "expected $((c - 1)), actual $c (late by 1)" out &&
    ok "vectors.bin, delayed plot: one 'late by 1' report at its record" || bad "vectors.bin delayed plot" "exit $rc, want '$want'"
run check V/vectors.bin B/vectors.bin --transactions
[ $rc = 0 ] && ok "--transactions passes the delayed plot record" || bad "--transactions, delayed plot record" "exit $rc"

# ------------------------------------------------------------ --errors
rm -rf E && cp -R A E
for k in $(seq 100 10 390); do
    read -r ln w < <(nth_data E/pix.actual.hex "$k")
    set_line E/pix.actual.hex "$ln" "$(flip_word "$w" 0)"
done
run check V E
[ $rc = 1 ] && [ "$(wc -l <out)" = 20 ] && grep -q 'FAIL: 30 mismatches .*(20 reported)' err &&
    ok "30 mismatches: 20 lines by default, the count exact" || bad "--errors default" "exit $rc, $(wc -l <out) lines"
run check V E --errors 7
[ $rc = 1 ] && [ "$(wc -l <out)" = 7 ] && grep -q 'FAIL: 30 mismatches .*(7 reported)' err &&
    ok "--errors 7: 7 lines, 30 counted" || bad "--errors 7" "exit $rc, $(wc -l <out) lines"
run check V E --errors=0
[ $rc = 1 ] && [ "$(wc -l <out)" = 30 ] && ok "--errors 0: all 30 lines" || bad "--errors 0" "exit $rc, $(wc -l <out) lines"

# ------------------------------------------------------------ the library
# The verifier through rtl_vectors/ef_check.h (tests/check/check_lib.c), as edgeflag-host and a
# testbench call it: the status the command's exit code says, the same mismatch lines and the same JUnit (but for
# its times) as the command, the same pixels marked, and not one byte on stderr (no status stream).
if [ -x "$LIB" ]; then
    for pair in "V/vectors.bin B/vectors.bin" "V/pix.expected.hex A/pix.actual.hex" "V A" "V E"; do
        read -r e a <<<"$pair"
        run check "$e" "$a" --errors 0 --junit jc.xml --diff-image dc.pam
        crc=$rc
        case $crc in 0) cst=pass ;; 1) cst=fail ;; 2) cst=input ;; *) cst="exit $crc" ;; esac # docs/cli.md
        "$LIB" "$e" "$a" lib_report lib_junit.xml >lib_out 2>lib_err
        hdr=$(grep -abo ENDHDR dc.pam | head -n 1 | cut -d: -f1)   # the pixels start after "ENDHDR\n"
        marked=$(tail -c +$((hdr + 8)) dc.pam | od -An -v -tx1 -w4 | grep -c '^ ff 00 ff ff$')
        if grep -q "^status $cst mismatches .* magenta $marked\$" lib_out && cmp -s out lib_report && [ ! -s lib_err ] &&
            cmp -s <(sed 's/time="[0-9.]*"//g' jc.xml) <(sed 's/time="[0-9.]*"//g' lib_junit.xml); then
            ok "ef_check_run on $e vs $a: status $cst (exit $crc), the command's report, JUnit and $marked marked pixels, silent"
        else
            bad "ef_check_run on $e vs $a" "command: exit $crc, $marked magenta; library: $(cat lib_out)" \
                "$(diff out lib_report | head -n 4)"
        fi
    done
else
    bad "tests/check/check_lib not built"
fi

# ------------------------------------------------------------ --junit
run check V E --junit j.xml
# E holds the six expected interfaces' dumps (cmd is stimulus, there is no vectors.bin).
if [ $rc = 1 ] && xmllint --noout j.xml 2>xmlerr && grep -q 'tests="6" failures="1" errors="0"' j.xml &&
    [ "$(grep -c '<testcase ' j.xml)" = 6 ] && grep -q '<failure type="mismatch" message="30 mismatches' j.xml; then
    ok "--junit: well-formed (xmllint), 6 test cases, one failure of 30"
else
    bad "--junit" "exit $rc; $(head -c 300 xmlerr 2>/dev/null)"
fi
weird="q&<>\"'$(printf '\001\377')x.hex"
cp A/pix.actual.hex "$weird"
run check V/pix.expected.hex "$weird" --junit "j&.xml"
[ $rc = 0 ] && xmllint --noout "j&.xml" 2>/dev/null && grep -q 'q&amp;&lt;&gt;&quot;&apos;\\x01\\xffx.hex' "j&.xml" &&
    ok "--junit escapes a file name with & < > \" ' and control bytes" || bad "--junit escaping" "exit $rc"
run check V A --junit j2.xml
[ $rc = 0 ] && xmllint --noout j2.xml && grep -q 'failures="0" errors="0"' j2.xml && ok "--junit of a pass: no failure" ||
    bad "--junit pass" "exit $rc"
printf 'zz\n' >Z.hex
run check V/pix.expected.hex Z.hex --junit j3.xml
[ $rc = 2 ] && xmllint --noout j3.xml && grep -q '<error type="unreadable input" message="Z.hex:1:1: ' j3.xml &&
    ok "--junit after an unreadable input: an <error> case, exit 2" || bad "--junit error case" "exit $rc"

# ------------------------------------------------------------ --diff-image
rm -rf P && cp -R A P
layout V/pix.expected.hex
read -r ln w < <(nth_data V/pix.expected.hex 3000)
set_line P/pix.actual.hex 3000 "$(flip_word "$w" 4)"
py=$(field "$w" y) px=$(field "$w" x)
run check V P --diff-image d.png
magic=$(od -An -tx1 -N8 d.png | tr -d ' ')
dims=$(od -An -tu1 -j16 -N8 d.png | awk '{ print ($1*16777216+$2*65536+$3*256+$4) "x" ($5*16777216+$6*65536+$7*256+$8) }')
[ $rc = 1 ] && [ "$magic" = 89504e470d0a1a0a ] && [ "$dims" = 160x120 ] && ! ls .d.png.* >/dev/null 2>&1 &&
    ok "--diff-image: a PNG of 160x120" || bad "--diff-image PNG" "exit $rc, magic $magic, size $dims"
run check V P --diff-image d.pam
hdr=$(head -c $(($(wc -c <d.pam) - 160 * 120 * 4)) d.pam | tr '\n' ' ')
marked=$(tail -c $((160 * 120 * 4)) d.pam | od -An -v -tx1 -w4 | tr -d ' ' | grep -n '^ff00ffff$' | cut -d: -f1 | tr '\n' ' ')
if [ $rc = 1 ] && [ "$hdr" = "P7 WIDTH 160 HEIGHT 120 DEPTH 4 MAXVAL 255 TUPLTYPE RGB_ALPHA ENDHDR " ] &&
    [ "$marked" = "$((py * 160 + px + 1)) " ]; then
    ok "--diff-image: exactly the mutated pixel ($px, $py) is marked"
else
    bad "--diff-image marks" "exit $rc, marked pixel(s) '$marked', want $((py * 160 + px + 1)) (x $px, y $py)"
fi
# The picture is the expected frame: the last pix word's pixel has its rgba.
read -r ln w < <(grep -n -v '^//' V/pix.expected.hex | tail -n 1 | tr ':' ' ')
lx=$(field "$w" x) ly=$(field "$w" y)
got=$(tail -c $((160 * 120 * 4)) d.pam | od -An -v -tx1 -w4 -j $(((ly * 160 + lx) * 4)) -N4 | tr -d ' ')
[ "$got" = "$(printf %08x "$(field "$w" rgba)")" ] && ok "--diff-image draws the expected frame (pixel $lx,$ly = $got)" ||
    bad "--diff-image background" "pixel $lx,$ly is $got, want $(printf %08x "$(field "$w" rgba)")"

# ------------------------------------------------------------ usage and outputs
usage_case() {   # WANT-REGEX ARGS...
    local re=$1
    shift
    run check "$@"
    if [ $rc = 2 ] && [ ! -s out ] && head -n 1 err | grep -Eq "^edgeflag: check: $re" && grep -q "^Try 'edgeflag check --help'" err; then
        ok "usage: check $* -> exit 2"
    else
        bad "usage: check $*" "exit $rc, want 2 and 'edgeflag: check: $re'"
    fi
}
usage_case 'two files or directories needed'
usage_case 'two files or directories needed' V
usage_case 'more than two files' V V V
usage_case "--errors must be a number" V V --errors x
usage_case "--errors must be a number" V V --errors -1
usage_case "--errors must be a number" V V --errors 99999999999
usage_case "--errors given twice" V V --errors 1 --errors 2
usage_case "--cycles and --transactions exclude each other" V V --cycles --transactions
usage_case "option '--cycles' takes no value" V V --cycles=yes
usage_case "unknown option '--frob'" V V --frob
usage_case "unknown option '--err'" V V --err 3   # no abbreviations (getopt_long would take it)
usage_case "unknown option '--trans'" V V --trans
usage_case "--diff-image must name a .png" V V --diff-image d.jpg
usage_case "option '--junit' needs a value" V V --junit
usage_case "--junit and --diff-image name the same file" V V --junit x.png --diff-image x.png
usage_case "--allow-missing cannot name pix" V A --allow-missing plot,pix
usage_case "--interfaces must include pix" V A --interfaces span
usage_case "--interfaces must be a comma-separated list of" V A --interfaces pix,frob
usage_case "empty --name" V A --name ""
run check --help
[ $rc = 0 ] && grep -q '^usage: edgeflag check EXPECTED ACTUAL' out && ok "check --help" || bad "check --help" "exit $rc"
run help check
[ $rc = 0 ] && grep -q '^usage: edgeflag check' out && ok "edgeflag help check" || bad "help check" "exit $rc"
run check V A/pix.actual.hex
[ $rc = 2 ] && grep -q '^edgeflag: V is a directory and A/pix.actual.hex is not' err && ok "a directory against a file: exit 2" ||
    bad "dir vs file" "exit $rc"
run check V missing_dir
[ $rc = 2 ] && grep -q '^edgeflag: missing_dir: cannot open: No such file or directory' err && ok "a missing ACTUAL: exit 2" ||
    bad "missing ACTUAL" "exit $rc"
mkdir empty_dir
run check V empty_dir
[ $rc = 2 ] && grep -q 'nothing to compare' err && ok "an ACTUAL directory without dumps: exit 2, nothing to compare" ||
    bad "empty ACTUAL dir" "exit $rc"
run check V E --junit no/such/dir/j.xml
[ $rc = 4 ] && [ ! -e no ] && grep -q "^edgeflag: cannot write 'no/such/dir/j.xml'" err && ok "--junit into a missing directory: exit 4" ||
    bad "--junit unwritable" "exit $rc"
mkdir ro && chmod a-w ro
run check V E --diff-image ro/d.png
if [ "$(id -u)" = 0 ]; then
    ok "# skip: --diff-image into a read-only directory (root ignores permissions)"
else
    [ $rc = 4 ] && [ -z "$(ls -A ro)" ] && ok "--diff-image into a read-only directory: exit 4, nothing left" ||
        bad "--diff-image unwritable" "exit $rc"
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
