// glint devices: every Vulkan device the loader sees, and which one GLINT_DEVICE selects.
#include "cli_commands.h"

#include <CLI/CLI.hpp>

#include <gpu/gpu_context.h>
#include <gpu/gpu_devices.h>

#include <cstdio>
#include <string>

namespace glint::cli {
namespace {

std::string subgroupOpsText(VkSubgroupFeatureFlags ops) {
    static const struct {
        VkSubgroupFeatureFlags bit;
        const char* name;
    } kOps[] = {{VK_SUBGROUP_FEATURE_BASIC_BIT, "basic"},
                {VK_SUBGROUP_FEATURE_VOTE_BIT, "vote"},
                {VK_SUBGROUP_FEATURE_ARITHMETIC_BIT, "arithmetic"},
                {VK_SUBGROUP_FEATURE_BALLOT_BIT, "ballot"},
                {VK_SUBGROUP_FEATURE_SHUFFLE_BIT, "shuffle"},
                {VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT, "shuffle-relative"},
                {VK_SUBGROUP_FEATURE_CLUSTERED_BIT, "clustered"},
                {VK_SUBGROUP_FEATURE_QUAD_BIT, "quad"}};
    std::string text;
    for (const auto& op : kOps)
        if (ops & op.bit) {
            if (!text.empty()) text.push_back(',');
            text.append(op.name);
        }
    return text.empty() ? "none" : text;
}

} // namespace

void addDevicesOptions(CLI::App&, DevicesOptions&) {}

int runDevices(DevicesOptions, bool validate) {
    // Creating the context both opens the instance and applies GLINT_DEVICE, so the listing
    // marks exactly the device every other verb would run on.
    gpu::ContextOptions options;
    options.validation = validate;
    options.synchronizationValidation = validate;
    gpu::Context context = gpu::createContext(options);
    const std::vector<gpu::DeviceInfo> devices =
        gpu::listDevices(context.instance, context.instanceApiVersion);
    for (const gpu::DeviceInfo& device : devices) {
        const bool chosen = device.index == context.info.index;
        std::printf("%c %u: %s (%s)\n", chosen ? '*' : ' ', device.index, device.name.c_str(),
                    gpu::deviceTypeName(device.type));
        std::printf("     driver %s %s, Vulkan %s, vendor 0x%04x\n",
                    device.driverName.empty() ? "?" : device.driverName.c_str(), device.driverInfo.c_str(),
                    gpu::versionString(device.apiVersion).c_str(), device.vendorID);
        std::printf("     subgroup size %u (%s), float16 %s, int16 %s, 16-bit storage %s, timestamps %s\n",
                    device.subgroupSize, subgroupOpsText(device.subgroupOps).c_str(),
                    device.float16 ? "yes" : "no", device.int16 ? "yes" : "no",
                    device.storage16 ? "yes" : "no", device.timestamps ? "yes" : "no");
    }
    std::printf("* = selected (GLINT_DEVICE=%s)\n",
                options.deviceSelector.empty() ? "<unset>" : options.deviceSelector.c_str());
    gpu::destroyContext(context);
    const uint32_t validationErrors = context.validation ? context.validation->errors.load() : 0u;
    if (validationErrors > 0) std::fprintf(stderr, "glint: %u validation errors\n", validationErrors);
    return devices.empty() || validationErrors > 0 ? kExitCheckFailed : kExitOk;
}

} // namespace glint::cli
