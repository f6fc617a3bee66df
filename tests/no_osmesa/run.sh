#!/usr/bin/env bash
# The build the day Debian drops OSMesa (Mesa 25.1 removed it; issue 25): in a tree configured
# with -DRUBE_OSMESA=OFF, builds only the renderer, rube and the test binaries that draw, and runs
# the renderer's tests, every offscreen screenshot test, the rube run cli tests (--gl auto must
# pick EGL, --gl osmesa must say it was not built) and the byte-identical frames check. Window
# tests, sanitizers, fuzzing and the cross-compiler check stay with the main tree.
# The tree is the cross-compiler check's g++ -O0 one (tests/determinism/cross_build.sh configures
# it with -DRUBE_OSMESA=OFF and builds rube there first; CTest runs this test after it), so only
# the test binaries are compiled here. Alone (the determinism test excluded) it configures the
# tree itself, with the same arguments. The physics gives the same bits at -O0, so the same
# goldens must pass.
#
# usage: run.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
start=$(date +%s)
# Testing on, on top of the cross-compiler check's configuration (which leaves it off): the
# objects already built keep their flags and are not compiled again.
cmake -S "$src" -B "$work" -DCMAKE_CXX_COMPILER=g++ -DCMAKE_BUILD_TYPE=Debug -DRUBE_OSMESA=OFF -DBUILD_TESTING=ON >/dev/null
cmake --build "$work" -j2 --target rube render_tests screenshot_tests scene_screenshot_tests level_screenshot_tests >/dev/null
built=$(date +%s)
if grep -rqi "osmesa" "$work/engine/render/CMakeFiles/rube_render.dir/link.txt" "$work/game/CMakeFiles/rube.dir/link.txt"; then
  echo "no-osmesa: the build links OSMesa although RUBE_OSMESA=OFF"
  exit 1
fi
ctest --test-dir "$work" -j2 --output-on-failure -R "^(render:|screenshot|cli: run)" -E "^screenshot: window"
echo "no-osmesa: configured and built in $((built - start)) s, tests in $(($(date +%s) - built)) s"
