// GLINT_DEVICE selection on made-up device lists: no GPU needed.
#include <gpu/gpu_devices.h>

#include <catch2/catch.hpp>

#include <vector>

using glint::gpu::chooseDevice;
using glint::gpu::DeviceInfo;

namespace {

DeviceInfo device(uint32_t index, const char* name, VkPhysicalDeviceType type,
                  uint32_t apiVersion = VK_API_VERSION_1_3) {
    DeviceInfo info;
    info.index = index;
    info.name = name;
    info.type = type;
    info.apiVersion = apiVersion;
    return info;
}

const std::vector<DeviceInfo> kMixed = {
    device(0, "llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU),
    device(1, "Intel(R) UHD Graphics 770", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
    device(2, "NVIDIA GeForce RTX 4090", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
    device(3, "Virtio-GPU Venus", VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU),
};

uint32_t chosen(const std::vector<DeviceInfo>& devices, std::string_view selector) {
    const auto choice = chooseDevice(devices, selector);
    INFO(choice.error);
    REQUIRE(choice.ok());
    return choice.index;
}

} // namespace

TEST_CASE("without a selector a discrete GPU beats integrated, virtual and CPU devices", "[device]") {
    CHECK(chosen(kMixed, "") == 2);
    CHECK(chosen({kMixed[0], kMixed[1], kMixed[3]}, "") == 1);
    CHECK(chosen({kMixed[0], kMixed[3]}, "") == 3);
}

TEST_CASE("without a selector lavapipe is chosen when it is the only device", "[device]") {
    CHECK(chosen({kMixed[0]}, "") == 0);
}

TEST_CASE("equally ranked devices go to the lowest index", "[device]") {
    const std::vector<DeviceInfo> twins = {
        device(0, "llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU),
        device(1, "NVIDIA GeForce RTX 4090", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
        device(2, "NVIDIA GeForce RTX 4090", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
    };
    CHECK(chosen(twins, "") == 1);
    CHECK(chosen(twins, "rtx") == 1);
}

TEST_CASE("a decimal selector picks that device index even if a better one exists", "[device]") {
    CHECK(chosen(kMixed, "0") == 0);
    CHECK(chosen(kMixed, "3") == 3);
    CHECK(chosen(kMixed, " 1 ") == 1);
}

TEST_CASE("a name selector matches a substring ignoring case", "[device]") {
    CHECK(chosen(kMixed, "LLVMPIPE") == 0);
    CHECK(chosen(kMixed, "rtx 4090") == 2);
    CHECK(chosen(kMixed, "intel") == 1);
    // Several matches: the better device type wins.
    CHECK(chosen(kMixed, "i") == 2);
}

TEST_CASE("a selector that matches nothing gives one line naming it and listing the devices", "[device]") {
    const auto choice = chooseDevice(kMixed, "radeon");
    REQUIRE_FALSE(choice.ok());
    CHECK_THAT(choice.error, Catch::Contains("GLINT_DEVICE='radeon'"));
    for (const DeviceInfo& info : kMixed) CHECK_THAT(choice.error, Catch::Contains(info.name));
    CHECK(choice.error.find('\n') == std::string::npos);
}

TEST_CASE("an index beyond the device list is an error", "[device]") {
    const auto choice = chooseDevice(kMixed, "4");
    REQUIRE_FALSE(choice.ok());
    CHECK_THAT(choice.error, Catch::Contains("GLINT_DEVICE='4'"));
    CHECK_THAT(choice.error, Catch::Contains("llvmpipe"));
}

TEST_CASE("devices older than Vulkan 1.1 are never chosen", "[device]") {
    const std::vector<DeviceInfo> devices = {
        device(0, "Old Discrete", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_0),
        device(1, "llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU, VK_API_VERSION_1_1),
    };
    CHECK(chosen(devices, "") == 1);
    CHECK_FALSE(chooseDevice(devices, "0").ok());
    CHECK_FALSE(chooseDevice(devices, "old").ok());
    CHECK_FALSE(chooseDevice({devices[0]}, "").ok());
}

TEST_CASE("an empty device list is an error, not a crash", "[device]") {
    const auto choice = chooseDevice({}, "");
    REQUIRE_FALSE(choice.ok());
    CHECK_THAT(choice.error, Catch::Contains("no Vulkan device"));
}
