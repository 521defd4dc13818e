# Same bits everywhere (tests/portability.sh, docs/testing.md): gcc and clang
# at -O0/-O3, 32-bit x86, aarch64 and big-endian s390x under qemu-user, all
# byte-identical on the shared SVGs and the generated regressions.
#   make portability        the whole matrix (11 builds)
#   make test-portability   make test's slice: gcc -O0, clang -O3, no-vector, gcc -m32, foreign -O3
.PHONY: portability test-portability
portability:
	@bash tests/portability.sh $(EF_SVG)
test-portability:
	@PORTABILITY_SLICE=1 bash tests/portability.sh $(EF_SVG)
