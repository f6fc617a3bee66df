#!/usr/bin/env bash
# SIGINT and SIGTERM stop scene runs and level runs alike (issue 27): one line on stderr naming
# the signal, exit status 1, no temporary left (the trace's t.csv.tmp-PID, summary.json.tmp), and
# the summary saying the run was interrupted (stdout; summary.json for a level run with --out).
# After a SIGKILL, the next run writing the same trace removes the dead run's temporary.
#
# usage: signals.sh RUBE SCENE LEVEL WORK_DIR   (SCENE and LEVEL must run for minutes uninterrupted)
set -uo pipefail
rube=$1 scene=$2 level=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
failures=0
fail() { echo "signals: $*"; failures=$((failures + 1)); }

# interrupt SIGNAL NAME ARGS...: starts rube ARGS, sends SIGNAL once it is well into its steps,
# and checks the status, the one line and the summary's "interrupted" line.
interrupt() {
  local signal=$1 name=$2
  shift 2
  "$rube" "$@" >"$work/$name.out" 2>"$work/$name.err" &
  local pid=$!
  sleep 1.5
  kill -"$signal" "$pid"
  # A run that ignores the signal is killed after 30 s, and fails below.
  for _ in $(seq 1 300); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  kill -0 "$pid" 2>/dev/null && kill -KILL "$pid"
  wait "$pid"
  local status=$?
  local lines
  lines=$(wc -l <"$work/$name.err")
  [ "$status" -eq 1 ] || fail "$name: exit status $status after SIG$signal, expected 1"
  [ "$lines" -eq 1 ] && grep -q "^rube run: interrupted by SIG$signal " "$work/$name.err" ||
    fail "$name: stderr is not one 'rube run: interrupted by SIG$signal ...' line: $(cat "$work/$name.err")"
  grep -q "^interrupted: *by SIG$signal " "$work/$name.out" || fail "$name: the printed summary does not say it was interrupted"
  echo "signals: $name: $(cat "$work/$name.err")"
}

for signal in INT TERM; do
  trace="$work/scene-$signal.csv"
  interrupt "$signal" "scene-$signal" run "$scene" --no-render --steps 100000000 --trace "$trace"
  left=$(find "$work" -maxdepth 1 -name "scene-$signal.csv*" | wc -l)
  [ "$left" -eq 0 ] || fail "scene-$signal: the trace or its temporary was left: $(ls "$work")"

  out="$work/level-$signal"
  interrupt "$signal" "level-$signal" run "$level" --steps 100000000 --out "$out" --size 32x18
  [ -f "$out/summary.json" ] || fail "level-$signal: no summary.json"
  grep -q '"interrupted": true' "$out/summary.json" && grep -q "\"signal\": \"SIG$signal\"" "$out/summary.json" ||
    fail "level-$signal: summary.json does not say SIG$signal interrupted it"
  [ ! -e "$out/summary.json.tmp" ] || fail "level-$signal: summary.json.tmp was left"
done

# SIGKILL cannot be caught: the killed run's t.csv.tmp-PID stays, and the next run writing the same
# trace removes it (its process is gone) before writing its own.
trace="$work/scene-KILL.csv"
"$rube" run "$scene" --no-render --steps 100000000 --trace "$trace" >/dev/null 2>&1 &
pid=$!
sleep 1
kill -KILL "$pid"
wait "$pid" 2>/dev/null
[ -e "$trace.tmp-$pid" ] || fail "scene-KILL: the SIGKILLed run left no $trace.tmp-$pid to clean up"
"$rube" run "$scene" --no-render --steps 2 --trace "$trace" >/dev/null 2>"$work/after-kill.err" ||
  fail "scene-KILL: the run after the SIGKILL failed: $(cat "$work/after-kill.err")"
left=$(find "$work" -maxdepth 1 -name "scene-KILL.csv.tmp-*" | wc -l)
[ "$left" -eq 0 ] && [ -f "$trace" ] || fail "scene-KILL: the next run left $left temporaries (or no trace)"
[ "$left" -eq 0 ] && echo "signals: scene-KILL: the next run removed the killed run's $trace.tmp-$pid"

[ "$failures" -eq 0 ] || exit 1
echo "signals: SIGINT and SIGTERM stop scenes and levels alike"
