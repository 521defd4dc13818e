#!/usr/bin/env bash
# tools/shellcheck.sh: shellcheck over every shell script of the tree (`make test-shellcheck`, a stage
# of `make test`; docs/source.md "Formatting").  A script is a tracked file named *.sh or *.sbatch, or
# one whose first line is a sh/bash shebang (tools/regress/ef-regress-shard, ...).  The tree's
# settings are .shellcheckrc's.  Exit 0 only when every script was read and nothing was found.
set -euo pipefail
cd "$(dirname "$0")/.." || exit 1
sc=${EF_SHELLCHECK:-shellcheck}
command -v "$sc" >/dev/null 2>&1 ||
    { echo "shellcheck: FAIL: $sc is not installed (Debian: apt-get install shellcheck; tools/install-deps.sh test)"; exit 1; }

scripts=()
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files | sort -u)
else
    mapfile -t files < <(find . -path ./build -prune -o -type f -print | sed 's|^\./||')
fi
nodot=()
for f in "${files[@]}"; do
    case $f in
    build/* | build-*/*) ;;
    *.sh | *.sbatch) scripts+=("$f") ;;
    *) case ${f##*/} in *.*) ;; *) [ -f "$f" ] && nodot+=("$f") ;; esac ;;
    esac
done
# Files without an extension are scripts when their first line is a sh/bash shebang (one awk reads them all).
if [ ${#nodot[@]} -gt 0 ]; then
    mapfile -t more < <(awk 'FNR == 1 { if ($0 ~ /^#!.*[\/ ](ba)?sh( |$)/) print FILENAME; nextfile }' "${nodot[@]}")
    scripts+=("${more[@]}")
fi
[ ${#scripts[@]} -gt 0 ] || { echo "shellcheck: FAIL: no shell script found"; exit 1; }

# Two calls at once (the machine's two cores), half of the scripts each; the findings in one report.
out=$(mktemp)
trap 'rm -f "$out"' EXIT
rc=0
half=$(((${#scripts[@]} + 1) / 2))
printf '%s\0' "${scripts[@]}" | xargs -0 -n "$half" -P 2 "$sc" -f gcc >"$out" 2>&1 || rc=$?
if [ -s "$out" ] || [ $rc -ne 0 ]; then
    cat "$out"
    echo "shellcheck: FAIL: $(grep -c ': \(note\|warning\|error\|style\):' "$out" || true) findings in ${#scripts[@]} scripts ($("$sc" --version | sed -n 's/^version: //p'))"
    exit 1
fi
echo "shellcheck: ${#scripts[@]} scripts, no findings ($("$sc" --version | sed -n 's/^version: //p'), .shellcheckrc)"
