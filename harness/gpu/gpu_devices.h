// Which Vulkan devices exist and which one the harness runs on. chooseDevice is a pure
// function of the device list and the GLINT_DEVICE selector so it can be tested without a GPU.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glint::gpu {

struct DeviceInfo {
    uint32_t index = 0; // position in vkEnumeratePhysicalDevices' order
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    std::string driverName; // VkPhysicalDeviceDriverProperties (empty before Vulkan 1.2)
    std::string driverInfo;
    uint32_t apiVersion = 0;
    uint32_t driverVersion = 0;
    uint32_t vendorID = 0;
    uint32_t subgroupSize = 0;
    VkSubgroupFeatureFlags subgroupOps = 0; // supportedOperations (compute stage assumed)
    bool float16 = false;                   // shaderFloat16
    bool int16 = false;                     // shaderInt16
    bool storage16 = false;                 // storageBuffer16BitAccess
    bool timestamps = false;                // timestampValidBits > 0
    uint32_t timestampValidBits = 0;        // of the queue family findComputeQueueFamily picks
};

// Every physical device of the instance, in enumeration order (info.index == position).
// instanceApiVersion is the version the instance was created with (at least 1.1): features
// and properties of newer Vulkan versions are only queried where both sides have them.
std::vector<DeviceInfo> listDevices(VkInstance instance, uint32_t instanceApiVersion = VK_API_VERSION_1_2);

// The queue family glint uses on a device: the first with compute (on desktop GPUs that is the
// universal graphics+compute family, the best tested path). UINT32_MAX when there is none.
uint32_t findComputeQueueFamily(VkPhysicalDevice physical);

struct DeviceChoice {
    uint32_t index = 0; // DeviceInfo::index of the chosen device, valid when error is empty
    std::string error;  // one line naming the selector and listing the available devices
    bool ok() const { return error.empty(); }
};

// selector is GLINT_DEVICE's value:
//   empty            the best device: discrete GPU > integrated > virtual > CPU > other,
//                    the lowest index among equals;
//   decimal number   the device with that index;
//   anything else    the best device whose name contains it, ignoring case.
// Devices older than Vulkan 1.1 are never chosen: glint needs subgroup operations.
DeviceChoice chooseDevice(const std::vector<DeviceInfo>& devices, std::string_view selector);

const char* deviceTypeName(VkPhysicalDeviceType type);
// "1.3.230"
std::string versionString(uint32_t apiVersion);

} // namespace glint::gpu
