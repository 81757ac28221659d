# Script mode: no code in harness/replay, harness/cli or harness/viewer compares against an effect's name. How an
# effect is scored, checked, previewed, reported and studied is its descriptor's evaluation
# (host/include/glint/glint_effect.h); a branch on a name would leave the next effect silently
# unscored. Fails naming each file and line that holds an effect name as a string literal
# ("shadows") or one beginning "<effect>/" on a line that compares ("==", "!=", rfind,
# starts_with, compare), outside comments.
#   -DSOURCE=<repository root>
cmake_minimum_required(VERSION 3.25)
set(names reflections shadows hybrid depth_pyramid roughness sssr shadow_denoiser)
set(found "")
file(GLOB_RECURSE files RELATIVE "${SOURCE}" "${SOURCE}/harness/replay/*.cpp" "${SOURCE}/harness/replay/*.h"
     "${SOURCE}/harness/cli/*.cpp" "${SOURCE}/harness/cli/*.h" "${SOURCE}/harness/viewer/*.cpp"
     "${SOURCE}/harness/viewer/*.h")
list(JOIN names "|" alternatives)
foreach(file IN LISTS files)
  file(STRINGS "${SOURCE}/${file}" lines)
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    string(REGEX REPLACE "^[ \t]*//.*$" "" code "${line}") # a comment line
    string(REGEX REPLACE "([;,{)])[ \t]+//.*$" "\\1" code "${code}") # a comment after code
    set(hits "")
    string(REGEX MATCHALL "\"(${alternatives})\"" exact "${code}")
    list(APPEND hits ${exact})
    if(code MATCHES "==|!=|rfind|starts_with|compare\\(")
      string(REGEX MATCHALL "\"(${alternatives})/" prefixed "${code}")
      list(APPEND hits ${prefixed})
    endif()
    foreach(hit IN LISTS hits)
      string(REGEX REPLACE "^\"([a-z_]+).*$" "\\1" name "${hit}")
      string(APPEND found "\n  ${file}:${number}: \"${name}\": ${line}")
    endforeach()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "effect names compared in the harness (put it in the effect's descriptor instead):${found}")
endif()
