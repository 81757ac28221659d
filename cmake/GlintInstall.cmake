# Install rules and the CMake package: find_package(glint [0.9] CONFIG [COMPONENTS hlsl core vulkan]).
#   glint::hlsl    INTERFACE: the HLSL library headers and entry files (include/glint-hlsl), which
#                  also hold the constants headers C++ and HLSL share
#   glint::core    the Vulkan-free plans (static), needs no Vulkan or SPIRV-Cross
#   glint::vulkan  the backend (static): create / dispatch / destroy of any effect's plan
# Each component has its own export file, so a package built without the Vulkan backend says
# which component is missing. The compiled SPIR-V of every module goes to share/glint/spirv with
# its reflection file (<module>.json), its GLSL 450 translation to share/glint/glsl, the SSSR
# tables as data files and a C++ header to share/glint/tables.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GLINT_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/glint")

install(DIRECTORY "${PROJECT_SOURCE_DIR}/hlsl/glint" "${PROJECT_SOURCE_DIR}/hlsl/entry"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/glint-hlsl" COMPONENT hlsl)
install(TARGETS glint_hlsl EXPORT glint_hlsl_targets)
install(EXPORT glint_hlsl_targets NAMESPACE glint:: FILE glint-hlsl-targets.cmake
        DESTINATION "${GLINT_CMAKE_DIR}")
set_target_properties(glint_hlsl PROPERTIES EXPORT_NAME hlsl)

install(DIRECTORY "${PROJECT_SOURCE_DIR}/host/include/glint" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.h")
install(TARGETS glint_core EXPORT glint_core_targets ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(EXPORT glint_core_targets NAMESPACE glint:: FILE glint-core-targets.cmake
        DESTINATION "${GLINT_CMAKE_DIR}")
set_target_properties(glint_core PROPERTIES EXPORT_NAME core)

if(TARGET glint_vulkan)
  install(TARGETS glint_vulkan EXPORT glint_vulkan_targets ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
  install(EXPORT glint_vulkan_targets NAMESPACE glint:: FILE glint-vulkan-targets.cmake
          DESTINATION "${GLINT_CMAKE_DIR}")
  set_target_properties(glint_vulkan PROPERTIES EXPORT_NAME vulkan)
endif()

install(FILES ${GLINT_TABLE_FILES} DESTINATION "${CMAKE_INSTALL_DATADIR}/glint/tables")

get_property(glint_spirv GLOBAL PROPERTY GLINT_SHADER_FILES_glint)
get_property(glint_reflection GLOBAL PROPERTY GLINT_SHADER_REFLECTION_FILES)
get_property(glint_glsl GLOBAL PROPERTY GLINT_SHADER_GLSL_FILES)
install(FILES ${glint_spirv} ${glint_reflection} DESTINATION "${CMAKE_INSTALL_DATADIR}/glint/spirv")
install(FILES ${glint_glsl} DESTINATION "${CMAKE_INSTALL_DATADIR}/glint/glsl")

# The compilers this build used, so a consumer compiles its own entry files the same way.
set(GLINT_PACKAGE_GLSLANG "${GLINT_GLSLANG}")
set(GLINT_PACKAGE_DXC "${GLINT_DXC}")
set(GLINT_PACKAGE_SPIRV_VAL "${GLINT_SPIRV_VAL}")
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/glint-config.cmake.in"
                              "${PROJECT_BINARY_DIR}/package/glint-config.cmake"
                              INSTALL_DESTINATION "${GLINT_CMAKE_DIR}"
                              PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_DATADIR)
# find_package(glint 0.9 CONFIG) accepts 0.9.x at or above the request and nothing else: below
# 1.0 a minor release may break the callback API (docs/integration.md, "Versions"), so
# SameMinorVersion; from 1.0 on this becomes SameMajorVersion.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/package/glint-config-version.cmake"
                                 VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/package/glint-config.cmake"
              "${PROJECT_BINARY_DIR}/package/glint-config-version.cmake" DESTINATION "${GLINT_CMAKE_DIR}")
