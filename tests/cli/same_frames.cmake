# Renders one scene three times and requires byte-identical PNG frames: twice as llvmpipe
# pleases, once with LP_NUM_THREADS=1, its rasteriser on a single thread.
#   cmake -DRUBE=<rube> -DSCENE=<file> -DFRAMES=<n> -DOUT=<folder prefix> -P same_frames.cmake
# Trails and impact markers are on, so translucent blending is part of what must agree.
set(runs a b one)
foreach(run IN LISTS runs)
  file(REMOVE_RECURSE "${OUT}-${run}")
  if(run STREQUAL "one")
    set(env LP_NUM_THREADS=1)
  else()
    set(env --unset=LP_NUM_THREADS)
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env}
                          "${RUBE}" run "${SCENE}" --out "${OUT}-${run}" --frames ${FRAMES} --size 320x180 --trails --debug-impacts
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "run ${run} failed with ${status}: ${err}")
  endif()
endforeach()
file(GLOB frames RELATIVE "${OUT}-a" "${OUT}-a/frame_*.png")
list(LENGTH frames count)
if(NOT count EQUAL FRAMES)
  message(FATAL_ERROR "run a wrote ${count} frames, expected ${FRAMES}")
endif()
foreach(other b one)
  foreach(frame IN LISTS frames)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}-a/${frame}" "${OUT}-${other}/${frame}" RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "${frame} differs between run a and run ${other} (${OUT}-a, ${OUT}-${other})")
    endif()
  endforeach()
endforeach()
