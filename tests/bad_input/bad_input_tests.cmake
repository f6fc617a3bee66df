# Bad input (issue 8): every bad scene, level and script gives exit status 2, exactly one line on
# stderr and writes nothing: no trace (nor its temporary), no frames folder, no summary.json.
# Included from tests/CMakeLists.txt after cli/cli_tests.cmake; runs the real binary through
# tests/cli/rube_cli.cmake.
#
# One fixture per case in this folder, its message in a '# expect: line:col: message' comment:
#   scene-*.toml, level-*.toml   run as `rube run FIXTURE --out DIR --trace FILE`
#   script-*.toml                run as `rube run levels/LEVEL.toml --script FIXTURE --out DIR --trace FILE`,
#                                LEVEL named by the fixture's '# level: NAME' comment
# The cases without a file of their own (missing, too large, unwritable output, limits on the
# command line) follow the loop.

set(RUBE_BAD_DIR ${CMAKE_CURRENT_LIST_DIR})
set(RUBE_BAD_OUT ${CMAKE_CURRENT_BINARY_DIR}/bad-input-out)
file(MAKE_DIRECTORY ${RUBE_BAD_OUT})

function(rube_bad_input_test name args exit)
  add_test(NAME "bad input: ${name}"
           COMMAND ${CMAKE_COMMAND} -DRUBE=$<TARGET_FILE:rube> "-DARGS=${args}" -DEXIT=${exit} ${ARGN}
                   -P ${PROJECT_SOURCE_DIR}/tests/cli/rube_cli.cmake)
endfunction()

file(GLOB bad_inputs CONFIGURE_DEPENDS ${RUBE_BAD_DIR}/*.toml)
list(LENGTH bad_inputs bad_input_count)
if(bad_input_count LESS 40)
  message(FATAL_ERROR "tests/bad_input holds ${bad_input_count} fixtures; issue 8 asks for at least 40")
endif()
foreach(fixture IN LISTS bad_inputs)
  get_filename_component(case ${fixture} NAME_WE)
  set(out ${RUBE_BAD_OUT}/${case})
  set(target ${fixture})
  if(case MATCHES "^script-")
    file(STRINGS ${fixture} level REGEX "^# level: " LIMIT_COUNT 1)
    if(NOT level)
      message(FATAL_ERROR "${fixture}: a script fixture needs a '# level: NAME' comment")
    endif()
    string(REGEX REPLACE "^# level: " "" level "${level}")
    set(target "${PROJECT_SOURCE_DIR}/levels/${level}.toml|--script|${fixture}")
  elseif(NOT case MATCHES "^(scene|level)-")
    message(FATAL_ERROR "${fixture}: a bad-input fixture is named scene-*, level-* or script-*")
  endif()
  rube_bad_input_test("${case}" "run|${target}|--out|${out}/frames|--size|32x18|--trace|${out}/trace.csv" 2
                      -DSTDERR_FIXTURE=${fixture} -DFRAMES_DIR=${out}/frames -DNO_FRAMES_DIR=ON
                      -DTRACE=${out}/trace.csv -DNO_TRACE=ON)
endforeach()

set(ramp ${PROJECT_SOURCE_DIR}/levels/ramp.toml)
set(ramp_solution ${PROJECT_SOURCE_DIR}/levels/ramp.solution.toml)
set(bounce ${PROJECT_SOURCE_DIR}/levels/physics/bounce.toml)

# Files that cannot be read: missing, a folder, too large (5 MiB of comment, written here
# rather than kept in the repository).
rube_bad_input_test("missing scene file" "run|${RUBE_BAD_OUT}/no-such-scene.toml|--out|${RUBE_BAD_OUT}/missing/frames" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/missing/frames -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=${RUBE_BAD_OUT}/no-such-scene.toml: cannot open file")
rube_bad_input_test("missing script file" "run|${ramp}|--script|${RUBE_BAD_OUT}/no-such.solution.toml|--out|${RUBE_BAD_OUT}/missing-script/frames" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/missing-script/frames -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=${RUBE_BAD_OUT}/no-such.solution.toml: cannot open file")
rube_bad_input_test("script is a folder" "run|${ramp}|--script|${RUBE_BAD_DIR}|--out|${RUBE_BAD_OUT}/folder-script/frames" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/folder-script/frames -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=${RUBE_BAD_DIR}: cannot open file")
set(huge ${RUBE_BAD_OUT}/huge.toml)
string(REPEAT "# padding padding padding padding padding padding padding padding padding padding\n" 65536 padding)
file(WRITE ${huge} "name = \"huge\"\n${padding}")
file(SIZE ${huge} huge_bytes)
rube_bad_input_test("file too large" "run|${huge}|--out|${RUBE_BAD_OUT}/huge/frames|--trace|${RUBE_BAD_OUT}/huge/trace.csv" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/huge/frames -DNO_FRAMES_DIR=ON
                    -DTRACE=${RUBE_BAD_OUT}/huge/trace.csv -DNO_TRACE=ON
                    "-DSTDERR_LINE=${huge}: file too large: ${huge_bytes} bytes, at most 4194304 (4 MiB)")
rube_bad_input_test("script too large" "run|${ramp}|--script|${huge}|--out|${RUBE_BAD_OUT}/huge-script/frames" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/huge-script/frames -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=${huge}: file too large: ${huge_bytes} bytes, at most 4194304 (4 MiB)")

# An unwritable output folder (--out under a plain file) for a level: no frames, no summary.json.
rube_bad_input_test("level --out under a plain file"
                    "run|${ramp}|--script|${ramp_solution}|--out|${RUBE_BAD_OUT}/blocker/out" 2
                    -DBLOCKER=${RUBE_BAD_OUT}/blocker -DFRAMES_DIR=${RUBE_BAD_OUT}/blocker/out -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=rube run: cannot write frames to ${RUBE_BAD_OUT}/blocker/out: Not a directory")

# Limits on the command line: steps (--steps, and --frames x --every) and the frame size.
rube_bad_input_test("too many --steps" "run|${bounce}|--steps|10000000000|--out|${RUBE_BAD_OUT}/steps/frames" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/steps/frames -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=rube: --steps: expected at most 1000000000 steps, got '10000000000' (see 'rube run --help')")
rube_bad_input_test("too many steps from --frames x --every"
                    "run|${bounce}|--frames|1000000|--every|1000000|--out|${RUBE_BAD_OUT}/frames-every/frames|--trace|${RUBE_BAD_OUT}/frames-every/trace.csv" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/frames-every/frames -DNO_FRAMES_DIR=ON
                    -DTRACE=${RUBE_BAD_OUT}/frames-every/trace.csv -DNO_TRACE=ON
                    "-DSTDERR_LINE=rube run: --frames 1000000 with --every 1000000 makes 999999000000 steps, more than the 1000000000 a run may take")
rube_bad_input_test("frame size 100000x100000" "run|${ramp}|--script|${ramp_solution}|--out|${RUBE_BAD_OUT}/size/frames|--size|100000x100000" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/size/frames -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=rube: --size: expected WxH in pixels, each from 1 to 8192, got '100000x100000' (see 'rube run --help')")

# Actions out of step order are an error at the later-listed action's step, nothing is played.
file(WRITE ${RUBE_BAD_OUT}/cannon-arc-unordered.solution.toml
     "level = \"cannon-arc\"\n\n[[action]]\nstep = 30\ndo = \"fire\"\nitem = \"gun\"\n\n"
     "[[action]]\nstep = 0\ndo = \"aim\"\nitem = \"gun\"\ntarget = \"bullseye\"\narc = \"high\"\n")
rube_bad_input_test("actions out of step order"
                    "run|${PROJECT_SOURCE_DIR}/levels/cannon-arc.toml|--script|${RUBE_BAD_OUT}/cannon-arc-unordered.solution.toml|--out|${RUBE_BAD_OUT}/unordered/frames" 2
                    -DFRAMES_DIR=${RUBE_BAD_OUT}/unordered/frames -DNO_FRAMES_DIR=ON
                    "-DSTDERR_LINE=${RUBE_BAD_OUT}/cannon-arc-unordered.solution.toml:9:8: actions must be listed in step order: step 0 comes after step 30 (line 3)")
