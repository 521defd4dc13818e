#!/usr/bin/env bash
# Installs the project's Python tools (PyPI, exact pinned versions) into a virtual environment inside
# the build folder, so a fresh machine and CI get the same tools:
#   tools/install-venv.sh GROUP...     one requirements file per group: tools/requirements/GROUP.txt
# The environment is $EF_VENV (default build/venv).  A group already installed at the same pins
# (its requirements file's hash is recorded in the venv) is not installed again.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=${EF_VENV:-build/venv}
[ $# -gt 0 ] || { echo "usage: tools/install-venv.sh GROUP... (groups: $(cd tools/requirements && for f in *.txt; do printf '%s ' "${f%.txt}"; done))" >&2; exit 2; }
for g in "$@"; do
    [ -f "tools/requirements/$g.txt" ] || { echo "install-venv: no group '$g' (tools/requirements/$g.txt)" >&2; exit 2; }
done
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv --help >/dev/null 2>&1 || bash tools/install-deps.sh venv
    python3 -m venv "$venv"
    "$venv/bin/python" -m pip install -q --upgrade pip
fi
for g in "$@"; do
    req=tools/requirements/$g.txt
    stamp=$venv/.installed-$g
    sum=$(sha256sum "$req" | cut -d' ' -f1)
    if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$sum" ]; then continue; fi
    echo "edgeflag: installing Python group '$g' into $venv ($req)" >&2
    "$venv/bin/python" -m pip install -q --disable-pip-version-check -r "$req"
    echo "$sum" >"$stamp"
done
