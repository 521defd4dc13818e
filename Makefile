# edgeflag - one non-recursive Makefile; each folder adds its fragment (module.mk).
# Objects go under $(BUILD).  Override on the command line: make CC=clang OPT=-O0 BUILD=build-clang
CC       ?= cc
OPT      ?= -O2
BUILD    ?= build
EXTRA_CFLAGS ?=
EXTRA_LDFLAGS ?=
PKG_CONFIG ?= pkg-config
PREFIX   ?= /usr/local
# The SVG illustrations every test and the bench use (tests/data/svg, in the repository).
EF_SVG   ?= $(abspath tests/data/svg)
export EF_SVG

WARN     := -std=c11 -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wvla
# CPPFLAGS = the defines (EF_DEFS) and the include path (EF_INC).  EF_INC here is the wide one that
# tests, bench and new folders compile with; each layer of the library and the CLI narrows it for its
# own objects in its module.mk (docs/source.md, "Layers"), so an include that the architecture forbids
# (the model reaching the readers, a library reaching cli/) is a build error, not a review comment.
# include/edgeflag/ holds the public headers: `#include "edgeflag.h"` resolves everywhere.
EF_DEFS  := -D_POSIX_C_SOURCE=200809L
# The one version number: edgeflag.h's EF_VERSION_STRING (the .pc files and ef_version() follow it).
EF_VERSION := $(shell sed -n 's/^#define EF_VERSION_STRING "\(.*\)"/\1/p' include/edgeflag/edgeflag.h)
EF_INC   := -Iinclude/edgeflag -Ifixed -Imodel
CPPFLAGS = $(EF_DEFS) $(EF_INC)
# Hidden by default: only declarations marked EF_API (include/edgeflag/ef_api.h) are exported.
CFLAGS_ALL = $(WARN) $(OPT) -g -fPIC -fvisibility=hidden -MMD -MP $(EXTRA_CFLAGS)
LDFLAGS_ALL = $(EXTRA_LDFLAGS)

# WITH_SVG=0 builds without expat (SVG input then fails with a clear error);
# WITH_PNG=0 builds without libpng (.png output then fails likewise).  The
# 32-bit bit-exact check uses both, as Debian 12 cannot co-install the i386
# -dev packages of these libraries reliably.
WITH_SVG ?= 1
WITH_PNG ?= 1
ifeq ($(WITH_SVG),1)
EXPAT_CFLAGS := $(shell $(PKG_CONFIG) --cflags expat 2>/dev/null)
EXPAT_LIBS   := $(shell $(PKG_CONFIG) --libs expat 2>/dev/null || echo -lexpat)
else
CPPFLAGS += -DEF_NO_SVG
endif
ifeq ($(WITH_PNG),1)
PNG_CFLAGS   := $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null)
PNG_LIBS     := $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null || echo -lpng)
else
CPPFLAGS += -DEF_NO_PNG
endif
CMOCKA_LIBS  := $(shell $(PKG_CONFIG) --libs cmocka 2>/dev/null || echo -lcmocka)
# WITH_MANIFEST=0 builds the vector tools without the manifest (manifest.json and its SHA-256):
# no GNU Nettle and no json-c, as the 32-bit and cross builds of the portability matrix must
# (Debian 12 cannot install their foreign -dev packages here).  VEC_LIBS links rtl_vectors/.
WITH_MANIFEST ?= 1
ifeq ($(WITH_MANIFEST),1)
VEC_LIBS     := $(shell $(PKG_CONFIG) --libs nettle json-c 2>/dev/null || echo -lnettle -ljson-c)
else
CPPFLAGS += -DEF_NO_MANIFEST
VEC_LIBS     :=
endif

.PHONY: all lib cli clean deps demo test check
all: lib cli host

# Compile rule shared by every fragment.
$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) $(EXPAT_CFLAGS) $(PNG_CFLAGS) -c $< -o $@

include fixed/module.mk
include model/module.mk
include rtl_vectors/module.mk
include util/module.mk
include dv/dpi/module.mk
include cli/module.mk
include proto/module.mk
include board/module.mk
include board/soc.mk
include host/module.mk
include python/module.mk
include tests/module.mk
include bench/module.mk

deps:
	@bash tools/install-deps.sh

clean:
	rm -rf build build-* out

-include $(shell find $(BUILD) -path '$(BUILD)/venv' -prune -o -type f -name '*.d' -print 2>/dev/null)

# The main job on the bundled default: the tiger at 640x480, 8/16/32 samples,
# and its cycle-level vectors at 8 samples, read back by `edgeflag check`.
DEMO_OUT ?= out/demo
demo:
	@bash tools/install-deps.sh
	@echo "edgeflag demo: building the library, edgeflag and edgeflag-host (make all, about 30 s the first time)"
	@$(MAKE) --no-print-directory -s all
	@# install-deps.sh's default mode installs libusb and libgpiod, so the host has its board links
	@$(EDGEFLAG_HOST) --version | sed -n 's/^  \(usb\|gpio\) */edgeflag demo: edgeflag-host \1: /p'
	@mkdir -p $(DEMO_OUT)
	@for n in 8 16 32; do \
	    $(EDGEFLAG) render tests/data/svg/tiger.svg -o $(DEMO_OUT)/tiger_$$n.png --samples $$n --size 640x480 || exit 1; \
	    echo "edgeflag demo: wrote $(DEMO_OUT)/tiger_$$n.png ($$n samples per pixel, 640x480)"; \
	done
	@$(EDGEFLAG) vectors tests/data/svg/tiger.svg -o $(DEMO_OUT)/vectors --samples 8 --size 640x480 --force 2>/dev/null
	@$(EDGEFLAG) vectors tests/data/svg/tiger.svg -o $(DEMO_OUT)/model_dumps --samples 8 --size 640x480 --force --dump --formats hex,bin >/dev/null
	@$(EDGEFLAG) check $(DEMO_OUT)/vectors $(DEMO_OUT)/model_dumps
	@echo "edgeflag demo: cycle-level vectors of the tiger (640x480, 8 samples) in $(DEMO_OUT)/vectors:"
	@echo "  cmd.stim.hex drives the pipeline; IFACE.expected.hex per interface (\$$readmemh), vectors.vcd,"
	@echo "  vectors.bin, manifest.json (docs/vectors.md). 'edgeflag check' compared them with a second run of the"
	@echo "  model written as a DUT's dumps ($(DEMO_OUT)/model_dumps, 'vectors --dump') and passed;"
	@echo "  check an RTL's dumps with: $(EDGEFLAG) check $(DEMO_OUT)/vectors DUMP_DIR (IFACE.actual.hex files)"
	@$(EDGEFLAG_HOST) verify $(DEMO_OUT)/vectors/vectors.bin --transport sim --results $(DEMO_OUT)/board
	@echo "edgeflag demo: streamed the tiger's command stream to the simulated board (edgeflag-host, docs/board.md)"
	@echo "  and checked every interface it returned ($(DEMO_OUT)/board/vectors.actual.bin) against the vectors;"
	@echo "  with a board attached: $(EDGEFLAG_HOST) list, then $(EDGEFLAG_HOST) verify $(DEMO_OUT)/vectors/vectors.bin"
