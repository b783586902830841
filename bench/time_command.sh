#!/usr/bin/env bash
# Median wall time of a whole command over repeated runs (after one warm-up
# run, so the input file is in the page cache).
#   bench/time_command.sh RUNS COMMAND...
# e.g. bench/time_command.sh 11 build/kappa curvature ../shared/meshes/bunny-1M.ply -o /tmp/out.ply -q
set -euo pipefail
runs=$1
shift
"$@" >/dev/null
times=()
for _ in $(seq "$runs"); do
  start=$(date +%s%N)
  "$@" >/dev/null
  end=$(date +%s%N)
  times+=($(((end - start) / 1000000)))
done
sorted=$(printf '%s\n' "${times[@]}" | sort -n)
median=$(echo "$sorted" | sed -n "$(((runs + 1) / 2))p")
echo "runs (ms): ${times[*]}"
echo "median: ${median} ms  min: $(echo "$sorted" | head -1) ms  max: $(echo "$sorted" | tail -1) ms"
