#!/usr/bin/env bash
# A short fuzz run of each libFuzzer target, for CI: the targets are built in the sanitizer tree
# (tests/sanitizers/configure.sh: clang++, ASan, UBSan, coverage counters; CTest runs this test
# after the sanitizer test has built it; alone, it configures the tree itself), then each runs for
# SECONDS over a scratch copy of its seed corpus in tests/fuzz/corpus/. Any crash, sanitizer
# error, leak or timeout fails the run, and the input is kept in WORK_DIR.
#
# usage: smoke.sh SOURCE_DIR TREE_DIR WORK_DIR SECONDS
set -euo pipefail
src=$1 tree=$2 work=$3 seconds=$4
bash "$src/tests/sanitizers/configure.sh" "$src" "$tree"
cmake --build "$tree" -j2 --target fuzz_level fuzz_script fuzz_step >/dev/null
mkdir -p "$work"
status=0
for target in level script step; do
  corpus="$work/corpus-$target"
  rm -rf "$corpus" && mkdir -p "$corpus" && cp "$src/tests/fuzz/corpus/$target/"* "$corpus/"
  if "$tree/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$work/crash-$target-" "$corpus" >"$work/fuzz_$target.log" 2>&1; then
    echo "fuzz_$target: $(grep -Eo 'Done [0-9]+ runs in [0-9]+ second' "$work/fuzz_$target.log" | tail -1), nothing found"
  else
    echo "fuzz_$target: FAILED, see $work/fuzz_$target.log"; tail -30 "$work/fuzz_$target.log"; status=1
  fi
done
exit $status
