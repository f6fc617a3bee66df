#!/usr/bin/env bash
# rube run --video (issue 25), checked with ffprobe: each format's frame count, size and rate;
# the same frames as --out (count); a level's playthrough; ffmpeg missing (one line naming the
# package, exit 1, nothing written); ffmpeg failing (its status and last line, exit 1, nothing
# under the final name); a run killed by SIGTERM or SIGINT (exit 1, no video, no temporary), and
# a SIGKILLed run's temporary removed by the next run writing the same video.
# Without ffmpeg the test is skipped (exit 77, CTest's SKIP_RETURN_CODE) with the reason; CI
# installs it (.ci/install-deps), so there it runs.
#
# usage: videos.sh RUBE SCENE LEVEL SCRIPT WORK_DIR   (SCENE: a physics scene with a 1/60 s step)
set -uo pipefail
rube=$1 scene=$2 level=$3 script=$4 work=$5
if ! command -v ffmpeg >/dev/null || ! command -v ffprobe >/dev/null; then
  echo "videos: SKIPPED: ffmpeg/ffprobe not installed (apt-get install ffmpeg, or bash .ci/install-deps)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
failures=0
fail() { echo "videos: FAIL: $*"; failures=$((failures + 1)); }

# probe FILE: "width,height,rate,frames" of the first video stream, frames counted by decoding.
probe() {
  ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=width,height,r_frame_rate,nb_read_frames \
    -of csv=p=0 "$1"
}

# Formats x sizes x frame rates: --every K at a 1/60 s step is 60/K frames a second. 10 and 20
# are exact in a GIF's hundredths of a second; 60/7 is not a whole number for mp4 and webm.
for format in mp4 webm gif; do
  for case in "320x180 6 12 10/1" "160x90 3 7 20/1" "96x64 7 5 60/7"; do
    read -r size every frames rate <<<"$case"
    [ "$format" = gif ] && [ "$rate" = 60/7 ] && continue
    video="$work/scene-$size-$every.$format"
    if ! "$rube" run "$scene" --video "$video" --size "$size" --every "$every" --frames "$frames" >"$video.out" 2>"$video.err"; then
      fail "$video: rube failed: $(cat "$video.err")"
      continue
    fi
    expected="${size%x*},${size#*x},$rate,$frames"
    got=$(probe "$video")
    [ "$got" = "$expected" ] || fail "$video: ffprobe says $got, expected $expected (width,height,rate,frames)"
    grep -q "^video: *$video ($frames frames of $size at " "$video.out" || fail "$video: the summary has no video line: $(cat "$video.out")"
    grep -q "^gl: " "$video.out" || fail "$video: the summary names no GL back end"
    echo "videos: $video: $got"
  done
done

# --video with --out: the video holds the frames the PNGs hold.
"$rube" run "$scene" --out "$work/both" --video "$work/both.mp4" --size 320x180 --every 4 --frames 9 >/dev/null 2>"$work/both.err" ||
  fail "--out with --video failed: $(cat "$work/both.err")"
pngs=$(find "$work/both" -name 'frame_*.png' | wc -l)
got=$(probe "$work/both.mp4")
[ "$pngs" -eq 9 ] && [ "${got##*,}" -eq 9 ] || fail "--out and --video: $pngs PNGs and ${got##*,} video frames, expected 9 and 9"

# A level's playthrough by its script, as the README's preview is made.
"$rube" run "$level" --script "$script" --video "$work/level.gif" --size 320x180 --every 6 >"$work/level.out" 2>"$work/level.err" ||
  fail "level video failed: $(cat "$work/level.err")"
# Its rate is 1 / (the level's time step x 6), here a whole number of hundredths (a GIF's unit).
got=$(probe "$work/level.gif")
summary=$(sed -n 's/^video: .*(\([0-9]*\) frames of \(320x180\) at \([0-9/]*\) fps.*/320,180,\3,\1/p' "$work/level.out")
[ -n "$summary" ] && [ "$got" = "$summary" ] || fail "level video: ffprobe says $got, the summary $summary"
echo "videos: $work/level.gif: $got"

# ffmpeg missing: one line naming the package, exit 1, nothing written.
PATH=/nonexistent "$rube" run "$scene" --video "$work/missing.mp4" --frames 3 >/dev/null 2>"$work/missing.err"
status=$?
[ "$status" -eq 1 ] || fail "missing ffmpeg: exit status $status, expected 1"
[ "$(wc -l <"$work/missing.err")" -eq 1 ] && grep -q "apt-get install ffmpeg" "$work/missing.err" ||
  fail "missing ffmpeg: not one line naming the package: $(cat "$work/missing.err")"
[ -z "$(find "$work" -name '*missing.mp4*')" ] || fail "missing ffmpeg: something was written: $(find "$work" -name '*missing.mp4*')"

# ffmpeg failing: a stand-in that reads a little, complains and exits 3. rube reports its status
# and its message, exits 1, and leaves nothing under the final name nor a temporary.
mkdir -p "$work/fake"
printf '#!/bin/sh\nhead -c 1000 >/dev/null\necho "fake ffmpeg: encoder exploded" >&2\nexit 3\n' >"$work/fake/ffmpeg"
chmod +x "$work/fake/ffmpeg"
PATH="$work/fake:$PATH" "$rube" run "$scene" --video "$work/failing.mp4" --frames 30 --size 320x180 >/dev/null 2>"$work/failing.err"
status=$?
[ "$status" -eq 1 ] || fail "failing ffmpeg: exit status $status, expected 1"
[ "$(wc -l <"$work/failing.err")" -eq 1 ] && grep -q "exit status 3.*fake ffmpeg: encoder exploded" "$work/failing.err" ||
  fail "failing ffmpeg: not one line with its status and message: $(cat "$work/failing.err")"
[ -z "$(find "$work" -name '*failing.mp4*')" ] || fail "failing ffmpeg: left $(find "$work" -name '*failing.mp4*')"

# Interrupted: SIGTERM and SIGINT once the temporary exists; exit 1, no video, no temporary.
for signal in TERM INT; do
  video="$work/killed-$signal.mp4"
  "$rube" run "$scene" --video "$video" --steps 100000000 --size 320x180 >/dev/null 2>"$work/killed-$signal.err" &
  pid=$!
  for _ in $(seq 1 300); do [ -n "$(find "$work" -name ".killed-$signal.mp4.*.part")" ] && break; sleep 0.1; done
  sleep 0.5
  kill -"$signal" "$pid"
  wait "$pid"
  status=$?
  [ "$status" -eq 1 ] || fail "SIG$signal: exit status $status, expected 1"
  grep -q "^rube run: interrupted by SIG$signal .*no video written" "$work/killed-$signal.err" ||
    fail "SIG$signal: stderr does not say no video was written: $(cat "$work/killed-$signal.err")"
  [ -z "$(find "$work" -name "*killed-$signal.mp4*")" ] || fail "SIG$signal: left $(find "$work" -name "*killed-$signal.mp4*")"
done

# SIGKILL: nothing under the final name; the dead run's temporary goes with the next run's video.
video="$work/killed-KILL.mp4"
"$rube" run "$scene" --video "$video" --steps 100000000 --size 320x180 >/dev/null 2>&1 &
pid=$!
for _ in $(seq 1 300); do [ -n "$(find "$work" -name ".killed-KILL.mp4.*.part")" ] && break; sleep 0.1; done
sleep 0.5
kill -KILL "$pid"
wait "$pid" 2>/dev/null
# Its ffmpeg, in a process group of its own, sees the input end and finishes the temporary.
for _ in $(seq 1 50); do pgrep -f "killed-KILL.mp4.$pid.part" >/dev/null || break; sleep 0.1; done
[ ! -e "$video" ] || fail "SIGKILL: a video was left under the final name"
[ -e "$work/.killed-KILL.mp4.$pid.part" ] || fail "SIGKILL: the killed run left no temporary to clean up (test broken?)"
"$rube" run "$scene" --video "$video" --frames 3 --size 320x180 >/dev/null 2>&1 || fail "the run after SIGKILL failed"
[ -z "$(find "$work" -name ".killed-KILL.mp4.*")" ] || fail "the run after SIGKILL left $(find "$work" -name '.killed-KILL.mp4.*')"

[ "$failures" -eq 0 ] || { echo "videos: $failures failure(s)"; exit 1; }
echo "videos: all checks passed"
