# Script mode (cmake -P): runs COMMAND (its arguments separated by '|') and fails when it fails
# or prints a warning. glslang exits 0 on a module without an entry point and only warns
# ("Entry point not found"), where DXC fails; the header checks hold both to DXC's standard.
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${out}${err}")
endif()
if("${out}${err}" MATCHES "[Ww][Aa][Rr][Nn][Ii][Nn][Gg]")
  message(FATAL_ERROR "warnings are errors in the header checks:\n${out}${err}")
endif()
