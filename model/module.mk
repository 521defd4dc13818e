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

# make install [PREFIX=/usr/local] [DESTDIR=]: the edgeflag command, the regression scripts,
# headers, both libraries, pkg-config file.
.PHONY: install
install: lib cli
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/include/edgeflag $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 755 $(EDGEFLAG) rtl_vectors/regress/ef-regress-shard rtl_vectors/regress/ef-regress-merge \
	    $(DESTDIR)$(PREFIX)/bin/
	install -m 644 model/edgeflag.h model/ef_scene.h model/ef_trace.h model/ef_filter.h $(DESTDIR)$(PREFIX)/include/edgeflag/
	install -m 644 $(LIB_A) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(LIB_SO) $(DESTDIR)$(PREFIX)/lib/libedgeflag.so.0
	ln -sf libedgeflag.so.0 $(DESTDIR)$(PREFIX)/lib/libedgeflag.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|0.1.0|' model/edgeflag.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/edgeflag.pc
