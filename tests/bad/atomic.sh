#!/usr/bin/env bash
# tests/bad/atomic.sh BUILD_DIR - atomic output under interruption and a full
# disk (docs/cli.md "Atomic output").  An interrupted or failed write must
# leave nothing that looks complete: no OUTPUT (or the previous OUTPUT, byte
# for byte) and no temporary ".OUTPUT.XXXXXX", with the documented status:
#   - SIGTERM, SIGINT, SIGHUP while the image is being written: the temporary
#     is removed and the process dies of that signal (128 + signal number);
#   - SIGKILL (cannot be caught): no OUTPUT appears; the dot-named temporary
#     may remain and is never taken for the image;
#   - the file size limit (ulimit -f: EFBIG, SIGXFSZ) for PNG, PAM and PGM:
#     exit 4, "File too large", nothing left behind;
#   - a full file system (ENOSPC; a 256 KiB tmpfs, only where mounting is
#     allowed, else skipped with the reason): exit 4, nothing left behind;
#   - a signal that was ignored when edgeflag started stays ignored.
# The write is caught in the act by polling for the temporary while a 6000 x
# 6000 PNG (about a second of encoding) is written; a run that finishes
# first is retried and, failing that, reported as a skip, never a pass.
# Ends with "N passed, M failed".
set -u
build=${1:?usage: tests/bad/atomic.sh BUILD_DIR}
case $build in /*) ;; *) build=$PWD/$build ;; esac
EF=$build/edgeflag
[ -x "$EF" ] || { echo "atomic: $EF not built"; echo "0 passed, 1 failed"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/edgeflag-atomic.XXXXXX") || exit 1
mnt=
bgpid=
cleanup() {
    [ -n "$bgpid" ] && kill -KILL "$bgpid" 2>/dev/null
    [ -n "$mnt" ] && umount "$mnt" 2>/dev/null
    rm -rf "$tmp"
}
trap cleanup EXIT
cd "$tmp" || exit 1

pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); echo "ok   - $1"; }
bad() { fail=$((fail + 1)); echo "FAIL - $1"; shift; for l in "$@"; do echo "       $l"; done; }
skipped() { skip=$((skip + 1)); echo "skip - $1"; }
temps() { find "${1:-.}" -maxdepth 1 -name '.out*' | head -n 3; }

cat >big.scene <<'SCENE'
scene 100 100
shape nonzero 255 0 0 200
contour 0 0 100 3 50 100
shape evenodd 0 255 0 100
contour 100 0 0 50 100 100 30 20
SCENE
"$EF" render big.scene -o probe.png >/dev/null 2>&1 && png=png || png=pam
rm -f probe.*

# interrupt SIG EXPECT_STATUS: start a big render, wait for its temporary,
# send SIG.  Checks status, OUTPUT (absent, or "previous" when it existed).
interrupt() {
    local sig=$1 want=$2 prev=$3 attempt size
    for attempt in 1 2 3; do
        size=$((4000 + 2000 * attempt))
        rm -f "out.$png" ./.out*
        [ "$prev" = keep ] && echo previous >"out.$png"
        # Background jobs of a script start with SIGINT ignored; give the
        # command the default disposition, as it has when run from a shell.
        env --default-signal=INT,TERM,HUP "$EF" render big.scene -o "out.$png" --size "${size}x$size" 2>err &
        bgpid=$!
        local seen=0
        for _ in $(seq 1 5000); do
            if [ -n "$(temps)" ]; then seen=1; break; fi
            kill -0 "$bgpid" 2>/dev/null || break
            sleep 0.002
        done
        if [ $seen = 0 ]; then
            wait "$bgpid"; bgpid=; continue
        fi
        kill "-$sig" "$bgpid"
        { wait "$bgpid"; } 2>/dev/null; local st=$?; bgpid=
        if [ $st = 0 ]; then continue; fi     # finished between the poll and the kill
        local left; left=$(temps)
        if [ "$sig" = KILL ]; then
            rm -f ./.out*                      # a SIGKILLed process cannot clean up
            left=
        fi
        if [ "$prev" = keep ]; then
            if [ $st = "$want" ] && [ -z "$left" ] && [ "$(cat "out.$png")" = previous ]; then
                ok "SIG$sig while writing over an existing OUTPUT: status $st, previous OUTPUT intact, no temporary"
            else
                bad "SIG$sig over an existing OUTPUT" "status $st (want $want), left: $left, OUTPUT: $(head -c 20 "out.$png" | tr -cd '[:print:]')"
            fi
        else
            if [ $st = "$want" ] && [ -z "$left" ] && [ ! -e "out.$png" ]; then
                ok "SIG$sig while writing: status $st, no OUTPUT, no temporary"
            else
                bad "SIG$sig while writing" "status $st (want $want), left: $left $(ls out.* 2>/dev/null)"
            fi
        fi
        return
    done
    skipped "SIG$sig: the write finished before it could be interrupted (3 attempts)"
}
interrupt TERM 143 new
interrupt INT 130 new
interrupt HUP 129 new
interrupt TERM 143 keep
interrupt KILL 137 new

# A signal ignored at start stays ignored: the run completes.
rm -f "out.$png"
( trap '' INT; "$EF" render big.scene -o "out.$png" --size 3000x3000 2>err & p=$!
  sleep 0.3; kill -INT $p 2>/dev/null; wait $p ); st=$?
if [ $st = 0 ] && [ -s "out.$png" ] && [ -z "$(temps)" ]; then
    ok "SIGINT ignored at start (trap '' INT) stays ignored: the image is written"
else
    bad "ignored SIGINT" "status $st"
fi
rm -f "out.$png"

# File size limit: 16 KiB; every format's 2000 x 2000 image is larger.
for fmt in png pam pgm; do
    [ $fmt = png ] && [ "$png" != png ] && continue
    rm -f "out.$fmt"
    ( ulimit -f 16; exec "$EF" render big.scene -o "out.$fmt" --size 2000x2000 ) 2>err; st=$?
    if [ $st = 4 ] && grep -q "^edgeflag: cannot write 'out.$fmt': File too large" err && [ ! -e "out.$fmt" ] &&
       [ -z "$(temps)" ]; then
        ok "file size limit (ulimit -f) writing .$fmt: exit 4, 'File too large', nothing left"
    else
        bad "file size limit writing .$fmt" "status $st (want 4), left: $(temps) $(ls out.* 2>/dev/null)" "$(head -n 2 err)"
    fi
    echo previous >"out.$fmt"
    ( ulimit -f 16; exec "$EF" render big.scene -o "out.$fmt" --size 2000x2000 ) 2>err; st=$?
    if [ $st = 4 ] && [ "$(cat "out.$fmt")" = previous ] && [ -z "$(temps)" ]; then
        ok "file size limit over an existing .$fmt: exit 4, previous OUTPUT intact"
    else
        bad "file size limit over an existing .$fmt" "status $st"
    fi
    rm -f "out.$fmt"
done

# A really full file system, where this user may mount a small tmpfs.
mkdir -p full
if [ "$(id -u)" = 0 ] && mount -t tmpfs -o size=256k tmpfs full 2>/dev/null; then
    mnt=$PWD/full
    "$EF" render big.scene -o full/out.pam --size 1000x1000 2>err; st=$?
    if [ $st = 4 ] && grep -q "No space left on device" err && [ ! -e full/out.pam ] && [ -z "$(temps full)" ]; then
        ok "full file system (ENOSPC): exit 4, nothing left"
    else
        bad "full file system" "status $st, left: $(ls -A full)" "$(head -n 2 err)"
    fi
    umount "$mnt"; mnt=
else
    skipped "full file system: cannot mount a tmpfs here (needs root in a namespace that allows it)"
fi

[ -z "$(temps)" ] || bad "stray temporaries at the end" "$(temps)"
[ $skip -gt 0 ] && echo "atomic: $skip skipped"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
