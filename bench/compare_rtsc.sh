#!/usr/bin/env bash
# kappa's line drawings against rtsc's own (../shared/anchors/rtsc-render,
# rtsc 1.6 headless), line type by line type, on the shared meshes: the same
# view (kappa view's default view of each mesh, saved as a trimesh2/rtsc .xf
# file), thresholds mapped through the two feature sizes, and the fraction of
# rtsc's ink within 2 px of kappa's and back (build/bench_render_agreement).
#
#   bench/compare_rtsc.sh [OUT_DIR]       (default /tmp/kappa-vs-rtsc; needs xvfb-run)
#
# Like for like: kappa with --detail off (the raw 1-ring fields, as rtsc),
# --crease-angle off (rtsc does not split meshes at sharp edges), --fade off
# (rtsc-render draws unfaded), no smoothing; white paper, 2 px lines.
# Thresholds: rtsc's defaults T on its feature size fs_r, kappa's
# S = T (fs_k / fs_r)^p with fs_k kappa's feature size and p the power of fs
# in the test: 2 for suggestive contours, highlights (on Dw kr and on
# (k1^2 - k2^2) n.v), 1 for ridges (on |k|); apparent ridges: rtsc tests the
# squared view-dependent curvature against T / fs_r^2, kappa the curvature
# against S / fs_k, so S = sqrt(T) fs_k / fs_r. The Dw kr lines are compared
# at threshold 0 (rtsc's lines are tan(theta) Dw kr = T / fs_r^2, kappa's
# Dw kr = S / fs_k^2: the same curve only at 0). Isophotes and topographic
# lines are left out: rtsc draws 20 levels of n.l from 0 and of depth along
# the view, kappa N levels at (k - 1/2) / N and heights along y.
# Writes OUT_DIR/MESH-TYPE-{kappa,rtsc}.png and prints a markdown table.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
kappa=$root/build/kappa
agree=$root/build/bench_render_agreement
rtsc=${RTSC_RENDER:-$root/../shared/anchors/rtsc-render}
meshes=${KAPPA_MESH_DIR:-$root/../shared/meshes}
out=${1:-/tmp/kappa-vs-rtsc}
size=640
mkdir -p "$out"
export OMP_NUM_THREADS=1  # rtsc-render: byte-reproducible

# kappa line | rtsc lines | kappa threshold option | rtsc option | rtsc value | power p (sqrt: apparent ridges)
types=(
  "contours|contours||||"
  "suggestive|suggestive|sc-threshold|sc_thresh|0.01|2"
  "suggestive-highlights|sugg_highlights|sh-threshold|sh_thresh|0.02|2"
  "ridges|ridges|rv-threshold|rv_thresh|0.1|1"
  "valleys|valleys|rv-threshold|rv_thresh|0.1|1"
  "apparent-ridges|apparent|ar-threshold|ar_thresh|0.1|sqrt"
  "principal-highlights|principal_highlights_r,principal_highlights_v|ph-threshold|ph_thresh|0.04|2"
  "parabolic|K0||||"
  "mean-zero|H0||||"
  "dwkr|DwKr|sc-threshold|sc_thresh|0|2"
  "boundaries|bdy||||"
)

xvfb() { xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"; }

echo "| mesh | line type | rtsc ink within 2 px of kappa's | kappa's within 2 px of rtsc's | ink rtsc / kappa | thresholds rtsc / kappa |"
echo "|---|---|---|---|---|---|"
for mesh in bunny.ply fandisk.obj spot.obj dragon-50k.ply; do
  name=${mesh%.*}
  path=$meshes/$mesh
  xf=$out/$name.xf
  printf 'frames 2\nsave-view %s\n' "$xf" >"$out/$name-save.txt"
  xvfb "$kappa" view "$path" --size ${size}x${size} --no-panel --script "$out/$name-save.txt" >/dev/null
  fs_k=$("$kappa" info "$path" | awk '/feature size/ {print $3}')
  fs_r=$(xvfb "$rtsc" "$path" -xf "$xf" -size ${size}x${size} -lines contours -out "$out/$name-probe.png" 2>&1 |
    sed -n 's/.*feature_size \([0-9.e+-]*\).*/\1/p')
  for t in "${types[@]}"; do
    IFS='|' read -r kline rline kopt ropt rval power <<<"$t"
    kargs=() rargs=() thresholds="-"
    if [ -n "$kopt" ]; then
      s=$(python3 -c "import math; r=$fs_k/$fs_r; T=$rval; print('%.4g' % (math.sqrt(T)*r if '$power'=='sqrt' else T*r**$power))")
      kargs=(--"$kopt" "$s")
      rargs=(-"$ropt" "$rval")
      thresholds="$rval / $s"
    fi
    kpng=$out/$name-$kline-kappa.png
    rpng=$out/$name-$kline-rtsc.png
    "$kappa" render "$path" -q -o "$kpng" --xf "$xf" --size ${size}x${size} --lines "$kline" --detail off \
      --crease-angle off --fade off --shading none "${kargs[@]}"
    xvfb "$rtsc" "$path" -xf "$xf" -size ${size}x${size} -lines "$rline" -out "$rpng" "${rargs[@]}" >/dev/null 2>&1
    read -r r_in_k k_in_r ink_r ink_k < <("$agree" "$rpng" "$kpng" 2)
    echo "| $name | $kline | $r_in_k | $k_in_r | $ink_r / $ink_k | $thresholds |"
  done
  echo "| $name | (feature sizes rtsc / kappa) | | | | $fs_r / $fs_k |"
done
