# Runs one scene twice and requires byte-identical traces: the determinism the %.17g trace exists for.
#   cmake -DRUBE=<rube> -DSCENE=<file> -DSTEPS=<n> -DTRACE=<file prefix> -P same_trace.cmake
foreach(run a b)
  file(REMOVE "${TRACE}-${run}.csv")
  execute_process(COMMAND "${RUBE}" run "${SCENE}" --no-render --steps ${STEPS} --trace "${TRACE}-${run}.csv"
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "run ${run} failed with ${status}: ${err}")
  endif()
  string(REGEX MATCH "state hash: +[0-9a-f]+" hash_${run} "${out}")
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${TRACE}-a.csv" "${TRACE}-b.csv" RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "two runs of ${SCENE} wrote different traces")
endif()
if(NOT hash_a OR NOT hash_a STREQUAL hash_b)
  message(FATAL_ERROR "state hashes differ or are missing: '${hash_a}' and '${hash_b}'")
endif()
