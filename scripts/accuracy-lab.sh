#!/usr/bin/env bash
# The accuracy lab (README, "Curvature estimators"): the paper's Fig. 8 for
# every estimator from exact analytic truth. Builds bench/accuracy_lab.cpp,
# runs it (about 4 minutes on 2 busy cores) and plots with scripts/plot_accuracy.py
# (Debian: python3-matplotlib) into docs/accuracy/: fig8.png, fig8.svg,
# table.md and the raw accuracy.csv.
#
#   scripts/accuracy-lab.sh [--quick] [--trials N]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
OUT=${OUT:-docs/accuracy}
PYTHON=${PYTHON:-/usr/bin/python3}
# On a fresh machine: the build's packages, and matplotlib for the plots.
scripts/install-deps.sh
if ! "$PYTHON" -c "import matplotlib" 2>/dev/null; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends python3-matplotlib
fi
if [ ! -f "$BUILD/build.ninja" ] && [ ! -f "$BUILD/Makefile" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD" --target accuracy_lab
mkdir -p "$OUT"
"$BUILD/accuracy_lab" --out "$OUT/accuracy.csv" "$@"
"$PYTHON" scripts/plot_accuracy.py "$OUT/accuracy.csv" "$OUT"
echo "wrote $OUT/fig8.png, $OUT/fig8.svg, $OUT/table.md"
