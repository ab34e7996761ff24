# Fails when doc/parameters.prm is not the current `masonry --print-parameters`.
# Called by ctest with -DMASONRY=<executable> -DREFERENCE=<doc/parameters.prm>
# -DOUTPUT=<scratch file>.
execute_process(COMMAND ${MASONRY} --print-parameters
  OUTPUT_FILE ${OUTPUT}
  RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "masonry --print-parameters failed (exit code ${_status})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${REFERENCE} ${OUTPUT}
  RESULT_VARIABLE _different)
if(_different)
  message(FATAL_ERROR
    "doc/parameters.prm is out of date: it differs from the output of "
    "`masonry --print-parameters` (now in ${OUTPUT}). Regenerate it with "
    "`contrib/update-doc` (or `build/masonry --print-parameters > "
    "doc/parameters.prm`) and commit it.")
endif()
message(STATUS "doc/parameters.prm is up to date")
