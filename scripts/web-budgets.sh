#!/usr/bin/env bash
# The browser page's budgets (docs/web.md), measured in headless Chromium with
# SwiftShader's software WebGL2 (tests/web/page_driver.py):
#   scripts/web-budgets.sh [SITE] [MESHES]   (default build/web, ../shared/meshes)
# prints the .wasm's size gzipped, the seconds from navigation until bunny.ply
# is drawn (three loads), and the frames a second while orbiting bunny.ply with
# contours and suggestive contours in an 800x600 canvas.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
site=${1:-$root/build/web}
meshes=${2:-$root/../shared/meshes}
[ -f "$site/kappa.wasm" ] || { echo "web-budgets.sh: no $site/kappa.wasm (scripts/build-web.sh $site)" >&2; exit 1; }
echo "kappa.wasm: $(stat -c %s "$site/kappa.wasm") bytes, $(gzip -9 -c "$site/kappa.wasm" | wc -c) gzipped (-9)"
echo "kappa.js: $(stat -c %s "$site/kappa.js") bytes, $(gzip -9 -c "$site/kappa.js" | wc -c) gzipped"
out=$(mktemp -d)
query='mesh=meshes/bunny.ply&size=800x600&panel=off'
python3 "$root/tests/web/page_driver.py" "$site" "$meshes" "$out" \
  "time:load-1:$query" "time:load-2:$query" "time:load-3:$query" \
  "orbit:orbit:$query&lines=contours,suggestive:60"
rm -rf "$out"
