#!/bin/bash
# Every figure the GPU path's targets ask for (issue "The GPU path", docs/gpu.md), in one call on
# the device machine, so that a session lent a GPU spends its minutes measuring, not preparing:
#
#   ../shared/tools/gpu-prepare.sh build kappa bench_render bench_view_fields make_subdivided
#   device run:  bash .gpu/run.sh 'bash bench/device_targets.sh'      carry: [".gpu"]
#
# Prints, in order: bunny-1M at 1920x1080 without MSAA, every configuration of bench_render --each
# twice (Lambert, contours + suggestive, shader hatching as while moving, every line type: the ratios
# the targets compare are within one run); the 17.8M-face subdivision of bunny-1M at 3840x2160,
# Lambert and contours + suggestive; kappa render of it (load, curvature, fields) beside kappa
# curvature's read; a new view's fields against the curvature job (bench_view_fields). About 5-6
# minutes on an H100 with 16 cores. --quick: small sizes and meshes, to try the script on llvmpipe.
set -u
M=${M:-$(cd "$(dirname "$0")/../../shared/meshes" 2>/dev/null && pwd)}
OUT=${OUT:-/tmp/device-targets}
mkdir -p "$OUT"
big=${BIG_MESH:-/tmp/kappa-b17.ply}
size=1920x1080 big_size=3840x2160 frames=31 big_frames=11 levels=2 base=$M/bunny-1M.ply
if [ "${1:-}" = --quick ]; then
    size=320x240 big_size=320x240 frames=3 big_frames=2 levels=1 base=$M/bunny.ply
    big=${BIG_MESH:-/tmp/kappa-quick-big.ply}
fi
step() { echo; echo "== $*"; }

step "GPU"
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null || echo "no nvidia-smi"
for run in 1 2; do
    step "bench_render run $run: $(basename "$base") $size, no MSAA, every configuration"
    bench_render --frames $frames --detail 12 --no-msaa --size $size --each "$base"
done

step "subdividing $(basename "$base") $levels times"
[ -f "$big" ] || /usr/bin/time -f "made in %e s" make_subdivided "$base" $levels "$big"
step "bench_render: $(basename "$big") $big_size, contours + suggestive"
bench_render --frames $big_frames --detail 12 --no-msaa --size $big_size --only contours+suggestive "$big"

for run in 1 2; do
    step "kappa render run $run (load, curvature, fields) and kappa curvature (read)"
    kappa render "$big" -o "$OUT/big-$run.png" --size $big_size
    kappa curvature "$big" -o /tmp/kappa-curvature.ply | grep 'time:'
done

step "bench_view_fields: a new view against the curvature job"
bench_view_fields "$big" --runs 2 --size $big_size --views-only
