# Renders one scene several times and requires byte-identical PNG frames: twice as llvmpipe
# pleases, once with LP_NUM_THREADS=1, its rasteriser on a single thread, and, when a second
# offscreen back end is built, once through it (issue 25: EGL and OSMesa are both Mesa's llvmpipe,
# so the same draw list must give the same bytes).
#   cmake -DRUBE=<rube> -DSCENE=<file> -DFRAMES=<n> -DOUT=<folder prefix> -DGL=<back end>
#         [-DOTHER_GL=<back end>] -P same_frames.cmake
# Trails and impact markers are on, so translucent blending is part of what must agree.
set(runs a b one)
if(OTHER_GL)
  list(APPEND runs other)
endif()
foreach(run IN LISTS runs)
  file(REMOVE_RECURSE "${OUT}-${run}")
  set(gl ${GL})
  if(run STREQUAL "one")
    set(env LP_NUM_THREADS=1)
  else()
    set(env --unset=LP_NUM_THREADS)
  endif()
  if(run STREQUAL "other")
    set(gl ${OTHER_GL})
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env}
                          "${RUBE}" run "${SCENE}" --out "${OUT}-${run}" --frames ${FRAMES} --size 320x180 --trails --debug-impacts
                          --gl ${gl}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "run ${run} (--gl ${gl}) failed with ${status}: ${err}")
  endif()
  if(NOT out MATCHES "\ngl: +${gl}\n")
    message(FATAL_ERROR "run ${run} asked for --gl ${gl} but its summary says otherwise:\n${out}")
  endif()
endforeach()
file(GLOB frames RELATIVE "${OUT}-a" "${OUT}-a/frame_*.png")
list(LENGTH frames count)
if(NOT count EQUAL FRAMES)
  message(FATAL_ERROR "run a wrote ${count} frames, expected ${FRAMES}")
endif()
list(REMOVE_ITEM runs a)
foreach(other IN LISTS runs)
  foreach(frame IN LISTS frames)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}-a/${frame}" "${OUT}-${other}/${frame}" RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "${frame} differs between run a (--gl ${GL}) and run ${other} (${OUT}-a, ${OUT}-${other})")
    endif()
  endforeach()
endforeach()
message(STATUS "${count} frames byte-identical across runs a, ${runs} (--gl ${GL}${OTHER_GL})")
