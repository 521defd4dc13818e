# `edgeflag check` (docs/vectors.md section 7): the CLI-level stage.
#   make test-check    tests/check/run.sh: real vectors of the tiger and of an
#                      `edgeflag gen` case pass against themselves (hex files,
#                      binary streams, directories, RTL-style dumps without a
#                      header); one flipped bit, one dropped and one delayed
#                      transaction each fail at the right interface, cycle and
#                      pixel; --transactions, --errors, --junit (xmllint),
#                      --diff-image; usage errors.
# The helpers link the vectors library (rtl_vectors/) as well as the core.
CHECK_TOOLS := $(BUILD)/tests/check/vec_mutate $(BUILD)/tests/check/vec_load $(BUILD)/tests/check/check_lib

$(BUILD)/tests/check/%: tests/check/%.c $(VEC_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) $< $(VEC_A) -o $@ $(LDFLAGS_ALL) $(LIB_A) $(EXPAT_LIBS) $(VEC_LIBS)

.PHONY: test-check
test-check: cli $(CHECK_TOOLS) $(BUILD)/tests/tools/vec_bin_check
	@bash tests/check/run.sh $(BUILD)

# The readers' unit test links them as well as the library; an explicit rule
# overrides tests/module.mk's pattern rule for this one binary (test-unit runs it).
$(BUILD)/tests/test_vec_read: tests/unit/test_vec_read.c $(VEC_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS_ALL) $< $(VEC_A) -o $@ $(LDFLAGS_ALL) $(TEST_LIBS)
