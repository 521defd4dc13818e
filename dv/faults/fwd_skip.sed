# fwd_skip: the fault `fwd` in the fast top's copy of SLB + FILL (ef_slb_fill_skip.v): SLB's write-to-read forwarding removed (a read in the cycle of a write to
# the same cell sees the old value).
# Caught on: span (tests/rtl/rtl-test.sh, tests/rtl/run.sh).
# file: ef_slb_fill_skip.v
s/^    wire          fwd  = lw_valid \&\& (lw_addr == s2_addr\[AW-1:0\]);$/    wire          fwd  = 1'b0 \&\& lw_valid \&\& (lw_addr == s2_addr[AW-1:0]);/
