# edgeflag-host against the simulated board (docs/board.md): tests/host/run.sh.
#   make test-host   the plain runs, the fault matrix with --resume, wrong use, bench
.PHONY: test-host
test-host: cli host
	@bash tests/host/run.sh $(BUILD)
# The host stages 5 times in a row with every core kept busy by stress-ng (docs/testing.md,
# tests/host/loaded.sh): not in `make test`; tools/install-deps.sh loaded installs stress-ng.
.PHONY: test-host-loaded
test-host-loaded: cli host
	@bash tests/host/loaded.sh
