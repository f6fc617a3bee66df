# The `rube` command's tests, included from tests/CMakeLists.txt. Each runs the real binary
# through rube_cli.cmake, which checks the exit status, the exact one-line message and the trace.

set(RUBE_CLI_DIR ${CMAKE_CURRENT_LIST_DIR})
set(RUBE_CLI_OUT ${CMAKE_CURRENT_BINARY_DIR}/cli-out)
set(RUBE_LEVELS ${PROJECT_SOURCE_DIR}/levels/physics)
file(MAKE_DIRECTORY ${RUBE_CLI_OUT})

# rube_cli_test(NAME <name> ARGS <a|b|c> EXIT <status> [checks as -D definitions...])
function(rube_cli_test name args exit)
  add_test(NAME "cli: ${name}"
           COMMAND ${CMAKE_COMMAND} -DRUBE=$<TARGET_FILE:rube> "-DARGS=${args}" -DEXIT=${exit} ${ARGN}
                   -P ${RUBE_CLI_DIR}/rube_cli.cmake)
endfunction()

# Every physics scene passes `rube check`.
file(GLOB physics_scenes CONFIGURE_DEPENDS ${RUBE_LEVELS}/*.toml)
foreach(scene IN LISTS physics_scenes)
  get_filename_component(stem ${scene} NAME_WE)
  rube_cli_test("check ${stem}" "check|${scene}" 0 "-DSTDOUT_MATCH=^[^\n]*${stem}.toml: ok\n$")
endforeach()

# Every bad fixture fails `rube check` with status 2 and exactly the one line its '# expect:' names.
file(GLOB bad_fixtures CONFIGURE_DEPENDS ${RUBE_CLI_DIR}/bad-*.toml)
foreach(fixture IN LISTS bad_fixtures)
  get_filename_component(stem ${fixture} NAME_WE)
  rube_cli_test("check ${stem}" "check|${fixture}" 2 -DSTDERR_FIXTURE=${fixture})
endforeach()

# A good and a bad file together: the good one is ok, and the status is still 2.
rube_cli_test("check good and bad" "check|${RUBE_LEVELS}/bounce.toml|${RUBE_CLI_DIR}/bad-radius.toml" 2
              "-DSTDOUT_MATCH=bounce.toml: ok" -DSTDERR_FIXTURE=${RUBE_CLI_DIR}/bad-radius.toml)
rube_cli_test("check missing file" "check|no-such-scene.toml" 2 "-DSTDERR_LINE=no-such-scene.toml: cannot open file")

# CMake's regular expressions have no {16}: spell out the 16 hex digits of the state hash.
string(REPEAT "[0-9a-f]" 16 hex16)

# Traces: the header, then (steps + 1) x dynamic bodies rows, step 0 being the initial state.
rube_cli_test("run bounce trace" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--steps|10|--trace|${RUBE_CLI_OUT}/bounce.csv" 0
              -DTRACE=${RUBE_CLI_OUT}/bounce.csv -DROWS=11 "-DSTDOUT_MATCH=state hash: +${hex16}\n")
rube_cli_test("run pool-break trace" "run|${RUBE_LEVELS}/pool-break.toml|--no-render|--steps|5|--trace|${RUBE_CLI_OUT}/pool.csv" 0
              -DTRACE=${RUBE_CLI_OUT}/pool.csv -DROWS=96)
rube_cli_test("run pile trace" "run|${RUBE_LEVELS}/pile.toml|--no-render|--steps|2|--trace|${RUBE_CLI_OUT}/pile.csv" 0
              -DTRACE=${RUBE_CLI_OUT}/pile.csv -DROWS=3000)
# A scene's boxes are rows too, after its circles: blocks' ball (0) and its six blocks (b0 to b5), so
# 7 rows a step, each block's row its slot, six numbers and an empty radius.
rube_cli_test("run blocks trace has the boxes" "run|${RUBE_LEVELS}/blocks.toml|--no-render|--steps|10|--trace|${RUBE_CLI_OUT}/blocks.csv" 0
              -DTRACE=${RUBE_CLI_OUT}/blocks.csv -DROWS=77
              "-DTRACE_MATCH=\n10,[^,\n]*,0,[^\n]*\n10,[^,\n]*,b0,-?[0-9][^\n]*,\n10,[^\n]*,b1,[^\n]*,\n10,[^\n]*,b2,[^\n]*,\n10,[^\n]*,b3,[^\n]*,\n10,[^\n]*,b4,[^\n]*,\n10,[^,\n]*,b5,[^\n]*,\n$")
# No --steps: the scene's duration, 1.8 s at 1/60 s, is 108 steps.
rube_cli_test("run steps from duration" "run|${RUBE_LEVELS}/projectile.toml|--no-render|--trace|${RUBE_CLI_OUT}/projectile.csv" 0
              -DTRACE=${RUBE_CLI_OUT}/projectile.csv -DROWS=109 "-DSTDOUT_MATCH=steps: +108\n")
rube_cli_test("run method override" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--steps|3|--method|discrete" 0
              "-DSTDOUT_MATCH=method: +discrete\n")
rube_cli_test("run without --out or --no-render notes it" "run|${RUBE_LEVELS}/bounce.toml|--steps|1" 0
              "-DSTDERR_LINE=rube run: note: no frames written without --out DIR or --video FILE (--no-render runs headless without this note)")

# Frames: --out DIR writes frame_00000.png (the initial state) and one frame every --every steps.
# Small frames keep these quick; the pictures themselves are the screenshot tests' business.
set(frames ${RUBE_CLI_OUT}/frames)
rube_cli_test("run --out writes --frames frames" "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/five|--size|64x36|--frames|5" 0
              -DFRAMES_DIR=${frames}/five -DFRAMES=5 -DSTDERR_EMPTY=ON
              "-DSTDOUT_MATCH=steps: +4\n.*frames: +5 of 64x36, [0-9]+ bytes per frame on average, in ${frames}/five\nframe rate: +[0-9.]+ fps")
rube_cli_test("run --out with --every writes steps / K + 1 frames" "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/every|--size|32x18|--steps|10|--every|4" 0
              -DFRAMES_DIR=${frames}/every -DFRAMES=3 "-DSTDOUT_MATCH=steps: +10\n")
rube_cli_test("run --frames without --steps runs (N - 1) x K steps" "run|${RUBE_LEVELS}/projectile.toml|--out|${frames}/nk|--size|32x18|--frames|4|--every|3" 0
              -DFRAMES_DIR=${frames}/nk -DFRAMES=4 "-DSTDOUT_MATCH=steps: +9\n")
rube_cli_test("run --frames stops the frames, not the steps" "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/cut|--size|32x18|--steps|20|--frames|2" 0
              -DFRAMES_DIR=${frames}/cut -DFRAMES=2 "-DSTDOUT_MATCH=steps: +20\n")
rube_cli_test("run --out replaces an earlier run's frames only" "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/again|--size|32x18|--frames|2" 0
              -DFRAMES_DIR=${frames}/again -DSEED_FRAMES=7 -DFRAMES=2)
rube_cli_test("run --out into a file's place is status 2 and writes nothing"
              "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/blocker/out|--trace|${frames}/blocked.csv" 2
              -DBLOCKER=${frames}/blocker -DFRAMES_DIR=${frames}/blocker/out -DNO_FRAMES_DIR=ON
              -DTRACE=${frames}/blocked.csv -DNO_TRACE=ON
              "-DSTDERR_LINE=rube run: cannot write frames to ${frames}/blocker/out: Not a directory")
foreach(size 0x720 wide 9000x100 640x -64x36)
  rube_cli_test("usage bad size ${size}" "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/size|--size|${size}" 2
                -DFRAMES_DIR=${frames}/size -DNO_FRAMES_DIR=ON
                "-DSTDERR_LINE=rube: --size: expected WxH in pixels, each from 1 to 8192, got '${size}' (see 'rube run --help')")
endforeach()
rube_cli_test("usage bad every" "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/k|--every|0" 2
              "-DSTDERR_LINE=rube: --every: expected a whole number of steps from 1 to 1000000000, got '0' (see 'rube run --help')")
rube_cli_test("usage --out with --no-render" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--out|${frames}/x" 2
              "-DSTDERR_LINE=rube: --no-render excludes --out (see 'rube run --help')")
rube_cli_test("usage --trails without --out" "run|${RUBE_LEVELS}/bounce.toml|--trails" 2
              "-DSTDERR_LINE=rube: --trails requires --out or --video (see 'rube run --help')")

# Failed runs: status 2, one line, and no trace (nor a temporary) left behind.
rube_cli_test("run bad scene leaves no trace" "run|${RUBE_CLI_DIR}/bad-unknown-key.toml|--no-render|--trace|${RUBE_CLI_OUT}/bad.csv" 2
              -DSTDERR_FIXTURE=${RUBE_CLI_DIR}/bad-unknown-key.toml -DTRACE=${RUBE_CLI_OUT}/bad.csv -DNO_TRACE=ON)
rube_cli_test("run a method that cannot turn bodies" "run|${RUBE_LEVELS}/seesaw-domino.toml|--no-render|--method|exact" 2
              "-DSTDERR_LINE=rube run: --method exact cannot move the turning boxes, capsules or pivots of ${RUBE_LEVELS}/seesaw-domino.toml: use auto or solver")
rube_cli_test("run exact refuses a joint without a closed form" "run|${RUBE_CLI_DIR}/exact-hinge.toml|--no-render|--method|exact" 2
              "-DSTDERR_LINE=rube run: --method exact: ${RUBE_CLI_DIR}/exact-hinge.toml: method 'exact' cannot move joints (joint 0: the exact method follows only springs to fixed points, not a revolute joint): use method 'auto' or 'solver'")
rube_cli_test("run unknown method leaves no trace" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--method|exat|--trace|${RUBE_CLI_OUT}/method.csv" 2
              "-DSTDERR_LINE=rube run: unknown method 'exat' (valid methods: discrete, turn-based, exact, solver, auto)"
              -DTRACE=${RUBE_CLI_OUT}/method.csv -DNO_TRACE=ON)
rube_cli_test("run missing file" "run|no-such-scene.toml|--no-render" 2 "-DSTDERR_LINE=no-such-scene.toml: cannot open file")
rube_cli_test("run trace into missing folder" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--trace|${RUBE_CLI_OUT}/no/such/t.csv" 2
              "-DSTDERR_LINE=${RUBE_CLI_OUT}/no/such/t.csv: cannot write trace: No such file or directory")

# Usage errors are status 2 and one line, whatever CLI11's own code for them would be.
rube_cli_test("usage no command" "" 2 "-DSTDERR_LINE=rube: A subcommand is required (see 'rube --help')")
rube_cli_test("usage unknown command" "frobnicate" 2 "-DSTDERR_LINE=rube: unknown command 'frobnicate': the commands are run, play, edit, check, items and solve (see 'rube --help')")
rube_cli_test("usage run without scene" "run|--no-render" 2 "-DSTDERR_LINE=rube: scene is required (see 'rube run --help')")
rube_cli_test("usage bad steps" "run|${RUBE_LEVELS}/bounce.toml|--steps|ten" 2
              "-DSTDERR_LINE=rube: --steps: expected a whole number of steps, 0 or more, got 'ten' (see 'rube run --help')")
rube_cli_test("usage unknown option" "check|${RUBE_LEVELS}/bounce.toml|--fast" 2 "-DSTDERR_LINE=rube: The following argument was not expected: --fast (see 'rube check --help')")

# Help is for level designers and teachers: it exits 0 and names what they need.
rube_cli_test("help" "--help" 0 "-DSTDOUT_MATCH=run .*check .*Exit status")
rube_cli_test("help run" "run|--help" 0 "-DSTDOUT_MATCH=--steps .*--trace .*--method .*step,time,body,x,y,vx,vy,angle,omega,radius")
rube_cli_test("help run explains frames" "run|--help" 0
              "-DSTDOUT_MATCH=--out DIR .*--video FILE .*--every K .*--frames N .*--size WxH .*--trails .*--debug-impacts .*--gl NAME .*frame_00000.png.*apt-get install ffmpeg.*ffmpeg -framerate 60 -i out/frame_%05d.png -pix_fmt yuv420p out.mp4")
rube_cli_test("help check" "check|--help" 0 "-DSTDOUT_MATCH=file:line:col: message")

# Issue 25: --gl and --video refusals are one line, status 2, before anything runs.
rube_cli_test("run unknown --gl" "run|${RUBE_LEVELS}/bounce.toml|--out|${RUBE_CLI_OUT}/gl-bad|--gl|vulkan" 2
              "-DSTDERR_LINE=rube: --gl: expected auto, egl or osmesa, got 'vulkan' (see 'rube run --help')")
rube_cli_test("run --gl without frames" "run|${RUBE_LEVELS}/bounce.toml|--gl|egl" 2
              "-DSTDERR_LINE=rube: --gl requires --out or --video (see 'rube run --help')")
rube_cli_test("run --video of an unknown kind" "run|${RUBE_LEVELS}/bounce.toml|--video|${RUBE_CLI_OUT}/bounce.avi" 2
              "-DSTDERR_LINE=rube: --video: expected a file ending in .mp4, .webm or .gif, got '${RUBE_CLI_OUT}/bounce.avi' (see 'rube run --help')")
rube_cli_test("run --video mp4 of odd size" "run|${RUBE_LEVELS}/bounce.toml|--video|${RUBE_CLI_OUT}/bounce.mp4|--size|321x180" 2
              "-DSTDERR_LINE=rube: --video ${RUBE_CLI_OUT}/bounce.mp4: H.264 (.mp4) needs an even width and height, got 321x180 (see 'rube run --help')")
rube_cli_test("run --video with --no-render" "run|${RUBE_LEVELS}/bounce.toml|--video|${RUBE_CLI_OUT}/bounce.gif|--no-render" 2
              "-DSTDERR_LINE=rube: --no-render excludes --video (see 'rube run --help')")
rube_cli_test("run --video into a missing folder" "run|${RUBE_LEVELS}/bounce.toml|--video|${RUBE_CLI_OUT}/no-such-folder/bounce.gif" 2
              "-DSTDERR_LINE=rube run: cannot write ${RUBE_CLI_OUT}/no-such-folder/bounce.gif: ${RUBE_CLI_OUT}/no-such-folder is not a folder")
# EGL that cannot start (glvnd pointed at no vendor library, as on a machine without
# libegl-mesa0): --gl egl says what it tried and what to install, in one line, exit 1; --gl auto
# falls back to OSMesa and says so.
if(RUBE_EGL)
  rube_cli_test("run --gl egl without an EGL driver" "run|${RUBE_LEVELS}/bounce.toml|--out|${RUBE_CLI_OUT}/gl-no-egl|--frames|2|--gl|egl" 1
                "-DSTDERR_LINE=rube run: cannot render: EGL: no display without a window system (tried EGL_EXT_platform_device (not offered), EGL_MESA_platform_surfaceless (not offered)): install libegl1, libegl-mesa0 and libgl1-mesa-dri")
  set_tests_properties("cli: run --gl egl without an EGL driver" PROPERTIES ENVIRONMENT "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent")
endif()
if(RUBE_EGL AND RUBE_OSMESA)
  rube_cli_test("run --gl auto without an EGL driver draws with OSMesa" "run|${RUBE_LEVELS}/bounce.toml|--out|${RUBE_CLI_OUT}/gl-auto-osmesa|--frames|2" 0
                "-DSTDOUT_MATCH=\ngl: +osmesa .chosen by --gl auto.\n" -DSTDERR_EMPTY=ON)
  set_tests_properties("cli: run --gl auto without an EGL driver draws with OSMesa" PROPERTIES ENVIRONMENT "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent")
  rube_cli_test("run --gl auto draws with EGL where it starts" "run|${RUBE_LEVELS}/bounce.toml|--out|${RUBE_CLI_OUT}/gl-auto-egl|--frames|2" 0
                "-DSTDOUT_MATCH=\ngl: +egl .chosen by --gl auto.\n")
endif()
rube_cli_test("level --video mp4 at a script's odd size" "run|${PROJECT_SOURCE_DIR}/levels/ramp.toml|--script|${RUBE_CLI_DIR}/levels/ramp-odd-size.solution.toml|--video|${RUBE_CLI_OUT}/ramp-odd.mp4" 2
              "-DSTDERR_LINE=rube run: cannot write ${RUBE_CLI_OUT}/ramp-odd.mp4: H.264 (.mp4) needs an even width and height, got 641x360")
if(NOT RUBE_OSMESA)
  rube_cli_test("run --gl osmesa in a build without it" "run|${RUBE_LEVELS}/bounce.toml|--out|${RUBE_CLI_OUT}/gl-osmesa|--gl|osmesa" 1
                "-DSTDERR_LINE=rube run: cannot render: OSMesa: this rube was built without it (cmake -DRUBE_OSMESA=OFF): use --gl egl or --gl auto")
endif()
if(NOT RUBE_EGL)
  rube_cli_test("run --gl egl in a build without it" "run|${RUBE_LEVELS}/bounce.toml|--out|${RUBE_CLI_OUT}/gl-egl|--gl|egl" 1
                "-DSTDERR_LINE=rube run: cannot render: EGL: this rube was built without it (cmake -DRUBE_EGL=OFF): use --gl osmesa or --gl auto")
endif()

# Determinism: two runs of the same scene write byte-identical traces and equal hashes.
add_test(NAME "cli: same trace twice"
         COMMAND ${CMAKE_COMMAND} -DRUBE=$<TARGET_FILE:rube> -DSCENE=${RUBE_LEVELS}/pool-break.toml -DSTEPS=60
                 -DTRACE=${RUBE_CLI_OUT}/twice -P ${RUBE_CLI_DIR}/same_trace.cmake)

# Rendering is deterministic: the same scene renders byte-identical PNGs twice, with llvmpipe on
# one thread (LP_NUM_THREADS=1) as on all of them, and through EGL as through OSMesa when both
# are built. Named "screenshot: " so that `ctest -R screenshot` runs it with the other tests that
# start a GL context.
if(RUBE_EGL AND RUBE_OSMESA)
  add_test(NAME "screenshot: rube run frames are byte-identical twice, with LP_NUM_THREADS=1, and under EGL and OSMesa"
           COMMAND ${CMAKE_COMMAND} -DRUBE=$<TARGET_FILE:rube> -DSCENE=${RUBE_LEVELS}/pool-break.toml -DFRAMES=40
                   -DOUT=${RUBE_CLI_OUT}/same-frames -DGL=egl -DOTHER_GL=osmesa -P ${RUBE_CLI_DIR}/same_frames.cmake)
else()
  add_test(NAME "screenshot: rube run frames are byte-identical twice and with LP_NUM_THREADS=1"
           COMMAND ${CMAKE_COMMAND} -DRUBE=$<TARGET_FILE:rube> -DSCENE=${RUBE_LEVELS}/pool-break.toml -DFRAMES=40
                   -DOUT=${RUBE_CLI_OUT}/same-frames -DGL=$<IF:$<BOOL:${RUBE_EGL}>,egl,osmesa> -P ${RUBE_CLI_DIR}/same_frames.cmake)
endif()

# Levels: a solution reaches the goal (0), the level as it stands does not (1), a bad placement
# is bad input (2) with the script's file:line:col.
set(RUBE_GAME_LEVELS ${PROJECT_SOURCE_DIR}/levels)
rube_cli_test("level ramp solved by its script" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${RUBE_GAME_LEVELS}/ramp.solution.toml" 0
              "-DSTDOUT_MATCH=goal: +reached at step 266\n")
rube_cli_test("level ramp unsolved as it stands" "run|${RUBE_GAME_LEVELS}/ramp.toml" 1
              "-DSTDERR_LINE=rube run: goal not reached: hit the flag with the ball")
rube_cli_test("level placement outside the zone" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${RUBE_CLI_DIR}/levels/ramp-outside.solution.toml" 2
              "-DSTDERR_LINE=${RUBE_CLI_DIR}/levels/ramp-outside.solution.toml:3:1: placement refused: ramp at [4, 2.5] is not wholly inside a placement zone (it spans [2.45, 2.45] to [5.55, 2.55])")
rube_cli_test("level script with an unknown cannon" "run|${RUBE_GAME_LEVELS}/cannon-arc.toml|--script|${RUBE_CLI_DIR}/levels/cannon-typo.solution.toml" 2
              "-DSTDERR_LINE=${RUBE_CLI_DIR}/levels/cannon-typo.solution.toml:5:8: unknown cannon 'gnu' in level 'cannon-arc' (did you mean 'gun'?)")
# The goal reached but an expectation missed is still a failed run (1), naming the expectation:
# the ramp's ball reaches the flag at step 266, so "before step 100" cannot be met.
set(early ${RUBE_CLI_OUT}/ramp-early.solution.toml)
file(READ ${RUBE_GAME_LEVELS}/ramp.solution.toml early_text)
file(WRITE ${early} "${early_text}\n[[expect]]\ngoal = true\nbefore_step = 100\n")
string(REGEX MATCHALL "\n" early_lines "${early_text}")
list(LENGTH early_lines early_line)
math(EXPR early_line "${early_line} + 2")
rube_cli_test("level goal reached but an expectation missed" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${early}" 1
              "-DSTDOUT_MATCH=goal: +reached at step 266\n"
              "-DSTDERR_LINE=${early}:${early_line}:1: expectation failed: goal reached before step 100")
# A level's run writes --trace with every dynamic body and its item's name: the ramp's one ball (an
# unnamed heavy ball, so its kind), steps + 1 rows (the goal at 266, then 0.5 s at 1/100 s, so 316
# steps). With --no-render too. The options a level has no use for are refused, not ignored.
rube_cli_test("level ramp --trace has steps + 1 rows" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${RUBE_GAME_LEVELS}/ramp.solution.toml|--no-render|--trace|${RUBE_CLI_OUT}/ramp.csv" 0
              -DTRACE=${RUBE_CLI_OUT}/ramp.csv -DLEVEL_ROWS=317 "-DTRACE_MATCH=\n316,3.16[0-9]*,c[0-9]+,heavy,"
              "-DSTDOUT_MATCH=steps: +316\n.*trace: +${RUBE_CLI_OUT}/ramp.csv \\(317 rows\\)")
# Every dynamic body: the crates level's two crates (boxes) are rows too, named as the level names them,
# beside its steel ball: 3 rows a step.
rube_cli_test("level crates --trace has the boxes, named" "run|${RUBE_GAME_LEVELS}/crates.toml|--script|${RUBE_GAME_LEVELS}/crates.solution.toml|--no-render|--steps|10|--trace|${RUBE_CLI_OUT}/crates.csv" 1
              -DTRACE=${RUBE_CLI_OUT}/crates.csv -DLEVEL_ROWS=33 "-DTRACE_MATCH=\n10,[^\n]*,b0,crate,[^\n]*\n10,[^\n]*,b1,last-crate,")
rube_cli_test("level with --method is refused" "run|${RUBE_GAME_LEVELS}/ramp.toml|--method|exact" 2
              "-DSTDERR_LINE=rube run: --method is for physics scenes, and ${RUBE_GAME_LEVELS}/ramp.toml is a level: a level runs by its own [world] method and is drawn as the game draws it")
rube_cli_test("level with --trails is refused" "run|${RUBE_GAME_LEVELS}/ramp.toml|--out|${frames}/trails|--trails" 2
              -DFRAMES_DIR=${frames}/trails -DNO_FRAMES_DIR=ON
              "-DSTDERR_LINE=rube run: --trails is for physics scenes, and ${RUBE_GAME_LEVELS}/ramp.toml is a level: a level runs by its own [world] method and is drawn as the game draws it")
rube_cli_test("level with --debug-impacts is refused" "run|${RUBE_GAME_LEVELS}/ramp.toml|--out|${frames}/impacts|--debug-impacts" 2
              -DFRAMES_DIR=${frames}/impacts -DNO_FRAMES_DIR=ON
              "-DSTDERR_LINE=rube run: --debug-impacts is for physics scenes, and ${RUBE_GAME_LEVELS}/ramp.toml is a level: a level runs by its own [world] method and is drawn as the game draws it")
# The summary of a level's run: the goal frame, then every event in order with its frame and item.
# The balloon's chain: the switch is hit and fires the cannon in one step, then the shot hits the target.
# Steps and frames (issue 23): the summary counts steps; summary.json also gives the time step, --every,
# the frame size and count, and the goal's step, time, the frame file that shows it (step 277 with a
# frame every 4 steps: frame 70, the first at or after it), where it happened (the bullseye's hit,
# not [0, 0]) and what did it (the gun's shot).
rube_cli_test("level balloon summary.json has the goal step, its frame and the hits"
              "run|${RUBE_GAME_LEVELS}/balloon.toml|--script|${RUBE_GAME_LEVELS}/balloon.solution.toml|--out|${frames}/balloon|--size|32x18|--every|4" 0
              -DFRAMES_DIR=${frames}/balloon
              "-DSTDOUT_MATCH=goal: +reached at step 277 \\(frame_00070.png\\)\n.*frames: +82 of 32x18, one every 4 steps, in ${frames}/balloon \\(summary in ${frames}/balloon/summary.json"
              "-DSUMMARY_MATCH=\"steps\": 327,\n  \"time_step\": 0.01,\n  \"time\": 3.27,\n  \"every\": 4,\n  \"frame_size\": \\[32, 18\\],\n  \"frames_written\": 82,.*\"goal_reached\": true,\n  \"goal\": {\"step\": 277, \"time\": 2.77, \"frame\": \"frame_00070.png\", \"position\": \\[4\\.[0-9]+, 0\\.[0-9]+\\], \"by\": \"gun\"},.*\"kind\": \"hit\", \"step\": 95, [^\n]*\"item\": \"button\", \"position\": \\[-4, 6.25\\], \"by\": \"\".*\"kind\": \"shot\", \"step\": 95, [^\n]*\"item\": \"gun\".*\"kind\": \"hit\", \"step\": 277, [^\n]*\"item\": \"bullseye\", \"position\": \\[4\\.[0-9]+, 0\\.[0-9]+\\], \"by\": \"gun\".*\"kind\": \"goal\", \"step\": 277, [^\n]*\"position\": \\[4\\.[0-9]+, 0\\.[0-9]+\\], \"by\": \"gun\".*\"expect\": \"'bullseye' hit before step 400\", \"met\": true, \"result\": \"met\"")

# `rube play` (issue 7). Without a display it says so in one line and names the ways on (exit 1);
# bad input is found before any window is asked for (exit 2). DISPLAY is unset for all of them.
# `rube play` and `rube edit` run with DISPLAY unset.
function(rube_windowless_test command name args exit)
  add_test(NAME "cli: ${command} ${name}"
           COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY
                   ${CMAKE_COMMAND} -DRUBE=$<TARGET_FILE:rube> "-DARGS=${command}|${args}" -DEXIT=${exit} ${ARGN}
                   -P ${RUBE_CLI_DIR}/rube_cli.cmake)
endfunction()
function(rube_play_test name args exit)
  rube_windowless_test(play "${name}" "${args}" ${exit} ${ARGN})
endfunction()
rube_play_test("without a display names rube run and xvfb-run" "${RUBE_GAME_LEVELS}/ramp.toml" 1
               "-DSTDERR_LINE=rube play: no display (DISPLAY is not set): render it off-screen with 'rube run ${RUBE_GAME_LEVELS}/ramp.toml --script FILE --out DIR', or give it a virtual display with 'xvfb-run rube play ${RUBE_GAME_LEVELS}/ramp.toml'")
rube_play_test("a physics scene is not a level" "${RUBE_LEVELS}/bounce.toml" 2
               "-DSTDERR_LINE=rube play: ${RUBE_LEVELS}/bounce.toml is a physics scene, not a level (it has no items, inventory or goal): watch it with 'rube run ${RUBE_LEVELS}/bounce.toml --out DIR'")
rube_play_test("--record into a missing folder" "${RUBE_GAME_LEVELS}/ramp.toml|--record|${RUBE_CLI_OUT}/no-such-folder/play.toml" 2
               "-DSTDERR_LINE=rube play: --record ${RUBE_CLI_OUT}/no-such-folder/play.toml: the folder ${RUBE_CLI_OUT}/no-such-folder does not exist")
rube_play_test("a bad --script is reported at its place" "${RUBE_GAME_LEVELS}/cannon-arc.toml|--script|${RUBE_CLI_DIR}/levels/cannon-typo.solution.toml" 2
               "-DSTDERR_LINE=${RUBE_CLI_DIR}/levels/cannon-typo.solution.toml:5:8: unknown cannon 'gnu' in level 'cannon-arc' (did you mean 'gun'?)")
rube_play_test("--quit-after 0 is refused" "${RUBE_GAME_LEVELS}/ramp.toml|--quit-after|0" 2
               "-DSTDERR_LINE=rube: --quit-after: expected a whole number of steps from 1 to 1000000000, got '0' (see 'rube play --help')")
# Issue 23: with no LEVEL, the list of the index's levels; an index that cannot be read is one
# line naming it, before any window is asked for; a --script needs its level.
rube_play_test("no level and an index that is not there" "--index|${RUBE_CLI_OUT}/no-index.toml" 2
               "-DSTDERR_LINE=${RUBE_CLI_OUT}/no-index.toml: cannot open file (no LEVEL given, so 'rube play' lists the levels of ${RUBE_CLI_OUT}/no-index.toml: give a LEVEL or --index FILE)")
# `rube edit` (issue 23): the same checks before any window, then no display is exit 1.
function(rube_edit_test name args exit)
  rube_windowless_test(edit "${name}" "${args}" ${exit} ${ARGN})
endfunction()
rube_edit_test("without a display says so" "--out|${RUBE_CLI_OUT}/new.toml" 1
               "-DSTDERR_LINE=rube edit: no display (DISPLAY is not set): give it a virtual display with 'xvfb-run rube edit'")
rube_edit_test("--out not a .toml" "--out|${RUBE_CLI_OUT}/new.txt" 2
               "-DSTDERR_LINE=rube edit: --out ${RUBE_CLI_OUT}/new.txt: a level file ends in .toml")
rube_edit_test("a bad level is reported at its place" "${RUBE_CLI_DIR}/bad-mass.toml" 2
               -DSTDERR_FIXTURE=${RUBE_CLI_DIR}/bad-mass.toml)
rube_play_test("a --script without a level" "--script|${RUBE_GAME_LEVELS}/ramp.solution.toml" 2
               "-DSTDERR_LINE=rube play: --script needs a LEVEL: the script belongs to one level")

# Methods without a broadphase (discrete, turn-based, exact) refuse a scene whose pair tests exceed
# 2^22 (issue 27: 100,000 circles under exact took 10 GB and minutes a step): status 2, one line
# naming the methods that scale; in the file at the method's name, on the command line as --method.
# The same scene naming no method runs under auto, and under --method auto or solver.
set(over ${RUBE_CLI_DIR}/pairs-over-budget.toml)
set(over_exact "method exact tests every pair of shapes, and 2100 moving bodies among 2101 shapes make 4412100 pair tests a search, more than the 4194304 it affords: use auto or solver")
rube_cli_test("exact refuses a scene over its pair budget" "run|${over}|--no-render|--steps|1|--trace|${RUBE_CLI_OUT}/over.csv" 2
              -DTRACE=${RUBE_CLI_OUT}/over.csv -DNO_TRACE=ON "-DSTDERR_LINE=${over}:5:10: ${over_exact}")
rube_cli_test("check names the method over its pair budget" "check|${over}" 2 "-DSTDERR_LINE=${over}:5:10: ${over_exact}")
file(READ ${over} over_text)
string(REPLACE "method = \"exact\"\n" "" over_text "${over_text}")
set(unnamed ${RUBE_CLI_OUT}/pairs-over-budget-unnamed.toml)
file(WRITE ${unnamed} "${over_text}")
rube_cli_test("a scene naming no method over the pair budget runs under auto" "run|${unnamed}|--no-render|--steps|2" 0
              "-DSTDOUT_MATCH=method: +auto")
foreach(method discrete turn-based exact)
  set(unit "a search")
  if(method STREQUAL "discrete")
    set(unit "a step")
  endif()
  rube_cli_test("--method ${method} refuses a scene over its pair budget" "run|${unnamed}|--no-render|--steps|1|--method|${method}" 2
                "-DSTDERR_LINE=rube run: ${unnamed}: method ${method} tests every pair of shapes, and 2100 moving bodies among 2101 shapes make 4412100 pair tests ${unit}, more than the 4194304 it affords: use auto or solver")
endforeach()
foreach(method auto solver)
  rube_cli_test("--method ${method} runs the scene over the pair budget" "run|${unnamed}|--no-render|--steps|2|--method|${method}" 0
                "-DSTDOUT_MATCH=steps: +2\n")
endforeach()
rube_cli_test("exact runs a scene inside its pair budget" "run|${RUBE_LEVELS}/pool-break.toml|--no-render|--steps|2|--method|exact" 0
              "-DSTDOUT_MATCH=steps: +2\n")

# `rube items`: the catalogue lists every kind (the heavy ball first, with its measured defaults),
# and --sheet draws one picture per kind; a folder that cannot be made is one line and status 2.
rube_cli_test("items lists every kind" "items" 0 "-DSTDOUT_MATCH=^heavy: [^\n]*\n  as made: a ball of radius 0.3 m, 8 kg")
rube_cli_test("items --sheet writes a picture per kind" "items|--sheet|${RUBE_CLI_OUT}/sheet|--size|80x60" 0
              "-DSTDOUT_MATCH=^rube items: [0-9]+ pictures, 80x60, in ${RUBE_CLI_OUT}/sheet\n$" -DSTDERR_EMPTY=ON)
rube_cli_test("items --sheet into a file is refused" "items|--sheet|${RUBE_CLI_DIR}/bad-mass.toml/sheet" 2
              "-DSTDERR_LINE=rube items: cannot write pictures to ${RUBE_CLI_DIR}/bad-mass.toml/sheet: Not a directory")
rube_cli_test("items --size without --sheet is refused" "items|--size|80x60" 2
              "-DSTDERR_LINE=rube: --size requires --sheet (see 'rube items --help')")

# Check and lint (issue 23). Every shipped level, with its scripts (its solution, other solutions
# and wrong attempts: game/src/level_folder.hpp), passes `rube check --strict`: no warning (the lint
# runs the level headless with nothing placed and with its solution), and each script reads
# against its level.
file(GLOB shipped_levels CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/levels/*.toml)
list(FILTER shipped_levels EXCLUDE REGEX "/[^/]*\\.[^/]*\\.toml$") # scripts: NAME.solution.toml, NAME.wrong.WORD.toml, ...
list(FILTER shipped_levels EXCLUDE REGEX "/index\\.toml$") # the list of levels, not a level
foreach(level IN LISTS shipped_levels)
  get_filename_component(stem ${level} NAME_WE)
  file(GLOB scripts ${PROJECT_SOURCE_DIR}/levels/${stem}.*.toml)
  list(JOIN scripts "|" scripts)
  rube_cli_test("check --strict level ${stem}" "check|--strict|${level}|${scripts}" 0 -DSTDERR_EMPTY=ON
                "-DSTDOUT_MATCH=^[^\n]*${stem}.toml: ok\n([^\n]*${stem}[.][a-z.-]+[.]toml: ok \\(a script for [^\n]*${stem}.toml\\)\n)+$")
endforeach()
# The level index is recognised and checked as one (every file it lists exists, no level twice).
rube_cli_test("check the level index" "check|${PROJECT_SOURCE_DIR}/levels/index.toml" 0 -DSTDERR_EMPTY=ON
              "-DSTDOUT_MATCH=index.toml: ok \\(a level index of [0-9]+ levels\\)\n$")
set(lint ${RUBE_CLI_DIR}/lint)
# Each lint fixture lists its warnings in '# expect:' lines; warnings leave the status 0, --strict makes it 2.
foreach(stem warnings self-solving missed goal-area)
  rube_cli_test("check lints ${stem}" "check|${lint}/${stem}.toml" 0 -DSTDERR_FIXTURE_ALL=${lint}/${stem}.toml
                "-DSTDOUT_MATCH=${stem}.toml: ok, [0-9]+ warnings?\n$")
  rube_cli_test("check --strict refuses ${stem}" "check|--strict|${lint}/${stem}.toml" 2 "-DSTDOUT_MATCH=^$")
endforeach()
# A script lists every error, reading errors and each refused placement alike, against --level.
foreach(script script-errors.toml placements.solution.toml no-heavy.toml)
  rube_cli_test("check script ${script}" "check|--level|${PROJECT_SOURCE_DIR}/levels/ramp.toml|${lint}/${script}" 2
                -DSTDERR_FIXTURE_ALL=${lint}/${script})
endforeach()
# Messages: the level's tables are among the top-level keys offered; a switch lists ropes among what it can switch,
# and one aimed at nothing it can switch (an empty name, an unknown one, a target) is refused by the level reader:
# an error at its `triggers` (exit 2, for check and run alike), not a lint warning.
foreach(stem zones-typo switch-empty switch-target switch-unknown)
  rube_cli_test("check ${stem}" "check|${lint}/${stem}.toml" 2 -DSTDERR_FIXTURE=${lint}/${stem}.toml)
endforeach()
rube_cli_test("run refuses a switch aimed at an unknown name" "run|${lint}/switch-unknown.toml|--no-render" 2
              -DSTDERR_FIXTURE=${lint}/switch-unknown.toml)
rube_cli_test("check script without its level" "check|${lint}/orphan.toml" 2
              "-DSTDERR_LINE=${lint}/orphan.toml: a script is checked against its level, and it is not named NAME.solution.toml, NAME.solution.WORD.toml or NAME.wrong.WORD.toml beside NAME.toml: name the level with --level LEVEL")
rube_cli_test("help check names --level and --strict" "check|--help" 0 "-DSTDOUT_MATCH=--level LEVEL.*--strict")
# A level without a [goal] has nothing to miss: `rube run` says so and exits 0.
rube_cli_test("run a level without a goal" "run|${lint}/warnings.toml|--no-render|--steps|20" 0
              "-DSTDOUT_MATCH=goal: +none \\(the level has no \\[goal\\]\\)\n" -DSTDERR_EMPTY=ON)

# One vocabulary (issue 23): a step is a simulation step, a frame a written picture. Scripts say
# `step` and `before_step`; the old keys are refused with the new name, each one listed.
set(cli_levels ${RUBE_CLI_DIR}/levels)
rube_cli_test("check a script in the old words names the new keys" "check|--level|${RUBE_GAME_LEVELS}/ramp.toml|${cli_levels}/old-keys.toml" 2
              -DSTDERR_FIXTURE_ALL=${cli_levels}/old-keys.toml)
rube_cli_test("run a script in the old words names the new key" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${cli_levels}/old-keys.toml|--no-render" 2
              "-DSTDERR_LINE=${cli_levels}/old-keys.toml:5:1: 'frame' is now 'step' in [[action]]")
# No option silently ignored: --frames N on a level runs (N - 1) x K steps, as on a scene, and writes N
# frames; the run stopped before the goal is reported as not reached in time (the level runs 800).
rube_cli_test("level --frames runs (N - 1) x K steps" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${RUBE_GAME_LEVELS}/ramp.solution.toml|--out|${frames}/level-frames|--size|32x18|--frames|10|--every|3" 1
              -DFRAMES_DIR=${frames}/level-frames "-DSUMMARY_MATCH=\"steps\": 27,.*\"every\": 3,\n  \"frame_size\": \\[32, 18\\],\n  \"frames_written\": 10,.*\"goal\": null,.*\"result\": \"not reached in time\""
              "-DSTDOUT_MATCH=steps: +27\n.*goal: +not reached in time: the run stopped at step 27 \\(--frames\\), the level runs 800\n")
# --steps that stops the run before an expectation's step: not reached in time, each expectation named
# (the ramp's solution expects the flag hit before step 600 and the goal before 800; it is at 266).
rube_cli_test("level --steps cutting a run short: expectations not reached in time" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${RUBE_GAME_LEVELS}/ramp.solution.toml|--no-render|--steps|100" 1
              "-DSTDOUT_MATCH=steps: +100\n.*goal: +not reached in time: the run stopped at step 100 \\(--steps\\), the level runs 800\n"
              "-DSTDERR_MATCH=^${RUBE_GAME_LEVELS}/ramp.solution.toml:13:1: expectation not reached in time: 'flag' hit before step 600 \\(the run stopped at step 100, cut short by --steps\\)\n${RUBE_GAME_LEVELS}/ramp.solution.toml:17:1: expectation not reached in time: goal reached before step 800 \\(the run stopped at step 100, cut short by --steps\\)\nrube run: goal not reached in time: hit the flag with the ball\n$")
# A run as long as the level, or one that passed an expectation's step, fails it: not "in time".
rube_cli_test("level --steps past an expectation's step fails it" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${early}|--no-render|--steps|700" 1
              "-DSTDERR_LINE=${early}:${early_line}:1: expectation failed: goal reached before step 100")

# Expectations name who (issue 23): the red ball hits the flag, so a script expecting red passes and
# one expecting blue fails, naming both expectations; a `by` naming nothing is an error at its place.
rube_cli_test("level expectations by the right ball are met" "run|${cli_levels}/two-balls.toml|--script|${cli_levels}/two-balls-red.toml|--no-render" 0
              "-DSTDOUT_MATCH=event: +step [0-9]+ hit flag by red\n(.*\n)?event: +step [0-9]+ goal flag by red\n" -DSTDERR_EMPTY=ON)
rube_cli_test("level expectations by the wrong ball fail" "run|${cli_levels}/two-balls.toml|--script|${cli_levels}/two-balls-blue.toml|--no-render" 1
              "-DSTDOUT_MATCH=goal: +reached at step [0-9]+\n"
              "-DSTDERR_MATCH=^${cli_levels}/two-balls-blue.toml:4:1: expectation failed: 'flag' hit by 'blue' before step 300\n${cli_levels}/two-balls-blue.toml:9:1: expectation failed: goal reached by 'blue' before step 300\n$")
rube_cli_test("check a by that names nothing" "check|--level|${cli_levels}/two-balls.toml|${cli_levels}/two-balls-bad-by.toml" 2
              -DSTDERR_FIXTURE_ALL=${cli_levels}/two-balls-bad-by.toml)

# Frames that explain themselves (issue 23): --labels and --zones draw on a level's frames, and are
# refused on a physics scene, which has neither items nor zones; like --trails they need frames.
rube_cli_test("level --labels --zones write frames" "run|${RUBE_GAME_LEVELS}/ramp.toml|--script|${RUBE_GAME_LEVELS}/ramp.solution.toml|--out|${frames}/labels|--size|64x36|--frames|2|--labels|--zones" 1
              -DFRAMES_DIR=${frames}/labels "-DSUMMARY_MATCH=\"frames_written\": 2,")
rube_cli_test("scene --labels is refused" "run|${RUBE_LEVELS}/bounce.toml|--out|${frames}/scene-labels|--labels" 2
              -DFRAMES_DIR=${frames}/scene-labels -DNO_FRAMES_DIR=ON
              "-DSTDERR_LINE=rube run: --labels is for levels, and ${RUBE_LEVELS}/bounce.toml is a physics scene: it has no items or placement zones")
rube_cli_test("usage --zones without --out" "run|${RUBE_GAME_LEVELS}/ramp.toml|--zones" 2
              "-DSTDERR_LINE=rube: --zones requires --out or --video (see 'rube run --help')")
rube_cli_test("help run explains steps, frames and the level options" "run|--help" 0
              "-DSTDOUT_MATCH=--labels .*--zones .*A step is one step of the simulation, a frame one picture.*step,time,body,item,x,y,vx,vy,angle,omega,radius.*'not reached in\n  time'")
# `rube solve`'s bad input: one line, status 2, before any search.
rube_cli_test("solve missing level" "solve|no-such-level.toml" 2 "-DSTDERR_LINE=no-such-level.toml: cannot open file")
rube_cli_test("solve a scene without a goal" "solve|${RUBE_LEVELS}/bounce.toml" 2
              "-DSTDERR_LINE=rube solve: ${RUBE_LEVELS}/bounce.toml has no [goal]: there is nothing to solve")
rube_cli_test("solve --json into a missing folder" "solve|${PROJECT_SOURCE_DIR}/levels/ramp.toml|--json|${RUBE_CLI_OUT}/no-such-folder/r.json" 2
              "-DSTDERR_LINE=rube solve: --json ${RUBE_CLI_OUT}/no-such-folder/r.json: no folder ${RUBE_CLI_OUT}/no-such-folder")
rube_cli_test("solve --merge of a file that is not a result" "solve|${PROJECT_SOURCE_DIR}/levels/ramp.toml|--merge|${RUBE_CLI_DIR}/bad-syntax.toml" 2
              "-DSTDERR_LINE=${RUBE_CLI_DIR}/bad-syntax.toml:1:1: expected a value")
rube_cli_test("solve --merge excludes --budget" "solve|${PROJECT_SOURCE_DIR}/levels/ramp.toml|--merge|x.json|--budget|5" 2
              "-DSTDERR_LINE=rube: --merge excludes --budget (the slices hold the search's own) (see 'rube solve --help')")
rube_cli_test("solve --shard out of range" "solve|${PROJECT_SOURCE_DIR}/levels/ramp.toml|--shard|2/2" 2
              "-DSTDERR_LINE=rube: --shard: expected I/N with 0 <= I < N (the I-th of N slices, counted from 0), got '2/2' (see 'rube solve --help')")
