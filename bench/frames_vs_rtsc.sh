#!/usr/bin/env bash
# Frame time against rtsc's, side by side: the same mesh, view (kappa's
# default view saved as .xf by kappa view), size (1024x768) and lines
# (contours and suggestive contours on a white unlit surface, default
# thresholds). rtsc-render (../shared/anchors, its own CPU line extraction
# every frame, under Xvfb) and build/bench_render --rtsc (EGL, no window)
# take turns, ROUNDS times; each prints the median of FRAMES frames. The
# ratio of each round is kappa / rtsc; the median ratio is printed for kappa
# without and with 4x MSAA.
#   bench/frames_vs_rtsc.sh [MESH] [ROUNDS] [FRAMES]   (default bunny.ply, 3, 21)
set -euo pipefail
cd "$(dirname "$0")/.."
mesh=${1:-../shared/meshes/bunny.ply}
rounds=${2:-3}
frames=${3:-21}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf "frames 2\nsave-view $dir/view.xf\n" > "$dir/steps.txt"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" build/kappa view "$mesh" --size 1024x768 --script "$dir/steps.txt" >/dev/null 2>&1
echo "$(basename "$mesh"), 1024x768, contours + suggestive contours on white, $frames frames a run"
for r in $(seq "$rounds"); do
  rt=$(OMP_NUM_THREADS=2 xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ../shared/anchors/rtsc-render "$mesh" -xf "$dir/view.xf" \
       -size 1024x768 -lines contours,suggestive -frames "$frames" -out "$dir/rtsc.png" 2>&1 | awk '/^median_frame_ms/ {print $2}')
  out=$(build/bench_render --rtsc --xf "$dir/view.xf" --frames "$frames" "$mesh")
  k=$(echo "$out" | awk '/white\+contours\+suggestive/ && /no msaa/ {for (i=1;i<=NF;i++) if ($i=="wall") print $(i+1)}')
  km=$(echo "$out" | awk '/white\+contours\+suggestive/ && /msaa 4x/ {for (i=1;i<=NF;i++) if ($i=="wall") print $(i+1)}')
  g=$(echo "$out" | awk '/geometry shader/ && /no msaa/ {for (i=1;i<=NF;i++) if ($i=="wall") print $(i+1)}')
  echo "round $r: rtsc $rt ms | kappa $k ms (ratio $(python3 -c "print('%.2f' % ($k/$rt))")), with MSAA $km ms ($(python3 -c "print('%.2f' % ($km/$rt))")), geometry-shader lines $g ms ($(python3 -c "print('%.2f' % ($g/$rt))"))"
done
