# bench/: efbench, edgeflag side by side with AGG, Cairo, FreeType and stb_truetype
# on the paper's protocol (bench/README.md).  Never part of `all` or `test-build`:
# it builds only through `make bench` / `make bench-quick`, which first install
# its Debian packages (tools/install-deps.sh bench).
#
#   make bench [BENCH_FRAMES=200] [BENCH_REPEAT=3] [BENCH_SIZES=320x240,640x480,1280x960]
#   make bench-quick          (smoke test: a few frames, one size, a few scenes; no timing asserted)
CXX ?= g++
BENCH_FRAMES ?= 200
BENCH_REPEAT ?= 3
BENCH_CHUNK ?= 10
BENCH_SIZES ?= 320x240,640x480,1280x960
# ef8t..ef16trgb: the options of docs/spec.md 10 (tent; RGB offsets), for their cost against the box
BENCH_RENDERERS ?= agg,cairo,cairo-noaa,freetype,stb,ef8,ef16,ef32,ef8t,ef16t,ef32t,ef16rgb,ef16trgb
BENCH_OUT ?= bench/results
BENCH_QUALITY_SIZE ?= 640x480
BENCH_QUALITY_FRAMES ?= 0,50,100,150

EFBENCH := $(BUILD)/bench/efbench
BENCH_SCENES := $(BUILD)/bench/scenes
BENCH_SRC_C := $(wildcard bench/*.c)
BENCH_SRC_CXX := $(wildcard bench/*.cpp)
BENCH_OBJ := $(BENCH_SRC_C:%.c=$(BUILD)/%.o) $(BENCH_SRC_CXX:%.cpp=$(BUILD)/%.o)
# Evaluated only when a bench rule runs (the packages may not be installed yet).
# The peers' headers are system headers: their warnings are not ours.
BENCH_PKGS := cairo freetype2 libagg
BENCH_PKG_CFLAGS = $(patsubst -I%,-isystem %,$(shell $(PKG_CONFIG) --cflags $(BENCH_PKGS)))
BENCH_PKG_LIBS = $(shell $(PKG_CONFIG) --libs $(BENCH_PKGS))

# Layer: the public headers and its own, as a user's program sees the library (tests/layers).
LAYER_INC_bench := -Iinclude/edgeflag -Ibench
$(BUILD)/bench/%.o: EF_INC := $(LAYER_INC_bench)
$(BUILD)/bench/%.o: bench/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Ibench $(CFLAGS_ALL) $(BENCH_PKG_CFLAGS) -c $< -o $@

$(BUILD)/bench/%.o: bench/%.cpp
	@mkdir -p $(dir $@)
	$(CXX) -std=c++11 -Wall -Wextra -Werror $(OPT) -g -MMD -MP -Ibench -Iinclude/edgeflag $(BENCH_PKG_CFLAGS) -c $< -o $@

$(EFBENCH): $(BENCH_OBJ) $(LIB_A)
	$(CXX) $(LDFLAGS_ALL) -o $@ $(BENCH_OBJ) $(LIB_A) $(EXPAT_LIBS) $(BENCH_PKG_LIBS) -lm

$(BENCH_SCENES)/.stamp: bench/paper_scenes.py
	@mkdir -p $(BENCH_SCENES)
	python3 $< $(BENCH_SCENES)
	@touch $@

SVGDIR := $(EF_SVG)
BENCH_REAL := tiger lion burning_car human_head antiloop2 lorem_ipsum_compound lorem_ipsum_separate flag_tm
BENCH_PAPER := star siemens_star circles random checkers square_basic square_many_edges square_long_edges \
               squares_overdraw squares_small
# Real-life scenes under both rules (every shape's rule overridden, so all renderers fill alike);
# the paper's tests come as one file per rule.
BENCH_CASES = $(foreach s,$(BENCH_REAL),$(SVGDIR)/$(s).svg@nonzero $(SVGDIR)/$(s).svg@evenodd) \
              text@nonzero text@evenodd \
              $(foreach s,$(BENCH_PAPER),$(BENCH_SCENES)/paper_$(s)_nonzero.txt $(BENCH_SCENES)/paper_$(s)_evenodd.txt)
BENCH_QUALITY_CASES = $(BENCH_SCENES)/star64.txt $(SVGDIR)/lion.svg $(SVGDIR)/tiger.svg text@nonzero text@nonzero+white

.PHONY: bench bench-run bench-quick bench-quick-run bench-build deps-bench
deps-bench:
	@bash tools/install-deps.sh bench

bench-build: $(EFBENCH)

bench: deps-bench
	@$(MAKE) --no-print-directory bench-run

bench-run: $(EFBENCH) $(BENCH_SCENES)/.stamp
	@mkdir -p $(BENCH_OUT)
	$(EFBENCH) run --sizes $(BENCH_SIZES) --frames $(BENCH_FRAMES) --repeat $(BENCH_REPEAT) --chunk $(BENCH_CHUNK) \
	    --renderers $(BENCH_RENDERERS) $(BENCH_CASES) > $(BENCH_OUT)/bench.csv.tmp
	mv $(BENCH_OUT)/bench.csv.tmp $(BENCH_OUT)/bench.csv
	$(EFBENCH) quality --size $(BENCH_QUALITY_SIZE) --frame-list $(BENCH_QUALITY_FRAMES) --pictures $(BENCH_OUT) \
	    $(BENCH_QUALITY_CASES) > $(BENCH_OUT)/quality.csv.tmp
	mv $(BENCH_OUT)/quality.csv.tmp $(BENCH_OUT)/quality.csv
	bash bench/machine.sh $(EFBENCH) > $(BENCH_OUT)/machine.txt
	$(EFBENCH) report --quality $(BENCH_OUT)/quality.csv --machine $(BENCH_OUT)/machine.txt --outdir $(BENCH_OUT) \
	    --results-md bench/RESULTS.md \
	    --command "make bench BENCH_FRAMES=$(BENCH_FRAMES) BENCH_REPEAT=$(BENCH_REPEAT) BENCH_SIZES=$(BENCH_SIZES)" \
	    $(BENCH_OUT)/bench.csv
	@for f in $(BENCH_OUT)/fig6_*.gp; do gnuplot $$f || exit 1; done
	@echo "bench: wrote bench/RESULTS.md and $(BENCH_OUT)/ (bench.csv, bench.json, quality.*, fig6_*.png, fig7_*.png)"

# Smoke test for CI: every step once on a tiny workload, into $(BUILD)/bench/quick.
# It checks that the bench builds and runs, never how fast anything is.
BENCH_QUICK_OUT := $(BUILD)/bench/quick
BENCH_QUICK_CASES = $(SVGDIR)/tiger.svg@nonzero text@evenodd $(BENCH_SCENES)/paper_star_evenodd.txt \
                    $(BENCH_SCENES)/paper_circles_nonzero.txt
bench-quick: deps-bench
	@$(MAKE) --no-print-directory bench-quick-run

bench-quick-run: $(EFBENCH) $(BENCH_SCENES)/.stamp
	@mkdir -p $(BENCH_QUICK_OUT)
	$(EFBENCH) run --sizes 320x240 --frames 3 --repeat 1 --chunk 1 $(BENCH_QUICK_CASES) > $(BENCH_QUICK_OUT)/bench.csv
	$(EFBENCH) quality --size 160x120 --frame-list 0 --pictures $(BENCH_QUICK_OUT) $(BENCH_SCENES)/star64.txt \
	    text@evenodd+white > $(BENCH_QUICK_OUT)/quality.csv
	bash bench/machine.sh $(EFBENCH) > $(BENCH_QUICK_OUT)/machine.txt
	$(EFBENCH) report --quality $(BENCH_QUICK_OUT)/quality.csv --machine $(BENCH_QUICK_OUT)/machine.txt \
	    --outdir $(BENCH_QUICK_OUT) --results-md $(BENCH_QUICK_OUT)/RESULTS.md $(BENCH_QUICK_OUT)/bench.csv
	@for f in $(BENCH_QUICK_OUT)/fig6_*.gp; do gnuplot $$f || exit 1; done
	@test -s $(BENCH_QUICK_OUT)/fig6_320x240.png && test -s $(BENCH_QUICK_OUT)/fig7_star64.png
	@grep -q '^text_dejavu_white,evenodd,' $(BENCH_QUICK_OUT)/quality.csv && test -s $(BENCH_QUICK_OUT)/fig7_text_dejavu_white.png
	@echo "bench-quick: ok ($$(grep -c , $(BENCH_QUICK_OUT)/bench.csv) rows; timings not checked)"
