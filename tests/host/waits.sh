# tests/host/waits.sh - sourced by the host stages' scripts: the waits that are NOT what a test
# measures, generous, times EF_TEST_TIMEOUT_SCALE (docs/testing.md, "What the tests assume").
# A run that goes well never waits for them, so they cost nothing; they only keep a busy machine
# (other jobs on both cores) from turning a slow moment into a timeout, a retransmission or a
# "board stopped answering".  A test that wants a timeout (a stalled or mute board) gives its
# own short one, which is what it measures, and asserts how the run ended.
#   EF_SCALE    the factor: EF_TEST_TIMEOUT_SCALE, a whole number 1..100 (default 1)
#   EF_LINK_MS  edgeflag-host's --timeout for runs that must not time out: 10 s x the factor
#   EF_GUARD_S  the bound on one command of a test (timeout(1)): 120 s x the factor
#   EF_READY_S  how long a test waits for a board process to listen: 30 s x the factor
# shellcheck shell=bash disable=SC2034
EF_SCALE=${EF_TEST_TIMEOUT_SCALE:-1}
case $EF_SCALE in
'' | *[!0-9]* | 0 | 0*) echo "EF_TEST_TIMEOUT_SCALE='$EF_SCALE': want a whole number 1..100" >&2; exit 2 ;;
esac
[ "$EF_SCALE" -le 100 ] || { echo "EF_TEST_TIMEOUT_SCALE='$EF_SCALE': want a whole number 1..100" >&2; exit 2; }
EF_LINK_MS=$((10000 * EF_SCALE))
EF_GUARD_S=$((120 * EF_SCALE))
EF_READY_S=$((30 * EF_SCALE))
