# host/gpio.mk - the GPIO transport (docs/board-gpio.md), included by
# host/module.mk.  The backend follows the installed libgpiod: 1.x -> the v1
# API (gpio_v1.c, Debian 12's 1.6.3), 2.x -> the v2 API (gpio_v2.c, 2.1 and
# newer), none -> gpio_none.c, whose operations say edgeflag-host was built
# without libgpiod.  WITH_GPIO=0 forces the last; GPIOD_PKG_CONFIG_PATH picks
# another libgpiod (the tests' private v2.3 build, tests/host/module.mk).
WITH_GPIO ?= 1
GPIOD_VERSION := $(if $(filter 1,$(WITH_GPIO)),$(shell $(PKG_CONFIG) --modversion libgpiod 2>/dev/null))
ifeq ($(GPIOD_VERSION),)
HOST_GPIO_BACKEND := none
else ifeq ($(firstword $(subst ., ,$(GPIOD_VERSION))),1)
HOST_GPIO_BACKEND := v1
else
HOST_GPIO_BACKEND := v2
endif
HOST_GPIO_CFLAGS := $(if $(GPIOD_VERSION),$(shell $(PKG_CONFIG) --cflags libgpiod))
HOST_GPIO_LIBS := $(if $(GPIOD_VERSION),$(shell $(PKG_CONFIG) --libs libgpiod))
HOST_GPIO_OBJS := $(BUILD)/host/transport_gpio.o $(BUILD)/host/gpio_$(HOST_GPIO_BACKEND).o
HOST_LIBS += $(HOST_GPIO_LIBS)

# The backend alone sees libgpiod's headers.
$(BUILD)/host/gpio_$(HOST_GPIO_BACKEND).o: host/gpio_$(HOST_GPIO_BACKEND).c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) $(HOST_GPIO_CFLAGS) -DEF_GPIOD_VERSION='"$(GPIOD_VERSION)"' -c $< -o $@
