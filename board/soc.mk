# board/soc.mk - the ULX3S board (docs/board-ulx3s.md): the SoC (board/soc), its firmware
# (board/firmware: board/ef_board.c unchanged) and the whole board under Verilator (board/sim).
# Included by the Makefile.
#
#   make bitstream BOARD=ulx3s-25f|ulx3s-85f [BOARD_NS=8|16] [BOARD_SEED=N] [BOARD_GPIO=0] [BOARD_USB=0]
#        -> build/board/$(BOARD)-ns$(BOARD_NS)/gateware/radiona_ulx3s.bit, utilisation and Fmax
#           printed; fails when timing is not met (nextpnr without --timing-allow-fail)
#   make firmware [BOARD=...]   the firmware alone (its size printed)
#   make board-sim              the simulated board (build/board/sim-ns8/obj/board_sim)
#   make board-sim-test         verify through the simulated board (tests/board/soc_sim.sh)
#   make board-sim-faults       the same with the whole fault set (EF_SOCSIM_FULL=1: digest mode's
#                               faults, an open shape refused, the bounded result queue on the SoC)
#   make board-gpio-test        edgeflag-host over emulated GPIO into its gateware (tests/board/gpio_cosim.sh)
#   BOARD_GPIO=0                the SoC without the GPIO bus slave (build/board/...-nogpio)
#   BOARD_USB=0                 the SoC without the USB device (build/board/...-nousb)
#   BOARD_SCHEDULE=overlap      ef_raster's fast configuration (SCHEDULE=1, docs/microarch.md section 6)
#                               in the SoC (build/board/...-overlap, the simulated board's too:
#                               build/board/sim-ns8-overlap); the board then needs vectors made with
#                               `edgeflag vectors --schedule overlap` (docs/board-ulx3s.md)
#   make board-sim-usb-test     the same over USB: libusb, umockdev, the SoC's USB device
#                               (tests/board/usb_sim.sh)
#   EF_BOARD_SERIAL=...         the serial number identify reports (default EFULX3S-0001)
BOARD ?= ulx3s-25f
BOARD_NS ?= 8
BOARD_SEED ?= 1
EF_VENV ?= build/venv
EF_VENV_PY := $(EF_VENV)/bin/python
BOARD_GPIO ?= 1
BOARD_USB ?= 1
BOARD_SCHEDULE ?= reference
BOARD_DIR := $(BUILD)/board/$(BOARD)-ns$(BOARD_NS)$(if $(filter 0,$(BOARD_GPIO)),-nogpio)$(if $(filter 0,$(BOARD_USB)),-nousb)$(if $(filter overlap,$(BOARD_SCHEDULE)),-overlap)
BOARD_SIM_DIR := $(BUILD)/board/sim-ns$(BOARD_NS)$(if $(filter overlap,$(BOARD_SCHEDULE)),-overlap)
BOARD_SOC_SRC := board/soc/soc.py board/soc/ef_periph.py board/soc/ef_gpio.py board/soc/ef_usb.py board/soc/usb_core.py board/soc/ef_gate_ecp5.v board/soc/ef_gate_sim.v \
                 $(wildcard rtl/*.v) $(wildcard rtl/*.vh)
BOARD_TOOLS := $(EF_VENV)/.installed-soc build/fpga-bin/nextpnr-ecp5

.PHONY: board-tools firmware bitstream board-sim board-sim-test board-sim-faults board-gpio-test board-sim-usb-test

# the tools: Debian's cross compiler and picolibc, the pinned PyPI groups, the PATH shims (one
# grouped recipe for both files: under make -j two copies of pip would race on one venv)
$(BOARD_TOOLS) &: tools/requirements/soc.txt tools/requirements/fpga.txt tools/requirements/usb.txt tools/install-fpga.sh
	bash tools/install-deps.sh board
	bash tools/install-fpga.sh soc
	touch $(BOARD_TOOLS)
board-tools: $(BOARD_TOOLS)

# FW_SOC's headers, then its firmware (board/firmware/firmware.mk), then the gateware with it in the ROM
include board/firmware/firmware.mk

$(BUILD)/board/%/software/include/generated/csr.h: $(BOARD_SOC_SRC) $(BOARD_TOOLS)
	@mkdir -p $(BUILD)/board
	$(EF_VENV_PY) board/soc/soc.py --target $(if $(filter sim-%,$*),sim,$(BOARD)) --ns $(BOARD_NS) \
	    $(if $(findstring -nogpio,$*),--no-gpio) $(if $(findstring -nousb,$*),--no-usb) $(if $(findstring -overlap,$*),--schedule overlap) --out $(BUILD)/board/$* --headers-only >$(BUILD)/board/$*.headers.log 2>&1 || \
	    { tail -n 20 $(BUILD)/board/$*.headers.log; exit 1; }

firmware: $(BOARD_TOOLS)
	$(MAKE) --no-print-directory $(BOARD_DIR)/firmware.bin FW_SOC=$(BOARD_DIR)

bitstream: $(BOARD_TOOLS)
	$(MAKE) --no-print-directory $(BOARD_DIR)/firmware.bin FW_SOC=$(BOARD_DIR)
	EF_SOC_FLAGS="$(if $(filter 0,$(BOARD_GPIO)),--no-gpio) $(if $(filter 0,$(BOARD_USB)),--no-usb) $(if $(filter overlap,$(BOARD_SCHEDULE)),--schedule overlap)" bash board/soc/bitstream.sh $(BOARD) $(BOARD_NS) \
	    $(BOARD_DIR) $(BOARD_SEED)

# The simulated board: the SoC's Verilog for the sim target with the firmware in its ROM, and
# the harness.  LiteX's generated Verilog and the VexRiscv core are third-party: their lint
# warnings are not ours to fix, so only errors stop the build there (rtl/ has its own -Wall lint).
BOARD_SIM_VFLAGS := --cc --exe --build -j 2 -O2 --x-assign fast --x-initial fast --no-assert -Wno-fatal \
                    -Wno-lint -Wno-style -Wno-MULTIDRIVEN -Wno-UNOPTFLAT -Wno-COMBDLY -Wno-TIMESCALEMOD \
                    --top-module sim -I$(abspath rtl)
# The ROM is $$readmemh'd from gateware/sim_rom.init when the model starts: a new firmware
# rewrites that image and needs no new model.
$(BOARD_SIM_DIR)/gateware/sim.v: $(BOARD_SOC_SRC) | $(BOARD_SIM_DIR)/firmware.bin
	$(EF_VENV_PY) board/soc/soc.py --target sim --ns $(BOARD_NS) --out $(BOARD_SIM_DIR) \
	    $(if $(filter overlap,$(BOARD_SCHEDULE)),--schedule overlap) --rom $(BOARD_SIM_DIR)/firmware.bin >$(BOARD_SIM_DIR)/gateware.log 2>&1 || \
	    { tail -n 20 $(BOARD_SIM_DIR)/gateware.log; exit 1; }
# the harness's C++ files (gpio_link.cpp: the GPIO header's socket, docs/board-gpio.md section 8;
# usb_link.cpp: the USB host controller, docs/board-ulx3s.md "USB in the simulation")
BOARD_SIM_CPP := board/sim/board_sim.cpp board/sim/gpio_link.cpp board/sim/usb_link.cpp
$(BOARD_SIM_DIR)/obj/board_sim: $(BOARD_SIM_DIR)/gateware/sim.v $(BOARD_SIM_CPP) $(wildcard board/sim/*.h)
	verilator $(BOARD_SIM_VFLAGS) -Mdir $(BOARD_SIM_DIR)/obj -o board_sim \
	    $$(cat $(BOARD_SIM_DIR)/gateware/sources.txt) $(BOARD_SIM_DIR)/gateware/sim.v \
	    $(abspath $(BOARD_SIM_CPP)) -CFLAGS -O2 -CFLAGS -I$(abspath board/sim) -LDFLAGS -lz \
	    >$(BOARD_SIM_DIR)/verilate.log 2>&1 || \
	    { tail -n 30 $(BOARD_SIM_DIR)/verilate.log; exit 1; }
$(BOARD_SIM_DIR)/gateware/sim_rom.init: $(BOARD_SIM_DIR)/firmware.bin $(BOARD_SIM_DIR)/gateware/sim.v
	od -An -v -tx4 -w4 $< | tr -d ' ' >$@.tmp && mv $@.tmp $@
board-sim: $(BOARD_TOOLS)
	$(MAKE) --no-print-directory $(BOARD_SIM_DIR)/obj/board_sim $(BOARD_SIM_DIR)/gateware/sim_rom.init \
	    FW_SOC=$(BOARD_SIM_DIR) BOARD=sim
	@echo "board-sim: $(BOARD_SIM_DIR)/obj/board_sim --dir $(BOARD_SIM_DIR)/gateware"

board-sim-test: all board-sim $(BUILD)/tests/host/ptyboard
	bash tests/board/soc_sim.sh $(BOARD_SIM_DIR)
board-sim-faults: all board-sim $(BUILD)/tests/host/ptyboard
	EF_SOCSIM_FULL=1 bash tests/board/soc_sim.sh $(BOARD_SIM_DIR)

# edgeflag-host over emulated GPIO into the simulated board's gateware (docs/board-gpio.md section 8)
board-gpio-test: all board-sim gpio-cosim
	bash tests/board/gpio_cosim.sh $(BOARD_SIM_DIR) $(BUILD)

# The simulated board over USB: the unmodified edgeflag-host and libusb under umockdev
# (tests/host/usb_emu --soc) against the SoC's USB device (tests/board/usb_sim.sh)
board-sim-usb-test: all board-sim
	@bash tools/install-deps.sh test
	@$(MAKE) --no-print-directory host-usb-emu
	bash tests/board/usb_sim.sh $(BOARD_SIM_DIR)
