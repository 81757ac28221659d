// Instance, validation layer, device and queue for the harness.
#include <gpu/gpu_context.h>

#include "glint/vulkan/vk_check.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

namespace glint::gpu {

namespace {

#if defined(__SANITIZE_ADDRESS__)
// LeakSanitizer checks for leaks after the Vulkan loader has unloaded the drivers and layers at
// exit. Mesa's lavapipe (libvulkan_lvp.so) keeps a 128-byte block it reallocs in a static of its
// own; once the library is unmapped nothing points at the block any more, and it is reported as a
// direct leak "from an unknown module". Keeping Mesa's drivers and the validation layer mapped
// until the process ends (RTLD_NODELETE on the already loaded library) keeps such statics, and
// the report, truthful: a block a library really loses is still reported, with its module's name
// (which is what tests/sanitizers/lsan.supp matches for the validation layer's own leaks).
void keepVulkanLibrariesLoaded() {
    dl_iterate_phdr(
        [](dl_phdr_info* object, std::size_t, void*) {
            const char* name = object->dlpi_name;
            if (name && (std::strstr(name, "/libvulkan_") != nullptr ||
                         std::strstr(name, "/libVkLayer_khronos_validation") != nullptr))
                dlopen(name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
            return 0;
        },
        nullptr);
}
#else
void keepVulkanLibrariesLoaded() {}
#endif

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
// A fence wait this long means the device hung; failing beats hanging a test run forever.
constexpr uint64_t kFenceTimeoutNs = 600ull * 1000 * 1000 * 1000;

bool contains(const std::vector<VkExtensionProperties>& extensions, std::string_view name) {
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return name == e.extensionName; });
}

std::vector<VkExtensionProperties> instanceExtensions(const char* layer) {
    uint32_t count = 0;
    GLINT_VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    GLINT_VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()));
    extensions.resize(count);
    return extensions;
}

bool hasInstanceLayer(std::string_view name) {
    uint32_t count = 0;
    GLINT_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    GLINT_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    layers.resize(count);
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& layer) { return name == layer.layerName; });
}

std::vector<VkExtensionProperties> deviceExtensions(VkPhysicalDevice physical) {
    uint32_t count = 0;
    GLINT_VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    GLINT_VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data()));
    extensions.resize(count);
    return extensions;
}

// glint needs 1.1 (subgroups, 16-bit storage in core); 1.2 brings the feature structs,
// shaderFloat16 and driver properties into core. Nothing from 1.3 is used, and the instance
// version caps what validation accepts, so a 1.3-only call made by mistake gets reported.
uint32_t chooseInstanceVersion() {
    uint32_t loader = VK_API_VERSION_1_0;
    GLINT_VK_CHECK(vkEnumerateInstanceVersion(&loader));
    if (loader < VK_API_VERSION_1_1) {
        throw std::runtime_error("glint: the Vulkan loader supports only Vulkan " + versionString(loader) +
                                 "; glint needs 1.1");
    }
    return std::min(loader, static_cast<uint32_t>(VK_API_VERSION_1_2));
}

void createInstance(const ContextOptions& options, Context& context) {
    context.instanceApiVersion = chooseInstanceVersion();

    std::vector<const char*> layers;
    std::vector<VkExtensionProperties> available = instanceExtensions(nullptr);
    if (options.validation) {
        if (!hasInstanceLayer(kValidationLayer)) {
            throw std::runtime_error("glint: validation was requested but VK_LAYER_KHRONOS_validation is not "
                                     "installed (Debian/Ubuntu: apt install vulkan-validationlayers)");
        }
        layers.push_back(kValidationLayer);
        std::vector<VkExtensionProperties> fromLayer = instanceExtensions(kValidationLayer);
        available.insert(available.end(), fromLayer.begin(), fromLayer.end());
    }

    std::vector<const char*> extensions;
    VkInstanceCreateFlags flags = 0;
    // Lists MoltenVK-style portability drivers too, so GLINT_DEVICE can select them.
    if (contains(available, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }
    // Debug utils also gives command-buffer labels to capture tools, so enable it when present.
    const bool debugUtils = contains(available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (options.validation && !debugUtils) {
        throw std::runtime_error("glint: validation was requested but VK_EXT_debug_utils is not available");
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "glint harness";
    app.pEngineName = "glint";
    app.apiVersion = context.instanceApiVersion;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.flags = flags;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();

    // Chained so that problems inside vkCreateInstance/vkDestroyInstance are counted too.
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    const VkValidationFeatureEnableEXT syncValidation =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    if (options.validation) {
        context.validation = std::make_unique<ValidationStats>();
        context.validation->printErrors = options.printValidationErrors;
        messengerInfo = messengerCreateInfo(*context.validation);
        info.pNext = &messengerInfo;
        if (options.synchronizationValidation) {
            if (!contains(available, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
                throw std::runtime_error("glint: synchronization validation was requested but the validation "
                                         "layer lacks VK_EXT_validation_features");
            }
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            features.enabledValidationFeatureCount = 1;
            features.pEnabledValidationFeatures = &syncValidation;
            messengerInfo.pNext = &features;
        }
    }
    for (const std::string& name : options.surfaceExtensions) {
        if (!contains(available, name))
            throw std::runtime_error("glint: the Vulkan loader lacks " + name + ", which the window needs");
        extensions.push_back(name.c_str());
    }
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    GLINT_VK_CHECK(vkCreateInstance(&info, nullptr, &context.instance));
    keepVulkanLibrariesLoaded();

    if (options.validation) context.messenger = createMessenger(context.instance, *context.validation);
}

VkPhysicalDevice physicalDevice(VkInstance instance, uint32_t index) {
    uint32_t count = 0;
    GLINT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    GLINT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, physicals.data()));
    return physicals.at(index);
}

// The optional features glint's shaders may use, each enabled only where supported, so that
// the same harness runs the fp16 permutations on capable devices and the fp32 path elsewhere.
struct FeatureChain {
    VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDevice16BitStorageFeatures storage16{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_16BIT_STORAGE_FEATURES};
    VkPhysicalDeviceShaderFloat16Int8Features float16{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES};
    // Only linked for the opt-in GLINT_PIPELINE_STATS diagnostic.
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executable{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    // Only linked where the device offers VK_KHR_acceleration_structure and VK_KHR_ray_query.
    VkPhysicalDeviceAccelerationStructureFeaturesKHR acceleration{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};

    FeatureChain() = default;
    // The pNext links point into the object itself; a copy would point into the original.
    FeatureChain(const FeatureChain&) = delete;
    FeatureChain& operator=(const FeatureChain&) = delete;

    // Links the structures valid for this device version (and extensions) behind core.
    void link(bool vulkan12, bool float16Extension, bool executableExtension, bool rayQueryExtensions) {
        if (vulkan12) {
            core.pNext = &v11;
            v11.pNext = &v12;
        } else {
            core.pNext = &storage16;
            if (float16Extension) storage16.pNext = &float16;
        }
        if (executableExtension) {
            // Appended at the end of whatever chain the branches above built.
            auto* last = reinterpret_cast<VkBaseOutStructure*>(&core);
            while (last->pNext) last = last->pNext;
            last->pNext = reinterpret_cast<VkBaseOutStructure*>(&executable);
        }
        if (rayQueryExtensions) {
            auto* last = reinterpret_cast<VkBaseOutStructure*>(&core);
            while (last->pNext) last = last->pNext;
            last->pNext = reinterpret_cast<VkBaseOutStructure*>(&acceleration);
            acceleration.pNext = &rayQuery;
        }
    }
};

void selectFeatures(const FeatureChain& supported, FeatureChain& enabled) {
    const VkPhysicalDeviceFeatures& s = supported.core.features;
    VkPhysicalDeviceFeatures& e = enabled.core.features;
    e.shaderInt16 = s.shaderInt16;
    e.shaderInt64 = s.shaderInt64;
    // R16F/RG16F/R8 storage images need the extended-formats capability in SPIR-V.
    e.shaderStorageImageExtendedFormats = s.shaderStorageImageExtendedFormats;
    e.shaderStorageImageReadWithoutFormat = s.shaderStorageImageReadWithoutFormat;
    e.shaderStorageImageWriteWithoutFormat = s.shaderStorageImageWriteWithoutFormat;
    e.shaderImageGatherExtended = s.shaderImageGatherExtended;

    enabled.v11.storageBuffer16BitAccess = supported.v11.storageBuffer16BitAccess;
    enabled.v11.uniformAndStorageBuffer16BitAccess = supported.v11.uniformAndStorageBuffer16BitAccess;
    enabled.v12.shaderFloat16 = supported.v12.shaderFloat16;
    enabled.v12.scalarBlockLayout = supported.v12.scalarBlockLayout;
    enabled.v12.uniformBufferStandardLayout = supported.v12.uniformBufferStandardLayout;
    enabled.v12.shaderSubgroupExtendedTypes = supported.v12.shaderSubgroupExtendedTypes;
    enabled.v12.hostQueryReset = supported.v12.hostQueryReset;

    enabled.storage16.storageBuffer16BitAccess = supported.storage16.storageBuffer16BitAccess;
    enabled.storage16.uniformAndStorageBuffer16BitAccess =
        supported.storage16.uniformAndStorageBuffer16BitAccess;
    enabled.float16.shaderFloat16 = supported.float16.shaderFloat16;
    enabled.executable.pipelineExecutableInfo = supported.executable.pipelineExecutableInfo;
}

// Ray queries need both extensions (with deferred host operations, which the acceleration
// structure extension requires), Vulkan 1.2 for SPIR-V 1.4 and buffer device addresses, and
// the features themselves.
bool rayQueryExtensionsOffered(bool vulkan12, const std::vector<VkExtensionProperties>& available) {
    return vulkan12 && contains(available, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
           contains(available, VK_KHR_RAY_QUERY_EXTENSION_NAME) &&
           contains(available, VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
}

bool rayQuerySupported(const FeatureChain& supported) {
    return supported.acceleration.accelerationStructure && supported.rayQuery.rayQuery &&
           supported.v12.bufferDeviceAddress;
}

// GLINT_PIPELINE_STATS=1 asks for the driver's statistics of every compute pipeline
// (VK_KHR_pipeline_executable_properties), printed to stderr as the pipelines are created.
bool pipelineStatisticsRequested() {
    const char* value = std::getenv("GLINT_PIPELINE_STATS");
    return value && std::string_view(value) == "1";
}

// A family with graphics and compute that presents to `surface`, or UINT32_MAX.
uint32_t findPresentQueueFamily(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t i = 0; i < count; ++i) {
        VkBool32 presents = VK_FALSE;
        GLINT_VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(physical, i, surface, &presents));
        if (families[i].queueCount > 0 && (families[i].queueFlags & needed) == needed && presents) return i;
    }
    return UINT32_MAX;
}

void createDevice(Context& context, VkPhysicalDevice physical) {
    const uint32_t family = context.surface ? findPresentQueueFamily(physical, context.surface)
                                            : findComputeQueueFamily(physical);
    if (family == UINT32_MAX) {
        throw std::runtime_error(
            "glint: device '" + context.info.name + "' has no " +
            (context.surface ? "queue that computes, draws and presents to the window" : "compute queue"));
    }

    const bool vulkan12 = std::min(context.info.apiVersion, context.instanceApiVersion) >= VK_API_VERSION_1_2;
    const std::vector<VkExtensionProperties> available = deviceExtensions(physical);
    std::vector<const char*> extensions;
    const bool float16Extension = !vulkan12 && contains(available, VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME);
    if (float16Extension) extensions.push_back(VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME);
    // The spec requires enabling it wherever it is offered (MoltenVK and similar layers).
    if (contains(available, "VK_KHR_portability_subset")) extensions.push_back("VK_KHR_portability_subset");
    // Lets benchmarks report how much device memory the process holds (deviceMemoryUse).
    const bool memoryBudget = contains(available, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    if (memoryBudget) extensions.push_back(VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    const bool executableExtension =
        pipelineStatisticsRequested() &&
        contains(available, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);

    const bool rayQueryExtensions = rayQueryExtensionsOffered(vulkan12, available);

    FeatureChain supported;
    supported.link(vulkan12, float16Extension, executableExtension, rayQueryExtensions);
    vkGetPhysicalDeviceFeatures2(physical, &supported.core);
    FeatureChain enabled;
    const bool pipelineStatistics = executableExtension && supported.executable.pipelineExecutableInfo;
    const bool rayQuery = rayQueryExtensions && rayQuerySupported(supported);
    enabled.link(vulkan12, float16Extension, pipelineStatistics, rayQuery);
    selectFeatures(supported, enabled);
    if (rayQuery) {
        enabled.acceleration.accelerationStructure = VK_TRUE;
        enabled.rayQuery.rayQuery = VK_TRUE;
        enabled.v12.bufferDeviceAddress = VK_TRUE;
        extensions.push_back(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME);
        extensions.push_back(VK_KHR_RAY_QUERY_EXTENSION_NAME);
        extensions.push_back(VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
    }
    if (pipelineStatistics) extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    if (context.surface) {
        if (!contains(available, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
            throw std::runtime_error("glint: device '" + context.info.name + "' cannot present (no " +
                                     VK_KHR_SWAPCHAIN_EXTENSION_NAME + ")");
        extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = family;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &enabled.core;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    GLINT_VK_CHECK(vkCreateDevice(physical, &info, nullptr, &context.device.device));

    vk::Device& device = context.device;
    device.physical = physical;
    device.queueFamily = family;
    vkGetDeviceQueue(device.device, family, 0, &device.queue);
    vkGetPhysicalDeviceProperties(physical, &device.properties);
    vkGetPhysicalDeviceMemoryProperties(physical, &device.memory);
    device.subgroupSize = context.info.subgroupSize;
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, families.data());
    context.info.timestampValidBits = families.at(family).timestampValidBits; // the queue in use
    device.timestampValidBits = context.info.timestampValidBits;
    device.timestamps = device.timestampValidBits > 0;
    device.pipelineStatistics = pipelineStatistics;
    device.rayQuery = rayQuery;
    context.memoryBudget = memoryBudget;

    // What DeviceInfo reports must be what the device has enabled.
    context.info.float16 = vulkan12 ? enabled.v12.shaderFloat16 : enabled.float16.shaderFloat16;
    context.info.int16 = enabled.core.features.shaderInt16;
    context.info.storage16 =
        vulkan12 ? enabled.v11.storageBuffer16BitAccess : enabled.storage16.storageBuffer16BitAccess;
}

} // namespace

DeviceMemoryUse deviceMemoryUse(const Context& context) {
    DeviceMemoryUse use;
    if (!context.memoryBudget) return use;
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT};
    VkPhysicalDeviceMemoryProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2};
    properties.pNext = &budget;
    vkGetPhysicalDeviceMemoryProperties2(context.device.physical, &properties);
    for (uint32_t heap = 0; heap < properties.memoryProperties.memoryHeapCount; ++heap) {
        if ((properties.memoryProperties.memoryHeaps[heap].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) == 0)
            continue;
        use.usedBytes += budget.heapUsage[heap];
        use.budgetBytes += budget.heapBudget[heap];
    }
    use.known = true;
    return use;
}

std::string deviceSelectorFromEnvironment() {
    const char* value = std::getenv("GLINT_DEVICE");
    return value ? value : "";
}

Context createContext(const ContextOptions& options) {
    Context context;
    try {
        createInstance(options, context);
        if (options.createSurface) context.surface = options.createSurface(context.instance);

        const std::vector<DeviceInfo> devices = listDevices(context.instance, context.instanceApiVersion);
        const DeviceChoice choice = chooseDevice(devices, options.deviceSelector);
        if (!choice.ok()) throw std::runtime_error("glint: " + choice.error);
        context.info = devices[choice.index];
        createDevice(context, physicalDevice(context.instance, choice.index));

        VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        // Resettable buffers, so that a benchmark can re-record one command buffer per run.
        poolInfo.flags =
            VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        poolInfo.queueFamilyIndex = context.device.queueFamily;
        GLINT_VK_CHECK(vkCreateCommandPool(context.device.device, &poolInfo, nullptr, &context.commandPool));
        context.immediate =
            std::make_unique<RecordedCommands>(recordCommands(context, [](VkCommandBuffer) {}));
    } catch (...) {
        destroyContext(context);
        throw;
    }
    return context;
}

void destroyContext(Context& context) {
    if (context.device.device) {
        // Best effort: on a lost device the objects still have to be destroyed.
        (void)vkDeviceWaitIdle(context.device.device);
        if (context.immediate) destroyRecorded(context, *context.immediate);
        context.immediate.reset();
        if (context.commandPool) vkDestroyCommandPool(context.device.device, context.commandPool, nullptr);
        vkDestroyDevice(context.device.device, nullptr);
    }
    if (context.instance) {
        if (context.surface) vkDestroySurfaceKHR(context.instance, context.surface, nullptr);
        destroyMessenger(context.instance, context.messenger);
        vkDestroyInstance(context.instance, nullptr);
    }
    context.instance = VK_NULL_HANDLE;
    context.messenger = VK_NULL_HANDLE;
    context.device = vk::Device{};
    context.commandPool = VK_NULL_HANDLE;
    context.surface = VK_NULL_HANDLE;
}

void submitAndWait(const Context& context, const std::function<void(VkCommandBuffer)>& record) {
    // The context's own pair, unless a recording callback submits in turn (then a pair of its own).
    if (context.immediate && !context.immediate->pending) {
        RecordedCommands& recorded = *context.immediate;
        recorded.pending = true; // marks the pair in use while the callback records
        try {
            GLINT_VK_CHECK(vkResetCommandBuffer(recorded.commands, 0));
            VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            GLINT_VK_CHECK(vkBeginCommandBuffer(recorded.commands, &beginInfo));
            record(recorded.commands);
            GLINT_VK_CHECK(vkEndCommandBuffer(recorded.commands));
            recorded.pending = false;
            submitRecorded(context, recorded);
            waitRecorded(context, recorded);
        } catch (...) {
            // Pending after a failed wait: idling keeps the next reset valid.
            if (recorded.pending) (void)vkDeviceWaitIdle(context.device.device);
            recorded.pending = false;
            throw;
        }
        return;
    }
    RecordedCommands recorded = recordCommands(context, record);
    try {
        submitRecorded(context, recorded);
        waitRecorded(context, recorded);
    } catch (...) {
        destroyRecorded(context, recorded);
        throw;
    }
    destroyRecorded(context, recorded);
}

RecordedCommands recordCommands(const Context& context, const std::function<void(VkCommandBuffer)>& record) {
    VkDevice device = context.device.device;
    RecordedCommands recorded;
    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = context.commandPool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    GLINT_VK_CHECK(vkAllocateCommandBuffers(device, &allocateInfo, &recorded.commands));
    try {
        VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        GLINT_VK_CHECK(vkBeginCommandBuffer(recorded.commands, &beginInfo));
        record(recorded.commands);
        GLINT_VK_CHECK(vkEndCommandBuffer(recorded.commands));
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        GLINT_VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &recorded.fence));
    } catch (...) {
        destroyRecorded(context, recorded);
        throw;
    }
    return recorded;
}

void submitRecorded(const Context& context, RecordedCommands& recorded) {
    if (recorded.pending)
        throw std::logic_error("glint::gpu::submitRecorded: the last submission is pending");
    GLINT_VK_CHECK(vkResetFences(context.device.device, 1, &recorded.fence));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &recorded.commands;
    GLINT_VK_CHECK(vkQueueSubmit(context.device.queue, 1, &submit, recorded.fence));
    recorded.pending = true;
}

void waitRecorded(const Context& context, RecordedCommands& recorded) {
    if (!recorded.pending) return;
    GLINT_VK_CHECK(vkWaitForFences(context.device.device, 1, &recorded.fence, VK_TRUE, kFenceTimeoutNs));
    recorded.pending = false;
}

void destroyRecorded(const Context& context, RecordedCommands& recorded) {
    VkDevice device = context.device.device;
    // Still pending (an error came between submit and wait, or the wait failed): idling first
    // keeps the frees valid.
    if (recorded.pending) (void)vkDeviceWaitIdle(device);
    if (recorded.fence) vkDestroyFence(device, recorded.fence, nullptr);
    if (recorded.commands) vkFreeCommandBuffers(device, context.commandPool, 1, &recorded.commands);
    recorded = RecordedCommands{};
}

} // namespace glint::gpu
