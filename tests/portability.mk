# Same bits everywhere (tests/portability.sh, docs/testing.md): gcc and clang
# at -O0/-O3, 32-bit x86, aarch64 and big-endian s390x under qemu-user, all
# byte-identical on the shared SVGs and the generated regressions.
.PHONY: portability test-portability
portability test-portability:
	@bash tests/portability.sh $(EF_SVG)
