# Repository hygiene targets.
#   glint_format       reformat every tracked C++/HLSL source with the repository's .clang-format
#   glint_format_check fail when any tracked source differs from its formatted self
find_program(GLINT_CLANG_FORMAT NAMES clang-format clang-format-14)
find_package(Git QUIET)
if(GLINT_CLANG_FORMAT AND GIT_FOUND)
  foreach(mode IN ITEMS format format_check)
    add_custom_target(glint_${mode}
      COMMAND "${CMAKE_COMMAND}" -DMODE=${mode} "-DCLANG_FORMAT=${GLINT_CLANG_FORMAT}" "-DGIT=${GIT_EXECUTABLE}"
              "-DROOT=${PROJECT_SOURCE_DIR}" -P "${PROJECT_SOURCE_DIR}/cmake/GlintFormat.cmake"
      COMMENT "clang-format (${mode})"
      VERBATIM)
  endforeach()
endif()
