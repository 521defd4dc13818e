CLI_SRC := $(wildcard cli/*.c)
CLI_OBJ := $(CLI_SRC:%.c=$(BUILD)/%.o) $(RTLV_OBJ)
EDGEFLAG := $(BUILD)/edgeflag
# Layer: the public headers, fixed/, the vector library and its own.
LAYER_INC_cli := -Iinclude/edgeflag -Ifixed -Irtl_vectors -Icli
$(CLI_SRC:%.c=$(BUILD)/%.o): EF_INC := $(LAYER_INC_cli)
# rtl-sim runs dv/rtl-sim.sh of the tree the command was built from
$(BUILD)/cli/cmd_rtl_sim.o: CPPFLAGS += -DEF_SOURCE_ROOT='"$(CURDIR)"'

cli: $(EDGEFLAG)
$(EDGEFLAG): $(CLI_OBJ) $(LIB_A)
	$(CC) $(LDFLAGS_ALL) -o $@ $(CLI_OBJ) $(LIB_A) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS)
