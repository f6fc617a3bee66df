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
# No --steps: the scene's duration, 1.8 s at 1/60 s, is 108 steps.
rube_cli_test("run steps from duration" "run|${RUBE_LEVELS}/projectile.toml|--no-render|--trace|${RUBE_CLI_OUT}/projectile.csv" 0
              -DTRACE=${RUBE_CLI_OUT}/projectile.csv -DROWS=109 "-DSTDOUT_MATCH=steps: +108\n")
rube_cli_test("run method override" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--steps|3|--method|discrete" 0
              "-DSTDOUT_MATCH=method: +discrete\n")
rube_cli_test("run without --no-render notes it" "run|${RUBE_LEVELS}/bounce.toml|--steps|1" 0
              "-DSTDERR_LINE=rube run: note: rendering is not built yet, running headless as with --no-render")

# Failed runs: status 2, one line, and no trace (nor a temporary) left behind.
rube_cli_test("run bad scene leaves no trace" "run|${RUBE_CLI_DIR}/bad-unknown-key.toml|--no-render|--trace|${RUBE_CLI_OUT}/bad.csv" 2
              -DSTDERR_FIXTURE=${RUBE_CLI_DIR}/bad-unknown-key.toml -DTRACE=${RUBE_CLI_OUT}/bad.csv -DNO_TRACE=ON)
rube_cli_test("run unknown method leaves no trace" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--method|exat|--trace|${RUBE_CLI_OUT}/method.csv" 2
              "-DSTDERR_LINE=rube run: unknown method 'exat' (valid methods: discrete, turn-based, exact, solver)"
              -DTRACE=${RUBE_CLI_OUT}/method.csv -DNO_TRACE=ON)
rube_cli_test("run missing file" "run|no-such-scene.toml|--no-render" 2 "-DSTDERR_LINE=no-such-scene.toml: cannot open file")
rube_cli_test("run trace into missing folder" "run|${RUBE_LEVELS}/bounce.toml|--no-render|--trace|${RUBE_CLI_OUT}/no/such/t.csv" 2
              "-DSTDERR_LINE=${RUBE_CLI_OUT}/no/such/t.csv: cannot write trace: No such file or directory")

# Usage errors are status 2 and one line, whatever CLI11's own code for them would be.
rube_cli_test("usage no command" "" 2 "-DSTDERR_LINE=rube: A subcommand is required (see 'rube --help')")
rube_cli_test("usage unknown command" "frobnicate" 2 "-DSTDERR_LINE=rube: unknown command 'frobnicate': the commands are run and check (see 'rube --help')")
rube_cli_test("usage run without scene" "run|--no-render" 2 "-DSTDERR_LINE=rube: scene is required (see 'rube run --help')")
rube_cli_test("usage bad steps" "run|${RUBE_LEVELS}/bounce.toml|--steps|ten" 2
              "-DSTDERR_LINE=rube: --steps: expected a whole number of steps, 0 or more, got 'ten' (see 'rube run --help')")
rube_cli_test("usage unknown option" "check|${RUBE_LEVELS}/bounce.toml|--fast" 2 "-DSTDERR_LINE=rube: The following argument was not expected: --fast (see 'rube check --help')")

# Help is for level designers and teachers: it exits 0 and names what they need.
rube_cli_test("help" "--help" 0 "-DSTDOUT_MATCH=run .*check .*Exit status")
rube_cli_test("help run" "run|--help" 0 "-DSTDOUT_MATCH=--steps .*--trace .*--method .*step,time,body,x,y,vx,vy,angle,omega,radius")
rube_cli_test("help check" "check|--help" 0 "-DSTDOUT_MATCH=file:line:col: message")

# Determinism: two runs of the same scene write byte-identical traces and equal hashes.
add_test(NAME "cli: same trace twice"
         COMMAND ${CMAKE_COMMAND} -DRUBE=$<TARGET_FILE:rube> -DSCENE=${RUBE_LEVELS}/pool-break.toml -DSTEPS=60
                 -DTRACE=${RUBE_CLI_OUT}/twice -P ${RUBE_CLI_DIR}/same_trace.cmake)
