#!/usr/bin/env bash
# The build the day Debian drops OSMesa (Mesa 25.1 removed it; issue 25): configures a second tree
# with -DRUBE_OSMESA=OFF, builds only the renderer, rube and the test binaries that draw, and runs
# the renderer's tests, every offscreen screenshot test, the rube run cli tests (--gl auto must
# pick EGL, --gl osmesa must say it was not built) and the byte-identical frames check. Window
# tests, sanitizers, fuzzing and the cross-compiler check stay with the main tree.
# Built at -O0 without debug information, a third cheaper than -O2 (2026-11-25, 2-core machine:
# 107 s of user CPU against 157 s for these targets): what is under test is the configuration,
# and the physics gives the same bits at -O0 (cross_build.sh), so the same goldens must pass.
#
# usage: run.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
start=$(date +%s)
if [ ! -f "$work/CMakeCache.txt" ]; then
  cmake -S "$src" -B "$work" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS=-O0 -DCMAKE_C_FLAGS=-O0 -DRUBE_OSMESA=OFF >/dev/null
fi
cmake --build "$work" -j2 --target rube render_tests screenshot_tests scene_screenshot_tests level_screenshot_tests >/dev/null
built=$(date +%s)
if grep -rqi "osmesa" "$work/engine/render/CMakeFiles/rube_render.dir/link.txt" "$work/game/CMakeFiles/rube.dir/link.txt"; then
  echo "no-osmesa: the build links OSMesa although RUBE_OSMESA=OFF"
  exit 1
fi
ctest --test-dir "$work" -j2 --output-on-failure -R "^(render:|screenshot|cli: run)" -E "^screenshot: window"
echo "no-osmesa: configured and built in $((built - start)) s, tests in $(($(date +%s) - built)) s"
