#!/usr/bin/env bash
# Builds kappa for the browser (web/, docs/web.md) with Debian's emscripten:
#   scripts/build-web.sh [OUTDIR]        (default build-web)
# OUTDIR then holds index.html, kappa-page.js, kappa.js and kappa.wasm, a static
# folder any web server can host (scripts/serve-web.sh serves it on localhost).
# Objects go to OUTDIR-cmake; ccache is used when installed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-build-web}")
objects="$out-cmake"
command -v emcmake >/dev/null || { echo "build-web.sh: emcmake not found (install emscripten: scripts/install-deps.sh)" >&2; exit 1; }
# emcc runs node with acorn, which Debian installs under /usr/share/nodejs
# (a node that is not Debian's does not look there). Debian's emscripten cache
# is prebuilt: EM_CACHE must not point elsewhere.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
unset EM_CACHE
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
emcmake cmake -S "$root/web" -B "$objects" -G Ninja "${launcher[@]}" >/dev/null
cmake --build "$objects" -j"${KAPPA_WEB_JOBS:-2}"
mkdir -p "$out"
cp "$objects/kappa.js" "$objects/kappa.wasm" "$root/web/page/index.html" "$root/web/page/kappa-page.js" "$out/"
echo "build-web.sh: $out (index.html kappa-page.js kappa.js kappa.wasm)"
