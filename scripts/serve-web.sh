#!/usr/bin/env bash
# Builds the browser page (scripts/build-web.sh) and serves it on localhost:
#   scripts/serve-web.sh [PORT]          (default 8000)
# then open http://localhost:PORT/ (add ?mesh=URL to open a mesh: docs/web.md).
# The meshes of ../shared/meshes, when that folder exists, are served under meshes/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
port=${1:-8000}
"$root/scripts/build-web.sh" "$root/build-web"
if [ -d "$root/../shared/meshes" ] && [ ! -e "$root/build-web/meshes" ]; then
  ln -s "$(cd "$root/../shared/meshes" && pwd)" "$root/build-web/meshes"
fi
echo "serve-web.sh: http://localhost:$port/ (Ctrl-C stops)"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$root/build-web"
