#!/usr/bin/env bash
# The main job on the built-in model: the interactive viewer when there is a
# display, otherwise a headless render to kappa-default.png (and, in builds
# without the renderer, the curvature fields as CSV).
set -euo pipefail
KAPPA=${KAPPA:-build/kappa}
has() { "$KAPPA" --help | grep -q "^  $1 "; }
if [ -n "${DISPLAY:-}" ] && has view; then
  exec "$KAPPA" view
elif has render; then
  "$KAPPA" render -o kappa-default.png
else
  "$KAPPA" info
  "$KAPPA" curvature -o kappa-default.csv
fi
