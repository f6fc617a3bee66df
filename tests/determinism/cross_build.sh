#!/usr/bin/env bash
# Determinism across compilers and optimisation levels: runs every physics scene under `rube` as
# the main build made it (g++ -O3, CMake's Release), as the sanitizer tree made it (clang++ -O2
# with ASan and UBSan, which add checks and change no arithmetic: tests/sanitizers/configure.sh;
# built by tests/sanitizers/build.sh if CTest has not built it yet), and as g++ -O0 makes it (a
# tree of its own beside the main build, `rube` alone, without debug information), and requires the
# traces to be byte-identical. -ffp-contract=off is what makes this hold. The clang++ witness was a
# third tree of its own until the sanitizer tree could serve: CI compiled the game once less.
#
# CTest builds the g++ -O0 tree first, as a test of its own (`--build-only`), so it compiles while
# the sanitizer tree does rather than after it.
#
# usage: cross_build.sh [--build-only] SOURCE_DIR MAIN_BUILD_DIR SANITIZER_TREE WORK_DIR
set -euo pipefail
build_only=0
[ "${1:-}" = "--build-only" ] && { build_only=1; shift; }
src=$1 main_build=$2 clang_tree=$3 work=$4
mkdir -p "$work"

build() { # name, compiler, build type, more cmake arguments...
  local dir="$work/$1"
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S "$src" -B "$dir" -DCMAKE_CXX_COMPILER="$2" -DCMAKE_BUILD_TYPE="$3" -DBUILD_TESTING=OFF "${@:4}" >/dev/null
  fi
  cmake --build "$dir" --target rube -j2 >/dev/null
  echo "$dir/rube"
}

# CMake's Release is -O3 (the main build's); Debug's -g is dropped: only the code matters here.
start=$(date +%s)
gcc_O0=$(build gcc-O0 g++ Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DCMAKE_C_FLAGS_DEBUG=-O0)
if [ $build_only = 1 ]; then echo "cross_build: g++ -O0 rube built in $(($(date +%s) - start)) s"; exit 0; fi
command -v clang++ >/dev/null || { echo "cross_build: clang++ is not installed (run .ci/install-deps)" >&2; exit 1; }
bash "$src/tests/sanitizers/build.sh" "$src" "$clang_tree" >/dev/null
# Nothing of Mesa is loaded without rendering, so the leak check stays on with no suppression.
export ASAN_OPTIONS="detect_leaks=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
binaries=("$main_build/rube" "$clang_tree/rube" "$gcc_O0")
names=("main (g++ -O3)" "clang++ -O2 (sanitizer tree)" "g++ -O0")

# Each scene under its own method, for a few simulated seconds; the small scenes under every method.
runs=()
for scene in "$src"/levels/physics/*.toml; do runs+=("$scene|"); done
for method in discrete turn-based exact solver; do
  runs+=("$src/levels/physics/pool-break.toml|$method" "$src/levels/physics/bounce.toml|$method")
done

status=0
for run in "${runs[@]}"; do
  scene=${run%|*} method=${run#*|}
  args=(run "$scene" --no-render --steps 240)
  [ -n "$method" ] && args+=(--method "$method")
  reference=""
  for i in "${!binaries[@]}"; do
    trace="$work/trace-$i.csv"
    "${binaries[$i]}" "${args[@]}" --trace "$trace" >/dev/null
    sum=$(sha256sum "$trace" | cut -c1-16)
    if [ -z "$reference" ]; then reference=$sum
    elif [ "$sum" != "$reference" ]; then
      echo "DIFFERS: $(basename "$scene") ${method:-(own method)}: ${names[$i]} $sum vs main $reference"
      status=1
    fi
  done
  echo "same: $(basename "$scene" .toml) ${method:-(own method)} $reference"
done
exit $status
