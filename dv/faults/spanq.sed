# spanq: COV's span queue one entry short (ef_spanq.v): the scan stalls a
# span earlier than the overlap schedule says; only the span's cycle moves.
# Caught on: span, its cycle, once a row has 16 spans waiting (the tiger at
# 64x48; tests/rtl/rtl-test.sh, the fast top).
# file: ef_spanq.v
s/^    localparam \[PW:0\]   FULL = {1'b0, LAST} + 1'b1;$/    localparam [PW:0]   FULL = {1'b0, LAST};/
