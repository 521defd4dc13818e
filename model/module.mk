# libedgeflag: fixed/ + model/ (+ model/input/), static and shared, with a pkg-config file.
MODEL_SRC := $(wildcard model/*.c) $(wildcard model/input/*.c)
MODEL_OBJ := $(MODEL_SRC:%.c=$(BUILD)/%.o)
LIB_OBJ   := $(FIXED_OBJ) $(MODEL_OBJ)
LIB_A     := $(BUILD)/libedgeflag.a
LIB_SO    := $(BUILD)/libedgeflag.so
LIB_PC    := $(BUILD)/edgeflag.pc

lib: $(LIB_A) $(LIB_SO) $(LIB_PC)

$(LIB_A): $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(LIB_SO): $(LIB_OBJ)
	$(CC) -shared -Wl,-soname,libedgeflag.so.0 $(LDFLAGS_ALL) -o $@ $^ $(EXPAT_LIBS)

$(LIB_PC): model/edgeflag.pc.in
	@mkdir -p $(dir $@)
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|0.1.0|' $< > $@
