# rtl_vectors/: generators for hardware regressions (`edgeflag gen`, docs/gen.md).
# Integer-only C, linked into the edgeflag CLI (cli/module.mk adds $(RTLV_OBJ)
# to CLI_OBJ) and into tests/unit/test_gen.c.
RTLV_SRC := $(wildcard rtl_vectors/*.c)
RTLV_OBJ := $(RTLV_SRC:%.c=$(BUILD)/%.o)
EF_INC += -Irtl_vectors
# Layer: the public headers, fixed/ (the bottom layer) and its own; never model/ or cli/.
LAYER_INC_rtl_vectors := -Iinclude/edgeflag -Ifixed -Irtl_vectors
$(RTLV_OBJ): EF_INC := $(LAYER_INC_rtl_vectors)

# test_gen needs the generator objects as well as the library; an explicit rule
# overrides tests/module.mk's pattern rule for this one binary.
$(BUILD)/tests/test_gen: tests/unit/test_gen.c $(RTLV_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS_ALL) $< $(RTLV_OBJ) -o $@ $(LDFLAGS_ALL) $(TEST_LIBS)

.PHONY: test-gen
test-gen: cli
	@bash tests/gen/run.sh $(BUILD)
