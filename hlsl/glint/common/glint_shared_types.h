// Types for the constants headers that C++ and HLSL both compile (glint_<effect>_constants.h).
// In C++ the HLSL vector names become plain structs with the same size and alignment as a
// cbuffer member, so one struct definition serves both languages; every constants struct is
// a whole number of 16-byte registers and is checked with static_asserts on the host side.
#ifndef GLINT_SHARED_TYPES_H
#define GLINT_SHARED_TYPES_H

#include "glint/common/glint_version.h"

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

namespace glint::shared {
using uint = std::uint32_t;
struct uint2 { uint x, y; };
struct uint4 { uint x, y, z, w; };
struct float2 { float x, y; };
struct float4 { float x, y, z, w; };
// Matrices are not a type here: glslang ignores row_major on a float4x4 member of a struct
// used as ConstantBuffer<T>, so the two compilers would disagree on the layout. Constants
// carry a matrix M (column-vector convention, M.p) as four float4 rows, and the shader
// computes M.p as float4(dot(row0, p), dot(row1, p), dot(row2, p), dot(row3, p)).
} // namespace glint::shared

#define GLINT_CONSTANTS_BEGIN(name) struct alignas(16) name {
#define GLINT_CONSTANTS_END(name)                                                                           \
    }                                                                                                      \
    ;                                                                                                      \
    static_assert(sizeof(name) % 16 == 0, #name " must be whole 16-byte registers")
#define GLINT_SHARED_USING using namespace glint::shared
#else
#define GLINT_CONSTANTS_BEGIN(name) struct name {
#define GLINT_CONSTANTS_END(name) }
#define GLINT_SHARED_USING
#endif

#endif // GLINT_SHARED_TYPES_H
