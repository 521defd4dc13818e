# topclip: the top clip one sample row low (r0 clipped to 1, not 0).
# Caught on: et_wr, fields r0, x, e or slot (tests/rtl/rtl-test.sh).
# file: ef_setup.v
s/r0_raw\[25\] ? 26'sd0 : r0_raw;/r0_raw[25] ? 26'sd1 : r0_raw;/
