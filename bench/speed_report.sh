#!/usr/bin/env bash
# The README's speed comparison in one command: the whole curvature job on
# bunny-1M.ply against trimesh2's (../shared/anchors/trimesh2-curvature, the
# paper author's library), alternately in one run (../shared/tools/ab-time.py),
# on 2 threads and on 1; then the scaling table (bench/scaling.sh).
#   bench/speed_report.sh [RUNS]   (default 7)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-7}
mesh=../shared/meshes/bunny-1M.ply
t2=../shared/anchors/trimesh2-curvature
echo "whole job on $(basename "$mesh"): kappa s, trimesh2 s, median ratio kappa/trimesh2 ($runs alternating runs)"
echo -n "2 threads: "
OMP_NUM_THREADS=2 ../shared/tools/ab-time.py "$runs" "build/kappa curvature $mesh -o /tmp/kappa-k.ply -q --threads 2" \
  "$t2 $mesh /tmp/kappa-t.ply"
echo -n "1 thread:  "
OMP_NUM_THREADS=1 ../shared/tools/ab-time.py "$runs" "build/kappa curvature $mesh -o /tmp/kappa-k.ply -q --threads 1" \
  "$t2 $mesh /tmp/kappa-t.ply"
rm -f /tmp/kappa-k.ply /tmp/kappa-t.ply
echo
bench/scaling.sh 3
