# dv/dpi/: the model as a command stream for lockstep testbenches
# (ef_model_stream.h), its DPI-C wrapper (ef_dpi.c) and SystemVerilog package
# (ef_model_pkg.sv); docs/dpi.md.
#   $(DPI_LIB)       libef_dpi.a: the stream, the DPI-C wrapper and libedgeflag's
#                    objects in one archive, for `verilator ... $(DPI_LIB)`
#   make test-dpi    tests/dpi/run.sh: the stream against `edgeflag vectors`'
#                    files (cmocka), and a Verilator lockstep bench, with faults
DPI_DIR   := dv/dpi
DPI_OBJ   := $(BUILD)/$(DPI_DIR)/model_stream.o
DPI_SV_OBJ := $(BUILD)/$(DPI_DIR)/ef_dpi.o
DPI_LIB   := $(BUILD)/libef_dpi.a
DPI_TEST  := $(BUILD)/tests/test_model_stream
# svdpi.h comes with the simulator (Verilator's copy here); only ef_dpi.o needs it.
SVDPI_INC = $(shell verilator --getenv VERILATOR_ROOT 2>/dev/null)/include/vltstd

# Layer: the public headers and its own; never model/'s internals, host/, board/ or cli/.
LAYER_INC_dpi := -Iinclude/edgeflag -I$(DPI_DIR)
$(DPI_OBJ) $(DPI_SV_OBJ): EF_INC := $(LAYER_INC_dpi)
$(DPI_TEST): CPPFLAGS += -I$(DPI_DIR)
$(DPI_SV_OBJ): CPPFLAGS += -I$(SVDPI_INC)

$(DPI_LIB): $(DPI_OBJ) $(DPI_SV_OBJ) $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(DPI_TEST): tests/dpi/test_model_stream.c $(DPI_OBJ) $(VEC_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) $< $(DPI_OBJ) $(VEC_A) -o $@ $(LDFLAGS_ALL) $(TEST_LIBS) -lpthread

.PHONY: test-dpi
# Without Verilator there is no svdpi.h: the archive is not built, and
# tests/dpi/run.sh runs the C part alone, saying that the bench is skipped.
test-dpi: cli $(DPI_TEST) $(if $(shell command -v verilator 2>/dev/null),$(DPI_LIB))
	@bash tests/dpi/run.sh $(BUILD)

# Not in `make test`: the lockstep bench over all 261 gen level-1 cases x NS 8/16/32
# x 3 rule settings (tests/dpi/sweep.sh; numbers in docs/dpi.md).
.PHONY: dpi-sweep
dpi-sweep: cli $(DPI_LIB)
	@bash tests/dpi/sweep.sh $(BUILD)
