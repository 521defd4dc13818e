#!/usr/bin/env bash
# Runs every test stage of `make test`, each in its own log, and ends with the
# line "N passed, M failed" (stages).  Exit status: 0 only if all passed.
set -u
cd "$(dirname "$0")/.." || exit 1
MAKE=${MAKE:-make}
logs=build/test-logs
mkdir -p "$logs"
stages=(test-build test-format test-shellcheck test-unit test-oracle test-filter test-mutants test-cli test-gen test-vectors test-check test-regress test-host test-host-usb test-host-gpio test-host-socket test-host-serial test-host-rtl board-sim-test board-gpio-test board-sim-usb-test test-rtl rtl-lint test-rtl-sim rtl-test test-rtl-mutants test-coverage test-fusesoc test-dpi test-python test-cocotb test-bad test-bitexact bench-quick test-sanitize test-integer test-fuzz-replay test-fuzz-smoke test-portability)
[ -n "${EF_TEST_STAGES:-}" ] && read -r -a stages <<<"$EF_TEST_STAGES"
pass=0 fail=0
for s in "${stages[@]}"; do
    t0=$(date +%s)
    if $MAKE --no-print-directory "$s" >"$logs/$s.log" 2>&1; then
        pass=$((pass + 1)); verdict=PASS
    else
        fail=$((fail + 1)); verdict=FAIL
    fi
    printf '%-14s %s  (%ss, log %s)\n' "$s" "$verdict" "$(( $(date +%s) - t0 ))" "$logs/$s.log"
    # Show what a reader needs: the stage's own summary lines, or the tail on failure.
    if [ $verdict = FAIL ]; then
        tail -n 40 "$logs/$s.log" | sed 's/^/    /'
    else
        grep -E '^(format|shellcheck|oracle|filter|area|mutant|bitexact|portability|fuzz|bench|cli|install|gpio|\[  PASSED  \]|[0-9]+ passed)' "$logs/$s.log" | grep -v ' agree$' |
            sed 's/^/    /' | tail -n 12
    fi
done
echo "stages: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
