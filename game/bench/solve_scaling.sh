#!/bin/bash
# rube solve's scaling with threads: the best of three wall times of the same search with --jobs 1
# and --jobs 2 (results identical, tested), their ratio, and the load average before and after,
# since on a shared machine the load decides what a second thread can get.
#   game/bench/solve_scaling.sh build/rube [LEVEL] [extra rube solve options...]
set -euo pipefail
rube=${1:?usage: solve_scaling.sh RUBE [LEVEL] [OPTIONS...]}
level=${2:-levels/seesaw.toml}
shift $(( $# >= 2 ? 2 : 1 ))
best() {
  local best=
  for _ in 1 2 3; do
    local start end t
    start=$(date +%s.%N)
    "$rube" solve "$level" "$@" > /dev/null || [ $? -eq 1 ]
    end=$(date +%s.%N)
    t=$(echo "$end - $start" | bc)
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc)" = 1 ]; then best=$t; fi
  done
  echo "$best"
}
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
one=$(best --jobs 1 "$@")
two=$(best --jobs 2 "$@")
echo "load after:  $(cut -d' ' -f1-3 /proc/loadavg)"
printf 'jobs 1: %.2f s\njobs 2: %.2f s\nscaling: %.2f x\n' "$one" "$two" "$(echo "$one / $two" | bc -l)"
