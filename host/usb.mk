# host/usb.mk - the USB transport of edgeflag-host (docs/board-usb.md) and its
# test against an emulated board (tests/host/usb.sh).  Included by
# host/module.mk.  With libusb-1.0's development files (Debian
# libusb-1.0-0-dev) the real transport is built; without them, or with
# WITH_USB=0, a stub whose version() says "built without libusb" and whose
# operations return EF_HOST_EUNSUPPORTED, so edgeflag-host builds anywhere.
ifndef EF_HOST_USB_MK
EF_HOST_USB_MK := 1

WITH_USB ?= 1
HOST_USB_HAVE := $(if $(filter 1,$(WITH_USB)),$(shell $(PKG_CONFIG) --exists libusb-1.0 2>/dev/null && echo 1))
ifeq ($(HOST_USB_HAVE),1)
HOST_USB_CFLAGS := $(shell $(PKG_CONFIG) --cflags libusb-1.0)
HOST_USB_LIBS   := $(shell $(PKG_CONFIG) --libs libusb-1.0)
HOST_USB_OBJS   := $(BUILD)/host/transport_usb.o
else
HOST_USB_CFLAGS :=
HOST_USB_LIBS   :=
HOST_USB_OBJS   := $(BUILD)/host/transport_usb_none.o
endif
$(HOST_USB_OBJS): CPPFLAGS += $(HOST_USB_CFLAGS)

# The emulated board (tests/host/usb_emu.c): umockdev (Debian libumockdev-dev)
# in front of the real board engine and its DUT, the C model.  The board's
# objects are host/module.mk's (HOST_BOARD_OBJ), named here because this file
# is read before that variable is set.
HOST_LIBS    += $(HOST_USB_LIBS)
USB_EMU      := $(BUILD)/tests/host/usb_emu
USB_EMU_OBJ  := $(BUILD)/tests/host/usb_emu.o
USB_EMU_BOARD_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(wildcard board/*.c proto/*.c))
UMOCKDEV_CFLAGS = $(shell $(PKG_CONFIG) --cflags umockdev-1.0 2>/dev/null)
UMOCKDEV_LIBS   = $(shell $(PKG_CONFIG) --libs umockdev-1.0 2>/dev/null || echo -lumockdev -lgobject-2.0 -lglib-2.0)
# GLib's headers are not -Wstrict-prototypes clean.
$(USB_EMU_OBJ): CPPFLAGS += -Ihost -Iboard -Iboard/sim -Iproto $(UMOCKDEV_CFLAGS)
$(USB_EMU_OBJ): WARN += -Wno-strict-prototypes
$(USB_EMU_OBJ): board/sim/usb_wire.h
$(USB_EMU): $(USB_EMU_OBJ) $(USB_EMU_BOARD_OBJ) $(VEC_A) $(LIB_A)
	$(CC) $(LDFLAGS_ALL) -o $@ $^ $(UMOCKDEV_LIBS) -lpthread $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS) -lz

# make install: the udev rule beside the program; udev itself reads
# /etc/udev/rules.d and /usr/lib/udev/rules.d (docs/board-usb.md section 8).
.PHONY: install-usb-rule
install: install-usb-rule
install-usb-rule:
	install -d $(DESTDIR)$(PREFIX)/lib/udev/rules.d
	install -m 644 host/60-edgeflag.rules $(DESTDIR)$(PREFIX)/lib/udev/rules.d/60-edgeflag.rules
	install -m 644 host/60-edgeflag-serial.rules $(DESTDIR)$(PREFIX)/lib/udev/rules.d/60-edgeflag-serial.rules

.PHONY: host-usb-emu test-host-usb
host-usb-emu: $(USB_EMU)

# At most 90 s: list, stream + verify, every fault, unplug + --resume.
test-host-usb:
	@bash tools/install-deps.sh test
	@$(MAKE) --no-print-directory $(EDGEFLAG_HOST) $(USB_EMU) $(EDGEFLAG)
	bash tests/host/usb.sh $(BUILD)

endif
