# span_skip: the fault `span` in the fast top's copy of SLB + FILL (ef_slb_fill_skip.v): a span of two or more pixels cut one pixel short.
# Caught on: span, field len (tests/rtl/rtl-test.sh, tests/dpi/run.sh).
# file: ef_slb_fill_skip.v
s/^    assign span_len   = span_end - start;$/    assign span_len   = (span_end - start > 15'd1) ? span_end - start - 15'd1 : span_end - start;/
