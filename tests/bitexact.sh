#!/usr/bin/env bash
# Same bits everywhere: builds edgeflag with gcc and clang at -O0 and -O3, and
# as 32-bit x86 (-m32), renders every shared SVG at 8/16/32 samples under the
# file's rules, even-odd and non-zero, and demands byte-identical PAM files
# (their SHA-256) from every build.   usage: tests/bitexact.sh SVG_DIR
set -u
cd "$(dirname "$0")/.."
svgdir=${1:?usage: tests/bitexact.sh SVG_DIR}
out=build/bitexact
rm -rf "$out"; mkdir -p "$out"

builds=("gcc -O0" "gcc -O3" "clang -O0" "clang -O3" "gcc -O2 -m32" "clang -O2 -m32")
if ! echo 'int main(void){return 0;}' | gcc -m32 -x c - -o "$out/m32probe" 2>/dev/null ||
   ! pkg-config --exists expat 2>/dev/null || [ ! -e /usr/lib/i386-linux-gnu/libexpat.so ]; then
    echo "bitexact: 32-bit toolchain or i386 libraries missing (make deps-test installs them)"; exit 1
fi

names=()
for b in "${builds[@]}"; do
    read -r cc opt m32 <<<"$b"
    name="build-bx-$cc$opt${m32:-}"; name=${name// /}
    names+=("$name")
    flags="" ; ldflags=""
    if [ -n "${m32:-}" ]; then flags="-m32"; ldflags="-m32"; fi
    if ! make --no-print-directory -s CC="$cc" OPT="$opt" BUILD="$name" EXTRA_CFLAGS="$flags" \
         EXTRA_LDFLAGS="$ldflags" PKG_CONFIG_PATH=${m32:+/usr/lib/i386-linux-gnu/pkgconfig} cli >"$out/$name.build.log" 2>&1; then
        echo "bitexact: build $b failed:"; tail -n 20 "$out/$name.build.log"; exit 1
    fi
    file "$name/edgeflag" | grep -q "${m32:+32-bit}" || { echo "bitexact: $name is not the expected kind"; exit 1; }
done

count=0
for svg in "$svgdir"/*.svg; do
    base=$(basename "$svg" .svg)
    for n in 8 16 32; do
        for rule in file evenodd nonzero; do
            ropt=(); [ "$rule" != file ] && ropt=(--rule "$rule")
            ref=""
            for name in "${names[@]}"; do
                img="$out/$name.$base.$n.$rule.pam"
                if ! "$name/edgeflag" render "$svg" -o "$img" --samples "$n" "${ropt[@]}" 2>>"$out/render.log"; then
                    echo "bitexact: $name failed to render $base ($n, $rule)"; exit 1
                fi
                h=$(sha256sum "$img" | cut -d' ' -f1)
                if [ -z "$ref" ]; then ref=$h
                elif [ "$h" != "$ref" ]; then
                    echo "bitexact: MISMATCH $base samples=$n rule=$rule: ${names[0]} $ref vs $name $h"; exit 1
                fi
                rm -f "$img"
            done
            count=$((count + 1))
        done
    done
done
echo "bitexact: ${#names[@]} builds (${builds[*]// /}) agree byte for byte on $count renders of $(ls "$svgdir"/*.svg | wc -l) SVGs"
echo "bitexact: $count passed, 0 failed"
