#!/usr/bin/env bash
# A run killed in the middle leaves only whole PNG frames, and running again overwrites cleanly.
# Starts `rube run --out` on the pile, SIGKILLs it while frames are being written, checks that
# every frame_NNNNN.png decodes completely, then runs again and checks the folder holds exactly
# the new run's frames (the killed run's extra frames and unfinished temporary files are gone).
#
# usage: kill_mid_run.sh RUBE SCENE WORK_DIR
set -euo pipefail
rube=$1 scene=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
frames="$work/frames"

"$rube" run "$scene" --out "$frames" --frames 100000 --size 640x360 >/dev/null 2>&1 &
pid=$!
# Kill once a few dozen frames exist: mid-run, with the writer thread busy.
for _ in $(seq 1 200); do
  count=$(find "$frames" -maxdepth 1 -name 'frame_*.png' 2>/dev/null | wc -l || true)
  [ "$count" -ge 30 ] && break
  sleep 0.05
done
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
killed=$(find "$frames" -maxdepth 1 -name 'frame_*.png' | wc -l)
[ "$killed" -ge 30 ] || { echo "kill_mid_run: only $killed frames before the kill"; exit 1; }
python3 "$(dirname "$0")/check_png.py" "$frames"/frame_*.png
echo "kill_mid_run: $killed whole frames after SIGKILL"

# Again, shorter: exactly its 10 frames remain, and nothing unfinished.
"$rube" run "$scene" --out "$frames" --frames 10 --size 640x360 >/dev/null
left=$(find "$frames" -maxdepth 1 -name 'frame_*.png' | wc -l)
litter=$(find "$frames" -maxdepth 1 -name '.*.part' | wc -l)
[ "$left" -eq 10 ] || { echo "kill_mid_run: $left frames after the rerun, expected 10"; exit 1; }
[ "$litter" -eq 0 ] || { echo "kill_mid_run: $litter unfinished files left after the rerun"; exit 1; }
python3 "$(dirname "$0")/check_png.py" "$frames"/frame_*.png
echo "kill_mid_run: the rerun left exactly its 10 frames"
