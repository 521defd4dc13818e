# The layering is enforced by include paths (docs/source.md, "Layers"): each C folder (the libraries,
# util/, cli/, proto/, board/, host/, dv/dpi/, bench/) compiles with its own LAYER_INC_<folder>; tests/
# keep the wide EF_INC on purpose (a unit test reaches the internals it tests).  make test-layers (run by test-build) compiles a
# one-line probe `#include "H"` with each layer's flags: every arrow in tests/layers/arrows.tsv must
# compile or fail as the table says.
.PHONY: test-layers layers-print
layers-print:
	@echo "fixed|$(LAYER_INC_fixed)"
	@echo "model|$(LAYER_INC_model)"
	@echo "input|$(LAYER_INC_input)"
	@echo "rtl_vectors|$(LAYER_INC_rtl_vectors)"
	@echo "cli|$(LAYER_INC_cli)"
	@echo "proto|$(LAYER_INC_proto)"
	@echo "board|$(LAYER_INC_board)"
	@echo "util|$(LAYER_INC_util)"
	@echo "host|$(LAYER_INC_host)"
	@echo "dpi|$(LAYER_INC_dpi)"
	@echo "bench|$(LAYER_INC_bench)"
	@echo "firmware|$(LAYER_INC_firmware)"
	@echo "python|$(LAYER_INC_python)"
	@echo "tests|$(EF_INC)"

test-layers: $(CORE_STAGED_H)
	@bash tests/layers/run.sh $(BUILD)
