// glint's version, for HLSL and C++ alike: MAJOR.MINOR.PATCH with the semantic-versioning rules
// of docs/integration.md, "Versions". Every constants header includes it (through
// glint_shared_types.h), so an entry file that includes a pass header can test it:
//   #if GLINT_VERSION_MAJOR != 0 || GLINT_VERSION_MINOR != 9
//   #error "written against glint 0.9: see docs/integration.md, Migration"
//   #endif
// The top-level CMakeLists.txt's project() states the same number; configuring fails when the
// two differ (cmake/GlintVersion.cmake).
#ifndef GLINT_VERSION_H
#define GLINT_VERSION_H

#define GLINT_VERSION_MAJOR 0
#define GLINT_VERSION_MINOR 9
#define GLINT_VERSION_PATCH 0
// One number that orders versions: MAJOR * 10000 + MINOR * 100 + PATCH.
#define GLINT_VERSION (GLINT_VERSION_MAJOR * 10000 + GLINT_VERSION_MINOR * 100 + GLINT_VERSION_PATCH)

#endif // GLINT_VERSION_H
