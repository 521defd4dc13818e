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
# One source for the RTL's numbers and a clean lint (issue 22):
#   make rtl-lint   tests/rtl/rtl-lint.sh: the generated rtl/ef_ifaces.vh,
#                   ef_ifaces_pkg.sv and ef_rooks.vh up to date, the n-rooks
#                   tables equal to the model's, a bad NS an elaboration
#                   error, every dv/faults/ variant applies, Verilator -Wall
#                   silent on every RTL and bench file (about 30 s)
#   make rtl-gen    regenerates the three generated files of rtl/
.PHONY: rtl-lint rtl-gen
rtl-lint: cli
	@bash tests/rtl/rtl-lint.sh $(BUILD)
rtl-gen: cli
	$(BUILD)/edgeflag vectors --rtl-headers -o rtl --force
	$(BUILD)/edgeflag patterns --emit-verilog >rtl/ef_rooks.vh.tmp && mv rtl/ef_rooks.vh.tmp rtl/ef_rooks.vh

# One command from vectors to a verdict (issue 27; docs/vectors.md section 9):
#   make rtl-sim VEC=DIR [SIM=verilator|icarus] [NS=N] [TOP="my_top.v ..."]
#   (dv/rtl-sim.sh: the bench built warning-clean and cached in build/rtl-sim,
#   run on DIR/cmd.stim.hex, then edgeflag check; the exit status is check's)
#   make test-rtl-sim  tests/rtl/rtl-sim-test.sh (Icarus, about 30 s)
.PHONY: rtl-sim test-rtl-sim
rtl-sim: cli
	@[ -n "$(VEC)" ] || { echo "make rtl-sim VEC=DIR [SIM=verilator|icarus] [NS=N] [TOP=\"files\"]"; exit 2; }
	@bash dv/rtl-sim.sh "$(VEC)" --edgeflag $(BUILD)/edgeflag --cache $(BUILD)/rtl-sim $(if $(SIM),--sim $(SIM)) \
	    $(if $(NS),--ns $(NS)) $(foreach f,$(TOP),--top $(f))
test-rtl-sim: cli
	@bash tests/rtl/rtl-sim-test.sh $(BUILD)

.PHONY: rtl-test rtl-regress rtl-synth
rtl-test: cli
	@bash tests/rtl/rtl-test.sh $(BUILD)
rtl-regress: cli
	@bash tests/rtl/rtl-regress.sh $(BUILD)
rtl-synth:
	@bash tools/install-deps.sh synth
	@bash syn/rtl-synth.sh
