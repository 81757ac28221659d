// Shared by every entry file (hlsl/entry/**): the one place that hides how the two HLSL
// compilers spell a storage image's format. lavapipe cannot load from storage images without
// a declared format, and NVIDIA may misbehave when the declared format is not the real one,
// so every RWTexture declares exactly the format of the image bound to it.
//
//   GLINT_IMAGE_FORMAT(rgba16f) RWTexture2D<float4> g_glint_output;
//
// glslang: [[spv::format_rgba16f]] (it ignores vk::image_format). DXC: [[vk::image_format("rgba16f")]]
// (it rejects spv::format_* under -WX).
#ifndef GLINT_ENTRY_COMMON_HLSLI
#define GLINT_ENTRY_COMMON_HLSLI

#if defined(__spirv__) && defined(__hlsl_dx_compiler)
#define GLINT_IMAGE_FORMAT(format) [[vk::image_format(#format)]]
#elif defined(GLINT_COMPILER_DXC)
#define GLINT_IMAGE_FORMAT(format) [[vk::image_format(#format)]]
#else
#define GLINT_IMAGE_FORMAT(format) [[spv::format_##format]]
#endif

#endif // GLINT_ENTRY_COMMON_HLSLI
