# edgeflag-host against the simulated board (docs/board.md): tests/host/run.sh.
#   make test-host   the plain runs, the fault matrix with --resume, wrong use, bench
.PHONY: test-host
test-host: cli host
	@bash tests/host/run.sh $(BUILD)
