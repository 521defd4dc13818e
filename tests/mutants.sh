#!/usr/bin/env bash
# Proves the oracle test can fail: builds the model with each injected bug
# (EF_MUTATION: 1 = one wrong n-rooks offset, 2 = off-by-one x rounding, both
# in the plotter, model/plotter.h; 3 = every sample shifted by half a sub-pixel, ctx.c) and
# demands that tests/oracle_check reports mismatches.  Mutant 3 must also fail
# tests/area_check, the exact-area comparison that guards the spec itself.
set -u
cd "$(dirname "$0")/.." || exit 1
svgdir=${EF_SVG:-$(pwd)/tests/data/svg}
pass=0 fail=0
for m in 1 2 3; do
    b=build-mutant$m
    if ! make --no-print-directory -s BUILD=$b EXTRA_CFLAGS=-DEF_MUTATION=$m $b/tests/oracle_check $b/tests/area_check >/dev/null 2>&1; then
        echo "mutant $m: build failed"; fail=$((fail + 1)); continue
    fi
    out=$($b/tests/oracle_check --random 2000 --seed 7 --max-report 0 2>&1)
    rc=$?
    n=$(printf '%s\n' "$out" | grep -c '^MISMATCH')
    if [ $rc -eq 1 ] && [ "$n" -gt 0 ]; then
        echo "mutant $m: caught ($n mismatching cases of 2000 random scenes)"; pass=$((pass + 1))
    else
        echo "mutant $m: NOT caught (exit $rc)"; fail=$((fail + 1))
    fi
    out=$($b/tests/oracle_check --shared "$svgdir" --max-report 0 2>&1 | grep -c '^MISMATCH')
    if [ "$out" -gt 0 ]; then
        echo "mutant $m: caught on the shared SVGs too ($out mismatching cases)"
    else
        echo "mutant $m: NOT caught on the shared SVGs"; fail=$((fail + 1))
    fi
    if [ $m = 3 ]; then
        if $b/tests/area_check >/dev/null 2>&1; then
            echo "mutant 3: NOT caught by the exact-area check"; fail=$((fail + 1))
        else
            echo "mutant 3: caught by the exact-area check too"
        fi
    fi
done
echo "mutant: $pass passed, $fail failed"
[ $fail -eq 0 ]
