#!/usr/bin/env bash
# Determinism across compilers and optimisation levels: builds `rube` with clang++ -O2 and
# g++ -O0 beside the main build (g++ -O3, CMake's Release), runs every physics scene under each,
# and requires the traces to be byte-identical to the main build's. -ffp-contract=off is what makes this hold.
#
# usage: cross_build.sh SOURCE_DIR MAIN_BUILD_DIR WORK_DIR
set -euo pipefail
src=$1 main_build=$2 work=$3
mkdir -p "$work"

build() { # name, compiler, build type, more cmake arguments...
  local dir="$work/$1"
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S "$src" -B "$dir" -DCMAKE_CXX_COMPILER="$2" -DCMAKE_BUILD_TYPE="$3" -DBUILD_TESTING=OFF "${@:4}" >/dev/null
  fi
  cmake --build "$dir" --target rube -j2 >/dev/null
  echo "$dir/rube"
}

command -v clang++ >/dev/null || { echo "cross_build: clang++ is not installed (run .ci/install-deps)" >&2; exit 1; }
# CMake's Release is -O3 (the main build's); the clang tree is given -O2 itself.
binaries=("$main_build/rube" "$(build clang-O2 clang++ Release -DCMAKE_CXX_FLAGS_RELEASE='-O2 -DNDEBUG')" "$(build gcc-O0 g++ Debug)")
names=("main (g++ -O3)" "clang++ -O2" "g++ -O0")

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
