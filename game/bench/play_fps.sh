#!/usr/bin/env bash
# play_fps.sh: frames per second of `rube play` in a window under Xvfb, for every level, playing
# its solution (--run --script SOLUTION) with vsync off (--no-vsync), so the figure is what the
# loop can draw, not the display's refresh. Each frame takes 2 steps (--steps-per-frame 2): more
# physics per frame than real time needs at 60 frames a second for any level (their steps are
# 1/100 s or longer), and 400 frames cover every level past its goal. Not a test: it depends on
# the machine and on what else it does. Prints CSV rows in the format of play_fps.csv.
#
# Usage: game/bench/play_fps.sh RUBE [FRAMES] [SIZE] [OTHER_LOAD]
#   e.g. game/bench/play_fps.sh build/rube 400 1280x720 idle >> game/bench/play_fps.csv
set -euo pipefail
rube=${1:?usage: play_fps.sh RUBE [FRAMES] [SIZE] [OTHER_LOAD]}
frames=${2:-400}
size=${3:-1280x720}
load=${4:-unknown}
here=$(cd "$(dirname "$0")" && pwd)
levels=$here/../../levels
commit=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
for solution in "$levels"/*.solution.toml; do
  name=$(basename "$solution" .solution.toml)
  summary=$(xvfb-run -a -s "-screen 0 1920x1200x24" "$rube" play "$levels/$name.toml" --script "$solution" --run \
              --quit-after "$frames" --steps-per-frame 2 --no-vsync --size "$size")
  fps=$(sed -n 's/^frame rate: *\([0-9.]*\) fps.*/\1/p' <<<"$summary")
  steps=$(sed -n 's/^steps: *//p' <<<"$summary")
  echo "$(date +%F),$commit,$load,$name,$frames,$size,$steps,$fps"
done
