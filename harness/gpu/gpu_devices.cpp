// Device enumeration and the GLINT_DEVICE selection rule.
#include <gpu/gpu_devices.h>

#include "glint/vulkan/vk_check.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace glint::gpu {

namespace {

bool hasDeviceExtension(VkPhysicalDevice physical, const char* name) {
    uint32_t count = 0;
    GLINT_VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    GLINT_VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data()));
    return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
        return std::string_view(e.extensionName) == name;
    });
}

std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice physical) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    return families;
}

void queryProperties(VkPhysicalDevice physical, uint32_t version, DeviceInfo& info) {
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties.pNext = &subgroup;
    // Driver properties are core in 1.2 and otherwise need VK_KHR_driver_properties.
    const bool hasDriver =
        version >= VK_API_VERSION_1_2 || hasDeviceExtension(physical, "VK_KHR_driver_properties");
    if (hasDriver) subgroup.pNext = &driver;
    vkGetPhysicalDeviceProperties2(physical, &properties);

    info.name = properties.properties.deviceName;
    info.type = properties.properties.deviceType;
    info.apiVersion = properties.properties.apiVersion;
    info.driverVersion = properties.properties.driverVersion;
    info.vendorID = properties.properties.vendorID;
    if (hasDriver) {
        info.driverName = driver.driverName;
        info.driverInfo = driver.driverInfo;
    }
    info.subgroupSize = subgroup.subgroupSize;
    // Operations only count if compute shaders may use them; that is all glint dispatches.
    if (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT)
        info.subgroupOps = subgroup.supportedOperations;
}

void queryFeatures(VkPhysicalDevice physical, uint32_t version, DeviceInfo& info) {
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    if (version >= VK_API_VERSION_1_2) {
        VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
        VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        features.pNext = &v11;
        v11.pNext = &v12;
        vkGetPhysicalDeviceFeatures2(physical, &features);
        info.storage16 = v11.storageBuffer16BitAccess;
        info.float16 = v12.shaderFloat16;
    } else {
        // Vulkan 1.1: 16-bit storage is core, shaderFloat16 comes from an extension.
        VkPhysicalDevice16BitStorageFeatures storage{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_16BIT_STORAGE_FEATURES};
        VkPhysicalDeviceShaderFloat16Int8Features float16{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES};
        features.pNext = &storage;
        if (hasDeviceExtension(physical, "VK_KHR_shader_float16_int8")) storage.pNext = &float16;
        vkGetPhysicalDeviceFeatures2(physical, &features);
        info.storage16 = storage.storageBuffer16BitAccess;
        info.float16 = float16.shaderFloat16;
    }
    info.int16 = features.features.shaderInt16;
}

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 3;
    default:
        return 4;
    }
}

bool usable(const DeviceInfo& device) {
    return device.apiVersion >= VK_API_VERSION_1_1;
}

std::string lowercase(std::string_view text) {
    std::string result(text);
    for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return result;
}

std::string_view trim(std::string_view text) {
    const auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

std::string deviceList(const std::vector<DeviceInfo>& devices) {
    if (devices.empty()) return "none";
    std::string list;
    for (const DeviceInfo& device : devices) {
        if (!list.empty()) list += ", ";
        list += std::to_string(device.index) + ": " + device.name + " (" + deviceTypeName(device.type) +
                ", Vulkan " + versionString(device.apiVersion) + ")";
    }
    return list;
}

DeviceChoice failure(const std::vector<DeviceInfo>& devices, const std::string& reason) {
    return {0, reason + "; available devices: " + deviceList(devices)};
}

// The preferred usable device among those passing `accept`, or nullptr.
template <typename Accept> const DeviceInfo* best(const std::vector<DeviceInfo>& devices, Accept accept) {
    const DeviceInfo* chosen = nullptr;
    for (const DeviceInfo& device : devices) {
        if (!usable(device) || !accept(device)) continue;
        if (!chosen || typeRank(device.type) < typeRank(chosen->type) ||
            (typeRank(device.type) == typeRank(chosen->type) && device.index < chosen->index)) {
            chosen = &device;
        }
    }
    return chosen;
}

} // namespace

uint32_t findComputeQueueFamily(VkPhysicalDevice physical) {
    const std::vector<VkQueueFamilyProperties> families = queueFamilies(physical);
    for (uint32_t i = 0; i < families.size(); ++i) {
        if (families[i].queueCount > 0 && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) return i;
    }
    return UINT32_MAX;
}

std::vector<DeviceInfo> listDevices(VkInstance instance, uint32_t instanceApiVersion) {
    uint32_t count = 0;
    GLINT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    GLINT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, physicals.data()));
    physicals.resize(count);

    std::vector<DeviceInfo> devices;
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties basic{};
        vkGetPhysicalDeviceProperties(physicals[i], &basic);
        DeviceInfo info;
        info.index = i;
        if (basic.apiVersion < VK_API_VERSION_1_1) {
            // Listed so the user sees it, but never chosen; its 1.1 queries would be invalid.
            info.name = basic.deviceName;
            info.type = basic.deviceType;
            info.apiVersion = basic.apiVersion;
            info.driverVersion = basic.driverVersion;
            info.vendorID = basic.vendorID;
        } else {
            const uint32_t version = std::min(basic.apiVersion, instanceApiVersion);
            queryProperties(physicals[i], version, info);
            queryFeatures(physicals[i], version, info);
        }
        const uint32_t family = findComputeQueueFamily(physicals[i]);
        if (family != UINT32_MAX) {
            info.timestampValidBits = queueFamilies(physicals[i])[family].timestampValidBits;
            info.timestamps = info.timestampValidBits > 0;
        }
        devices.push_back(std::move(info));
    }
    return devices;
}

DeviceChoice chooseDevice(const std::vector<DeviceInfo>& devices, std::string_view selector) {
    selector = trim(selector);
    if (devices.empty()) return failure(devices, "no Vulkan device found");

    if (selector.empty()) {
        const DeviceInfo* chosen = best(devices, [](const DeviceInfo&) { return true; });
        if (!chosen) return failure(devices, "no Vulkan device supports Vulkan 1.1");
        return {chosen->index, {}};
    }

    const std::string quoted = "GLINT_DEVICE='" + std::string(selector) + "'";
    uint32_t number = 0;
    const auto [end, error] = std::from_chars(selector.data(), selector.data() + selector.size(), number);
    if (error == std::errc{} && end == selector.data() + selector.size()) {
        const auto found = std::find_if(devices.begin(), devices.end(),
                                        [&](const DeviceInfo& device) { return device.index == number; });
        if (found == devices.end()) return failure(devices, quoted + " is not a device index");
        if (!usable(*found))
            return failure(devices, quoted + " supports only Vulkan " + versionString(found->apiVersion) +
                                        ", glint needs 1.1");
        return {found->index, {}};
    }

    const std::string needle = lowercase(selector);
    const DeviceInfo* chosen = best(devices, [&](const DeviceInfo& device) {
        return lowercase(device.name).find(needle) != std::string::npos;
    });
    if (!chosen) return failure(devices, quoted + " matches no Vulkan 1.1 device name");
    return {chosen->index, {}};
}

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "CPU";
    default:
        return "other";
    }
}

std::string versionString(uint32_t apiVersion) {
    return std::to_string(VK_API_VERSION_MAJOR(apiVersion)) + "." +
           std::to_string(VK_API_VERSION_MINOR(apiVersion)) + "." +
           std::to_string(VK_API_VERSION_PATCH(apiVersion));
}

} // namespace glint::gpu
