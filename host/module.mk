# host/: edgeflag-host, the board protocol's host side, its transports and the
# board engine (board/) that the simulated and emulated boards run.
# docs/board.md.  It links the libraries (util/, the vectors library, libedgeflag),
# never the edgeflag command's objects: verify calls ef_check_run.  USB and GPIO come from host/usb.mk and host/gpio.mk, which
# build their transport when libusb-1.0 / libgpiod is installed and a table
# saying "built without ..." otherwise (WITH_USB=0 / WITH_GPIO=0 force that).
HOST_BOARD_SRC := $(wildcard board/*.c proto/*.c)
HOST_SRC := host/main.c host/host_link.c host/bench_link.c host/transport.c host/transport_sim.c \
            host/transport_null.c host/transport_socket.c \
            host/transport_stream.c host/transport_serial.c
# Layer: the public headers, the vectors library, util/, proto/, board/ (the simulated board runs
# the engine) and its own; never cli/ (tests/layers checks it), model/'s internals or fixed/.
LAYER_INC_host := -Iinclude/edgeflag -Irtl_vectors -Iutil -Iproto -Iboard -Ihost
HOST_LIBS := $(shell $(PKG_CONFIG) --libs zlib 2>/dev/null || echo -lz)
include host/usb.mk
include host/gpio.mk
include board/rtl_dut.mk
HOST_BOARD_OBJ := $(HOST_BOARD_SRC:%.c=$(BUILD)/%.o)
# with the RTL DUT (board/rtl_dut.mk) its real dut_rtl.o replaces the stub
HOST_BOARD_LINK := $(filter-out $(HOST_RTL_DUT_STUB),$(HOST_BOARD_OBJ)) $(HOST_RTL_DUT_OBJS)
HOST_OBJ := $(HOST_SRC:%.c=$(BUILD)/%.o) $(HOST_USB_OBJS) $(HOST_GPIO_OBJS)
EDGEFLAG_HOST := $(BUILD)/edgeflag-host

$(BUILD)/host/%.o: EF_INC := $(LAYER_INC_host)
$(BUILD)/host/%.o: host/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) -c $< -o $@

.PHONY: host
host: $(EDGEFLAG_HOST)
$(EDGEFLAG_HOST): $(HOST_OBJ) $(HOST_BOARD_LINK) $(UTIL_OBJ) $(VEC_A) $(LIB_A) $(HOST_RTL_FLAG)
	$(HOST_LINK) $(LDFLAGS_ALL) -o $@ $(HOST_OBJ) $(HOST_BOARD_LINK) $(UTIL_OBJ) $(VEC_A) $(LIB_A) $(HOST_LIBS) $(PNG_LIBS) \
	    $(EXPAT_LIBS) $(VEC_LIBS) $(HOST_RTL_LDLIBS)

# make install puts edgeflag-host beside edgeflag (host/usb.mk adds the udev rule).
.PHONY: install-host
install: install-host
install-host: host
	install -d $(DESTDIR)$(PREFIX)/bin
	install -m 755 $(EDGEFLAG_HOST) $(DESTDIR)$(PREFIX)/bin/
