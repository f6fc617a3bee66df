#!/usr/bin/env bash
# Configures the one extra tree CI builds beside the main one for three checks, so the physics and
# the game are compiled once for all of them (issue 25's no-OSMesa build, the sanitizers, the fuzz
# smoke run; CI took 36 minutes when each had its own tree):
#   - clang++ with AddressSanitizer and UndefinedBehaviorSanitizer, -O2 -g1 (line tables: enough for
#     the sanitizers' stack traces), any error aborting the test that hit it; its `rube` is also the
#     cross-compiler determinism check's clang++ -O2 witness (tests/determinism/cross_build.sh): the
#     sanitizers only add checks, they change no arithmetic, and -O2 compiles here no slower than -O1;
#   - edge coverage counters (-fsanitize-coverage=inline-8bit-counters,pc-table), what libFuzzer
#     steers by, and the fuzz targets (-DRUBE_FUZZ=ON); the comparison tracing libFuzzer can also
#     use (trace-cmp) is left out: it calls out at every comparison and would slow every test;
#   - without OSMesa (-DRUBE_OSMESA=OFF): the renderer, rube and every offscreen screenshot test
#     built and run on EGL alone, so the day Debian drops OSMesa (Mesa 25.1 removed it) nothing
#     breaks. The main tree runs the same goldens under both back ends.
# No bench programs (a speed run means nothing here).
#
# usage: configure.sh SOURCE_DIR WORK_DIR    (does nothing when WORK_DIR is configured already)
set -euo pipefail
src=$1 work=$2
[ -f "$work/CMakeCache.txt" ] && exit 0
command -v clang++ >/dev/null || { echo "sanitizers: clang++ is not installed (run .ci/install-deps)" >&2; exit 1; }
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
flags="$flags -fsanitize-coverage=inline-8bit-counters,pc-table"
cmake -S "$src" -B "$work" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRUBE_BENCH=OFF -DRUBE_OSMESA=OFF -DRUBE_FUZZ=ON \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
