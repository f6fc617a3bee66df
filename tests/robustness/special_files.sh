#!/usr/bin/env bash
# Reading stops at the limit whatever the file is (issue 27): a FIFO with no writer, a FIFO with an
# endless writer, /dev/zero and /dev/urandom each fail at once with one line and exit status 2,
# for a scene, a level's script and `rube check`. Every run is under `timeout`, so a regression
# (a read that blocks or runs on) fails the test instead of hanging it.
#
# usage: special_files.sh RUBE LEVEL WORK_DIR
set -uo pipefail
rube=$1 level=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
failures=0

# expect_refused NAME FILE ARGS...: exit 2 within 10 s, exactly one line naming FILE, nothing written.
expect_refused() {
  local name=$1 file=$2
  shift 2
  timeout 10 "$rube" "$@" >"$work/out" 2>"$work/err"
  local status=$?
  local lines
  lines=$(wc -l <"$work/err")
  if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q "^$file: not a regular file" "$work/err"; then
    echo "special_files: $name: exit $status (124 is the timeout), $lines lines on stderr, expected 2 and one line:"
    cat "$work/err"
    failures=$((failures + 1))
  elif [ -e "$work/frames" ]; then
    echo "special_files: $name: refused, but wrote $work/frames"
    failures=$((failures + 1))
  else
    echo "special_files: $name: $(cat "$work/err")"
  fi
}

fifo="$work/scene.fifo"
mkfifo "$fifo"
expect_refused "FIFO without a writer (run)" "$fifo" run "$fifo" --out "$work/frames"
expect_refused "FIFO without a writer (check)" "$fifo" check "$fifo"
expect_refused "FIFO without a writer (script)" "$fifo" run "$level" --script "$fifo" --out "$work/frames"

# An endless writer: `yes` blocks on the FIFO until a reader opens it, then writes for ever.
yes 'name = "endless"' >"$fifo" &
writer=$!
expect_refused "FIFO with an endless writer" "$fifo" run "$fifo" --out "$work/frames"
kill "$writer" 2>/dev/null
wait "$writer" 2>/dev/null

for device in /dev/zero /dev/urandom; do
  expect_refused "$device" "$device" run "$device" --out "$work/frames"
done

[ "$failures" -eq 0 ] || exit 1
echo "special_files: every special file refused at once"
