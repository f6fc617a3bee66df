#!/usr/bin/env bash
# Two runs into one --out folder never mix their frames (issue 27). A long run holds the folder;
# a second run started meanwhile refuses with one line ("DIR is in use by another rube run (pid N)"),
# exit status 2, and writes nothing: the first run ends with exactly its own frames. A run killed
# with SIGKILL leaves no lock behind (flock dies with the process): the next run goes ahead.
#
# usage: two_runs_one_folder.sh RUBE LONG_SCENE SHORT_SCENE WORK_DIR
set -euo pipefail
rube=$1 long=$2 short=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
frames="$work/frames"
fail() { echo "two_runs_one_folder: $*"; exit 1; }

# wait_for_frames N: until the folder holds N frames (the first run owns it by then).
wait_for_frames() {
  for _ in $(seq 1 400); do
    [ "$(find "$frames" -maxdepth 1 -name 'frame_*.png' 2>/dev/null | wc -l)" -ge "$1" ] && return 0
    sleep 0.05
  done
  fail "the first run wrote fewer than $1 frames in 20 s"
}

"$rube" run "$long" --out "$frames" --size 64x36 --frames 1200 >"$work/first.out" 2>"$work/first.err" &
first=$!
wait_for_frames 5
set +e
timeout 60 "$rube" run "$short" --out "$frames" --size 64x36 --frames 10 >"$work/second.out" 2>"$work/second.err"
second=$?
set -e
wait "$first" || fail "the first run failed: $(cat "$work/first.err")"
[ "$second" -eq 2 ] || fail "the second run exited $second, expected 2"
expected="rube run: $frames is in use by another rube run (pid $first)"
[ "$(cat "$work/second.err")" = "$expected" ] || fail "the second run said '$(cat "$work/second.err")', expected '$expected'"
[ ! -s "$work/second.out" ] || fail "the refused run printed a summary"
count=$(find "$frames" -maxdepth 1 -name 'frame_*.png' | wc -l)
[ "$count" -eq 1200 ] || fail "the folder holds $count frames, expected the first run's 1200"
echo "two_runs_one_folder: the second run refused while the first held the folder; 1200 frames, all the first run's"

# A SIGKILLed holder: its lock goes with it.
"$rube" run "$long" --out "$frames" --size 64x36 --frames 100000 >/dev/null 2>&1 &
killed=$!
wait_for_frames 5
kill -KILL "$killed"
wait "$killed" 2>/dev/null || true
timeout 60 "$rube" run "$short" --out "$frames" --size 64x36 --frames 10 >/dev/null 2>"$work/after.err" ||
  fail "the run after a SIGKILL was refused: $(cat "$work/after.err")"
count=$(find "$frames" -maxdepth 1 -name 'frame_*.png' | wc -l)
[ "$count" -eq 10 ] || fail "after the killed run's successor the folder holds $count frames, expected 10"
echo "two_runs_one_folder: a SIGKILLed run's lock did not block the next run"
