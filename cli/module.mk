# cli/: the edgeflag command.  It links the vectors library (libedgeflag_vectors.a), util/ and
# libedgeflag; nothing else links cli/ (edgeflag-host calls the libraries, not a command's main).
CLI_SRC := $(wildcard cli/*.c)
CLI_OBJ := $(CLI_SRC:%.c=$(BUILD)/%.o)
EDGEFLAG := $(BUILD)/edgeflag
# Layer: the public headers, fixed/, the vector library, util/ and its own.
LAYER_INC_cli := -Iinclude/edgeflag -Ifixed -Irtl_vectors -Iutil -Icli
$(CLI_OBJ): EF_INC := $(LAYER_INC_cli)

cli: $(EDGEFLAG)
$(EDGEFLAG): $(CLI_OBJ) $(UTIL_OBJ) $(VEC_A) $(LIB_A)
	$(CC) $(LDFLAGS_ALL) -o $@ $(CLI_OBJ) $(UTIL_OBJ) $(VEC_A) $(LIB_A) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS)
