# Issue 27: how much the tests cover, and whether they would notice.
#   make test-coverage   `edgeflag coverage` (functional cover points of dv/coverage/points.tsv):
#                        its own checks, then the shared SVGs + gen level 1 must hit every point
#   make test-fusesoc    ef_raster.core: fusesoc lint and the Icarus sim target (build/venv)
#   make test-rtl-mutants  the slice in make test: the RTL mutants of tests/mutants/slice_keys.tsv
#                        under Icarus on rtl-test's small cases (<= 4,000 cycles) and tb_err, each
#                        with its verdict; then the score check must fail without an equivalent line
#   make test-rtl-cov    a slice of the code coverage (Verilator --coverage at NS 8 over a third of
#                        rtl-test's cases, the per-module summary; a Verilator build: not in make test)
#   make rtl-coverage    the code coverage of both configurations (reference and fast: rtl-test's
#                        cases, the directed ones, the level-1 regression at three NS x rule settings
#                        a case each, cases of at most 250,000 cycles: the README's run; override with
#                        EF_COV_REGRESS, EF_COV_REG_MAXCYC), HTML in build/rtl-coverage/html; targets required
#   make rtl-mutants     the mutation run over rtl/ (EF_MUT_SAMPLE, EF_MUT_SEED: see the script)
#   make c-mutants       mutants of board/ef_board.c and host/host_link.c against make test-host
.PHONY: test-coverage test-fusesoc test-rtl-cov test-rtl-mutants rtl-coverage rtl-mutants c-mutants
test-coverage: cli
	@bash tests/cov/run.sh $(BUILD)
test-fusesoc: cli
	@bash tests/fusesoc/run.sh $(BUILD)
test-rtl-cov: cli
	@EF_COV_NS=8 EF_COV_REGRESS=0 EF_COV_SLICE_ONLY=3 bash tests/cov/rtl-coverage.sh $(BUILD) $(BUILD)/rtl-coverage-slice
test-rtl-mutants: cli
	@bash tests/mutants/rtl-mutants-slice.sh $(BUILD)
rtl-coverage: cli
	@EF_COV_REQUIRE=1 EF_COV_REGRESS=$${EF_COV_REGRESS:-3} EF_COV_REG_MAXCYC=$${EF_COV_REG_MAXCYC:-250000} \
	    bash tests/cov/rtl-coverage.sh $(BUILD)
rtl-mutants: cli
	@bash tests/mutants/rtl-mutants.sh $(BUILD)
c-mutants: cli host
	@bash tests/mutants/c-mutants.sh $(BUILD)
