# The vectors in a real hardware flow (issue 5): Icarus and Verilator read
# every hex file with $readmemh and write it back for `edgeflag check`, and
# the RTL scanline buffer + filler (rtl_vectors/rtl/ef_slb_fill.v, written
# from docs/microarch.md) must reproduce the model's spans cycle for cycle.
#   make test-rtl    tests/rtl/run.sh (skips, saying so, without iverilog)
.PHONY: test-rtl
test-rtl: cli
	@bash tests/rtl/run.sh $(BUILD)
