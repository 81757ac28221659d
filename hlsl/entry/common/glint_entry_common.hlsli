// Shared by every entry file (hlsl/entry/**): the one place that hides how the compilers and
// targets spell Vulkan-only attributes, so one entry file compiles to SPIR-V (DXC -spirv,
// glslang) and to DXIL (DXC without -spirv) with warnings as errors.
//
//   GLINT_BINDING(2, 0) GLINT_IMAGE_FORMAT(rgba16f) RWTexture2D<float4> g_glint_output;
//
// GLINT_BINDING(slot, set): [[vk::binding(slot, set)]] for SPIR-V. DXIL has no descriptor sets
// and DXC warns that the attribute is ignored ("attribute ignored" is an error under -WX), so
// it expands to nothing there and DXC assigns registers in declaration order; an engine that
// binds by register writes its own entry file with register(tN, spaceM).
//
// GLINT_IMAGE_FORMAT(format): a storage image's format. lavapipe cannot load from storage
// images without a declared format, and NVIDIA may misbehave when the declared format is not
// the real one, so every RWTexture declares exactly the format of the image bound to it.
// glslang: [[spv::format_rgba16f]] (it ignores vk::image_format). DXC -spirv:
// [[vk::image_format("rgba16f")]] (it rejects spv::format_* under -WX). DXIL: nothing (typed
// UAVs carry their format in the resource).
//
//   GLINT_BINDING(3, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_output;
//
// GLINT_FLOAT4_STORAGE(is16) / GLINT_FLOAT_STORAGE(is16): the storage image of a pass whose
// 16-bit permutation narrows what it stores: RWTexture2D<float4> / RWTexture2D<float> declared
// rgba16f / r16f when is16 is 1 and rgba32f / r32f when it is 0. is16 is the permutation's
// macro, defined as 0 or 1: the permutations' macros below are 0 unless the build sets them.
#ifndef GLINT_ENTRY_COMMON_HLSLI
#define GLINT_ENTRY_COMMON_HLSLI

#if defined(__hlsl_dx_compiler) || defined(GLINT_COMPILER_DXC)
#if defined(__spirv__)
#define GLINT_BINDING(slot, set) [[vk::binding(slot, set)]]
#define GLINT_IMAGE_FORMAT(format) [[vk::image_format(#format)]]
#else
// DXC compiling to DXIL.
#define GLINT_BINDING(slot, set)
#define GLINT_IMAGE_FORMAT(format)
#endif
#else
// glslang's HLSL front end, which always targets SPIR-V.
#define GLINT_BINDING(slot, set) [[vk::binding(slot, set)]]
#define GLINT_IMAGE_FORMAT(format) [[spv::format_##format]]
#endif

#ifndef GLINT_RD_HALF_STORAGE
#define GLINT_RD_HALF_STORAGE 0
#endif
#ifndef GLINT_SSSR_HALF_STORAGE
#define GLINT_SSSR_HALF_STORAGE 0
#endif
#define GLINT_ENTRY_JOIN_(a, b) a##b
#define GLINT_ENTRY_JOIN(a, b) GLINT_ENTRY_JOIN_(a, b)
#define GLINT_FLOAT4_STORAGE(is16) GLINT_ENTRY_JOIN(GLINT_FLOAT4_STORAGE_, is16)
#define GLINT_FLOAT4_STORAGE_0 GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4>
#define GLINT_FLOAT4_STORAGE_1 GLINT_IMAGE_FORMAT(rgba16f) RWTexture2D<float4>
#define GLINT_FLOAT_STORAGE(is16) GLINT_ENTRY_JOIN(GLINT_FLOAT_STORAGE_, is16)
#define GLINT_FLOAT_STORAGE_0 GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float>
#define GLINT_FLOAT_STORAGE_1 GLINT_IMAGE_FORMAT(r16f) RWTexture2D<float>

#endif // GLINT_ENTRY_COMMON_HLSLI
