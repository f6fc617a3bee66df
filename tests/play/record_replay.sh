#!/usr/bin/env bash
# Every level played in a window (under the caller's xvfb-run) from its solution script, recorded
# with --record, and the recording replayed off-screen by `rube run`: the replay must reach the
# goal at the same step the window session did.
#   record_replay.sh RUBE LEVELS_DIR WORK_DIR
set -euo pipefail
rube=$1 levels=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
failed=0
for solution in "$levels"/*.solution.toml; do
  name=$(basename "$solution" .solution.toml)
  level="$levels/$name.toml"
  # 1000 frames at one step each outlast every level's goal (the latest is paddle's, 809) and
  # every solution's before_step (at most 1000).
  if ! "$rube" play "$level" --script "$solution" --run --quit-after 1000 --steps-per-frame 1 --no-vsync \
        --size 320x180 --record "$work/$name.toml" > "$work/$name.play.txt" 2>&1; then
    echo "$name: rube play failed:"; cat "$work/$name.play.txt"; failed=1; continue
  fi
  played=$(sed -n 's/^goal: *//p' "$work/$name.play.txt")
  if ! "$rube" run "$level" --script "$work/$name.toml" --no-render > "$work/$name.run.txt" 2>&1; then
    echo "$name: the recording does not replay to the goal:"; cat "$work/$name.run.txt"; failed=1; continue
  fi
  replayed=$(sed -n 's/^goal: *//p' "$work/$name.run.txt")
  if [[ -z "$played" || "$played" != "$replayed" ]]; then
    echo "$name: window session: goal '$played'; replay: goal '$replayed'"; failed=1; continue
  fi
  echo "$name: $played in the window and in the replay"
done
exit $failed
