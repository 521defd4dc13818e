# Integer sanitizer stage (docs/testing.md): the unit tests, the oracle check
# (2,000 random scenes) and the CLI tests built with clang
# -fsanitize=undefined,integer and no recovery, so signed overflow, shifts past
# the width, division by zero, value-changing implicit conversions and any
# unsigned wrap that is not listed in tests/sanitize/integer.ignorelist (the
# functions that wrap on purpose, each with its reason) stop the test.
INT_BUILD ?= build-isan
INT_SAN := -fsanitize=undefined,integer -fsanitize-ignorelist=tests/sanitize/integer.ignorelist \
           -fno-sanitize-recover=all -fno-omit-frame-pointer

.PHONY: test-integer
test-integer:
	@bash tools/install-deps.sh test
	@# The ignorelist is compiled in: a changed list rebuilds everything.
	@if [ tests/sanitize/integer.ignorelist -nt $(INT_BUILD)/.ignorelist ]; then rm -rf $(INT_BUILD); fi
	@mkdir -p $(INT_BUILD) && cp tests/sanitize/integer.ignorelist $(INT_BUILD)/.ignorelist
	@UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 $(MAKE) --no-print-directory BUILD=$(INT_BUILD) CC=clang OPT=-O1 \
	    EXTRA_CFLAGS="$(INT_SAN)" EXTRA_LDFLAGS="-fsanitize=undefined,integer" ORACLE_SCENES=2000 \
	    test-unit test-oracle test-cli test-check
