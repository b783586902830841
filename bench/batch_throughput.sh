#!/usr/bin/env bash
# Throughput of `kappa batch` serial and on Dask (scripts/dask_batch.py) on this machine:
# 16 meshes (4 copies each of bunny, dragon-50k, fandisk and spot from ../shared/meshes, so that
# each is its own task) x 4 views at 512x384, default settings. Prints meshes per minute.
#   bench/batch_throughput.sh [BUILD_DIR] [WORKERS]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
workers=${2:-$(nproc)}
meshes=${KAPPA_MESH_DIR:-$here/../shared/meshes}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for copy in 1 2 3 4; do
  for m in bunny.ply dragon-50k.ply fandisk.obj spot.obj; do
    cp "$meshes/$m" "$work/$copy-$m"
    for az in 0 90 180 270; do
      echo "$copy-$m out/$copy-${m%.*}-$az.png --view $az,20 --size 512x384"
    done
  done
done > "$work/jobs.txt"
start=$(date +%s.%N)
"$build/kappa" batch -q "$work/jobs.txt"
serial=$(echo "$(date +%s.%N) - $start" | bc)
mv "$work/out" "$work/serial"
start=$(date +%s.%N)
PYTHONPATH="$build/python" /usr/bin/python3 "$here/scripts/dask_batch.py" "$work/jobs.txt" --workers "$workers" 2>&1 |
  grep -v "^dask_batch: \[" || true
dask=$(echo "$(date +%s.%N) - $start" | bc)
diff -rq "$work/serial" "$work/out" && echo "the same 64 files from both runs"
printf 'serial kappa batch: %.1f s, %.1f meshes/minute\n' "$serial" "$(echo "16 * 60 / $serial" | bc -l)"
printf 'dask_batch.py, %s workers (with cluster start-up): %.1f s, %.1f meshes/minute\n' "$workers" "$dask" \
  "$(echo "16 * 60 / $dask" | bc -l)"
