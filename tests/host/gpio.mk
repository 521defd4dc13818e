# The GPIO transport's tests against an emulated chip (docs/board-gpio.md
# section 8): `make test-host-gpio`, a stage of `make test` (under a minute).
# gpio_emu links the transport with the system's libgpiod (1.6 on Debian 12);
# gpio_emu_v2 links it with libgpiod 2.3 built by tests/host/libgpiod2.sh.
GPIO_UMOCKDEV_CFLAGS := $(shell $(PKG_CONFIG) --cflags umockdev-1.0 2>/dev/null)
GPIO_UMOCKDEV_LIBS := $(shell $(PKG_CONFIG) --libs umockdev-1.0 2>/dev/null || echo -lumockdev -lgobject-2.0 -lglib-2.0)
GPIO_EMU := $(BUILD)/tests/host/gpio_emu
GPIO_EMU_V2 := $(BUILD)/tests/host/gpio_emu_v2
GPIO_EMU_OBJ := $(BUILD)/tests/host/gpio_emu.o $(BUILD)/tests/host/gpio_chip.o
GPIO_EMU_LINK := $(BUILD)/host/host_link.o $(BUILD)/host/transport.o $(HOST_BOARD_OBJ) $(UTIL_OBJ) $(VEC_A) $(LIB_A)
GPIOD2_PREFIX := $(BUILD)/libgpiod2/prefix

# A static pattern rule: only these objects, so other tests in tests/host keep their own flags.
$(GPIO_EMU_OBJ): $(BUILD)/tests/host/%.o: tests/host/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Ihost -Iboard -Iproto -Iutil -Itests/host $(CFLAGS_ALL) $(GPIO_UMOCKDEV_CFLAGS) -c $< -o $@

$(GPIO_EMU): $(GPIO_EMU_OBJ) $(HOST_GPIO_OBJS) $(GPIO_EMU_LINK)
	$(CC) $(LDFLAGS_ALL) -o $@ $^ $(HOST_GPIO_LIBS) $(GPIO_UMOCKDEV_LIBS) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS) -lz

# The v2 backend against the private libgpiod 2.3 (run tests/host/libgpiod2.sh first).
$(BUILD)/gpiod2/gpio_v2.o: host/gpio_v2.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Ihost -Iboard -Iproto -Iutil $(CFLAGS_ALL) -I$(GPIOD2_PREFIX)/include \
	    -DEF_GPIOD_VERSION='"$(shell PKG_CONFIG_PATH=$(GPIOD2_PREFIX)/lib/pkgconfig $(PKG_CONFIG) --modversion libgpiod)"' \
	    -c $< -o $@
$(GPIO_EMU_V2): $(GPIO_EMU_OBJ) $(BUILD)/host/transport_gpio.o $(BUILD)/gpiod2/gpio_v2.o $(GPIO_EMU_LINK)
	$(CC) $(LDFLAGS_ALL) -o $@ $^ -L$(GPIOD2_PREFIX)/lib -Wl,-rpath,$(abspath $(GPIOD2_PREFIX)/lib) -lgpiod \
	    $(GPIO_UMOCKDEV_LIBS) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS) -lz

.PHONY: test-host-gpio gpio-emu-v2
gpio-emu-v2: $(GPIO_EMU_V2)
test-host-gpio: $(GPIO_EMU) cli host
	@bash tests/host/gpio.sh $(BUILD)

# The co-simulation with the simulated board's gateware (docs/board-gpio.md section 8): gpio_cosim
# runs edgeflag-host (host/main.c compiled unchanged, its main renamed) on the emulated chip whose
# lines lead to board_sim's GPIO header.  Run by tests/board/gpio_cosim.sh.
GPIO_COSIM := $(BUILD)/tests/host/gpio_cosim
GPIO_COSIM_V2 := $(BUILD)/tests/host/gpio_cosim_v2
GPIO_COSIM_HOST := $(filter-out $(BUILD)/host/main.o $(HOST_GPIO_OBJS),$(HOST_OBJ))
$(BUILD)/tests/host/gpio_cosim.o: tests/host/gpio_cosim.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Ihost -Iboard -Iproto -Iutil -Itests/host $(CFLAGS_ALL) $(GPIO_UMOCKDEV_CFLAGS) -c $< -o $@
$(BUILD)/tests/host/host_main_cosim.o: host/main.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(LAYER_INC_host) $(CFLAGS_ALL) -Dmain=edgeflag_host_main -c $< -o $@
GPIO_COSIM_OBJ := $(BUILD)/tests/host/gpio_cosim.o $(BUILD)/tests/host/gpio_chip.o $(BUILD)/tests/host/host_main_cosim.o \
                  $(GPIO_COSIM_HOST) $(HOST_BOARD_OBJ) $(UTIL_OBJ) $(VEC_A) $(LIB_A)
GPIO_COSIM_LIBS := $(HOST_USB_LIBS) $(GPIO_UMOCKDEV_LIBS) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS) -lz
$(GPIO_COSIM): $(GPIO_COSIM_OBJ) $(HOST_GPIO_OBJS)
	$(CC) $(LDFLAGS_ALL) -o $@ $^ $(HOST_GPIO_LIBS) $(GPIO_COSIM_LIBS)
$(GPIO_COSIM_V2): $(GPIO_COSIM_OBJ) $(BUILD)/host/transport_gpio.o $(BUILD)/gpiod2/gpio_v2.o
	$(CC) $(LDFLAGS_ALL) -o $@ $^ -L$(GPIOD2_PREFIX)/lib -Wl,-rpath,$(abspath $(GPIOD2_PREFIX)/lib) -lgpiod \
	    $(GPIO_COSIM_LIBS)
.PHONY: gpio-cosim gpio-cosim-v2
gpio-cosim: $(GPIO_COSIM)
gpio-cosim-v2: $(GPIO_COSIM_V2)
