# cli/: the edgeflag command.  It links the vectors library (libedgeflag_vectors.a), util/ and
# libedgeflag; nothing else links cli/ (edgeflag-host calls the libraries, not a command's main).
CLI_SRC := $(wildcard cli/*.c)
CLI_OBJ := $(CLI_SRC:%.c=$(BUILD)/%.o)
EDGEFLAG := $(BUILD)/edgeflag
# Layer: the public headers, fixed/, the vector library, util/ and its own.
LAYER_INC_cli := -Iinclude/edgeflag -Ifixed -Irtl_vectors -Iutil -Icli
$(CLI_OBJ): EF_INC := $(LAYER_INC_cli)
# rtl-sim runs dv/rtl-sim.sh of the tree the command was built from
$(BUILD)/cli/cmd_rtl_sim.o: CPPFLAGS += -DEF_SOURCE_ROOT='"$(CURDIR)"'

cli: $(EDGEFLAG)
$(EDGEFLAG): $(CLI_OBJ) $(UTIL_OBJ) $(VEC_A) $(LIB_A)
	$(CC) $(LDFLAGS_ALL) -o $@ $(CLI_OBJ) $(UTIL_OBJ) $(VEC_A) $(LIB_A) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS)

# `edgeflag coverage` compiles in the cover points of dv/coverage/points.tsv
# (one data file, shared with the cocotb bench): a C table generated from it.
$(BUILD)/cli/coverage_points.h: dv/coverage/points.tsv
	@mkdir -p $(@D)
	awk -F'\t' '/^#/ || $$1 == "name" || NF < 3 { next } { for (i = 1; i <= 3; i++) { gsub(/\\/, "\\\\", $$i); gsub(/"/, "\\\"", $$i) } printf "{ \"%s\", \"%s\", \"%s\" },\n", $$1, $$2, $$3 }' $< >$@.tmp && mv $@.tmp $@
$(BUILD)/cli/cmd_coverage.o: $(BUILD)/cli/coverage_points.h
$(BUILD)/cli/cmd_coverage.o: EF_INC := $(LAYER_INC_cli) -I$(BUILD)/cli
