// Descriptor layouts from SPIR-V reflection (SPIRV-Cross), so that no binding table is
// written twice: the entry file's declarations are the only source of truth.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace glint::vk {

struct BlockMember {
    std::string name;
    uint32_t offset = 0;
    uint32_t size = 0;
};

struct ReflectedBinding {
    std::string name; // the shader variable's name, which passes bind resources by
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
    uint32_t count = 1;                         // array size (arrays of storage images, e.g. per mip)
    bool writable = true;                       // storage resources not decorated NonWritable
    uint32_t blockSize = 0;                     // uniform buffers: declared size in bytes
    VkFormat imageFormat = VK_FORMAT_UNDEFINED; // storage images: the declared format (UNDEFINED: unknown)
    std::vector<BlockMember> members;           // uniform buffers: top-level members
};

struct ReflectedShader {
    uint32_t localSize[3] = {1, 1, 1};
    std::vector<ReflectedBinding> bindings; // sorted by binding; descriptor set 0 only
};

// Throws std::runtime_error naming the module when the SPIR-V cannot be parsed, uses a
// descriptor set other than 0, push constants, or a resource kind the backend does not bind.
// An acceleration structure (RayQuery) is a VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR binding.
ReflectedShader reflectComputeShader(std::span<const uint32_t> spirv, const std::string& moduleName);

// Every pair of resources a module puts on the same descriptor set and binding, in any set: one
// line each naming the module, both variables and the slot. HLSL registers of different classes
// (b0, t0, u0, s0 in one space) land on one binding unless shifted; that compiles and passes
// spirv-val, but Vulkan gives a binding one descriptor type (docs/integration.md, 5.2). Empty
// when every resource has a slot of its own. Throws std::runtime_error naming the module when
// the SPIR-V cannot be parsed.
std::vector<std::string> sharedBindings(std::span<const uint32_t> spirv, const std::string& moduleName);

} // namespace glint::vk
