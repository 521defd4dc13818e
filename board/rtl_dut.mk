# board/rtl_dut.mk - the Verilated reference RTL as the simulated board's DUT
# (`edgeflag-host ... --transport sim --sim-dut rtl`, docs/board.md 5.3).
# Included by host/module.mk.  `make host-rtl` builds edgeflag-host with it
# (WITH_RTL_DUT=1; about 30 s of Verilator and C++ on two cores, so the
# default `make` leaves it out: WITH_RTL_DUT=0); WITH_RTL_DUT=auto builds it
# when `verilator` is on the PATH.  Without it, dut_rtl.c is a stub, --version
# says so and `--sim-dut rtl` is an error naming `make host-rtl`.
#
# The setting is a build option that stays: `make host-rtl` or `make
# WITH_RTL_DUT=1|auto|0` on the command line writes it to $(BUILD)/options.mk,
# and every later `make` of that BUILD reads it from there (so a plain `make`
# no longer relinks edgeflag-host without the RTL).  `make WITH_RTL_DUT=0`
# turns it off again; `make clean` forgets it.
#
# RTL_DUT_NS       sample counts to build a model for (one Verilated model each)
# RTL_DUT_W_MAX .. the RTL's parameters (what identify then says)
# RTL_DUT_SRC      the RTL's folder (rtl/, or an RTL variant's copy made by
#                  dv/rtl-variant.sh: a planted fault, tests only)
# RTL_DUT_FAULT    the planted fault's name, for identify and --version only
# RTL_DUT_DIR      where the Verilated models and objects go
ifndef EF_HOST_RTL_DUT_MK
EF_HOST_RTL_DUT_MK := 1

EF_OPTIONS := $(BUILD)/options.mk
-include $(EF_OPTIONS)
ifeq ($(origin WITH_RTL_DUT),command line)
# given by the user (a sub-make's copy of the line is not a new choice)
ifeq ($(MAKELEVEL),0)
$(shell mkdir -p $(BUILD) && echo 'WITH_RTL_DUT_SAVED := $(WITH_RTL_DUT)' >$(EF_OPTIONS))
endif
else ifneq ($(WITH_RTL_DUT_SAVED),)
WITH_RTL_DUT := $(WITH_RTL_DUT_SAVED)
endif
WITH_RTL_DUT ?= 0
RTL_DUT_NS ?= 8 16 32
RTL_DUT_W_MAX ?= 1024
RTL_DUT_H_MAX ?= 1024
RTL_DUT_E_MAX ?= 32768
RTL_DUT_SRC ?= rtl
RTL_DUT_FAULT ?=
RTL_DUT_DIR ?= $(BUILD)/host/rtl
RTL_DUT_OPT ?= -O1
CXX ?= c++
VERILATOR ?= verilator

ifeq ($(WITH_RTL_DUT),auto)
HOST_RTL_HAVE := $(shell command -v $(VERILATOR) >/dev/null 2>&1 && echo 1)
else ifeq ($(WITH_RTL_DUT),1)
HOST_RTL_HAVE := 1
else
HOST_RTL_HAVE :=
endif

ifeq ($(HOST_RTL_HAVE),1)
VERILATOR_ROOT_DIR := $(shell $(VERILATOR) --getenv VERILATOR_ROOT 2>/dev/null)
RTL_DUT_VSRC := dv/tb/dut_rtl.v $(wildcard $(RTL_DUT_SRC)/*.v)
RTL_DUT_VINC := $(wildcard $(RTL_DUT_SRC)/*.vh)
RTL_DUT_LIBS := $(foreach n,$(RTL_DUT_NS),$(RTL_DUT_DIR)/vl$(n)/Vef_rtl_dut$(n)__ALL.a)
# Verilator's runtime: the same for every build of the models, so shared
RTL_DUT_VLOBJ := $(BUILD)/host/verilated.o $(BUILD)/host/verilated_threads.o
RTL_DUT_OBJS := $(RTL_DUT_DIR)/dut_rtl.o $(RTL_DUT_DIR)/dut_rtl_vl.o $(RTL_DUT_LIBS) $(RTL_DUT_VLOBJ)
RTL_DUT_DEFS := -DEF_RTL_W_MAX=$(RTL_DUT_W_MAX) -DEF_RTL_H_MAX=$(RTL_DUT_H_MAX) -DEF_RTL_E_MAX=$(RTL_DUT_E_MAX) \
                -DEF_RTL_FAULT='"$(RTL_DUT_FAULT)"'
RTL_DUT_CXXFLAGS := -std=c++17 $(RTL_DUT_OPT) -g -fPIC -Iboard -Iproto -isystem $(VERILATOR_ROOT_DIR)/include \
                    -isystem $(VERILATOR_ROOT_DIR)/include/vltstd $(foreach n,$(RTL_DUT_NS),-isystem $(RTL_DUT_DIR)/vl$(n) -DEF_RTL_NS$(n))
# the link: the stub dut_rtl.o out, the real one, the models and the C++ runtime in
HOST_RTL_DUT_OBJS := $(RTL_DUT_OBJS)
HOST_RTL_DUT_STUB := $(BUILD)/board/dut_rtl.o
HOST_LINK := $(CXX)
HOST_RTL_LDLIBS := -lpthread

# The models follow what they are built from: another RTL folder, other
# parameters, a fault or another optimisation rebuild them.
RTL_DUT_SRC_FLAG := $(RTL_DUT_DIR)/models.flag
RTL_DUT_SRC_TEXT := $(abspath $(RTL_DUT_SRC)) $(RTL_DUT_W_MAX) $(RTL_DUT_H_MAX) $(RTL_DUT_E_MAX) $(RTL_DUT_FAULT) $(RTL_DUT_OPT)
$(shell mkdir -p $(RTL_DUT_DIR) && { [ "$$(cat $(RTL_DUT_SRC_FLAG) 2>/dev/null)" = "$(RTL_DUT_SRC_TEXT)" ] || \
    echo "$(RTL_DUT_SRC_TEXT)" >$(RTL_DUT_SRC_FLAG); })

# One Verilated model per sample count (the parameters are elaboration-time).
# Verilator's generated makefile compiles the model; its warnings on the RTL
# are the RTL owner's (tests/rtl lints it), not fatal here.
define rtl_dut_model
$(RTL_DUT_DIR)/vl$(1)/Vef_rtl_dut$(1)__ALL.a: $(RTL_DUT_VSRC) $(RTL_DUT_VINC) dv/tb/ef_raster_conn.vh $(RTL_DUT_SRC_FLAG) board/rtl_dut.mk
	@mkdir -p $(RTL_DUT_DIR)/vl$(1)
	$(VERILATOR) --cc -O3 -Wno-fatal -Wno-lint -Wno-style --Mdir $(RTL_DUT_DIR)/vl$(1) --prefix Vef_rtl_dut$(1) \
	    --top-module ef_rtl_dut -GNS=$(1) -GW_MAX=$(RTL_DUT_W_MAX) -GH_MAX=$(RTL_DUT_H_MAX) -GE_MAX=$(RTL_DUT_E_MAX) \
	    -I$(RTL_DUT_SRC) -Idv/tb $(RTL_DUT_VSRC) >$(RTL_DUT_DIR)/vl$(1)/verilator.log 2>&1 || \
	    { cat $(RTL_DUT_DIR)/vl$(1)/verilator.log; exit 1; }
	+$(MAKE) --no-print-directory -s -C $(RTL_DUT_DIR)/vl$(1) -f Vef_rtl_dut$(1).mk OPT_FAST=$(RTL_DUT_OPT) \
	    OPT_SLOW=-O0 CXX=$(CXX) Vef_rtl_dut$(1)__ALL.a
endef
$(foreach n,$(RTL_DUT_NS),$(eval $(call rtl_dut_model,$(n))))

RTL_DUT_VLFLAGS := -std=c++17 $(RTL_DUT_OPT) -g -fPIC -isystem $(VERILATOR_ROOT_DIR)/include \
                   -isystem $(VERILATOR_ROOT_DIR)/include/vltstd
$(BUILD)/host/verilated.o: $(VERILATOR_ROOT_DIR)/include/verilated.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(RTL_DUT_VLFLAGS) -c $< -o $@
$(BUILD)/host/verilated_threads.o: $(VERILATOR_ROOT_DIR)/include/verilated_threads.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(RTL_DUT_VLFLAGS) -c $< -o $@
$(RTL_DUT_DIR)/dut_rtl_vl.o: board/dut_rtl.cpp board/dut_rtl.h $(RTL_DUT_LIBS)
	$(CXX) $(RTL_DUT_CXXFLAGS) -Wall -Wextra -Werror -c $< -o $@
$(RTL_DUT_DIR)/dut_rtl.o: EF_INC := $(LAYER_INC_board)
$(RTL_DUT_DIR)/dut_rtl.o: board/dut_rtl.c board/dut_rtl.h board/rtl_dut.mk $(RTL_DUT_SRC_FLAG)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) -DEF_RTL_DUT $(RTL_DUT_DEFS) -c $< -o $@
else
HOST_RTL_DUT_OBJS :=
HOST_RTL_DUT_STUB :=
HOST_LINK := $(CC)
HOST_RTL_LDLIBS :=
endif

# The link follows the setting: a build with and one without the RTL DUT
# relink edgeflag-host (host/module.mk makes it depend on this file).
HOST_RTL_FLAG := $(RTL_DUT_DIR).flag
HOST_RTL_FLAG_TEXT := $(HOST_RTL_HAVE) $(RTL_DUT_NS) $(RTL_DUT_W_MAX) $(RTL_DUT_H_MAX) $(RTL_DUT_E_MAX) $(RTL_DUT_FAULT) $(RTL_DUT_DIR)
$(shell mkdir -p $(dir $(RTL_DUT_DIR)) && { [ "$$(cat $(HOST_RTL_FLAG) 2>/dev/null)" = "$(HOST_RTL_FLAG_TEXT)" ] || \
    echo "$(HOST_RTL_FLAG_TEXT)" >$(HOST_RTL_FLAG); })

# edgeflag-host with the RTL DUT (remembered, as `make WITH_RTL_DUT=1`), or a clear error without
# Verilator.
.PHONY: host-rtl
host-rtl:
	@command -v $(VERILATOR) >/dev/null 2>&1 || { echo "make host-rtl: verilator is not installed" \
	    "(Debian: apt-get install verilator; tools/install-deps.sh test)"; exit 1; }
	@mkdir -p $(BUILD) && echo 'WITH_RTL_DUT_SAVED := 1' >$(EF_OPTIONS)
	+@$(MAKE) --no-print-directory WITH_RTL_DUT=1 host
	@echo "make host-rtl: edgeflag-host has the RTL DUT; later builds of $(BUILD) keep it (make WITH_RTL_DUT=0 drops it)"

# At most 90 s with the Verilator build (tests/host/rtl.sh builds what it
# needs: edgeflag-host with the RTL DUT, one with a planted RTL fault, one
# without); skips, saying so, without verilator.
.PHONY: test-host-rtl
test-host-rtl:
	bash tests/host/rtl.sh $(BUILD)

endif
