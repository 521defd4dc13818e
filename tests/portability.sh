#!/usr/bin/env bash
# Same bits everywhere (`make portability`).  Builds edgeflag
#   - natively with gcc and clang at -O0 and -O3, and with gcc -O2
#     -DEF_NO_VECTOR (the word-at-a-time filler that builds without GCC's
#     vector extension take, and the plotter without its SSE2 whole-row
#     path, as on every non-x86-64 target),
#   - as 32-bit x86 programs (gcc and clang -m32 -O2),
#   - for aarch64 (little-endian) and s390x (big-endian) with clang
#     --target=... -static against Debian's cross C libraries, at -O0 and -O3,
#     run under qemu-user (qemu-aarch64-static, qemu-s390x-static),
# and demands byte-identical PAM images (SHA-256) from every build for
#   - the exact device-space dump (tests/tools/scene_dump) of every shared SVG
#     at 8/16/32 samples under the file's rules, even-odd and non-zero;
#   - a generated regression scene (tests/tools/regress_scene: polygons far
#     outside the canvas, winding wrap, the coordinate extremes, long shallow
#     edges, sub-pixel triangles, every kind of alpha), same 9 configurations;
#   - when the command exists, the seeded regression set of `edgeflag gen`
#     (level 1), each case at one of the 9 configurations in turn;
#   - the cycle-level vectors (`edgeflag vectors`: every hex file and the
#     binary stream) of the regression scene at 3 configurations (8 file,
#     16 evenodd, 32 nonzero) and of two shared SVG dumps;
# and runs the fixed-point unit tests (tests/unit/test_fixed.c, without
# cmocka) as aarch64 and s390x programs.  The 32-bit and foreign builds are
# WITH_SVG=0 WITH_PNG=0 WITH_MANIFEST=0 (no target expat, libpng, Nettle) and render the dumps; the
# native builds render the SVGs too, which must agree with their dumps.
#
# A foreign architecture whose tools are missing and cannot be installed
# (tools/install-deps.sh portability) is skipped with a loud reason, never
# silently; everything that did run must agree.
#   usage: tests/portability.sh SVG_DIR
set -u
cd "$(dirname "$0")/.." || exit 1
svgdir=${1:?usage: tests/portability.sh SVG_DIR}
out=build/portability
rm -rf "$out"; mkdir -p "$out"
JOBS=${PORTABILITY_JOBS:-2}
pass=0 fail=0 skips=()
die() { echo "portability: $*"; echo "$pass passed, $((fail + 1)) failed"; exit 1; }

bash tools/install-deps.sh portability >"$out/install.log" 2>&1 ||
    echo "portability: tools/install-deps.sh portability failed (see $out/install.log); missing targets are skipped"

cross_ok() {   # triple qemu: the cross C library, a linker and qemu are present
    [ -e "/usr/$1/lib/crt1.o" ] && [ -e "/usr/$1/include/stdio.h" ] && command -v "$1-ld" >/dev/null 2>&1 &&
        command -v "$2" >/dev/null 2>&1 && command -v clang >/dev/null 2>&1
}
elf() { od -An -tu1 -j "$2" -N "$3" "$1" | tr -s ' ' | sed 's/^ //; s/ $//'; }

# build NAME RUNNER "CLASS DATA MACHINE" MAKE-ARGS...: builds the command,
# checks its ELF header (class 1/2 = 32/64-bit, data 1/2 = little/big-endian,
# machine 62 x86-64, 3 i386, 183 aarch64, 22 s390) and adds it to the list.
names=() runners=() natives=()
build() {
    local name=$1 runner=$2 want=$3
    shift 3
    if ! make --no-print-directory -s -j"$JOBS" BUILD="$name" "$@" cli >"$out/$name.build.log" 2>&1; then
        echo "portability: build $name failed:"; tail -n 15 "$out/$name.build.log"; fail=$((fail + 1)); return
    fi
    local cls data m0 m1 mach
    cls=$(elf "$name/edgeflag" 4 1) data=$(elf "$name/edgeflag" 5 1)
    read -r m0 m1 <<<"$(elf "$name/edgeflag" 18 2)"
    if [ "$data" = 2 ]; then mach=$((m0 * 256 + m1)); else mach=$((m1 * 256 + m0)); fi
    if [ "$cls $data $mach" != "$want" ]; then
        echo "portability: $name/edgeflag is ELF class/data/machine '$cls $data $mach', want '$want'"
        fail=$((fail + 1)); return
    fi
    names+=("$name"); runners+=("$runner")
    case " $* " in *" WITH_SVG=0 "*) ;; *) [ -z "$runner" ] && natives+=("$name") ;; esac
}
# PORTABILITY_SLICE=1 (make test's test-portability): one build of each kind that can differ —
# gcc -O0, clang -O3, the word-at-a-time filler, 32-bit, and each foreign CPU at -O3 — the rest
# of the matrix in `make portability`.  A build left out is named, never silent.
slice=${PORTABILITY_SLICE:-0}
full() { if [ "$slice" = 1 ]; then skips+=("$1: not in the make test slice (make portability builds it)"); return 1; fi; }
build build-bx-gcc-O0 "" "2 1 62" CC=gcc OPT=-O0
full gcc-O3 && build build-bx-gcc-O3 "" "2 1 62" CC=gcc OPT=-O3
full clang-O0 && build build-bx-clang-O0 "" "2 1 62" CC=clang OPT=-O0
build build-bx-clang-O3 "" "2 1 62" CC=clang OPT=-O3
build build-bx-gcc-O2-novector "" "2 1 62" CC=gcc OPT=-O2 EXTRA_CFLAGS=-DEF_NO_VECTOR
build build-bx-gcc-O2-m32 "" "1 1 3" CC=gcc OPT=-O2 EXTRA_CFLAGS=-m32 EXTRA_LDFLAGS=-m32 WITH_SVG=0 WITH_PNG=0 WITH_MANIFEST=0
full clang-O2-m32 && build build-bx-clang-O2-m32 "" "1 1 3" CC=clang OPT=-O2 EXTRA_CFLAGS=-m32 EXTRA_LDFLAGS=-m32 WITH_SVG=0 WITH_PNG=0 WITH_MANIFEST=0
foreign=()
for arch in "aarch64 aarch64-linux-gnu qemu-aarch64-static 183 1" "s390x s390x-linux-gnu qemu-s390x-static 22 2"; do
    read -r a triple qemu mach data <<<"$arch"
    if ! cross_ok "$triple" "$qemu"; then
        skips+=("$a: cross tools missing (want /usr/$triple/lib/crt1.o from libc6-dev-*-cross, $triple-ld from binutils-$triple, $qemu, clang)")
        continue
    fi
    foreign+=("$triple $qemu")
    for opt in O0 O3; do
        [ "$opt" = O0 ] && ! full "$a-O0" && continue
        build "build-px-$a-$opt" "$qemu" "2 $data $mach" "CC=clang --target=$triple" OPT=-$opt EXTRA_LDFLAGS=-static \
            WITH_SVG=0 WITH_PNG=0 WITH_MANIFEST=0
    done
done
[ ${#names[@]} -gt 0 ] || die "nothing built"
ref=${names[0]}
make --no-print-directory -s BUILD="$ref" "$ref/tests/tools/scene_dump" "$ref/tests/tools/regress_scene" \
    >>"$out/$ref.build.log" 2>&1 || die "scene_dump / regress_scene build failed"

# ------------------------------------------- fixed-point tests on foreign CPUs
for f in "${foreign[@]}"; do
    read -r triple qemu <<<"$f"
    t=$out/test_fixed.$triple
    if clang --target="$triple" -static -std=c11 -Wall -Wextra -Werror -O2 -DEF_TEST_NO_CMOCKA -Ifixed -Imodel \
            tests/unit/test_fixed.c fixed/*.c -lm -o "$t" >"$t.log" 2>&1 && "$qemu" "$t" >>"$t.log" 2>&1; then
        echo "portability: fixed-point unit tests pass as $triple programs ($(grep -c 'OK \]' "$t.log") tests, $qemu)"
    else
        echo "portability: fixed-point unit tests FAIL as $triple programs:"; tail -n 15 "$t.log"; fail=$((fail + 1))
    fi
done

# ------------------------------------------------------------------ inputs
jobs=()   # "label|file|options" ; svg jobs only for native full builds
"$ref/tests/tools/regress_scene" >"$out/regress.scene" || die "regress_scene failed"
cfgs=()
for n in 8 16 32; do for rule in file evenodd nonzero; do cfgs+=("$n $rule"); done; done
# the scenes written from the shared SVGs, in name order (not the generated regression)
scenes() { local f; for f in "$out"/*.scene; do [ "$f" = "$out/regress.scene" ] || echo "$f"; done; }
opts_of() { local n=${1% *} rule=${1#* }; printf -- '--samples %s' "$n"; [ "$rule" != file ] && printf -- ' --rule %s' "$rule"; }
nsvg=0
for svg in "$svgdir"/*.svg; do
    base=$(basename "$svg" .svg)
    "$ref/tests/tools/scene_dump" "$svg" >"$out/$base.scene" 2>>"$out/dump.log" || die "cannot dump $svg"
    nsvg=$((nsvg + 1))
    for c in "${cfgs[@]}"; do
        o=$(opts_of "$c"); jobs+=("$base ($c)|$out/$base.scene|$o|$svg")
    done
done
for c in "${cfgs[@]}"; do o=$(opts_of "$c"); jobs+=("regress ($c)|$out/regress.scene|$o|"); done
# the section 3.5 options (docs/spec.md 10): tent, channel offsets, both, on SVG dumps (regress_scene
# has vertices at the coordinate limit, which a channel's shift cannot move: refused by design)
if "$ref/edgeflag" render --help 2>/dev/null | grep -q -- --filter; then
    k=0
    for f in $(scenes | head -n 6); do
        case $((k % 3)) in
        0) o="--samples 8 --filter tent" ;;
        1) o="--samples 16 --subpixel bgr" ;;
        *) o="--samples 32 --filter tent --subpixel rgb" ;;
        esac
        jobs+=("$(basename "$f" .scene) ($o)|$f|$o|"); k=$((k + 1))
    done
fi
ngen=0
if "$ref/edgeflag" gen --help >/dev/null 2>&1 && "$ref/edgeflag" gen -o "$out/gen" --level 1 >"$out/gen.log" 2>&1; then
    k=0
    for f in "$out"/gen/*.scene; do
        o=$(opts_of "${cfgs[$((k % 9))]}"); jobs+=("gen $(basename "$f" .scene) (${cfgs[$((k % 9))]})|$f|$o|")
        k=$((k + 1)); ngen=$((ngen + 1))
    done
else
    echo "portability: note: no 'edgeflag gen' in this tree; the generated regression is regress_scene alone"
fi

vjobs=()   # "label|file|options": vectors, every build
if "$ref/edgeflag" vectors --help >/dev/null 2>&1; then
    # three configurations cover both rules and every N; qemu makes each set cost
    for c in "8 file" "16 evenodd" "32 nonzero"; do
        o=$(opts_of "$c"); vjobs+=("vectors regress ($c)|$out/regress.scene|$o")
    done
    for f in $(scenes | head -n 2); do
        vjobs+=("vectors $(basename "$f" .scene) (8 file)|$f|--samples 8")
    done
    if "$ref/edgeflag" vectors --help 2>/dev/null | grep -q -- --filter; then
        f=$(scenes | head -n 1)
        vjobs+=("vectors $(basename "$f" .scene) (16 tent rgb)|$f|--samples 16 --filter tent --subpixel rgb")
    fi
fi

# ------------------------------------------------------------------ renders
# Each build renders every job into its own directory and writes the hashes
# to sums (a line "ERROR ..." on failure); JOBS builds render at a time.
render_all() {   # name runner native(0/1)
    local name=$1 run=$2 native=$3 d=$out/img.$1 j=0 job label file o svg h
    mkdir -p "$d"
    : >"$d/sums"
    for job in "${jobs[@]}"; do
        IFS='|' read -r label file o svg <<<"$job"
        j=$((j + 1))
        # shellcheck disable=SC2086
        if ! $run "$name/edgeflag" render "$file" -o "$d/$j.pam" $o 2>>"$d/render.log"; then
            echo "ERROR $name failed to render $label: $(tail -n 1 "$d/render.log")" >>"$d/sums"; return
        fi
        h=$(sha256sum "$d/$j.pam" | cut -c1-64)
        if [ -n "$svg" ] && [ "$native" = 1 ]; then
            # shellcheck disable=SC2086
            if ! "$name/edgeflag" render "$svg" -o "$d/$j.svg.pam" $o 2>>"$d/render.log"; then
                echo "ERROR $name failed to render $svg" >>"$d/sums"; return
            fi
            if [ "$(sha256sum "$d/$j.svg.pam" | cut -c1-64)" != "$h" ]; then
                echo "ERROR $name: $label differs between the SVG and its dump" >>"$d/sums"; return
            fi
            rm -f "$d/$j.svg.pam"
        fi
        echo "$h $label" >>"$d/sums"
        rm -f "$d/$j.pam"
    done
    # Vectors: the frame image's name depends on libpng and the manifest
    # names it, so the hex files, the VCD and the stream are compared.
    for job in "${vjobs[@]}"; do
        IFS='|' read -r label file o <<<"$job"
        j=$((j + 1))
        # shellcheck disable=SC2086
        # hex and bin: every transaction twice over; the VCD (same values, more
        # text) is left to test-vectors' gcc/clang comparison, it is the slow part under qemu
        if ! $run "$name/edgeflag" vectors "$file" -o "$d/v$j" $o --formats hex,bin >/dev/null 2>>"$d/render.log"; then
            echo "ERROR $name failed to write $label: $(tail -n 1 "$d/render.log")" >>"$d/sums"; return
        fi
        h=$(cd "$d/v$j" && cat ./*.hex vectors.bin | sha256sum | cut -c1-64)
        echo "$h $label" >>"$d/sums"
        rm -rf "$d/v$j"
    done
}
running=0
for i in "${!names[@]}"; do
    name=${names[$i]}
    native=0; [[ " ${natives[*]} " == *" $name "* ]] && native=1
    render_all "$name" "${runners[$i]}" "$native" &
    running=$((running + 1))
    if [ "$running" -ge "$JOBS" ]; then wait -n; running=$((running - 1)); fi
done
wait
for name in "${names[@]}"; do
    d=$out/img.$name
    if grep -q '^ERROR' "$d/sums"; then
        fail=$((fail + 1)); echo "portability: $(grep -m1 '^ERROR' "$d/sums" | cut -c7-)"
    elif [ "$name" = "$ref" ] || cmp -s "$d/sums" "$out/img.$ref/sums"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        first=$(diff "$out/img.$ref/sums" "$d/sums" | grep '^>' | head -n 1 | cut -d' ' -f3-)
        echo "portability: MISMATCH $name vs $ref: $(diff "$out/img.$ref/sums" "$d/sums" | grep -c '^>') of $((${#jobs[@]} + ${#vjobs[@]})) outputs differ, first: $first"
    fi
done

if [ "$fail" -eq 0 ]; then
    echo "portability: builds ${names[*]#build-} agree byte for byte"
else
    echo "portability: builds ${names[*]#build-} do NOT all agree (see above)"
fi
echo "portability: ${#jobs[@]} images per build: $nsvg shared SVGs (dumps; SVG = dump on native builds) and regress_scene at 8/16/32 x file/evenodd/nonzero, and $ngen 'edgeflag gen' cases, and 6 with --filter/--subpixel (docs/spec.md 10)"
echo "portability: ${#vjobs[@]} vector sets per build (hex and bin): regress_scene at 3 configurations and 2 SVG dumps"
for s in "${skips[@]}"; do echo "portability: SKIPPED $s"; done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
