#!/usr/bin/env bash
# A short fuzz run of each libFuzzer target, for CI: builds the fuzz tree with clang (once), then
# runs every target for SECONDS over a scratch copy of its seed corpus in tests/fuzz/corpus/.
# Any crash, sanitizer error, leak or timeout fails the run, and the input is kept in WORK_DIR.
#
# usage: smoke.sh SOURCE_DIR WORK_DIR SECONDS
set -euo pipefail
src=$1 work=$2 seconds=$3
command -v clang++ >/dev/null || { echo "fuzz: clang++ is not installed (run .ci/install-deps)" >&2; exit 1; }
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all"
if [ ! -f "$work/build/CMakeCache.txt" ]; then
  cmake -S "$src" -B "$work/build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DRUBE_FUZZ=ON \
        -DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" >/dev/null
fi
cmake --build "$work/build" -j2 --target fuzz_level fuzz_script fuzz_step >/dev/null
status=0
for target in level script step; do
  corpus="$work/corpus-$target"
  rm -rf "$corpus" && mkdir -p "$corpus" && cp "$src/tests/fuzz/corpus/$target/"* "$corpus/"
  if "$work/build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$work/crash-$target-" "$corpus" >"$work/fuzz_$target.log" 2>&1; then
    echo "fuzz_$target: $(grep -Eo 'Done [0-9]+ runs in [0-9]+ second' "$work/fuzz_$target.log" | tail -1), nothing found"
  else
    echo "fuzz_$target: FAILED, see $work/fuzz_$target.log"; tail -30 "$work/fuzz_$target.log"; status=1
  fi
done
exit $status
