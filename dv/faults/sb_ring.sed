# sb_ring: the divider's side-band ring read one entry short.
# Caught on: et_wr, fields x, e, qs, rs, dy (tests/rtl/rtl-test.sh).
# file: ef_div.v
s/^    wire \[SA-1:0\] rp = wp - QOFF;$/    wire [SA-1:0] rp = wp - QOFF + 1'b1;/
