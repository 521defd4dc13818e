# `edgeflag vectors` (docs/vectors.md): the writers' unit test and the CLI-level stage.
#   make test-vectors    tests/vectors/run.sh: every shared SVG and a sample of
#                        `edgeflag gen` level 1 at 8/16/32 x both rules, all formats,
#                        read back by independent tools (od, sha256sum, GTKWave's
#                        vcd2fst/fst2vcd, tests/tools/vec_bin_check, vcd_compare)
VEC_OBJ := $(addprefix $(BUILD)/rtl_vectors/,vec_crc32.o vec_sha256.o vec_out.o vec_collect.o vec_merge.o \
             vec_hex.o vec_vcd.o vec_bin.o vec_manifest.o vec_seed.o vec_formats.o)

# test_vec links the writers' objects as well as the library; an explicit rule
# overrides tests/module.mk's pattern rule for this one binary.
$(BUILD)/tests/test_vec: tests/unit/test_vec.c $(VEC_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS_ALL) $< $(VEC_OBJ) -o $@ $(LDFLAGS_ALL) $(TEST_LIBS)

.PHONY: test-vectors
test-vectors: cli $(BUILD)/tests/test_vec $(BUILD)/tests/tools/vcd_compare $(BUILD)/tests/tools/vec_bin_check
	$(BUILD)/tests/test_vec
	@bash tests/vectors/run.sh $(BUILD)
