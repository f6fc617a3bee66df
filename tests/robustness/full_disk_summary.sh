#!/usr/bin/env bash
# A full disk when summary.json is written (issue 27): the run fails with one line that gives the
# reason, leaves no temporary, and no stale summary.json of an earlier run beside the new frames.
# The full disk is /dev/full standing at the summary's temporary name (a symlink), so the write
# fails with ENOSPC as on a real full disk; this needs neither root nor a mount.
#
# usage: full_disk_summary.sh RUBE LEVEL SOLUTION WORK_DIR
set -euo pipefail
rube=$1 level=$2 solution=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
out="$work/out"
fail() { echo "full_disk_summary: $*"; exit 1; }
[ -w /dev/full ] || { echo "full_disk_summary: SKIPPED: /dev/full is not writable here"; exit 0; }

# An earlier run's summary, and the full disk waiting at the temporary's name.
mkdir -p "$out"
echo '{"level": "an earlier run"}' >"$out/summary.json"
ln -s /dev/full "$out/summary.json.tmp"
set +e
"$rube" run "$level" --script "$solution" --out "$out" --size 32x18 >"$work/stdout" 2>"$work/stderr"
status=$?
set -e
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
expected="rube run: cannot write $out/summary.json: No space left on device"
[ "$(cat "$work/stderr")" = "$expected" ] || fail "stderr '$(cat "$work/stderr")', expected '$expected'"
[ ! -e "$out/summary.json.tmp" ] && [ ! -L "$out/summary.json.tmp" ] || fail "the temporary $out/summary.json.tmp was left behind"
[ ! -e "$out/summary.json" ] || fail "the earlier run's summary.json is still beside the new frames"
[ -e "$out/frame_00000.png" ] || fail "no frames were written before the summary"
echo "full_disk_summary: $(cat "$work/stderr"); no temporary, no stale summary"
