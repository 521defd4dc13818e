# rooks: a wrong n-rooks offset: sample row 1 uses sample row 2's offset.
# Caught on: plot, field q (tests/rtl/rtl-test.sh, tests/host/rtl.sh).
# file: ef_plot.v
s/^    wire \[7:0\] off = off_of(s);$/    wire [7:0] off = off_of((s == 5'd1) ? 5'd2 : s);/
