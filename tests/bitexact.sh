#!/usr/bin/env bash
# Same bits everywhere.  Builds edgeflag with gcc and clang at -O0 and -O3, and
# as 32-bit x86 (-m32) with gcc and clang, renders every shared SVG at 8/16/32
# samples under the file's rules, even-odd and non-zero, and demands
# byte-identical PAM files (SHA-256) from every build.
#
# Debian 12 cannot reliably co-install the i386 -dev packages of expat and
# libpng beside the amd64 ones, so the 32-bit builds are made WITH_SVG=0
# WITH_PNG=0 and render the exact device-space dump of each SVG
# (tests/tools/scene_dump.c: Q16.8 coordinates as exact decimals).  The 64-bit
# builds render both the SVG and its dump, which must agree too, so the chain
# SVG -> dump -> 32-bit render is checked link by link.
#
#   usage: tests/bitexact.sh SVG_DIR
set -u
cd "$(dirname "$0")/.." || exit 1
svgdir=${1:?usage: tests/bitexact.sh SVG_DIR}
out=build/bitexact
rm -rf "$out"; mkdir -p "$out"

full=("gcc -O0" "gcc -O3" "clang -O0" "clang -O3")
m32=("gcc -O2" "clang -O2")
build() {   # name cc opt [extra make args...]
    local name=$1 cc=$2 opt=$3; shift 3
    if ! make --no-print-directory -s CC="$cc" OPT="$opt" BUILD="$name" "$@" cli >"$out/$name.build.log" 2>&1; then
        echo "bitexact: build $name failed:"; tail -n 20 "$out/$name.build.log"; exit 1
    fi
}
names=() names32=()
for b in "${full[@]}"; do
    read -r cc opt <<<"$b"; name="build-bx-$cc$opt"
    build "$name" "$cc" "$opt"; names+=("$name")
done
for b in "${m32[@]}"; do
    read -r cc opt <<<"$b"; name="build-bx-$cc$opt-m32"
    build "$name" "$cc" "$opt" EXTRA_CFLAGS=-m32 EXTRA_LDFLAGS=-m32 WITH_SVG=0 WITH_PNG=0 WITH_MANIFEST=0
    # ELF header byte 4 (EI_CLASS) is 1 for a 32-bit program (no dependency on file(1)).
    [ "$(od -An -tu1 -j4 -N1 "$name/edgeflag" | tr -d ' ')" = 1 ] ||
        { echo "bitexact: $name/edgeflag is not a 32-bit program"; exit 1; }
    names32+=("$name")
done
make --no-print-directory -s BUILD="${names[0]}" "${names[0]}/tests/tools/scene_dump" >"$out/dump.build.log" 2>&1 ||
    { echo "bitexact: scene_dump build failed"; tail "$out/dump.build.log"; exit 1; }

# The fixed-point library's own tests, as 32-bit programs (cmocka has no i386
# package that installs beside the amd64 one either; test_fixed carries a
# minimal stand-in for that case).
for cc in gcc clang; do
    $cc -m32 -std=c11 -Wall -Wextra -Werror -O2 -DEF_TEST_NO_CMOCKA -Ifixed -Imodel tests/unit/test_fixed.c fixed/*.c \
        -lm -o "$out/test_fixed_m32_$cc" >"$out/test_fixed_m32_$cc.log" 2>&1 &&
        "$out/test_fixed_m32_$cc" >>"$out/test_fixed_m32_$cc.log" 2>&1 ||
        { echo "bitexact: test_fixed as a 32-bit $cc program failed:"; tail -n 20 "$out/test_fixed_m32_$cc.log"; exit 1; }
    echo "bitexact: fixed-point unit tests pass as 32-bit $cc programs ($(grep -c 'OK \]' "$out/test_fixed_m32_$cc.log") tests)"
done

count=0 nsvg=0
for svg in "$svgdir"/*.svg; do
    base=$(basename "$svg" .svg)
    dump="$out/$base.scene"
    "${names[0]}/tests/tools/scene_dump" "$svg" >"$dump" || { echo "bitexact: cannot dump $base"; exit 1; }
    nsvg=$((nsvg + 1))
    for n in 8 16 32; do
        for rule in file evenodd nonzero fit; do
            ropt=(); [ "$rule" = evenodd ] || [ "$rule" = nonzero ] && ropt=(--rule "$rule")
            # "fit": the file's rules, scaled into an odd canvas (the Q31.32
            # transform path of the readers, on every build)
            [ "$rule" = fit ] && ropt=(--size 333x177)
            unset ref first; declare -A ref first
            for job in "${names[@]/%/:svg}" "${names[@]/%/:dump}" "${names32[@]/%/:dump}"; do
                name=${job%:*} src=$svg
                [ "${job#*:}" = dump ] && src=$dump
                img="$out/render.pam"
                if ! "$name/edgeflag" render "$src" -o "$img" --samples "$n" "${ropt[@]}" 2>>"$out/render.log"; then
                    echo "bitexact: $name failed to render $src ($n, $rule)"; tail -n 3 "$out/render.log"; exit 1
                fi
                h=$(sha256sum "$img" | cut -d' ' -f1)
                # Fitting an SVG flattens its curves at the new scale, fitting the
                # dump scales the already flattened polygon: compare like with like.
                key=all; [ "$rule" = fit ] && key=${job#*:}
                if [ -z "${ref[$key]:-}" ]; then ref[$key]=$h; first[$key]=$job
                elif [ "$h" != "${ref[$key]}" ]; then
                    echo "bitexact: MISMATCH $base samples=$n rule=$rule: ${first[$key]} ${ref[$key]} vs $job $h"; exit 1
                fi
            done
            count=$((count + 1))
        done
    done
done
echo "bitexact: builds ${names[*]#build-bx-} (SVG and dump) and ${names32[*]#build-bx-} (dump) agree byte for byte"
echo "bitexact: $count configurations of $nsvg SVGs (8/16/32 samples x file/evenodd/nonzero rules, and fitted to 333x177)"
echo "bitexact: $count passed, 0 failed"
