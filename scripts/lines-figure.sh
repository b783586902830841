#!/usr/bin/env bash
# docs/lines.png: the bunny drawn with each line family and two shadings, as
# rtsc's panel shows them, from the default view, at --detail 4 (finer than
# the default 12 px: more lines at this small size). Each panel is one
# `kappa render` (printed as it runs); scripts/png_grid.py puts them in a
# 4 x 3 grid, left to right, top to bottom.
#   scripts/lines-figure.sh [MESH] [OUT.png]    (default ../shared/meshes/bunny.ply, docs/lines.png)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mesh=${1:-$root/../shared/meshes/bunny.ply}
out=${2:-$root/docs/lines.png}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
panels=(
  "--lines contours,suggestive --shading none"
  "--lines contours,suggestive-highlights --shading none"
  "--lines contours,ridges,valleys --shading none"
  "--lines contours,apparent-ridges --shading none"
  "--lines contours,principal-highlights --shading none"
  "--lines contours,parabolic,mean-zero --shading none"
  "--lines contours,dwkr --shading none"
  "--lines contours,isophotes --shading none"
  "--lines contours,topo --shading none"
  "--lines silhouette,suggestive --hidden-lines on --shading none"
  "--lines contours,suggestive --shading toon-bw"
  "--lines contours,suggestive --shading gooch"
)
files=()
for i in "${!panels[@]}"; do
  f=$tmp/$i.png
  # shellcheck disable=SC2086
  echo "kappa render $(basename "$mesh") -o out.png --size 320x320 --detail 4 ${panels[$i]}"
  # shellcheck disable=SC2086
  "$root/build/kappa" render "$mesh" -o "$f" -q --size 320x320 --detail 4 ${panels[$i]}
  files+=("$f")
done
python3 "$root/scripts/png_grid.py" "$out" 4 "${files[@]}"
echo "wrote $out"
