# div_floor: the divider's floor correction of the quotient skipped.
# Caught on: et_wr, fields x, e, qs, rs (tests/rtl/rtl-test.sh, blocks_a.sh).
# file: ef_div.v
s/^    wire \[QB:0\]   qa_fl = qa_nr - {{QB{1'b0}}, nega};$/    wire [QB:0]   qa_fl = qa_nr;/
s/^    wire \[QB:0\]   qb_fl = qb_nr - {{QB{1'b0}}, negb};$/    wire [QB:0]   qb_fl = qb_nr;/
