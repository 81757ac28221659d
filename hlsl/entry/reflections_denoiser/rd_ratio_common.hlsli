// Bindings and callbacks the ratio-estimator path's entries (rd_reconstruct, rd_cleanup) share:
// the path's constants, the tile list and the current guides; the same bindings as
// rd_common.hlsli with the larger constants struct. Included before the pass header.
//
// Permutation GLINT_RD_HALF_STORAGE=1 (with SSSR's halfPrecisionStorage): the images the
// passes write are 16-bit float; both passes clamp to the fp16 range before storing.
#ifndef RD_ENTRY_RATIO_COMMON_HLSLI
#define RD_ENTRY_RATIO_COMMON_HLSLI

#include "entry/common/glint_entry_common.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_ratio_constants.h"

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value.
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_ReflectionsDenoiserRatioConstants g_glint_rd_ratio; };
GLINT_BINDING(1, 0) StructuredBuffer<uint> g_glint_tile_list;
GLINT_BINDING(2, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(3, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(4, 0) Texture2D<float> g_glint_roughness;

uint GLINT_RD_LoadTile(uint index) { return g_glint_tile_list[index]; }
float GLINT_RD_LoadDepth(int2 pixel) { return g_glint_depth.Load(int3(pixel, 0)); }
float3 GLINT_RD_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float GLINT_RD_LoadRoughness(int2 pixel) { return g_glint_roughness.Load(int3(pixel, 0)); }

#endif // RD_ENTRY_RATIO_COMMON_HLSLI
