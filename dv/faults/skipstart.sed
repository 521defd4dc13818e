# skipstart: the scan of the overlap schedule starts one cell right of xmin
# (ef_slb_fill_skip.v): an off-by-one in the skipping scan; cell xmin, still
# marked, is then visited after xmin + 1, out of order.  Its first symptom
# in the 32x24 tiger is a row's scan a step longer: the shape drains a cycle
# late, so the next shape's first seg is the earliest mismatch (its cycle).
# Caught on: seg (tests/rtl/rtl-test.sh, the fast top).
# file: ef_slb_fill_skip.v
s/^                    ptr      <= new_xmin;$/                    ptr      <= new_xmin + 15'd1;/
