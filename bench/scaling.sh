#!/usr/bin/env bash
# Scaling of the whole `kappa curvature MESH -o OUT.ply` job (read, normals,
# curvature, C, write) with the mesh size: bunny-1M.ply (1.1M faces) and its
# midpoint subdivisions (4.4M and 17.8M faces, made once by
# build/make_subdivided into $KAPPA_BENCH_DIR, default /tmp/kappa-bench).
# Per size: the median wall time of RUNS runs and the peak resident memory,
# then per million faces and per face: linear scaling keeps both flat.
#   bench/scaling.sh [RUNS]   (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
dir=${KAPPA_BENCH_DIR:-/tmp/kappa-bench}
mkdir -p "$dir"
base=../shared/meshes/bunny-1M.ply
[ -f "$dir/bunny-4M.ply" ] || build/make_subdivided "$base" 1 "$dir/bunny-4M.ply" >/dev/null
[ -f "$dir/bunny-18M.ply" ] || build/make_subdivided "$base" 2 "$dir/bunny-18M.ply" >/dev/null
printf "%-14s %10s %10s %12s %12s %12s\n" mesh faces "median s" "ms/M faces" "peak MB" "bytes/face"
for mesh in "$base" "$dir/bunny-4M.ply" "$dir/bunny-18M.ply"; do
  faces=$(head -c 400 "$mesh" | tr -d '\r' | awk '/^element face/{print $3}')
  times=() mem=0
  for _ in $(seq "$runs"); do
    out=$( { /usr/bin/time -f "%e %M" build/kappa curvature "$mesh" -o "$dir/out.ply" -q; } 2>&1 | tail -1)
    times+=("${out% *}")
    kb=${out#* }; [ "$kb" -gt "$mem" ] && mem=$kb
  done
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(((runs + 1) / 2))p")
  python3 -c "
f=$faces; t=$median; m=$mem*1024
print('%-14s %10d %10.3f %12.1f %12.0f %12.0f' % ('$(basename "$mesh")', f, t, t*1000/(f/1e6), m/2**20, m/f))"
done
rm -f "$dir/out.ply"
