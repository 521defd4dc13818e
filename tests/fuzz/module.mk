# Fuzzing (docs/fuzzing.md).  libFuzzer targets built with clang and
# -fsanitize=fuzzer,address,undefined,integer in their own build directory:
#
#   make fuzz [FUZZ_SECONDS=60] [FUZZ_TARGETS="svg scene"]   fuzz each target (one core)
#   make test-fuzz-smoke                                      CI: 10 s of each target
#   make test-fuzz-replay                                     CI: every corpus and regression input once
#   make fuzz-merge                                           minimise the fuzzed corpora into tests/fuzz/corpus/
#
# The library, oracle and CLI objects of $(FUZZ_BUILD) carry coverage
# instrumentation (-fsanitize=fuzzer-no-link); only the targets link libFuzzer.
FUZZ_BUILD ?= build-fuzz
FUZZ_CC ?= clang
FUZZ_SECONDS ?= 60
FUZZ_SMOKE_SECONDS ?= 10
FUZZ_TARGETS ?= svg scene cli_args decimal render vec_read board host_results dut_file
FUZZ_ALL := svg scene cli_args decimal render vec_read board host_results dut_file
# ASan + UBSan, plus clang's integer checks with the intended wraps listed in
# tests/sanitize/integer.ignorelist (as in `make test-integer`).
FUZZ_SAN := -fsanitize=address,undefined,integer -fsanitize-ignorelist=tests/sanitize/integer.ignorelist \
            -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_BINS := $(FUZZ_ALL:%=$(BUILD)/fuzz/fuzz_%)
# The SVG reader's work limit (docs/limits.md) is 2^28 units, seconds of work
# in a normal build but minutes under the sanitizers: the fuzz build stops at
# 2^20, so every input stays well inside libFuzzer's 10 s timeout and the
# limit itself is reached often.
FUZZ_DEFS := -DEF_IN_MAX_WORK_LOG2=20u
# The vector readers stream files in chunks (64 KiB); the fuzz build reads
# them 7 bytes at a time, so every token and record crosses a chunk boundary.
FUZZ_DEFS += -DEF_VR_CHUNK=7u

.PHONY: fuzz fuzz-build fuzz-bins fuzz-merge test-fuzz-smoke test-fuzz-replay

# Built by a sub-make with BUILD=$(FUZZ_BUILD) so every object is instrumented.
fuzz-build:
	@bash tools/install-deps.sh test
	@# The flags and the ignorelist are compiled in: a change rebuilds everything.
	@if [ tests/sanitize/integer.ignorelist -nt $(FUZZ_BUILD)/.flags ] || \
	    [ "$$(cat $(FUZZ_BUILD)/.flags 2>/dev/null)" != "$(FUZZ_SAN) $(FUZZ_DEFS)" ]; then rm -rf $(FUZZ_BUILD); fi
	@mkdir -p $(FUZZ_BUILD) && echo "$(FUZZ_SAN) $(FUZZ_DEFS)" >$(FUZZ_BUILD)/.flags
	@$(MAKE) --no-print-directory BUILD=$(FUZZ_BUILD) CC=$(FUZZ_CC) OPT=-O1 \
	    EXTRA_CFLAGS="-fsanitize=fuzzer-no-link $(FUZZ_SAN) $(FUZZ_DEFS)" EXTRA_LDFLAGS="$(FUZZ_SAN)" fuzz-bins

fuzz-bins: $(FUZZ_BINS)

FUZZ_CLI_OBJ = $(filter-out $(BUILD)/cli/main.o,$(CLI_OBJ)) $(UTIL_OBJ) $(VEC_A)
$(BUILD)/fuzz/fuzz_render: $(ORACLE_OBJ)
$(BUILD)/fuzz/fuzz_cli_args: $(FUZZ_CLI_OBJ)
$(BUILD)/fuzz/fuzz_dut_file: $(BUILD)/cli/dut_file.o
$(BUILD)/fuzz/fuzz_vec_read: $(VEC_A)
$(BUILD)/fuzz/fuzz_board: $(HOST_BOARD_OBJ) $(VEC_A)
FUZZ_HOST_OBJ = $(BUILD)/host/host_link.o $(BUILD)/host/transport.o $(HOST_BOARD_OBJ)
$(BUILD)/fuzz/fuzz_host_results: $(FUZZ_HOST_OBJ) $(UTIL_OBJ) $(VEC_A)
$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_common.h $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests/fuzz -Itests/oracle -Icli -Iutil -Ihost -Iboard -Iproto $(CFLAGS_ALL) -fsanitize=fuzzer $< \
	    $(if $(filter fuzz_render,$(notdir $@)),$(ORACLE_OBJ)) \
	    $(if $(filter fuzz_cli_args,$(notdir $@)),$(FUZZ_CLI_OBJ)) \
	    $(if $(filter fuzz_dut_file,$(notdir $@)),$(BUILD)/cli/dut_file.o) \
	    $(if $(filter fuzz_vec_read,$(notdir $@)),$(VEC_A)) \
	    $(if $(filter fuzz_board,$(notdir $@)),$(HOST_BOARD_OBJ) $(VEC_A)) \
	    $(if $(filter fuzz_host_results,$(notdir $@)),$(FUZZ_HOST_OBJ) $(UTIL_OBJ) $(VEC_A)) \
	    -o $@ $(LDFLAGS_ALL) $(LIB_A) $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS) $(HOST_LIBS)

fuzz: fuzz-build
	@bash tests/fuzz/run.sh $(FUZZ_BUILD) fuzz $(FUZZ_SECONDS) $(FUZZ_TARGETS)

fuzz-merge: fuzz-build
	@bash tests/fuzz/run.sh $(FUZZ_BUILD) merge 0 $(FUZZ_TARGETS)

test-fuzz-smoke: fuzz-build
	@bash tests/fuzz/run.sh $(FUZZ_BUILD) smoke $(FUZZ_SMOKE_SECONDS) $(FUZZ_ALL)

test-fuzz-replay: fuzz-build
	@bash tests/fuzz/run.sh $(FUZZ_BUILD) replay 0 $(FUZZ_ALL)
