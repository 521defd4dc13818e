# Tests.  `make test` runs every stage through tests/run.sh, which prints a
# final "N passed, M failed" line; the stages are also targets of their own.
UNIT_SRC  := $(wildcard tests/unit/test_*.c)
UNIT_BIN  := $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)
ORACLE_SRC := $(filter-out tests/oracle/oracle_selftest.c,$(wildcard tests/oracle/*.c))
ORACLE_OBJ := $(ORACLE_SRC:%.c=$(BUILD)/%.o)
ORACLE_CHECK := $(BUILD)/tests/oracle_check
ORACLE_SELFTEST := $(BUILD)/tests/oracle_selftest
TEST_LIBS = $(LIB_A) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS) $(CMOCKA_LIBS)

.PHONY: test test-build test-unit test-oracle test-mutants test-cli test-bitexact test-sanitize deps-test

deps-test:
	@bash tools/install-deps.sh test

$(BUILD)/tests/test_%: tests/unit/test_%.c $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests $(CFLAGS_ALL) $< -o $@ $(LDFLAGS_ALL) $(TEST_LIBS) -lm

$(ORACLE_SELFTEST): tests/oracle/oracle_selftest.c $(ORACLE_OBJ)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -Itests/oracle $^ -o $@ $(LDFLAGS_ALL)

$(ORACLE_CHECK): tests/oracle_check.c $(ORACLE_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests/oracle $(CFLAGS_ALL) $< $(ORACLE_OBJ) -o $@ $(LDFLAGS_ALL) $(TEST_LIBS)

TOOL_SRC := $(wildcard tests/tools/*.c)
TOOL_BIN := $(TOOL_SRC:tests/tools/%.c=$(BUILD)/tests/tools/%)
$(BUILD)/tests/tools/%: tests/tools/%.c $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) $< -o $@ $(LDFLAGS_ALL) $(LIB_A) $(EXPAT_LIBS)

AREA_CHECK := $(BUILD)/tests/area_check
$(AREA_CHECK): tests/area_check.c $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS_ALL) $< -o $@ $(LDFLAGS_ALL) $(LIB_A) $(EXPAT_LIBS) -lm

test-build: lib cli $(UNIT_BIN) $(ORACLE_CHECK) $(ORACLE_SELFTEST) $(TOOL_BIN) $(AREA_CHECK)
	bash tests/install_check.sh $(BUILD)
	@bash tests/layers/run.sh $(BUILD)

# The house style (.clang-format, docs/source.md "Formatting"): `make format` applies it.
.PHONY: test-format format test-shellcheck
test-format:
	@bash tools/format.sh --check
# shellcheck over every shell script (.shellcheckrc): no finding allowed.
test-shellcheck:
	@bash tools/shellcheck.sh
format:
	@bash tools/format.sh

test-unit: $(UNIT_BIN)
	@set -e; for t in $(UNIT_BIN); do echo "== $$t"; EF_SVG=$(EF_SVG) $$t; done

ORACLE_SCENES ?= 10000
ORACLE_SEED ?= 20070101
test-oracle: $(ORACLE_CHECK) $(ORACLE_SELFTEST) $(AREA_CHECK)
	$(ORACLE_SELFTEST)
	$(AREA_CHECK)
	$(ORACLE_CHECK) --shared $(EF_SVG) --random $(ORACLE_SCENES) --seed $(ORACLE_SEED)
	$(ORACLE_CHECK) --shared tests/data/mask_rows

test-mutants:
	@bash tests/mutants.sh

test-cli: cli
	@bash tests/cli/run.sh $(BUILD)

test-bitexact:
	@bash tests/bitexact.sh $(EF_SVG)

test-sanitize:
	@$(MAKE) --no-print-directory BUILD=build-san OPT=-O1 \
	    EXTRA_CFLAGS="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
	    EXTRA_LDFLAGS="-fsanitize=address,undefined" ORACLE_SCENES=2000 test-unit test-oracle test-cli test-check

test: deps-test
	@bash tests/run.sh

# Robustness (issue 3): fuzzing, the bad-input catalogue, integer sanitizer, portability.
include tests/fuzz/module.mk
include tests/bad/module.mk
include tests/vectors/module.mk
include tests/check/module.mk
include tests/host/gpio.mk
include tests/rtl/module.mk
include tests/regress/module.mk
include tests/host/module.mk
include tests/host/socket.mk
include tests/host/serial.mk
include tests/sanitize/module.mk
include tests/portability.mk
include tests/filter/module.mk
include tests/layers/module.mk
include tests/cov/module.mk
