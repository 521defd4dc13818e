# The bad-input catalogue and atomic-output tests (tests/bad/README.md).
#   make test-bad      every CATALOGUE.tsv entry through `edgeflag render`, then
#                      interrupted and disk-full writes (tests/bad/atomic.sh)
.PHONY: test-bad
test-bad: cli $(BUILD)/tests/tools/load_check $(BUILD)/tests/check/vec_load
	@bash tests/bad/run.sh $(BUILD)
	@bash tests/bad/atomic.sh $(BUILD)
