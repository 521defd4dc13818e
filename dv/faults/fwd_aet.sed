# fwd_aet: the AET ring's forwarding path removed.  In simulation the read of a
# never-written entry then gives x, which edgeflag check refuses as such, so
# rtl-test plants SLB's forwarding fault (fwd) instead; kept so that the
# recipe is still checked to apply.
# file: ef_aet.v
s/^    wire          fwd_hit = lw_v \&\& (lw_addr == rq_addr);$/    wire          fwd_hit = 1'b0;/
