#!/usr/bin/env bash
# The look of Rusinkiewicz 2004, Fig. 6-7: one mesh's mean curvature with each
# estimator side by side (`kappa render --colormap mean --estimator NAME
# --detail off`, each with its own robust colour range, so outliers show as
# saturated speckle), composed with matplotlib (Debian: python3-matplotlib).
#
#   scripts/estimator-figure.sh [MESH] [OUT.png]
#
# Defaults: ../shared/meshes/bunny.ply (a scan: noise and an irregular
# tessellation) and docs/estimators.png.
set -euo pipefail
cd "$(dirname "$0")/.."
KAPPA=${KAPPA:-build/kappa}
MESH=${1:-../shared/meshes/bunny.ply}
OUT=${2:-docs/estimators.png}
MAP=${MAP:-mean}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
names=(rusinkiewicz jet tensor-averaging normal-fit points-normals-fit)
for e in "${names[@]}"; do
  "$KAPPA" render "$MESH" -o "$tmp/$e.png" --colormap "$MAP" --lines none --detail off --estimator "$e" \
    --size 300x300 -q
done
"${PYTHON:-/usr/bin/python3}" - "$tmp" "$OUT" "${names[@]}" <<'PY'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
tmp, out, names = sys.argv[1], sys.argv[2], sys.argv[3:]
fig, axes = plt.subplots(1, len(names), figsize=(2.6 * len(names), 2.9))
fig.subplots_adjust(left=0, right=1, bottom=0, top=0.9, wspace=0)
for ax, name in zip(axes, names):
    ax.imshow(plt.imread(f"{tmp}/{name}.png"))
    ax.set_title(name, fontsize=10)
    ax.axis("off")
fig.savefig(out, dpi=90)
PY
echo "wrote $OUT"
