# rtl_vectors/: the vectors library, libedgeflag_vectors (docs/source.md, "The libraries"): the
# vector writers and readers, the verifier (`edgeflag check`) and the regression scenes
# (`edgeflag gen`).  Its API is ef_vec.h, ef_vec_read.h, ef_check.h and ef_gen.h, each function marked
# EF_API; it is built as a static and a shared library above libedgeflag (the shared one needs
# libedgeflag.so and exports only the EF_API functions), with its own pkg-config file
# edgeflag-vectors.pc (Requires: edgeflag).  The edgeflag command, edgeflag-host, the tests and a
# user's testbench link it.
RTLV_SRC := $(wildcard rtl_vectors/*.c)
RTLV_OBJ := $(RTLV_SRC:%.c=$(BUILD)/%.o)
VEC_PUBLIC_H := rtl_vectors/ef_vec.h rtl_vectors/ef_vec_read.h rtl_vectors/ef_check.h rtl_vectors/ef_gen.h
EF_INC += -Irtl_vectors
# Layer: the public headers, fixed/ (the bottom layer) and its own; never model/ or cli/.
LAYER_INC_rtl_vectors := -Iinclude/edgeflag -Ifixed -Irtl_vectors
$(RTLV_OBJ): EF_INC := $(LAYER_INC_rtl_vectors)

VEC_A  := $(BUILD)/libedgeflag_vectors.a
VEC_SO := $(BUILD)/libedgeflag_vectors.so
VEC_PC := $(BUILD)/edgeflag-vectors.pc
# Without the manifest (WITH_MANIFEST=0) the library needs neither Nettle nor json-c.
VEC_PC_REQUIRES := $(if $(filter 1,$(WITH_MANIFEST)),nettle json-c)

.PHONY: lib-vectors
lib: lib-vectors
lib-vectors: $(VEC_A) $(VEC_SO) $(VEC_PC)

$(VEC_A): $(RTLV_OBJ)
	@rm -f $@
	ar rcs $@ $^

# The integer primitives (fixed/) it uses are hidden in libedgeflag.so: the shared library has its
# own private copy of them; everything of the model it calls is EF_API.
$(VEC_SO): $(RTLV_OBJ) $(FIXED_OBJ) $(LIB_SO)
	$(CC) -shared -Wl,-soname,libedgeflag_vectors.so.0 -Wl,--no-undefined $(LDFLAGS_ALL) -o $@ $(RTLV_OBJ) \
	    $(FIXED_OBJ) -L$(BUILD) -ledgeflag $(VEC_LIBS) -lpthread

$(VEC_PC): rtl_vectors/edgeflag-vectors.pc.in
	@mkdir -p $(dir $@)
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(EF_VERSION)|' -e 's|@REQUIRES_PRIVATE@|$(VEC_PC_REQUIRES)|' \
	    $< > $@

.PHONY: install-vectors
install: install-vectors
install-vectors: lib-vectors
	install -d $(DESTDIR)$(PREFIX)/include/edgeflag $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 $(VEC_PUBLIC_H) $(DESTDIR)$(PREFIX)/include/edgeflag/
	install -m 644 $(VEC_A) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(VEC_SO) $(DESTDIR)$(PREFIX)/lib/libedgeflag_vectors.so.0
	ln -sf libedgeflag_vectors.so.0 $(DESTDIR)$(PREFIX)/lib/libedgeflag_vectors.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(EF_VERSION)|' -e 's|@REQUIRES_PRIVATE@|$(VEC_PC_REQUIRES)|' \
	    rtl_vectors/edgeflag-vectors.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/edgeflag-vectors.pc

# test_gen needs the generator objects as well as the library; an explicit rule
# overrides tests/module.mk's pattern rule for this one binary.
$(BUILD)/tests/test_gen: tests/unit/test_gen.c $(VEC_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS_ALL) $< $(VEC_A) -o $@ $(LDFLAGS_ALL) $(TEST_LIBS)

.PHONY: test-gen
test-gen: cli
	@bash tests/gen/run.sh $(BUILD)
