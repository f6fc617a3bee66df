#!/usr/bin/env bash
# Builds the extra tree that tests/sanitizers/configure.sh describes (clang++, ASan and UBSan,
# coverage counters, the fuzz targets, no OSMesa) and checks that nothing in it links OSMesa. CTest
# runs it as the setup of the three checks that use the tree (the sanitizer run, the fuzz run and
# the cross-compiler determinism check, whose clang++ witness is this tree's `rube`), so it is
# compiled once and each of them can start as soon as it is built. Does nothing already done.
#
# usage: build.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
start=$(date +%s)
bash "$src/tests/sanitizers/configure.sh" "$src" "$work"
cmake --build "$work" -j2 >/dev/null
if grep -rqi "osmesa" "$work/engine/render/CMakeFiles/rube_render.dir/link.txt" "$work/game/CMakeFiles/rube.dir/link.txt"; then
  echo "no-osmesa: the build links OSMesa although RUBE_OSMESA=OFF"
  exit 1
fi
echo "sanitizers: configured and built in $(($(date +%s) - start)) s (no OSMesa linked)"
