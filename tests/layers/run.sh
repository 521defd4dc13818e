#!/usr/bin/env bash
# Every arrow of tests/layers/arrows.tsv through the compiler: a probe that
# includes the header, compiled with the layer's own include path (make
# layers-print).  An "ok" arrow that fails is as much a failure as a
# "forbidden" one that compiles: both directions are checked.
set -u
cd "$(dirname "$0")/../.." || exit 1
build=${1:-build}
cc=${CC:-cc}
declare -A inc
while IFS='|' read -r layer flags; do inc[$layer]=$flags; done < <(make --no-print-directory -s BUILD="$build" layers-print)
probe=$(mktemp --suffix=.c)
trap 'rm -f "$probe"' EXIT
n=0 bad=0
while IFS=$'\t' read -r layer header expect; do
    case $layer in ''|'#'*) continue ;; esac
    [ -n "${inc[$layer]+x}" ] || { echo "layers: unknown layer '$layer'"; bad=$((bad + 1)); continue; }
    printf '#include "%s"\nint ef_layer_probe;\n' "$header" >"$probe"
    # shellcheck disable=SC2086
    if $cc -std=c11 -D_POSIX_C_SOURCE=200809L ${inc[$layer]} -fsyntax-only "$probe" 2>/dev/null; then got=ok; else got=forbidden; fi
    n=$((n + 1))
    if [ "$got" != "$expect" ]; then
        echo "layers: $layer including $header: expected $expect, the compiler says $got (flags: ${inc[$layer]})"
        bad=$((bad + 1))
    fi
done <tests/layers/arrows.tsv
[ $n -gt 0 ] || { echo "layers: no arrows checked"; exit 1; }
# Every C/C++ source folder has a layer (tests/layers/folders.tsv), and that layer is one make prints.
declare -A folder
while IFS=$'\t' read -r f layer; do
    case $f in ''|'#'*) continue ;; esac
    folder[$f]=$layer
    if [ "$layer" != verilator ] && [ -z "${inc[$layer]+x}" ]; then
        echo "layers: tests/layers/folders.tsv gives $f the layer '$layer', which make layers-print does not know"
        bad=$((bad + 1))
    fi
done <tests/layers/folders.tsv
nf=0
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    while read -r d; do
        nf=$((nf + 1))
        [ -n "${folder[$d]+x}" ] ||
            { echo "layers: $d holds C sources but has no layer in tests/layers/folders.tsv"; bad=$((bad + 1)); }
    done < <(git ls-files '*.c' '*.cpp' | sed 's|/[^/]*$||' | sort -u)
fi
if [ $bad -ne 0 ]; then echo "layers: FAIL: $bad wrong ($n arrows, $nf source folders checked)"; exit 1; fi
echo "layers: $n arrows as tests/layers/arrows.tsv says (include paths per folder); $nf C source folders, each with its layer"
