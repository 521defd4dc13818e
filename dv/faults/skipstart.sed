# skipstart: the scan starts one cell right of xmin (ef_slb_fill.v); planted
# in the overlap schedule's skipping scan (SCHEDULE=1, SKIP=1): an off-by-one
# there; cell xmin, still marked, is then visited after xmin + 1, out of
# order.  Its first symptom in the 32x24 tiger is a row's scan a step
# longer: the shape drains a cycle late, so the next shape's first seg is
# the earliest mismatch (its cycle).
# Caught on: seg (tests/rtl/rtl-test.sh, the fast configuration).
# file: ef_slb_fill.v
s/^                    ptr      <= new_xmin;$/                    ptr      <= new_xmin + 15'd1;/
