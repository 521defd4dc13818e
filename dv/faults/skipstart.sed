# skipstart: the skipping scan's start (ef_slb_fill.v, SKIP = 1: the
# overlap schedule, SCHEDULE=1) forgets the row's previous xmin when a later
# plot of the row lands left of it in the same 64-cell word: that cell is
# never visited, so its winding is neither accumulated nor cleared (an
# off-by-one of the row's start in the shadow of its lowest word).  Its
# first symptom in the 32x24 tiger: a span starting a cell right.
# Caught on: span, field x (tests/rtl/rtl-test.sh, the fast configuration).
# file: ef_slb_fill.v
s/^                        lwx_n = lwx | xb;$/                        lwx_n = lwx;/
