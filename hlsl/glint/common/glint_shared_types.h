// Types for the constants headers that C++ and HLSL both compile (glint_<effect>_constants.h).
// In C++ the HLSL vector names become plain structs with the same size and alignment as a
// cbuffer member, so one struct definition serves both languages; every constants struct is
// a whole number of 16-byte registers and is checked with static_asserts on the host side.
#ifndef GLINT_SHARED_TYPES_H
#define GLINT_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

namespace glint::shared {
using uint = std::uint32_t;
struct uint2 { uint x, y; };
struct uint4 { uint x, y, z, w; };
struct float2 { float x, y; };
struct float4 { float x, y, z, w; };
// Row-major 4x4 (m[row * 4 + column]); HLSL declares it GLINT_ROW_MAJOR float4x4 so that the
// memory layout is the same in both languages and mul(M, v) means M.v.
struct float4x4 { float m[16]; };
} // namespace glint::shared

#define GLINT_CONSTANTS_BEGIN(name) struct alignas(16) name {
#define GLINT_CONSTANTS_END(name)                                                                           \
    }                                                                                                      \
    ;                                                                                                      \
    static_assert(sizeof(name) % 16 == 0, #name " must be whole 16-byte registers")
#define GLINT_ROW_MAJOR
#define GLINT_SHARED_USING using namespace glint::shared
#else
#define GLINT_CONSTANTS_BEGIN(name) struct name {
#define GLINT_CONSTANTS_END(name) }
#define GLINT_ROW_MAJOR row_major
#define GLINT_SHARED_USING
#endif

#endif // GLINT_SHARED_TYPES_H
