CLI_SRC := $(wildcard cli/*.c)
CLI_OBJ := $(CLI_SRC:%.c=$(BUILD)/%.o) $(RTLV_OBJ)
EDGEFLAG := $(BUILD)/edgeflag

cli: $(EDGEFLAG)
$(EDGEFLAG): $(CLI_OBJ) $(LIB_A)
	$(CC) $(LDFLAGS_ALL) -o $@ $(CLI_OBJ) $(LIB_A) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS)
