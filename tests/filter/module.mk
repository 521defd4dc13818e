# Issue 16: the 2x2-pixel tent filter and per-channel sample offsets (docs/spec.md section 10).
#   make test-filter   the model against the slow model (tests/oracle/oracle_filter.c) on every
#                      shared SVG at 8/16/32 samples (two settings that together exercise every part)
#                      and on FILTER_SCENES random polygons (all five settings in turn); the exact-area
#                      check of the tent; and the default-off byte identity
#   make filter-full   every setting on every shared SVG and 10,000 random polygons (minutes)
FILTER_CHECK := $(BUILD)/tests/filter_check
FILTER_SCENES ?= 2000
FILTER_CONFIGS ?= tent-rgb,box-bgr
$(FILTER_CHECK): tests/filter/filter_check.c $(ORACLE_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests/oracle $(CFLAGS_ALL) $< $(ORACLE_OBJ) -o $@ $(LDFLAGS_ALL) $(TEST_LIBS)

.PHONY: test-filter filter-full
test-filter: $(FILTER_CHECK) $(AREA_CHECK)
	$(FILTER_CHECK) --shared $(EF_SVG) --configs $(FILTER_CONFIGS)
	$(FILTER_CHECK) --random $(FILTER_SCENES) --seed $(ORACLE_SEED)
	$(AREA_CHECK) --filter

filter-full: $(FILTER_CHECK)
	$(FILTER_CHECK) --shared $(EF_SVG) --random 10000 --seed $(ORACLE_SEED)
