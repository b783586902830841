#!/usr/bin/env bash
# docs/cad.png: fandisk, spot and an 8-vertex cube, each `kappa render` with
# default options at 300x300 (printed as it runs), side by side
# (scripts/png_grid.py).
#   scripts/cad-figure.sh [OUT.png]    (default docs/cad.png)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
meshes=${KAPPA_MESH_DIR:-$root/../shared/meshes}
out=${1:-$root/docs/cad.png}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf 'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n%s\n' \
  "f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 4 8 7 3
f 1 5 8 4
f 2 3 7 6" >"$tmp/cube.obj"
files=()
for mesh in "$meshes/fandisk.obj" "$meshes/spot.obj" "$tmp/cube.obj"; do
  f=$tmp/$(basename "$mesh" .obj).png
  echo "kappa render $(basename "$mesh") -o out.png --size 300x300"
  "$root/build/kappa" render "$mesh" -o "$f" -q --size 300x300
  files+=("$f")
done
python3 "$root/scripts/png_grid.py" "$out" 3 "${files[@]}"
echo "wrote $out"
