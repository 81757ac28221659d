# Strict warnings (and errors) for glint's own targets only; third-party headers are
# included as SYSTEM by their imported targets, so their warnings never fail our build.
function(glint_target_defaults target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
    -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
    -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough
    # VkFooCreateInfo info{VK_STRUCTURE_TYPE_FOO}; zero-initialises the rest on purpose.
    -Wno-missing-field-initializers)
  if(GLINT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
    # GCC 12 at -O3 reports these through libstdc++ inlining where no bug exists; they
    # stay warnings there (and errors in the debug build, where they are reliable).
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE
        $<$<NOT:$<CONFIG:Debug>>:-Wno-error=maybe-uninitialized -Wno-error=restrict>)
    endif()
  endif()
  if(GLINT_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()
