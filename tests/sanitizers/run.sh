#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer, in the extra tree that
# tests/sanitizers/configure.sh describes (clang++, coverage counters for the fuzz targets, no
# OSMesa): builds it if CTest has not (tests/sanitizers/build.sh, which also checks that nothing in
# it links OSMesa) and runs its CTest (the offscreen screenshot tests there run on EGL alone: the
# no-OSMesa build's check).
# Left out: the tests that build or use trees of their own (the cross-compiler determinism check, this one,
# the fuzz run, which uses this tree after it), the bench (a speed run), and what only repeats code
# the other tests run, at several times the cost here: `rube solve`'s searches (hundreds of level
# runs each; the solve tests of a few runs stay), the window replay of every level (one level's
# window tests stay), the videos (ffmpeg's work) and the signal tests (their time is waiting). The
# random-case tests play fewer cases: the first 2,000 invariant scenes per method of 10,000, 50
# random scenes of 200, 100 random level plays of 400. This keeps CI under its time.
#
# usage: run.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
bash "$src/tests/sanitizers/build.sh" "$src" "$work"
built=$(date +%s)
# Mesa's llvmpipe keeps its compiled shaders and driver state until exit on purpose: its
# allocations are not ours to fix, so leaks from inside Mesa and LLVM are suppressed, nothing else.
export LSAN_OPTIONS="suppressions=$src/tests/sanitizers/lsan.supp:print_suppressions=0"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export RUBE_INVARIANT_SCENES=2000 RUBE_RANDOM_SCENES=50 RUBE_RANDOM_LEVELS=100
repeats="solve:every shipped level|solve:rope, chain-reaction and balloon|solve:pegs gave|cli: solve crates slices|video:|robustness: SIGINT"
ctest --test-dir "$work" -j2 --output-on-failure \
      -E "^(determinism: (traces|rube built)|sanitizers|fuzz|bench|screenshot: window|window:|$repeats)"
# The window test loads Mesa's DRI driver through GLX, which is unloaded before exit: LeakSanitizer
# then cannot name the module its allocations came from, so a suppression cannot match them. It
# runs with every other check on and leak detection off.
ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0" ctest --test-dir "$work" --output-on-failure -R "^(screenshot: window|window:)" \
      -E "^screenshot: window: every level played"
echo "sanitizers: tests in $(($(date +%s) - built)) s"
