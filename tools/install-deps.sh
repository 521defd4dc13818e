#!/usr/bin/env bash
# Installs what edgeflag needs from Debian 12's packages, only when missing.
#   tools/install-deps.sh          build + demo: compiler, expat, libpng, libusb and libgpiod (the USB and
#                                  GPIO transports of the edgeflag-host that `make demo` builds)
#   tools/install-deps.sh test     + cmocka, clang, 32-bit multilib, Icarus, Verilator, GTKWave (the
#                                  test suite), and the
#                                  aarch64/s390x cross C libraries and qemu-user (best effort)
#                                  lcov (genhtml: make rtl-coverage's report),
#   tools/install-deps.sh portability   the same (what `make portability` needs)
#   tools/install-deps.sh bench    + the peers and plotting for `make bench` (bench/README.md)
#   tools/install-deps.sh synth    + Yosys, nextpnr-ice40 and icestorm for `make rtl-synth` (docs/synthesis.md)
#   tools/install-deps.sh venv     + python3-venv for tools/install-venv.sh (PyPI tools in build/venv)
#   tools/install-deps.sh board    + the RISC-V cross compiler, picolibc, Verilator and python3-venv for the
#                                  ULX3S board's firmware, SoC and simulation (docs/board-ulx3s.md);
#                                  the FPGA tools and LiteX come from PyPI (tools/install-venv.sh fpga soc)
#   tools/install-deps.sh farm     + GNU parallel, Slurm and munge for `make farm-test` (docs/regress.md)
#   tools/install-deps.sh loaded   + stress-ng for `make test-host-loaded` (docs/testing.md)
set -euo pipefail

pkgs=(gcc make pkg-config libexpat1-dev libpng-dev nettle-dev libjson-c-dev zlib1g-dev)
# edgeflag-host's USB and GPIO transports: without them it builds, but says "built without ..."
pkgs+=(libusb-1.0-0-dev libgpiod-dev)
optional=()
if [ "${1:-}" = test ] || [ "${1:-}" = portability ]; then
    pkgs+=(libcmocka-dev clang gcc-multilib libclang-rt-14-dev)
    # make test-format: the house style is stated for Debian 12's clang-format (14)
    pkgs+=(clang-format)
    # make test-shellcheck: every shell script of the tree (docs/source.md "Formatting")
    pkgs+=(shellcheck)
    # the vectors' real readers: Icarus and Verilator ($readmemh testbenches), GTKWave's
    # vcd2fst/fst2vcd (VCD round trip), xmllint (JUnit XML well-formedness)
    pkgs+=(iverilog verilator gtkwave libxml2-utils)
    # the regression flow's shards run under GNU parallel in make test (docs/regress.md)
    pkgs+=(parallel)
    # edgeflag-host's USB transport and its emulated board (test-host-usb, docs/board-usb.md)
    pkgs+=(libusb-1.0-0-dev umockdev libumockdev-dev)
    # the GPIO transport's tests (docs/board-gpio.md 8): libgpiod 1.6, umockdev's emulated chip, and
    # meson + ninja to build libgpiod 2.3 (the v2 API) into build/ from ../shared when present
    pkgs+=(libgpiod-dev libumockdev-dev umockdev meson ninja-build)
    # tests/host/pyboard.py: the socket transport's board written from docs/board.md (test-host-socket)
    pkgs+=(python3)
    # test-dpi runs the DPI-C lockstep bench once under valgrind's memcheck (docs/dpi.md)
    pkgs+=(valgrind)
    # test-python and test-cocotb (docs/python.md): the venv, and libpython's shared library, which
    # cocotb embeds in the simulator (Debian's python3 binary does not need it, so it is not there)
    pkgs+=(python3-venv python3-pip libpython3-dev)
    # make rtl-coverage and its slice in make test: verilator_coverage's lcov output to HTML (genhtml)
    pkgs+=(lcov)
    # `make portability` builds static aarch64 and s390x (big-endian) programs
    # with clang --target and runs them under qemu-user.  gcc-aarch64-linux-gnu
    # cannot be installed beside gcc-multilib in Debian 12; these can.  Best
    # effort: without them that stage skips those targets and says why.
    optional+=(qemu-user-static libc6-dev-arm64-cross libgcc-12-dev-arm64-cross binutils-aarch64-linux-gnu
               libc6-dev-s390x-cross libgcc-12-dev-s390x-cross binutils-s390x-linux-gnu)
fi
if [ "${1:-}" = farm ]; then
    pkgs+=(parallel libxml2-utils slurm-wlm munge)
fi
if [ "${1:-}" = loaded ]; then
    # make test-host-loaded: the host stages again and again with both cores kept busy
    pkgs+=(stress-ng)
fi
if [ "${1:-}" = synth ]; then
    # make rtl-synth (docs/synthesis.md): Yosys synth_ice40, nextpnr-ice40 and its chip database
    pkgs+=(yosys nextpnr-ice40 fpga-icestorm)
fi
if [ "${1:-}" = board ]; then
    # board/firmware (ef_board.c as the SoC's firmware), board/sim (the SoC under Verilator), the venv
    pkgs+=(gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf verilator g++ python3-venv python3-pip)
fi
if [ "${1:-}" = venv ]; then
    # tools/install-venv.sh: Python's venv module and pip (the PyPI tools live in build/venv)
    pkgs+=(python3-venv python3-pip)
fi
if [ "${1:-}" = bench ]; then
    pkgs+=(g++ libagg-dev libcairo2-dev libfreetype-dev libstb-dev fonts-dejavu-core gnuplot-nox python3)
fi

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=() opt_missing=()
for p in "${pkgs[@]}"; do installed "$p" || missing+=("$p"); done
for p in "${optional[@]}"; do installed "$p" || opt_missing+=("$p"); done
[ ${#missing[@]} -eq 0 ] && [ ${#opt_missing[@]} -eq 0 ] && exit 0

echo "edgeflag: installing from Debian's packages: ${missing[*]} ${opt_missing[*]}" >&2
SUDO=
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
        SUDO=sudo
    else
        echo "edgeflag: not root and no sudo; please install: ${missing[*]} ${opt_missing[*]}" >&2
        [ ${#missing[@]} -eq 0 ] && exit 0
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
# A stale or empty package list makes apt-get install fail: refresh it once.
$SUDO apt-get update -qq
if [ ${#missing[@]} -gt 0 ]; then
    $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ ${#opt_missing[@]} -gt 0 ] &&
   ! $SUDO apt-get install -y -qq --no-install-recommends "${opt_missing[@]}" >/dev/null; then
    echo "edgeflag: could not install ${opt_missing[*]}; make portability will skip the foreign targets" >&2
fi
