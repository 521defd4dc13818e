#!/usr/bin/env bash
# tests/host/loaded.sh - the host stages again and again on a busy machine (docs/testing.md, "What
# the tests assume of the machine"): stress-ng keeps every core busy (CPU, memory and cache workers
# at normal priority) while tests/run.sh runs the host stages ROUNDS times in a row.  Not a stage of
# `make test`: `make test-host-loaded` (tools/install-deps.sh loaded installs stress-ng).
#   EF_LOADED_ROUNDS (default 5), EF_LOADED_STAGES (default: the six host stages)
# Bounded: stress-ng stops by itself after 15 minutes a round, and is stopped by its pid when the
# rounds end.  Each round's stage lines and load average are printed; a failing round's logs are
# kept in build/test-loaded/round-N.  Ends with "N passed, M failed" (rounds); exit 0 only if
# every round passed.
set -u
cd "$(dirname "$0")/../.." || exit 1
rounds=${EF_LOADED_ROUNDS:-5}
stages=${EF_LOADED_STAGES:-test-host test-host-usb test-host-gpio test-host-socket test-host-serial test-host-rtl}
case $rounds in '' | *[!0-9]* | 0) echo "loaded: EF_LOADED_ROUNDS='$rounds': want a whole number >= 1"; exit 2 ;; esac
if ! command -v stress-ng >/dev/null; then
    echo "loaded: stress-ng is not installed (tools/install-deps.sh loaded installs it)"
    echo "0 passed, 1 failed"
    exit 1
fi
n=$(nproc)
out=build/test-loaded
rm -rf "$out" && mkdir -p "$out"
stress-ng --cpu "$n" --vm 1 --vm-bytes 1G --cache 1 --timeout $((rounds * 900))s --quiet >"$out/stress.log" 2>&1 &
spid=$!
trap 'kill "$spid" 2>/dev/null; wait "$spid" 2>/dev/null' EXIT
sleep 2
kill -0 "$spid" 2>/dev/null || { cat "$out/stress.log"; echo "loaded: stress-ng did not start"; echo "0 passed, 1 failed"; exit 1; }
echo "loaded: stress-ng --cpu $n --vm 1 --vm-bytes 1G --cache 1 (pid $spid) on $n cores; stages: $stages"
pass=0 fail=0
for r in $(seq "$rounds"); do
    t0=$(date +%s)
    EF_TEST_STAGES="$stages" bash tests/run.sh >"$out/round-$r.txt" 2>&1
    rc=$?
    echo "round $r: $([ $rc = 0 ] && echo PASS || echo FAIL) in $(($(date +%s) - t0)) s, load average $(cut -d' ' -f1-3 /proc/loadavg)"
    grep -E '^test-' "$out/round-$r.txt" | sed 's/^/    /'
    if [ $rc = 0 ]; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        mkdir -p "$out/round-$r" && cp build/test-logs/*.log "$out/round-$r/" 2>/dev/null
        grep -E 'FAIL' "$out/round-$r.txt" | head -n 20 | sed 's/^/    /'
    fi
done
echo "$pass passed, $fail failed (rounds of the host stages under stress-ng)"
[ "$fail" = 0 ]
