# Script mode: glint run on a capture whose last frame is truncated must exit 2 with one stderr
# line naming that frame, and leave no output folder behind (the frames before it included).
#   -DGLINT=<glint> -DCAPTURE=<sequence> -DOUT=<output folder>
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${GLINT}" run "${CAPTURE}" --out "${OUT}" RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 2)
  message(FATAL_ERROR "expected exit 2, got ${status}: ${err}")
endif()
string(STRIP "${err}" stripped)
if(NOT stripped MATCHES "^glint: [^\n]*frame_0001.exr: [^\n]*truncated[^\n]*$")
  message(FATAL_ERROR "expected one line naming frame_0001.exr as truncated, got:\n${err}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "${OUT} was written before the bad frame was found")
endif()
