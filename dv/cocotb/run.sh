#!/usr/bin/env bash
# dv/cocotb/run.sh SET BUILD_DIR: the cocotb bench of ef_raster through pytest and cocotb's runner
# (dv/cocotb/test_runner.py).  SET is `slice` (make test-cocotb) or `regress` (make cocotb-regress).
# Prints the merged coverage report (build/cocotb/SET/coverage.txt) and ends with
# "N passed, M failed"; exit status 0 only if every test passed.
set -u
set_=${1:?usage: dv/cocotb/run.sh slice|regress BUILD_DIR}
build=${2:?usage: dv/cocotb/run.sh slice|regress BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$root/$build ;; esac
for t in iverilog vvp verilator; do
    command -v $t >/dev/null 2>&1 || { echo "cocotb: $t is not installed (make deps-test)"; echo "0 passed, 1 failed"; exit 1; }
done
venv=$root/build/venv
rm -rf "$build/cocotb/$set_"
mkdir -p "$build/cocotb/$set_"
cd "$root/dv/cocotb" || exit 1
# The slice compiles Verilator's C++ at -O0: a third less compile time, and the bench's speed is its
# Python's, not the model's (docs/python.md section 6).
mf=-j2
[ "$set_" = slice ] && mf="-j2 OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0"
PATH=$venv/bin:$PATH EF_BUILD=$build EF_COCOTB_SET=$set_ EDGEFLAG_LIBDIR=$build MAKEFLAGS=$mf \
    PYTHONPATH=$root/dv/cocotb:$root/python "$venv/bin/python" -m pytest -p no:cacheprovider -q -rA \
    --junitxml="$build/cocotb/$set_/junit.xml" test_runner.py >"$build/cocotb/$set_/pytest.log" 2>&1
rc=$?
grep -E '^(PASSED|FAILED|ERROR|SKIPPED)' "$build/cocotb/$set_/pytest.log" | sed 's/^/  /'
[ $rc -eq 0 ] || tail -n 60 "$build/cocotb/$set_/pytest.log"
[ -f "$build/cocotb/$set_/coverage.txt" ] && cat "$build/cocotb/$set_/coverage.txt"
pass=$(grep -cE '^PASSED' "$build/cocotb/$set_/pytest.log")
fail=$(grep -cE '^(FAILED|ERROR)' "$build/cocotb/$set_/pytest.log")
[ $rc -eq 0 ] || [ "$fail" -gt 0 ] || fail=1
echo "$pass passed, $fail failed"
[ $rc -eq 0 ] && [ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
