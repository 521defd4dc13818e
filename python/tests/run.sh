#!/usr/bin/env bash
# make test-python: the package's tests (pytest, python/tests/) against the library in BUILD, then
# `pip install ./python` into a fresh virtual environment (its dependencies and build tools from
# PyPI, constrained to the pins of tools/requirements/cocotb.txt) and `python -c` there rendering
# the tiger at 640x480 equal to `edgeflag render`'s bytes.  Ends with "N passed, M failed".
set -u
build=${1:?usage: python/tests/run.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
case $build in /*) ;; *) build=$root/$build ;; esac
py=$root/build/venv/bin/python
pass=0 fail=0
result() { if [ "$1" = 0 ]; then pass=$((pass + 1)); echo "PASS $2"; else fail=$((fail + 1)); echo "FAIL $2"; fi; }

EF_BUILD=$build EDGEFLAG_LIBDIR=$build PYTHONPATH=$root/python "$py" -m pytest -q -p no:cacheprovider "$root/python/tests"
result $? "pytest python/tests"

work=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-pip.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
if "$py" -m venv "$work/venv" >"$work/pip.log" 2>&1 &&
    (cd "$root" && EF_BUILD_DIR=$build PIP_CONSTRAINT=$root/tools/requirements/cocotb.txt \
        "$work/venv/bin/python" -m pip install -q --disable-pip-version-check ./python) >>"$work/pip.log" 2>&1; then
    "$build/edgeflag" render "$root/tests/data/svg/tiger.svg" -o "$work/cli.pam" --size 640x480 --samples 8
    (cd "$work" && "$work/venv/bin/python" -c '
import sys, edgeflag as ef
assert ef.__file__.startswith(sys.argv[1]), ef.__file__
img = ef.render(ef.Scene.load(sys.argv[2], fit=(640, 480)), samples=8)
pam = open(sys.argv[3], "rb").read()
body = pam[pam.index(b"ENDHDR\n") + 7:]
assert img.shape == (480, 640, 4) and img.tobytes() == body, "python render differs from the CLI"
print("pip-installed edgeflag: the tiger at 640x480 equals edgeflag render byte for byte (%d bytes)" % len(body))
' "$work/venv" "$root/tests/data/svg/tiger.svg" "$work/cli.pam")
    result $? "pip install ./python into a fresh venv; python -c renders the tiger equal to the CLI"
else
    tail -20 "$work/pip.log"
    result 1 "pip install ./python"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
