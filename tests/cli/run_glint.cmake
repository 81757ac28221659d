# For the CLI's script-mode tests: run_glint(EXPECTED_EXIT args...) runs ${GLINT} with the
# arguments, logs what it printed, fails unless it exits with EXPECTED_EXIT, and leaves its
# stdout and stderr in run_out and run_err.
function(run_glint expected)
  execute_process(COMMAND "${GLINT}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "glint ${ARGN}: exit ${status}\n${out}${err}")
  if(NOT "${status}" STREQUAL "${expected}")
    message(FATAL_ERROR "glint ${ARGN}: expected exit ${expected}, got ${status}")
  endif()
  set(run_out "${out}" PARENT_SCOPE)
  set(run_err "${err}" PARENT_SCOPE)
endfunction()
