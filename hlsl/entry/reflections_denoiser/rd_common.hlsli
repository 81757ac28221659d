// Permutation GLINT_RD_HALF_STORAGE=1 (used with SSSR's halfPrecisionStorage): radiance,
// variance and history length stored in 16-bit float. Every pass clamps what it stores to the
// fp16 range first and computes in 32 bits; the guides and tile averages stay 32-bit.
//
// Bindings and callbacks every reflections-denoiser entry shares: constants, the tile list and
// the current guides. Included by the entry files before the pass header.
#ifndef RD_ENTRY_COMMON_HLSLI
#define RD_ENTRY_COMMON_HLSLI

#include "entry/common/glint_entry_common.hlsli"

// The 16-bit permutation also carries the neighbourhood statistics' spans as halves
// (glint_reflections_denoiser_common.hlsli, GLINT_RD_SpanTexel); the default stays 32-bit.
#if GLINT_RD_HALF_STORAGE
#define GLINT_RD_HALF_GROUPSHARED 1
#endif
#include "glint/reflections_denoiser/glint_reflections_denoiser_constants.h"

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value.
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_ReflectionsDenoiserConstants g_glint_rd; };
GLINT_BINDING(1, 0) StructuredBuffer<uint> g_glint_tile_list;
GLINT_BINDING(2, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(3, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(4, 0) Texture2D<float> g_glint_roughness;

uint GLINT_RD_LoadTile(uint index) { return g_glint_tile_list[index]; }
float GLINT_RD_LoadDepth(int2 pixel) { return g_glint_depth.Load(int3(pixel, 0)); }
float3 GLINT_RD_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float GLINT_RD_LoadRoughness(int2 pixel) { return g_glint_roughness.Load(int3(pixel, 0)); }

#endif // RD_ENTRY_COMMON_HLSLI
