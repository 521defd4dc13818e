# libedgeflag: fixed/ + model/ (+ model/input/), static and shared, with a pkg-config file.
MODEL_SRC := $(wildcard model/*.c) $(wildcard model/input/*.c)
MODEL_OBJ := $(MODEL_SRC:%.c=$(BUILD)/%.o)
PUBLIC_H  := $(wildcard include/edgeflag/*.h)

# Layers (docs/source.md).  The model core (model/*.c) sees fixed/, its own headers and only the
# public headers of the core, staged in $(BUILD)/include/core: not the scene layer (ef_scene*.h)
# nor model/input/.  The scene layer (model/input/: the container, the readers, ef_scene_render)
# sees every public header, fixed/ and its own folder, never model/'s internals.
CORE_PUBLIC_H := edgeflag.h ef_api.h ef_trace.h ef_patterns.h ef_filter.h
CORE_STAGED_H := $(CORE_PUBLIC_H:%=$(BUILD)/include/core/%)
MODEL_CORE_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(wildcard model/*.c))
MODEL_INPUT_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(wildcard model/input/*.c))
$(BUILD)/include/core/%.h: include/edgeflag/%.h
	@mkdir -p $(dir $@)
	ln -sf $(abspath $<) $@
LAYER_INC_model := -I$(BUILD)/include/core -Ifixed -Imodel
LAYER_INC_input := -Iinclude/edgeflag -Ifixed -Imodel/input
$(MODEL_CORE_OBJ): EF_INC := $(LAYER_INC_model)
$(MODEL_CORE_OBJ): | $(CORE_STAGED_H)
$(MODEL_INPUT_OBJ): EF_INC := $(LAYER_INC_input)
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
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(EF_VERSION)|' $< > $@

# make install [PREFIX=/usr/local] [DESTDIR=]: the edgeflag command, the regression scripts,
# headers, both libraries, pkg-config file.
.PHONY: install
install: lib cli
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/include/edgeflag $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 755 $(EDGEFLAG) tools/regress/ef-regress-shard tools/regress/ef-regress-merge \
	    $(DESTDIR)$(PREFIX)/bin/
	install -m 644 $(PUBLIC_H) $(DESTDIR)$(PREFIX)/include/edgeflag/
	install -m 644 $(LIB_A) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(LIB_SO) $(DESTDIR)$(PREFIX)/lib/libedgeflag.so.0
	ln -sf libedgeflag.so.0 $(DESTDIR)$(PREFIX)/lib/libedgeflag.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(EF_VERSION)|' model/edgeflag.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/edgeflag.pc
