#!/usr/bin/env bash
# `rube play` under the caller's xvfb-run, as the README prints it: --quit-after counts simulation
# steps (not frames drawn), so the run ends at step N on any machine; a run that ends without its
# goal exits 1, as `rube run` does; a goal reached is kept in the progress file under
# $XDG_DATA_HOME/rube; with no LEVEL and an index that cannot be read, exit 2 and one line.
#   quit_after_progress.sh RUBE LEVELS_DIR WORK_DIR
set -uo pipefail
rube=$1 levels=$2 work=$3
rm -rf "$work" && mkdir -p "$work/data"
export XDG_DATA_HOME="$work/data"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# The README's example, at real-time pace: each run at a different pace reaches the same step.
for steps in 300 420; do
  "$rube" play "$levels/cannon-arc.toml" --script "$levels/cannon-arc.solution.toml" --run --quit-after "$steps" \
      > "$work/arc-$steps.txt" 2>&1
  status=$?
  cat "$work/arc-$steps.txt"
  [[ $status == 0 ]] || fail "--quit-after $steps: exit $status, expected 0"
  grep -q "^steps: *$steps\$" "$work/arc-$steps.txt" || fail "--quit-after $steps: the run did not stop at step $steps"
  grep -q "^goal: *reached at step" "$work/arc-$steps.txt" || fail "--quit-after $steps: goal not reached"
done
grep -qx "cannon-arc" "$work/data/rube/solved.txt" || fail "cannon-arc not kept as solved in \$XDG_DATA_HOME/rube/solved.txt"

# Stopped before its goal: exit 1 with "goal: not reached"; with 7 steps drawn a frame, the step
# count is still exact (the session takes no step past N).
goal=$(sed -n 's/^goal: *reached at step //p' "$work/arc-300.txt")
early=$((goal / 2))
(( early % 7 != 0 )) || early=$((early + 1)) # not a multiple of the pace of 7 steps a frame below
for pace in 1 7; do
  "$rube" play "$levels/cannon-arc.toml" --script "$levels/cannon-arc.solution.toml" --run --quit-after "$early" \
      --steps-per-frame "$pace" --no-vsync > "$work/early-$pace.txt" 2>&1
  status=$?
  cat "$work/early-$pace.txt"
  [[ $status == 1 ]] || fail "stopped at step $early of $goal (pace $pace): exit $status, expected 1"
  grep -q "^steps: *$early\$" "$work/early-$pace.txt" || fail "pace $pace: did not stop at step $early"
  grep -q "^goal: *not reached" "$work/early-$pace.txt" || fail "pace $pace: expected goal: not reached"
done

# No level and no index: one line, exit 2.
"$rube" play --index "$work/missing-index.toml" > "$work/no-index.txt" 2>&1
status=$?
cat "$work/no-index.txt"
[[ $status == 2 ]] || fail "a missing index: exit $status, expected 2"
[[ $(wc -l < "$work/no-index.txt") == 1 ]] || fail "a missing index: expected one line"
grep -q "missing-index.toml" "$work/no-index.txt" || fail "a missing index: the message does not name the file"
exit $failed
