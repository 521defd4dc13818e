#!/usr/bin/env bash
# tests/bad/run.sh BUILD_DIR - runs the bad-input catalogue (CATALOGUE.tsv;
# README.md explains it).  For every entry, `edgeflag render FILE -o OUT ARGS`
# (or, for an entry whose command column says check, `edgeflag check ARGS`; gen:
# `edgeflag gen --list --dut-file FILE ARGS`; host: `edgeflag-host stream FILE ...`)
# must:
#   - exit with the documented code, never by a signal (no crash), within 60 s;
#   - print "edgeflag: FILE:LINE:COL: MESSAGE" (or "edgeflag: FILE: MESSAGE"
#     for a whole-file error, "edgeflag: render: MESSAGE" for a usage error)
#     with the entry's position and MESSAGE matching the entry's regex;
#   - leave no OUT and no temporary ".OUT.XXXXXX" behind on failure, and a
#     complete OUT on success;
# and the library (tests/tools/load_check) must report the entry's exact error
# class and the same position.  Ends with "N passed, M failed".
set -u
build=${1:?usage: tests/bad/run.sh BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
LC=$build/tests/tools/load_check
VL=$build/tests/check/vec_load     # the vector readers, for the `check` entries
EH=$build/edgeflag-host            # the `host` entries
ext=${EF_BAD_EXT:-png}      # .pam for a WITH_PNG=0 build
for b in "$EF" "$LC" "$VL"; do
    [ -x "$b" ] || { echo "bad: $b not built"; echo "0 passed, 1 failed"; exit 1; }
done

tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-bad.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cp -R "$here/files/." "$tmp/"
bash "$here/gen.sh" "$tmp" || { echo "bad: gen.sh failed"; echo "0 passed, 1 failed"; exit 1; }
cd "$tmp" || exit 1

pass=0 fail=0
bad() {
    fail=$((fail + 1))
    echo "FAIL - $1"
    shift
    for l in "$@"; do echo "       $l"; done
    sed 's/^/       stderr: /' err | head -n 3
}
# exit_ok: the exit code $rc is $want, and not a signal or a timeout; else a FAIL line, 1
exit_ok() {
    if [ "$rc" -ge 124 ]; then
        bad "$what" "exit $rc: killed by a signal or timed out (want $want)"; return 1
    fi
    if [ "$rc" != "$want" ]; then
        bad "$what" "exit $rc, want $want"; return 1
    fi
}
# msg_ok PREFIX: $msg is PREFIX and then a text ($text) that matches $regex; else a FAIL line, 1
msg_ok() {
    case $msg in
    "$1"*) text=${msg#"$1"} ;;
    *) bad "$what" "message does not start with '$1'"; return 1 ;;
    esac
    if ! printf '%s\n' "$text" | grep -Eq -- "$regex"; then
        bad "$what" "message '$text' does not match /$regex/"; return 1
    fi
}
# check_entry: one `edgeflag check ARGS` entry (command column "check"): the
# exit code, the message (on stderr; stdout empty unless mismatches, which no
# entry has), no output file, and the readers' own class and place.
check_entry() {
    # shellcheck disable=SC2086
    timeout 60 "$EF" check $args >stdout 2>err
    rc=$?
    what="check $args"
    msg=$(grep -v '^edgeflag: warning: ' err | grep -m1 '^edgeflag: ')
    exit_ok || return
    if [ "$want" = 0 ]; then
        if [ -s stdout ] || [ -n "$msg" ]; then bad "$what" "exit 0 but output or an error message"; return; fi
    else
        if [ "$class" = usage ]; then
            prefix="edgeflag: check: "
        elif [ "$where" = - ]; then
            prefix="edgeflag: $file: "
        else
            prefix="edgeflag: $file:$where: "
        fi
        msg_ok "$prefix" || return
    fi
    if [ "$class" != usage ]; then
        # shellcheck disable=SC2086
        got=$("$VL" $args)
        gclass=$(printf '%s' "$got" | cut -f1) gwhere=$(printf '%s' "$got" | cut -f2)
        if [ "$gclass" != "$class" ] || [ "$gwhere" != "$where" ]; then
            bad "$what" "library says '$gclass' at $gwhere, want '$class' at $where"; return
        fi
    fi
    pass=$((pass + 1))
    echo "ok   - $what -> $want${class:+ ($class)}"
}

# host_entry: one `edgeflag-host stream FILE --transport sim ARGS` entry (command
# column "host"): a vectors file the host must refuse before sending anything —
# the exit code (docs/board.md section 7), `edgeflag-host: FILE: MESSAGE` with the
# reader's place in MESSAGE, and no results written.
host_entry() {
    rm -rf hostout
    # shellcheck disable=SC2086
    timeout 60 "$EH" stream "$file" --transport sim --results hostout --quiet $args >stdout 2>err
    rc=$?
    what="edgeflag-host stream $file${args:+ $args}"
    msg=$(grep -m1 '^edgeflag-host: ' err)
    exit_ok || return
    prefix="edgeflag-host: $file: "
    msg_ok "$prefix" || return
    if [ -e hostout/vectors.actual.bin ]; then
        bad "$what" "results written for a refused input"; return
    fi
    pass=$((pass + 1))
    echo "ok   - $what -> $want"
}

# gen_entry: one `edgeflag gen --list --dut-file FILE ARGS` entry (command column "gen"): a DUT
# limits file (docs/gen.md section 11) -- exit 2 with `edgeflag: FILE:LINE:COL: MESSAGE` (or the
# identify record's byte offset in MESSAGE, where "-") and nothing on standard output; or, for
# class ok, exit 0 with the index on standard output and no error message.
gen_entry() {
    # shellcheck disable=SC2086
    timeout 60 "$EF" gen --list --dut-file "$file" $args >stdout 2>err
    rc=$?
    what="gen --dut-file $file${args:+ $args}"
    msg=$(grep -m1 '^edgeflag: ' err)
    exit_ok || return
    if [ "$want" = 0 ]; then
        if ! grep -q '^case	file	kind' stdout || [ -n "$msg" ]; then bad "$what" "exit 0 but no index, or an error message"; return; fi
    else
        if [ -s stdout ]; then bad "$what" "exit $rc but an index on standard output"; return; fi
        if [ "$where" = - ]; then prefix="edgeflag: $file: "; else prefix="edgeflag: $file:$where: "; fi
        msg_ok "$prefix" || return
    fi
    pass=$((pass + 1))
    echo "ok   - $what -> $want"
}

n=0
while IFS=$'\t' read -r file want class regex where args command; do
    case $file in ''|'#'*|file) continue ;; esac
    n=$((n + 1))
    if [ "${command:-render}" = check ]; then
        check_entry
        continue
    fi
    if [ "${command:-render}" = host ]; then
        host_entry
        continue
    fi
    if [ "${command:-render}" = gen ]; then
        gen_entry
        continue
    fi
    out=out$n.$ext
    # shellcheck disable=SC2086
    timeout 60 "$EF" render "$file" -o "$out" $args >stdout 2>err
    rc=$?
    what="$file${args:+ $args}"
    msg=$(grep -v '^edgeflag: warning: ' err | grep -m1 '^edgeflag: ')
    exit_ok || continue
    temps=$(find . -maxdepth 1 -name ".$out.*" | head -n 3)
    if [ -n "$temps" ]; then
        bad "$what" "temporary left behind: $temps"; rm -f ./.out*; continue
    fi
    if [ "$want" = 0 ]; then
        if [ ! -s "$out" ] || [ -n "$msg" ]; then
            bad "$what" "exit 0 but no complete output, or an error message"; continue
        fi
        rm -f "$out"
    else
        if [ -e "$out" ]; then
            bad "$what" "failed (exit $rc) but left $out"; rm -f "$out"; continue
        fi
        if [ "$want" = 2 ]; then
            prefix="edgeflag: render: "
        elif [ "$where" = - ]; then
            prefix="edgeflag: $file: "
        else
            prefix="edgeflag: $file:$where: "
        fi
        msg_ok "$prefix" || continue
    fi
    if [ "$class" != usage ]; then
        size=()
        [[ "$args" == --size* ]] && read -r -a size <<<"$args"
        got=$("$LC" "$file" "${size[@]}")
        gclass=$(printf '%s' "$got" | cut -f1) gwhere=$(printf '%s' "$got" | cut -f2)
        if [ "$gclass" != "$class" ] || { [ "$class" != ok ] && [ "$gwhere" != "$where" ]; }; then
            bad "$what" "library says '$gclass' at $gwhere, want '$class' at $where"; continue
        fi
    fi
    pass=$((pass + 1))
    echo "ok   - $what -> $want${class:+ ($class)}"
done <"$here/CATALOGUE.tsv"
if find . -maxdepth 1 -name '.out*' | grep -q .; then
    bad "stray temporaries at the end" "$(find . -maxdepth 1 -name '.out*' | head -n 3)"
fi
echo "bad: $n catalogue entries"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
