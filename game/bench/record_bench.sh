#!/usr/bin/env bash
# record_bench.sh: end-to-end cost of `rube run --out`, the way a user records a video: simulate,
# draw, render offscreen, encode and write every frame. Not a test: the figures depend on the
# machine and on what else it is doing. Prints one CSV row per offscreen back end in the format of
# results.csv: EGL, then OSMesa, one after the other in the same run so their figures compare
# (GL_BACKENDS: "egl osmesa" by default; a back end this rube was built without is skipped).
#
# Usage: game/bench/record_bench.sh RUBE [SCENE] [FRAMES] [SIZE] [OTHER_LOAD] [GL_BACKENDS]
#   e.g. game/bench/record_bench.sh build/rube levels/physics/pool-break.toml 600 1280x720 idle
set -euo pipefail
rube=${1:?usage: record_bench.sh RUBE [SCENE] [FRAMES] [SIZE] [OTHER_LOAD] [GL_BACKENDS]}
here=$(cd "$(dirname "$0")" && pwd)
scene=${2:-$here/../../levels/physics/pool-break.toml}
frames=${3:-600}
size=${4:-1280x720}
load=${5:-unknown}
backends=${6:-egl osmesa}
out=$(mktemp -d)
trap 'rm -rf "$out" "$out.time"' EXIT
commit=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)

for gl in $backends; do
  # /usr/bin/time gives the CPU time of every thread (llvmpipe's and the PNG writer's too).
  if ! summary=$(/usr/bin/time -f 'cpu %U %S' "$rube" run "$scene" --out "$out" --frames "$frames" --size "$size" --gl "$gl" 2>"$out.time"); then
    grep -q "built without" "$out.time" && continue
    cat "$out.time" >&2
    exit 1
  fi
  cpu=$(awk '/^cpu/ {print $2 + $3}' "$out.time")
  fps=$(sed -n 's/^frame rate: *\([0-9.]*\) fps.*/\1/p' <<<"$summary")
  bytes=$(sed -n 's/^frames: .*, \([0-9]*\) bytes per frame.*/\1/p' <<<"$summary")
  cpu_ms=$(awk -v c="$cpu" -v n="$frames" 'BEGIN { printf "%.1f", 1000 * c / n }')
  echo "$(date +%F),$commit,$load,$(basename "$scene" .toml),$frames,$size,$fps,$cpu_ms,$bytes,$gl"
done
