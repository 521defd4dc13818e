#!/usr/bin/env bash
# tests/mutants/c-mutants.sh - mutation testing of the board engine and the
# host link (issue 27; make c-mutants): tests/mutants.sh's idea (the tests must
# fail on a broken build) over board/ef_board.c and host/host_link.c.
#   1. a private copy of BUILD_DIR (edgeflag, edgeflag-host) in the work folder;
#   2. tests/host/run.sh (make test-host: verify on every interface, the fault
#      matrix, resume, wrong use) must pass on it unmutated;
#   3. for each mutant drawn (tests/mutants/c_mutate.py: comparisons flipped,
#      && and || swapped, decimal constants off by one; EF_CMUT_SAMPLE per file,
#      seeded by EF_CMUT_SEED), the mutated file is compiled with the build's
#      own command line into the copy, edgeflag-host relinked, and
#      tests/host/run.sh run (EF_CMUT_TIMEOUT s): a failure kills the mutant;
#      a mutant that does not compile is stillborn (not counted);
#   4. the report: per file mutants, stillborn, killed, survivors with their
#      line and text.
#   5. a survivor of tests/host/run.sh meets the file's second oracle: for the board
#      engine tests/board/probe.py against the copy's sockboard; for the host link the
#      host's byte-stream stages, tests/host/socket.sh (edgeflag-host against pyboard and
#      sockboard) and tests/host/serial.sh (against ptyboard through pseudo-terminals),
#      killed as in 3 when fewer of their checks pass than unmutated;
#      tests/mutants/c_equivalent.tsv lists the equivalent ones.
# usage: bash tests/mutants/c-mutants.sh BUILD_DIR   (EF_CMUT_SAMPLE (20),
#        EF_CMUT_SEED (27), EF_CMUT_FILES, EF_CMUT_TIMEOUT (600), EF_CMUT_OUT=DIR,
#        EF_CMUT_IDS=FILE:ID,... only these of the draw, EF_CMUT_ORACLE=probe the second
#        oracle alone (for the survivors of an earlier run), EF_CMUT_REQUIRE=1 fail on a survivor)
# Ends with "N passed, M failed".
set -u
export LC_ALL=C
build=${1:?usage: tests/mutants/c-mutants.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
sample=${EF_CMUT_SAMPLE:-20}
seed=${EF_CMUT_SEED:-27}
tmo=${EF_CMUT_TIMEOUT:-600}
files=${EF_CMUT_FILES:-board/ef_board.c host/host_link.c}
[ -x "$build/edgeflag-host" ] && [ -x "$build/edgeflag" ] || { echo "c-mutants: build edgeflag and edgeflag-host first (make cli host)"; echo "0 passed, 1 failed"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-cmut.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
t0=$(date +%s)
b=$work/b
mkdir -p "$b"
(cd "$build" && tar --exclude=./venv -cf - .) | (cd "$b" && tar -xf -)
cd "$root" || exit 1
# the copy is relinked with the tree's make rules: a tree that changes under the run (a merge)
# would rebuild the copy from other sources and "kill" every mutant; the run stops instead
treestate() { { git -C "$root" rev-parse HEAD; git -C "$root" status --porcelain --untracked-files=no; } 2>/dev/null | cksum; }
tree0=$(treestate)
relink() { make --no-print-directory -s BUILD="$b" "$b/edgeflag-host" "$b/tests/host/sockboard" "$b/tests/host/ptyboard" >"$work/link.log" 2>&1; }
# the second oracle, for a mutant that tests/host/run.sh does not kill: tests/board/probe.py (the
# engine's answers to what no correct host sends, make test-host-socket) against the copy's
# sockboard (the engine behind a unix socket, relinked with the mutant)
probe() {
    local sock=$work/p.sock pid rc
    rm -f "$sock"
    "$b/tests/host/sockboard" "$sock" 2>/dev/null &
    pid=$!
    for _ in $(seq 100); do [ -S "$sock" ] && break; sleep 0.1; done
    timeout 120 python3 "$root/tests/board/probe.py" "unix:$sock" >"$work/probe.log" 2>&1; rc=$?
    # a mutant can spin (a search that never ends) where SIGTERM's handler is never reached
    kill "$pid" 2>/dev/null; sleep 0.5; kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
    [ $rc = 0 ] && tail -n 1 "$work/probe.log" | grep -q ' 0 failed$'
}
# the host link's second oracle: edgeflag-host on the byte-stream transports (make test-host-socket,
# make test-host-serial) against the copy; killed when fewer checks pass than unmutated (hostio_ok)
declare -A hostio_ok=()
hostio() {
    local s n
    for s in socket serial; do
        timeout "$tmo" bash "$root/tests/host/$s.sh" "$b" </dev/null >"$work/probe.log" 2>&1
        n=$(grep -c '^ok - ' "$work/probe.log")
        if [ -z "${hostio_ok[$s]:-}" ]; then hostio_ok[$s]=$n; [ "$n" -gt 0 ] || return 1
        elif [ "$n" -lt "${hostio_ok[$s]}" ]; then return 1; fi
    done
}
oracle2() { case $1 in host/*) hostio ;; *) probe ;; esac; }
relink || { cat "$work/link.log"; echo "FAIL c-mutants: the copy does not link"; echo "0 passed, 1 failed"; exit 1; }
# The baseline: what tests/host/run.sh says of the unmutated copy.  A check that already fails
# there (a test out of step with the tree) is no oracle: a mutant is killed when fewer checks
# pass than unmutated ("ok - " lines), or the run times out.
timeout "$tmo" bash "$root/tests/host/run.sh" "$b" </dev/null >"$work/m0.log" 2>&1
grep '^FAIL - ' "$work/m0.log" >"$work/m0.fail"
nok=$(grep -c '^ok - ' "$work/m0.log")
[ "$nok" -gt 0 ] || { tail -20 "$work/m0.log"; echo "FAIL c-mutants: tests/host/run.sh passes nothing on the unmutated copy"; echo "0 passed, 1 failed"; exit 1; }
echo "PASS c-mutants: tests/host/run.sh on the unmutated copy: $(tail -n 1 "$work/m0.log") (the baseline)"
case " $files " in *" board/"*)
    probe || { cat "$work/probe.log"; echo "FAIL c-mutants: tests/board/probe.py fails on the unmutated copy"; echo "1 passed, 1 failed"; exit 1; }
    echo "PASS c-mutants: tests/board/probe.py on the unmutated copy: $(tail -n 1 "$work/probe.log")" ;;
esac
case " $files " in *" host/"*)
    hostio || { tail -20 "$work/probe.log"; echo "FAIL c-mutants: tests/host/socket.sh or serial.sh passes nothing on the unmutated copy"; echo "1 passed, 1 failed"; exit 1; }
    echo "PASS c-mutants: tests/host/socket.sh and serial.sh on the unmutated copy: ${hostio_ok[socket]} and ${hostio_ok[serial]} checks pass (the baseline)" ;;
esac
[ -s "$work/m0.fail" ] && sed 's/^/    already failing unmutated, not an oracle: /' "$work/m0.fail"
: >"$work/results.tsv"
for f in $files; do
    obj=$b/${f%.c}.o
    cp "$obj" "$work/orig.o"
    # the build's own compile command for this object, with the source swapped
    cmd=$(make --no-print-directory -n -B BUILD="$b" "$obj" 2>/dev/null | grep -E "(^| )-c $f " | tail -n 1)
    [ -n "$cmd" ] || { echo "FAIL c-mutants: no compile command for $f"; echo "0 passed, 1 failed"; exit 1; }
    python3 "$root/tests/mutants/c_mutate.py" list "$f" >"$work/all.tsv"
    python3 - "$work/all.tsv" "$sample" "$seed" "${EF_CMUT_IDS:-}" "$f" >"$work/sel.tsv" <<'EOF'
import random, sys
rows = [l.rstrip("\n") for l in open(sys.argv[1]) if l.strip()]
n = int(sys.argv[2])
if 0 < n < len(rows):
    rows = sorted(random.Random(int(sys.argv[3])).sample(rows, n), key=lambda r: int(r.split("\t")[0]))
if sys.argv[4]:     # EF_CMUT_IDS: of the draw, only these FILE:ID
    ids = {x.split(":")[1] for x in sys.argv[4].split(",") if x.split(":")[0] == sys.argv[5]}
    rows = [r for r in rows if r.split("\t")[0] in ids]
print("\n".join(rows))
EOF
    echo "c-mutants: $f: $(grep -c . "$work/sel.tsv") of $(grep -c . "$work/all.tsv") mutants drawn (seed $seed)"
    # the draw on fd 3: nothing a test runs (script(1) reads its stdin) can eat the list
    while IFS=$'\t' read -r id line op old new <&3; do
        if [ "$(treestate)" != "$tree0" ]; then
            echo "FAIL c-mutants: the tree changed under the run (a commit or an edit): its verdicts would not be of one build"
            echo "1 passed, 1 failed"; exit 1
        fi
        mdir=$work/src/$(dirname "$f"); mkdir -p "$mdir"
        python3 "$root/tests/mutants/c_mutate.py" write "$f" "$id" "$mdir/$(basename "$f")"
        mcmd=${cmd/ -c $f / -iquote $(dirname "$f") -c $mdir/$(basename "$f") }
        if ! eval "$mcmd" >"$work/cc.log" 2>&1 || ! relink; then
            printf '%s\t%s\t%s\t%s\t%s\t%s\tstillborn\n' "$f" "$id" "$line" "$op" "$old" "$new" >>"$work/results.tsv"
        else
            if [ "${EF_CMUT_ORACLE:-}" = probe ]; then
                : >"$work/run.log"; rc=0   # run.sh skipped: the draw's survivors of an earlier run
            else
                timeout "$tmo" bash "$root/tests/host/run.sh" "$b" </dev/null >"$work/run.log" 2>&1; rc=$?
            fi
            nf=$(grep -m1 '^FAIL - ' "$work/run.log")
            if [ $rc = 124 ] || { [ "${EF_CMUT_ORACLE:-}" != probe ] && [ "$(grep -c '^ok - ' "$work/run.log")" -lt "$nok" ]; }; then
                printf '%s\t%s\t%s\t%s\t%s\t%s\tkilled %s\n' "$f" "$id" "$line" "$op" "$old" "$new" \
                    "$( [ $rc = 124 ] && echo timeout || echo "${nf:-no summary}" | cut -c1-80)" >>"$work/results.tsv"
            elif ! oracle2 "$f"; then
                printf '%s\t%s\t%s\t%s\t%s\t%s\tkilled-oracle2 %s\n' "$f" "$id" "$line" "$op" "$old" "$new" \
                    "$(grep -m1 '^FAIL - ' "$work/probe.log" | cut -c1-80)" >>"$work/results.tsv"
            else
                printf '%s\t%s\t%s\t%s\t%s\t%s\tSURVIVED\n' "$f" "$id" "$line" "$op" "$old" "$new" >>"$work/results.tsv"
            fi
        fi
    done 3<"$work/sel.tsv"
    cp "$work/orig.o" "$obj"; touch "$obj"; relink
done
# the report: per file; a survivor listed in tests/mutants/c_equivalent.tsv (file, operator, old,
# new, the line before and the mutated line as they read, the reason) is equivalent, not a miss
python3 - "$work/results.tsv" "$root/tests/mutants/c_equivalent.tsv" "$root" >"$work/report.txt" <<'EOF'
import sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if l.strip()]
eqv = {}
for l in open(sys.argv[2]):
    if l.startswith("#") or l.startswith("file\t") or not l.strip():
        continue
    f, op, old, new, src, why = l.rstrip("\n").split("\t")
    eqv[(f, op, old, new, src)] = why
src = {}
per = {}
surv = []
apart = []
for f, mid, line, op, old, new, verdict in rows:
    if f not in src:
        src[f] = open(sys.argv[3] + "/" + f).read().split("\n")
    ln = int(line)
    text = " ".join(src[f][ln - 2].split()) + " / " + " ".join(src[f][ln - 1].split())   # the line before, and it
    c = per.setdefault(f, [0, 0, 0, 0, 0, 0])   # mutants, stillborn, killed run.sh, killed 2nd oracle, equivalent, survived
    c[0] += 1
    if verdict == "stillborn":
        c[1] += 1
    elif verdict.startswith("killed-oracle2") or verdict.startswith("killed-probe"):
        c[3] += 1
    elif verdict.startswith("killed"):
        c[2] += 1
    elif (f, op, old, new, text) in eqv:
        c[4] += 1
        kind = eqv[(f, op, old, new, text)].split(" ")[0].rstrip(":")
        if kind in ("UNREACHABLE", "TIMING"):
            apart.append("listed %s (counted with the equivalent ones, not a behavioural equivalence): %s:%s %s: %s -> %s" % (kind, f, line, op, old, new))
    else:
        c[5] += 1
        surv.append("survivor: %s:%s %s: %s -> %s  | %s" % (f, line, op, old, new, text))
print("%-18s %8s %10s %9s %7s %10s %9s %12s %12s" % ("file", "mutants", "stillborn", "host-run", "oracle2",
                                                     "equivalent", "survived", "score(host)", "score(+2nd)"))
print("(oracle2: tests/board/probe.py for board/, tests/host/socket.sh and serial.sh for host/)")
for f in sorted(per):
    c = per[f]
    ne = c[0] - c[1] - c[4]
    print("%-18s %8d %10d %9d %7d %10d %9d %11.1f%% %11.1f%%" % (f, c[0], c[1], c[2], c[3], c[4], c[5],
          100.0 * c[2] / ne if ne else 0, 100.0 * (c[2] + c[3]) / ne if ne else 0))
for l in apart + surv:
    print(l)
print("SURVIVORS %d" % len(surv))
EOF
cat "$work/report.txt"
[ -n "${EF_CMUT_OUT:-}" ] && { mkdir -p "$EF_CMUT_OUT"; cp "$work/results.tsv" "$work/report.txt" "$EF_CMUT_OUT/"; }
echo "c-mutants: $(( $(date +%s) - t0 )) s"
nsv=$(sed -n 's/^SURVIVORS //p' "$work/report.txt")
if [ "${EF_CMUT_REQUIRE:-0}" = 1 ] && [ "${nsv:-1}" != 0 ]; then
    echo "FAIL c-mutants: $nsv non-equivalent mutants survive"; echo "1 passed, 1 failed"; exit 1
fi
echo "2 passed, 0 failed"
