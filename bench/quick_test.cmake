# The "bench: quick" test: runs rube_bench --quick and checks that the CSV it writes is well formed
# (a header, the same number of fields on every row, numbers where numbers belong, every scene on
# every rube method, the scaling sweep's smallest point asleep and awake and a failure table row per method).
# It checks that the bench runs, never how fast: CI machines vary too much.
# Usage: cmake -DBENCH=<rube_bench> -DCSV=<file> -DFAILURES=<file> -P quick_test.cmake

cmake_minimum_required(VERSION 3.25) # list() keeps empty fields (CMP0007)

file(REMOVE ${CSV} ${FAILURES})
execute_process(COMMAND ${BENCH} --quick --csv ${CSV} --failures-md ${FAILURES} RESULT_VARIABLE result ERROR_VARIABLE log)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "rube_bench --quick failed (${result}):\n${log}")
endif()

file(STRINGS ${CSV} lines)
list(LENGTH lines count)
if(count LESS 2)
  message(FATAL_ERROR "${CSV}: no rows")
endif()
list(GET lines 0 header)
string(REPLACE "," ";" columns "${header}")
list(LENGTH columns width)
if(NOT header MATCHES "^scene,engine,kind,dt_s,bodies,steps,repeats,ms_per_step,")
  message(FATAL_ERROR "${CSV}: unexpected header '${header}'")
endif()

set(number "^-?[0-9.]+(e[-+][0-9]+)?$")
set(seen "")
list(SUBLIST lines 1 -1 rows)
foreach(row IN LISTS rows)
  string(REPLACE "," ";" fields "${row}")
  list(LENGTH fields n)
  if(NOT n EQUAL width)
    message(FATAL_ERROR "${CSV}: ${n} fields, header has ${width}: '${row}'")
  endif()
  list(GET fields 0 scene)
  list(GET fields 1 engine)
  list(GET fields 3 dt)
  list(GET fields 7 msPerStep)
  list(GET fields 19 timeout)
  if(NOT dt MATCHES "${number}")
    message(FATAL_ERROR "${CSV}: dt_s is not a number in '${row}'")
  endif()
  # A timed-out run has no cost; every other row must have one.
  if(timeout STREQUAL "0" AND NOT msPerStep MATCHES "${number}")
    message(FATAL_ERROR "${CSV}: ms_per_step is not a number in '${row}'")
  endif()
  list(APPEND seen "${scene}/${engine}")
endforeach()

foreach(scene bounce projectile pool-break ball-stack pile bullet newton-cradle rolling-disc)
  foreach(method discrete turn-based exact solver)
    if(NOT "${scene}/rube-${method}" IN_LIST seen)
      message(FATAL_ERROR "${CSV}: no row for ${scene} on rube-${method}")
    endif()
  endforeach()
endforeach()
foreach(engine rube-solver rube-solver-awake)
  if(NOT "pile-scaling-100/${engine}" IN_LIST seen)
    message(FATAL_ERROR "${CSV}: no row for the scaling sweep's pile-scaling-100 on ${engine}")
  endif()
endforeach()
# The awake variant belongs to the scaling sweep only.
if("pile/rube-solver-awake" IN_LIST seen)
  message(FATAL_ERROR "${CSV}: rube-solver-awake ran outside the scaling sweep")
endif()

# The failure table: a Markdown table with one row per method, each cell a failing value or "holds".
file(READ ${FAILURES} failures)
foreach(method discrete turn-based exact solver)
  if(NOT failures MATCHES "\n\\| ${method} \\| [^\n]*\\|[^\n]*\\|[^\n]*\\|[^\n]*\\|\n")
    message(FATAL_ERROR "${FAILURES}: no table row for ${method}")
  endif()
endforeach()

math(EXPR rowCount "${count} - 1")
message(STATUS "bench: quick: ${rowCount} well-formed rows in ${CSV}")
