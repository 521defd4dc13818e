# The farm flow (docs/regress.md): tools/regress/ef-regress-shard and ef-regress-merge.
#   make test-regress   level 1 in 4 shards under GNU parallel, merged; killed and missing shards,
#                       wrong, silent and hanging DUTs, shards that do not belong together
#   make farm-test      the same flow as a Slurm job array on a single-node Slurm that
#                       tools/slurm-local.sh starts and stops (not part of make test)
.PHONY: test-regress farm-test
test-regress: cli
	@bash tests/regress/run.sh $(BUILD)

farm-test: cli
	@bash tools/install-deps.sh farm
	@bash tests/regress/farm.sh $(BUILD)
