#!/usr/bin/env bash
# What vector output costs beyond the PNG render: `kappa render MESH -o x.svg`
# (surface pass + CPU strokes + SVG) against `-o x.png` (surface + GPU line
# passes + PNG), run alternately (../shared/tools/ab-time.py), contours and
# suggestive contours on a white surface, 1024x768. Prints both medians, the
# difference, and the SVG's size.
#   bench/vector_output.sh [MESH] [RUNS]   (default ../shared/meshes/bunny-1M.ply, 7)
set -euo pipefail
cd "$(dirname "$0")/.."
mesh=${1:-../shared/meshes/bunny-1M.ply}
runs=${2:-7}
out=$(mktemp -d)
common="build/kappa render $mesh --shading none --lines contours,suggestive -q"
read -r svg png ratio < <(../shared/tools/ab-time.py "$runs" "$common -o $out/x.svg" "$common -o $out/x.png")
echo "$(basename "$mesh"): svg $svg s, png $png s (medians of $runs, alternating): svg costs $(python3 -c "print('%+.3f' % ($svg - $png))") s beyond the PNG"
echo "svg size: $(stat -c %s "$out/x.svg") bytes, $(grep -c '<path' "$out/x.svg") paths"
rm -rf "$out"
