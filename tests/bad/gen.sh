#!/usr/bin/env bash
# tests/bad/gen.sh DIR - writes the catalogue's large and special inputs into
# DIR at test time (gen_* names in CATALOGUE.tsv), so the repository holds no
# megabytes.  Each is built from coreutils in well under a second.
set -eu
d=${1:?usage: gen.sh DIR}
cd "$d"
MiB=$((1024 * 1024))
H='<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">'

# Past the 64 MiB input limit by one byte (sparse: nothing is written to disk).
truncate -s $((64 * MiB + 1)) gen_too_large.svg gen_too_large.scene
# Exactly 64 MiB, valid: loads (one long comment line).
{ printf 'scene 1 1\n#'; head -c $((64 * MiB - 12)) /dev/zero | tr '\0' x; printf '\n'; } >gen_size_ok.scene

# One contour of 2^22 + 1 points: one edge more than the model takes
# (EF_MAX_EDGES_PER_SHAPE); the same with 2^22 points loads and renders.
{ printf 'scene 4 4\nshape nonzero 1 2 3 255\ncontour'; yes ' 1 2 3 1' | head -n $((1 << 21)) | tr -d '\n'
  printf ' 0 0\n'; } >gen_edges.scene
{ printf 'scene 4 4\nshape nonzero 1 2 3 255\ncontour'; yes ' 1 2 3 1' | head -n $((1 << 21)) | tr -d '\n'
  printf '\n'; } >gen_edges_ok.scene

# Enormous path data: one <path> of 2^22 + 2 vertices (10 MiB of "h1v1h-1v-1"),
# and of exactly 2^22 (loads and renders).
{ printf '%s\n<path d="M0 0' "$H"; yes 'h1v1h-1v-1' | head -n $((1 << 20)) | tr -d '\n'; printf 'h2"/>\n</svg>\n'; } >gen_big_path.svg
{ printf '%s\n<path d="M0 0' "$H"; yes 'h1v1h-1v-1' | head -n $((1 << 20)) | tr -d '\n'; printf '"/>\n</svg>\n'; } >gen_big_path_ok.svg

# More than 2^24 points in a scene: a path of 2^21 + 1 points drawn 9 times.
{ printf '%s\n<defs><path id="p" d="M0 0' "$H"; yes 'h1v1h-1v-1' | head -n $((1 << 19)) | tr -d '\n'
  printf 'h2"/></defs>\n'; for _ in 1 2 3 4 5 6 7 8 9; do printf '<use href="#p"/>\n'; done; printf '</svg>\n'; } >gen_points.svg

# 2^20 + 1 elements (the root and 2^20 <g/>).
{ printf '%s\n' "$H"; yes '<g/>' | head -n $((1 << 20)) | tr -d '\n'; printf '\n</svg>\n'; } >gen_elements.svg

# Work bombs: 100 KB of path data read 2^20 times through a tree of <use>;
# 2^17 style rules times 2^17 elements.
{ printf '%s\n<defs>\n<path id="p0" d="' "$H"; yes 'M0 0 ' | head -n 20000 | tr -d '\n'; printf '"/>\n'
  for i in $(seq 1 20); do printf '<g id="p%d"><use href="#p%d"/><use href="#p%d"/></g>\n' "$i" $((i - 1)) $((i - 1)); done
  printf '</defs>\n<use href="#p20"/>\n</svg>\n'; } >gen_work_use.svg
{ printf '%s\n<style>' "$H"; seq 1 131072 | sed 's/.*/.c&{fill:red}/' | tr -d '\n'; printf '</style>\n'
  yes '<g/>' | head -n 131072 | tr -d '\n'; printf '\n</svg>\n'; } >gen_work_css.svg

# A number of a million digits (1 followed by zeros): out of range, found
# without arithmetic on all of them.
{ printf 'scene 10 10\nshape nonzero 1 2 3 255\ncontour 1 1 5 1 5 '; printf '1'; head -c 1000000 /dev/zero | tr '\0' 0
  printf '\n'; } >gen_long_number.scene

# A directory where a file is expected.
mkdir -p gen_dir.scene

# Style rules that a single element matches in falling specificity (sorting
# them one insertion at a time was quadratic: 3 s for this 1.3 MB file): loads.
{ printf '%s\n<style>' "$H"; yes '#a{fill:red}' | head -n 50000 | tr -d '\n'; yes 'rect{fill:blue}' | head -n 50000 | tr -d '\n'
  printf '</style>\n<rect id="a" width="5" height="5"/>\n</svg>\n'; } >gen_css_sort.svg

# A 100 KB style attribute parsed again at each of 2^20 <use> instances.
{ printf '%s\n<defs>\n<rect id="p0" width="1" height="1" style="' "$H"; yes 'fill:red;' | head -n 11000 | tr -d '\n'; printf '"/>\n'
  for i in $(seq 1 20); do printf '<g id="p%d"><use href="#p%d"/><use href="#p%d"/></g>\n' "$i" $((i - 1)) $((i - 1)); done
  printf '</defs>\n<use href="#p20"/>\n</svg>\n'; } >gen_work_style.svg
