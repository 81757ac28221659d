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

#endif // GLINT_ENTRY_COMMON_HLSLI
