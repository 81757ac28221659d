#include "glint/vulkan/vk_reflect.h"

#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>
#include <stdexcept>

namespace glint::vk {
namespace {

// The formats entry files declare on storage images (GLINT_IMAGE_FORMAT).
VkFormat toVkFormat(spv::ImageFormat format) {
    switch (format) {
    case spv::ImageFormatRgba32f:
        return VK_FORMAT_R32G32B32A32_SFLOAT;
    case spv::ImageFormatRgba16f:
        return VK_FORMAT_R16G16B16A16_SFLOAT;
    case spv::ImageFormatRg32f:
        return VK_FORMAT_R32G32_SFLOAT;
    case spv::ImageFormatRg16f:
        return VK_FORMAT_R16G16_SFLOAT;
    case spv::ImageFormatR32f:
        return VK_FORMAT_R32_SFLOAT;
    case spv::ImageFormatR16f:
        return VK_FORMAT_R16_SFLOAT;
    case spv::ImageFormatRgba8:
        return VK_FORMAT_R8G8B8A8_UNORM;
    case spv::ImageFormatR8:
        return VK_FORMAT_R8_UNORM;
    case spv::ImageFormatR32ui:
        return VK_FORMAT_R32_UINT;
    default:
        return VK_FORMAT_UNDEFINED;
    }
}

void addBindings(const spirv_cross::Compiler& compiler,
                 const spirv_cross::SmallVector<spirv_cross::Resource>& resources, VkDescriptorType type,
                 const std::string& moduleName, ReflectedShader& out) {
    for (const spirv_cross::Resource& resource : resources) {
        const uint32_t set = compiler.get_decoration(resource.id, spv::DecorationDescriptorSet);
        if (set != 0)
            throw std::runtime_error(moduleName + ": '" + resource.name + "' is in descriptor set " +
                                     std::to_string(set) + "; glint entry files use set 0 only");
        ReflectedBinding binding;
        binding.name = compiler.get_name(resource.id);
        if (binding.name.empty()) binding.name = resource.name;
        binding.binding = compiler.get_decoration(resource.id, spv::DecorationBinding);
        binding.type = type;
        const spirv_cross::SPIRType& spirType = compiler.get_type(resource.type_id);
        binding.count = 1;
        for (uint32_t dimension : spirType.array) binding.count *= std::max(dimension, 1u);
        const spirv_cross::Bitset decorations = compiler.get_decoration_bitset(resource.id);
        binding.writable = !decorations.get(spv::DecorationNonWritable);
        if (type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)
            binding.imageFormat = toVkFormat(compiler.get_type(resource.base_type_id).image.format);
        if (type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
            const spirv_cross::SPIRType& block = compiler.get_type(resource.base_type_id);
            binding.blockSize = static_cast<uint32_t>(compiler.get_declared_struct_size(block));
            for (uint32_t i = 0; i < block.member_types.size(); ++i) {
                BlockMember member;
                member.name = compiler.get_member_name(resource.base_type_id, i);
                member.offset = compiler.type_struct_member_offset(block, i);
                member.size = static_cast<uint32_t>(compiler.get_declared_struct_member_size(block, i));
                binding.members.push_back(std::move(member));
            }
        }
        out.bindings.push_back(std::move(binding));
    }
}

} // namespace

ReflectedShader reflectComputeShader(std::span<const uint32_t> spirv, const std::string& moduleName) {
    if (spirv.empty()) throw std::runtime_error(moduleName + ": no SPIR-V module of that name is embedded");
    try {
        spirv_cross::Compiler compiler(spirv.data(), spirv.size());
        ReflectedShader shader;
        const auto entryPoints = compiler.get_entry_points_and_stages();
        if (entryPoints.empty() || entryPoints[0].execution_model != spv::ExecutionModelGLCompute)
            throw std::runtime_error(moduleName + ": not a compute shader");
        const spirv_cross::SPIREntryPoint& entry =
            compiler.get_entry_point(entryPoints[0].name, spv::ExecutionModelGLCompute);
        shader.localSize[0] = entry.workgroup_size.x;
        shader.localSize[1] = entry.workgroup_size.y;
        shader.localSize[2] = entry.workgroup_size.z;

        const spirv_cross::ShaderResources resources = compiler.get_shader_resources();
        if (!resources.push_constant_buffers.empty())
            throw std::runtime_error(moduleName + ": push constants are not used by glint entry files");
        if (!resources.subpass_inputs.empty() || !resources.atomic_counters.empty())
            throw std::runtime_error(moduleName +
                                     ": declares a resource kind the compute backend does not bind");
        addBindings(compiler, resources.uniform_buffers, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, moduleName,
                    shader);
        addBindings(compiler, resources.storage_buffers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, moduleName,
                    shader);
        addBindings(compiler, resources.storage_images, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, moduleName, shader);
        addBindings(compiler, resources.separate_images, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, moduleName,
                    shader);
        addBindings(compiler, resources.separate_samplers, VK_DESCRIPTOR_TYPE_SAMPLER, moduleName, shader);
        addBindings(compiler, resources.sampled_images, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, moduleName,
                    shader);
        addBindings(compiler, resources.acceleration_structures,
                    VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, moduleName, shader);
        std::sort(shader.bindings.begin(), shader.bindings.end(),
                  [](const ReflectedBinding& a, const ReflectedBinding& b) { return a.binding < b.binding; });
        for (std::size_t i = 1; i < shader.bindings.size(); ++i)
            if (shader.bindings[i].binding == shader.bindings[i - 1].binding)
                throw std::runtime_error(moduleName + ": '" + shader.bindings[i].name + "' and '" +
                                         shader.bindings[i - 1].name + "' share binding " +
                                         std::to_string(shader.bindings[i].binding));
        return shader;
    } catch (const spirv_cross::CompilerError& error) {
        throw std::runtime_error(moduleName + ": SPIR-V reflection failed: " + error.what());
    }
}

std::vector<std::string> sharedBindings(std::span<const uint32_t> spirv, const std::string& moduleName) {
    if (spirv.empty()) throw std::runtime_error(moduleName + ": empty SPIR-V module");
    try {
        spirv_cross::Compiler compiler(spirv.data(), spirv.size());
        const spirv_cross::ShaderResources r = compiler.get_shader_resources();
        struct Slot {
            uint32_t set, binding;
            std::string name, kind;
        };
        std::vector<Slot> slots;
        const auto add = [&](const spirv_cross::SmallVector<spirv_cross::Resource>& resources,
                             const char* kind) {
            for (const spirv_cross::Resource& resource : resources) {
                std::string name = compiler.get_name(resource.id);
                if (name.empty()) name = resource.name;
                slots.push_back({compiler.get_decoration(resource.id, spv::DecorationDescriptorSet),
                                 compiler.get_decoration(resource.id, spv::DecorationBinding), name, kind});
            }
        };
        add(r.uniform_buffers, "uniform buffer");
        add(r.storage_buffers, "storage buffer");
        add(r.storage_images, "storage image");
        add(r.separate_images, "sampled image");
        add(r.separate_samplers, "sampler");
        add(r.sampled_images, "combined image sampler");
        add(r.acceleration_structures, "acceleration structure");
        std::stable_sort(slots.begin(), slots.end(), [](const Slot& a, const Slot& b) {
            return a.set != b.set ? a.set < b.set : a.binding < b.binding;
        });
        std::vector<std::string> problems;
        for (std::size_t i = 1; i < slots.size(); ++i) {
            const Slot& a = slots[i - 1];
            const Slot& b = slots[i];
            if (a.set != b.set || a.binding != b.binding) continue;
            problems.push_back(moduleName + ": '" + a.name + "' (" + a.kind + ") and '" + b.name + "' (" +
                               b.kind + ") share descriptor set " + std::to_string(a.set) + ", binding " +
                               std::to_string(a.binding) +
                               "; Vulkan gives a binding one descriptor type: give each register class its "
                               "own range (docs/integration.md, 5.2)");
        }
        return problems;
    } catch (const spirv_cross::CompilerError& error) {
        throw std::runtime_error(moduleName + ": SPIR-V reflection failed: " + error.what());
    }
}

} // namespace glint::vk
