# util/: what the two programs, `edgeflag` (cli/) and `edgeflag-host` (host/), both need, one layer
# below both (docs/source.md, "Layers"): the atomic file writer and mkdir -p (atomic_file.c), exact
# decimal numbers of a command line (parse.c), the image encoders (image_write.c: PNG, PAM, PGM) and
# the verifier's report files (check_files.c: --junit, --diff-image).  It may include the public
# headers, fixed/ and the vectors library, never cli/ or host/ (tests/layers checks it).
UTIL_SRC := $(wildcard util/*.c)
UTIL_OBJ := $(UTIL_SRC:%.c=$(BUILD)/%.o)
LAYER_INC_util := -Iinclude/edgeflag -Ifixed -Irtl_vectors -Iutil
$(UTIL_OBJ): EF_INC := $(LAYER_INC_util)
