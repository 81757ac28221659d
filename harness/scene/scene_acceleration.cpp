#include "scene/scene_acceleration.h"

#include "scene/scene_file.h"

#include "glint/vulkan/vk_check.h"
#include "glint/vulkan/vk_resources.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace glint::scene {
namespace {

// The extension's entry points, which the loader does not export.
struct AccelerationFunctions {
    PFN_vkGetAccelerationStructureBuildSizesKHR buildSizes = nullptr;
    PFN_vkCreateAccelerationStructureKHR create = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroy = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR build = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR address = nullptr;
};

template <typename F> F load(VkDevice device, const char* name) {
    auto function = reinterpret_cast<F>(vkGetDeviceProcAddr(device, name));
    if (!function) throw std::runtime_error(std::string("the device has no ") + name);
    return function;
}

AccelerationFunctions loadFunctions(VkDevice device) {
    AccelerationFunctions f;
    f.buildSizes =
        load<PFN_vkGetAccelerationStructureBuildSizesKHR>(device, "vkGetAccelerationStructureBuildSizesKHR");
    f.create = load<PFN_vkCreateAccelerationStructureKHR>(device, "vkCreateAccelerationStructureKHR");
    f.destroy = load<PFN_vkDestroyAccelerationStructureKHR>(device, "vkDestroyAccelerationStructureKHR");
    f.build = load<PFN_vkCmdBuildAccelerationStructuresKHR>(device, "vkCmdBuildAccelerationStructuresKHR");
    f.address = load<PFN_vkGetAccelerationStructureDeviceAddressKHR>(
        device, "vkGetAccelerationStructureDeviceAddressKHR");
    return f;
}

// A buffer the device reads or writes by address (build inputs, scratch, structure storage);
// host-visible ones stay mapped.
struct AddressedBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceAddress address = 0;
    void* mapped = nullptr;
};

AddressedBuffer createAddressed(const vk::Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                                bool hostVisible) {
    AddressedBuffer out;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = std::max<VkDeviceSize>(size, 16);
    info.usage = usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    GLINT_VK_CHECK(vkCreateBuffer(device.device, &info, nullptr, &out.buffer));
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.device, out.buffer, &requirements);
    const VkMemoryPropertyFlags required =
        hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT : 0;
    const uint32_t type = vk::findMemoryType(device, requirements.memoryTypeBits, required,
                                             hostVisible ? 0 : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (type == UINT32_MAX) {
        vkDestroyBuffer(device.device, out.buffer, nullptr);
        throw vk::VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY,
                              "no memory type for an acceleration structure buffer");
    }
    VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    VkMemoryAllocateInfo allocation{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocation.pNext = &flags;
    allocation.allocationSize = requirements.size;
    allocation.memoryTypeIndex = type;
    if (const VkResult result = vkAllocateMemory(device.device, &allocation, nullptr, &out.memory);
        result != VK_SUCCESS) {
        vkDestroyBuffer(device.device, out.buffer, nullptr);
        throw vk::VulkanError(result, "vkAllocateMemory for an acceleration structure buffer");
    }
    GLINT_VK_CHECK(vkBindBufferMemory(device.device, out.buffer, out.memory, 0));
    if (hostVisible) GLINT_VK_CHECK(vkMapMemory(device.device, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped));
    VkBufferDeviceAddressInfo addressInfo{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    addressInfo.buffer = out.buffer;
    out.address = vkGetBufferDeviceAddress(device.device, &addressInfo);
    return out;
}

void destroyAddressed(const vk::Device& device, AddressedBuffer& buffer) {
    if (buffer.buffer) vkDestroyBuffer(device.device, buffer.buffer, nullptr);
    if (buffer.memory) vkFreeMemory(device.device, buffer.memory, nullptr);
    buffer = {};
}

VkDeviceSize roundUp(VkDeviceSize value, VkDeviceSize multiple) {
    return multiple <= 1 ? value : (value + multiple - 1) / multiple * multiple;
}

VkDeviceSize scratchAlignment(const vk::Device& device) {
    VkPhysicalDeviceAccelerationStructurePropertiesKHR acceleration{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties.pNext = &acceleration;
    vkGetPhysicalDeviceProperties2(device.physical, &properties);
    return acceleration.minAccelerationStructureScratchOffsetAlignment;
}

} // namespace

struct SceneAccelerationStructure::Level {
    const vk::Device* device = nullptr;
    AccelerationFunctions functions;
    AddressedBuffer input;   // vertices (bottom) or instances (top)
    AddressedBuffer storage; // the structure
    AddressedBuffer scratch;
    VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
    VkDeviceAddress address = 0;

    ~Level() {
        if (handle) functions.destroy(device->device, handle, nullptr);
        for (AddressedBuffer* buffer : {&input, &storage, &scratch}) destroyAddressed(*device, *buffer);
    }

    // Creates the structure for one geometry of `count` primitives and its scratch memory, and
    // fills `build` for the command that builds it.
    void create(VkAccelerationStructureTypeKHR type, const VkAccelerationStructureGeometryKHR& geometry,
                uint32_t count, VkAccelerationStructureBuildGeometryInfoKHR& build) {
        build = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
        build.type = type;
        build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
        build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
        build.geometryCount = 1;
        build.pGeometries = &geometry;
        VkAccelerationStructureBuildSizesInfoKHR sizes{
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
        functions.buildSizes(device->device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build, &count,
                             &sizes);
        storage = createAddressed(*device, sizes.accelerationStructureSize,
                                  VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR, false);
        const VkDeviceSize alignment = scratchAlignment(*device);
        scratch = createAddressed(*device, sizes.buildScratchSize + alignment,
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
        VkAccelerationStructureCreateInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
        info.buffer = storage.buffer;
        info.size = sizes.accelerationStructureSize;
        info.type = type;
        GLINT_VK_CHECK(functions.create(device->device, &info, nullptr, &handle));
        VkAccelerationStructureDeviceAddressInfoKHR addressInfo{
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
        addressInfo.accelerationStructure = handle;
        address = functions.address(device->device, &addressInfo);
        build.dstAccelerationStructure = handle;
        build.scratchData.deviceAddress = roundUp(scratch.address, alignment);
    }
};

std::ptrdiff_t firstSphere(std::span<const shaders::ScenePrimitive> primitives) {
    const auto it = std::find_if(primitives.begin(), primitives.end(), [](const shaders::ScenePrimitive& p) {
        return p.kind != GLINT_SCENE_PRIM_TRIANGLE;
    });
    return it == primitives.end() ? -1 : it - primitives.begin();
}

SceneAccelerationStructure::SceneAccelerationStructure(const gpu::Context& context) : context_(context) {
    if (!context.device.rayQuery)
        throw std::runtime_error(
            "device '" + context.info.name +
            "' has no ray queries (VK_KHR_acceleration_structure, VK_KHR_ray_query), which "
            "hybrid.rayQuery needs");
}

SceneAccelerationStructure::~SceneAccelerationStructure() = default;

VkAccelerationStructureKHR SceneAccelerationStructure::topLevel() const {
    return top_ ? top_->handle : VK_NULL_HANDLE;
}

void SceneAccelerationStructure::build(std::span<const shaders::ScenePrimitive> primitives) {
    const std::span<const std::byte> bytes = std::as_bytes(primitives);
    if (top_ && built_.size() == bytes.size() && std::equal(bytes.begin(), bytes.end(), built_.begin()))
        return;
    if (const std::ptrdiff_t sphere = firstSphere(primitives); sphere >= 0)
        throw SceneError("acceleration structure: primitive " + std::to_string(sphere) + " (object " +
                         std::to_string(primitives[static_cast<std::size_t>(sphere)].object) +
                         ") is a sphere; the structure holds triangles only");
    const vk::Device& device = context_.device;
    top_.reset();
    bottom_.reset();
    built_.clear();
    const AccelerationFunctions functions = loadFunctions(device.device);
    auto bottom = std::make_unique<Level>();
    auto top = std::make_unique<Level>();
    bottom->device = top->device = &device;
    bottom->functions = top->functions = functions;

    // Bottom level: the triangles unindexed, three vertices each, in the BVH's order, so that
    // triangle i is primitive index i.
    const uint32_t triangles = static_cast<uint32_t>(primitives.size());
    std::vector<float> vertices;
    vertices.reserve(std::size_t{9} * triangles);
    for (const shaders::ScenePrimitive& p : primitives)
        for (const shaders::float3& v : {p.p0, p.p1, p.p2}) vertices.insert(vertices.end(), {v.x, v.y, v.z});
    const VkBufferUsageFlags inputUsage =
        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;
    bottom->input = createAddressed(device, vertices.size() * sizeof(float), inputUsage, true);
    if (!vertices.empty())
        std::memcpy(bottom->input.mapped, vertices.data(), vertices.size() * sizeof(float));
    VkAccelerationStructureGeometryKHR triangleGeometry{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    triangleGeometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
    triangleGeometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
    VkAccelerationStructureGeometryTrianglesDataKHR& data = triangleGeometry.geometry.triangles;
    data.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
    data.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
    data.vertexData.deviceAddress = bottom->input.address;
    data.vertexStride = 3 * sizeof(float);
    data.maxVertex = triangles == 0 ? 0 : 3 * triangles - 1;
    data.indexType = VK_INDEX_TYPE_NONE_KHR;
    VkAccelerationStructureBuildGeometryInfoKHR bottomBuild;
    bottom->create(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, triangleGeometry, triangles, bottomBuild);

    // Top level: one instance, identity transform, both faces (the BVH tracer is two-sided).
    VkAccelerationStructureInstanceKHR instance{};
    instance.transform.matrix[0][0] = instance.transform.matrix[1][1] = instance.transform.matrix[2][2] =
        1.0f;
    instance.instanceCustomIndex = kSceneInstanceCustomIndex;
    instance.mask = 0xFF;
    instance.instanceShaderBindingTableRecordOffset = 0;
    instance.flags =
        VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR | VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR;
    instance.accelerationStructureReference = bottom->address;
    const uint32_t instances = triangles == 0 ? 0 : 1;
    top->input = createAddressed(device, sizeof(instance), inputUsage, true);
    std::memcpy(top->input.mapped, &instance, sizeof(instance));
    VkAccelerationStructureGeometryKHR instanceGeometry{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    instanceGeometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    instanceGeometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
    instanceGeometry.geometry.instances.sType =
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    instanceGeometry.geometry.instances.arrayOfPointers = VK_FALSE;
    instanceGeometry.geometry.instances.data.deviceAddress = top->input.address;
    VkAccelerationStructureBuildGeometryInfoKHR topBuild;
    top->create(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, instanceGeometry, instances, topBuild);

    gpu::submitAndWait(context_, [&](VkCommandBuffer cmd) {
        const VkAccelerationStructureBuildRangeInfoKHR bottomRange{triangles, 0, 0, 0};
        const VkAccelerationStructureBuildRangeInfoKHR* bottomRanges = &bottomRange;
        functions.build(cmd, 1, &bottomBuild, &bottomRanges);
        // The top level reads the bottom level's address: the bottom build must be done.
        VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
        barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                             VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &barrier, 0,
                             nullptr, 0, nullptr);
        const VkAccelerationStructureBuildRangeInfoKHR topRange{instances, 0, 0, 0};
        const VkAccelerationStructureBuildRangeInfoKHR* topRanges = &topRange;
        functions.build(cmd, 1, &topBuild, &topRanges);
        // Later submissions trace it from compute shaders.
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    });
    bottom_ = std::move(bottom);
    top_ = std::move(top);
    built_.assign(bytes.begin(), bytes.end());
}

} // namespace glint::scene
