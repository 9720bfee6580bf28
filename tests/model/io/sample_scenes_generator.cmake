# The committed sample scenes are exactly what scripts/make_sample_scenes.py
# writes, so the script stays the record of where every number comes from.
# cmake -DPYTHON=... -DSOURCE=<repository> -DOUT=<scratch directory> -P this
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${PYTHON}" "${SOURCE}/scripts/make_sample_scenes.py" "${OUT}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "scripts/make_sample_scenes.py failed (${status})")
endif()
foreach(name cornell-box.json two-lights-room.json)
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUT}/${name}" "${SOURCE}/resources/scenes/${name}"
                  RESULT_VARIABLE different)
  if(NOT different EQUAL 0)
    message(FATAL_ERROR "resources/scenes/${name} is not what scripts/make_sample_scenes.py writes: "
                        "run the script and commit both, or change the script to match")
  endif()
endforeach()
