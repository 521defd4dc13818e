# python/: the Python package `edgeflag` (docs/python.md).  It loads two shared libraries:
#   $(LIB_SO)      libedgeflag.so, the model's public API (include/edgeflag/)
#   $(EFPY_SO)     libefpy.so: the vectors readers and writers, the checker, `gen` and the model
#                  stream (rtl_vectors/, dv/dpi/), which libedgeflag.so does not export,
#                  compiled again with their symbols visible, and python/csrc/efpy.c
#   make python          both libraries (what `pip install ./python` runs too)
#   make test-python     the package's tests (pytest, in build/venv)
#   make test-cocotb     the cocotb bench of ef_raster, a slice, under Icarus and Verilator
#   make cocotb-regress  the bench on every level-1 gen case (not in make test)
EFPY_SO   := $(BUILD)/libefpy.so
EFPY_SRC  := $(wildcard rtl_vectors/*.c) dv/dpi/model_stream.c python/csrc/efpy.c
EFPY_OBJ  := $(EFPY_SRC:%.c=$(BUILD)/efpy/%.o)
# Layer: the public headers, the vectors library (and the fixed/ it compiles with), the DPI model
# stream; never model/'s internals, cli/, util/ or host/ (tests/layers checks it).
LAYER_INC_python := -Iinclude/edgeflag -Ifixed -Irtl_vectors -Idv/dpi
$(BUILD)/efpy/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(EF_DEFS) $(LAYER_INC_python) \
	    $(filter-out -fvisibility=hidden,$(CFLAGS_ALL)) -c $< -o $@
$(BUILD)/efpy/python/csrc/efpy.o: CFLAGS_ALL += -Wno-missing-prototypes
# The model's internals that the vectors code calls come from the static library (not exported
# again: --exclude-libs); its public API from libedgeflag.so.
$(EFPY_SO): $(EFPY_OBJ) $(LIB_SO) $(LIB_A)
	$(CC) -shared -Wl,-soname,libefpy.so $(LDFLAGS_ALL) -o $@ $(EFPY_OBJ) \
	    -L$(BUILD) -l:libedgeflag.so -Wl,--exclude-libs,ALL $(LIB_A) $(VEC_LIBS) $(EXPAT_LIBS) -lpthread \
	    -Wl,-rpath,'$$ORIGIN'

.PHONY: python test-python test-cocotb cocotb-regress
python: lib $(EFPY_SO)

test-python: python cli
	@bash tools/install-venv.sh cocotb
	@bash python/tests/run.sh $(BUILD)

test-cocotb: python cli
	@bash tools/install-venv.sh cocotb
	@bash dv/cocotb/run.sh slice $(BUILD)

cocotb-regress: python cli
	@bash tools/install-venv.sh cocotb
	@bash dv/cocotb/run.sh regress $(BUILD)
