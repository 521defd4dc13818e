# The vectors in a real hardware flow (issue 5): Icarus and Verilator read
# every hex file with $readmemh and write it back for `edgeflag check`, and
# the RTL scanline buffer + filler (rtl/ef_slb_fill.v, written
# from docs/microarch.md) must reproduce the model's spans cycle for cycle.
#   make test-rtl    tests/rtl/run.sh (skips, saying so, without iverilog)
.PHONY: test-rtl
test-rtl: cli
	@bash tests/rtl/run.sh $(BUILD)

# The whole pipeline in RTL (issue 18): ef_raster against the vectors, in
# Icarus and Verilator, with injected faults (tests/rtl/rtl-test.sh); the
# full level-1 set and the tiger at 640x480 (rtl-regress, not in make test);
# Yosys + nextpnr-ice40 figures (rtl-synth, not in make test).
.PHONY: rtl-test rtl-regress rtl-synth
rtl-test: cli
	@bash tests/rtl/rtl-test.sh $(BUILD)
rtl-regress: cli
	@bash tests/rtl/rtl-regress.sh $(BUILD)
rtl-synth:
	@bash tools/install-deps.sh synth
	@bash syn/rtl-synth.sh
