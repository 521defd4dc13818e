# pad_skip: the fault `pad` in the fast top's copy of SLB + FILL (ef_slb_fill_skip.v): the carry out of a 7-bit winding lane (the packed word's pad bit) is not
# masked off in the non-zero coverage test.
# Caught on: span, fields mask, x, len or an extra span (tests/rtl/rtl-test.sh).
# file: ef_slb_fill_skip.v
s/^            assign mask_next\[l\] = f_rule ? an\[0\] : (|an);$/            wire [7:0] an8 = {1'b0, a} + {1'b0, c};\n            assign mask_next[l] = f_rule ? an[0] : (|an8);/
