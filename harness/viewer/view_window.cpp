#include "view_window.h"

#include "glint/vulkan/vk_check.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace glint::cli::view {
namespace {

// GLFW reports errors through a callback; the last one goes into the one-line message.
std::string& lastGlfwError() {
    static std::string error;
    return error;
}

void checkUiResult(VkResult result) {
    vk::check(result, "Dear ImGui's Vulkan backend");
}

// The window image's format: what the picture and the controls are drawn in (UNORM: the
// picture's bytes are already display-encoded, as in glint run's PNGs).
constexpr VkFormat kWindowFormat = VK_FORMAT_R8G8B8A8_UNORM;

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                  VkAccessFlags dstAccess) {
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

VkImageBlit fullBlit(std::int32_t srcWidth, std::int32_t srcHeight, std::int32_t x0, std::int32_t y0,
                     std::int32_t x1, std::int32_t y1) {
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {srcWidth, srcHeight, 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.dstOffsets[0] = {x0, y0, 0};
    blit.dstOffsets[1] = {x1, y1, 1};
    return blit;
}

} // namespace

std::string missingDisplayMessage() {
    for (const char* variable : {"DISPLAY", "WAYLAND_DISPLAY"}) {
        const char* value = std::getenv(variable);
        if (value && *value) return {};
    }
    return "glint view: no display; set DISPLAY or use glint run";
}

Window::Window(std::uint32_t width, std::uint32_t height, const std::string& title) {
    glfwSetErrorCallback(
        [](int, const char* description) { lastGlfwError() = description ? description : "?"; });
    if (!glfwInit()) {
        const char* display = std::getenv("DISPLAY");
        throw std::runtime_error("glint view: cannot open the display" +
                                 (display && *display ? " '" + std::string(display) + "'" : std::string()) +
                                 " (GLFW: " + lastGlfwError() + "); set DISPLAY or use glint run");
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw std::runtime_error("glint view: GLFW finds no Vulkan loader with window-system support (" +
                                 lastGlfwError() + ")");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(static_cast<int>(std::max(width, 1u)), static_cast<int>(std::max(height, 1u)),
                               title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("glint view: cannot create a window (GLFW: " + lastGlfwError() + ")");
    }
    // Installed before Dear ImGui's, which calls it before its own.
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int, int action, int) {
        if (action == GLFW_PRESS || action == GLFW_REPEAT)
            static_cast<Window*>(glfwGetWindowUserPointer(window))->pressedKeys_.push_back(key);
    });
}

std::vector<int> Window::takePressedKeys() {
    std::vector<int> keys;
    keys.swap(pressedKeys_);
    return keys;
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> Window::instanceExtensions() const {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw std::runtime_error("glint view: the Vulkan loader cannot present to this display");
    return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    const VkResult result = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
    if (result != VK_SUCCESS)
        throw std::runtime_error("glint view: cannot make a Vulkan surface for the window (" +
                                 std::string(vk::resultName(result)) + ")");
    return surface;
}

bool Window::closeRequested() const {
    return glfwWindowShouldClose(window_);
}

void Window::pollEvents() const {
    glfwPollEvents();
}

void Window::screenSize(std::uint32_t& width, std::uint32_t& height) {
    width = height = 0;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor())
        if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) {
            width = static_cast<std::uint32_t>(std::max(mode->width, 0));
            height = static_cast<std::uint32_t>(std::max(mode->height, 0));
        }
}

Presenter::Presenter(const gpu::Context& context, Window& window)
    : context_(context), window_(window), device_(context.device.device) {
    try {
        VkAttachmentDescription attachment{};
        attachment.format = kWindowFormat;
        attachment.samples = VK_SAMPLE_COUNT_1_BIT;
        attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD; // the picture is already there
        attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        attachment.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkSubpassDescription subpass{};
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        subpass.colorAttachmentCount = 1;
        subpass.pColorAttachments = &reference;
        VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
        passInfo.attachmentCount = 1;
        passInfo.pAttachments = &attachment;
        passInfo.subpassCount = 1;
        passInfo.pSubpasses = &subpass;
        GLINT_VK_CHECK(vkCreateRenderPass(device_, &passInfo, nullptr, &renderPass_));

        const VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
        poolInfo.maxSets = 8;
        poolInfo.poolSizeCount = 1;
        poolInfo.pPoolSizes = &poolSize;
        GLINT_VK_CHECK(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &uiPool_));

        VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        allocateInfo.commandPool = context_.commandPool;
        allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocateInfo.commandBufferCount = 1;
        GLINT_VK_CHECK(vkAllocateCommandBuffers(device_, &allocateInfo, &commands_));
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        GLINT_VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &done_));
        VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        GLINT_VK_CHECK(vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &imageAcquired_));

        createSwapchain();

        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr; // no imgui.ini left in the working folder
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForVulkan(window_.handle(), true);
        ImGui_ImplVulkan_InitInfo info{};
        info.Instance = context_.instance;
        info.PhysicalDevice = context_.device.physical;
        info.Device = device_;
        info.QueueFamily = context_.device.queueFamily;
        info.Queue = context_.device.queue;
        info.DescriptorPool = uiPool_;
        info.MinImageCount = 2;
        info.ImageCount = std::max<std::uint32_t>(2, static_cast<std::uint32_t>(swapchainImages_.size()));
        info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
        info.CheckVkResultFn = checkUiResult;
        ImGui_ImplVulkan_Init(&info, renderPass_);
        gpu::submitAndWait(context_, [](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
        ImGui_ImplVulkan_DestroyFontUploadObjects();
    } catch (...) {
        release();
        throw;
    }
}

Presenter::~Presenter() {
    release();
}

void Presenter::release() {
    if (device_) (void)vkDeviceWaitIdle(device_);
    if (ImGui::GetCurrentContext()) {
        if (ImGui::GetIO().BackendRendererUserData) ImGui_ImplVulkan_Shutdown();
        if (ImGui::GetIO().BackendPlatformUserData) ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    destroySwapchain();
    vk::destroyImage(context_.device, pictureImage_);
    vk::destroyBuffer(context_.device, pictureUpload_);
    vk::destroyBuffer(context_.device, screenshotReadback_);
    if (imageAcquired_) vkDestroySemaphore(device_, imageAcquired_, nullptr);
    if (done_) vkDestroyFence(device_, done_, nullptr);
    if (commands_) vkFreeCommandBuffers(device_, context_.commandPool, 1, &commands_);
    if (uiPool_) vkDestroyDescriptorPool(device_, uiPool_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device_, renderPass_, nullptr);
    imageAcquired_ = VK_NULL_HANDLE;
    done_ = VK_NULL_HANDLE;
    commands_ = VK_NULL_HANDLE;
    uiPool_ = VK_NULL_HANDLE;
    renderPass_ = VK_NULL_HANDLE;
}

void Presenter::createSwapchain() {
    const VkPhysicalDevice physical = context_.device.physical;
    const VkSurfaceKHR surface = context_.surface;
    VkSurfaceCapabilitiesKHR caps{};
    GLINT_VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &caps));
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.handle(), &width, &height);
    extent_ = caps.currentExtent;
    if (extent_.width == UINT32_MAX) {
        extent_.width = std::clamp(static_cast<std::uint32_t>(std::max(width, 0)), caps.minImageExtent.width,
                                   caps.maxImageExtent.width);
        extent_.height = std::clamp(static_cast<std::uint32_t>(std::max(height, 0)),
                                    caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (extent_.width == 0 || extent_.height == 0) return; // minimized: nothing to show until restored
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if ((caps.supportedUsageFlags & usage) != usage)
        throw std::runtime_error("glint view: the window's swapchain images cannot be copied to");

    std::uint32_t count = 0;
    GLINT_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    GLINT_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
    formats.resize(count);
    if (formats.empty()) throw std::runtime_error("glint view: the window offers no surface format");
    // A UNORM format shows the picture's bytes as they are (blits into an sRGB one would encode twice).
    VkSurfaceFormatKHR chosen = formats.front();
    for (const VkSurfaceFormatKHR& format : formats)
        if (format.format == VK_FORMAT_B8G8R8A8_UNORM || format.format == VK_FORMAT_R8G8B8A8_UNORM) {
            chosen = format;
            break;
        }
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(physical, chosen.format, &properties);
    if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
        throw std::runtime_error("glint view: the window's format cannot be blitted to");
    swapchainFormat_ = chosen.format;

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = std::max(caps.minImageCount, 2u);
    if (caps.maxImageCount > 0) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
    info.imageFormat = chosen.format;
    info.imageColorSpace = chosen.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = usage;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    for (VkCompositeAlphaFlagBitsKHR alpha :
         {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
          VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR})
        if (caps.supportedCompositeAlpha & static_cast<VkCompositeAlphaFlagsKHR>(alpha)) {
            info.compositeAlpha = alpha;
            break;
        }
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR; // always there; the frame loop is paced by the replay anyway
    info.clipped = VK_TRUE;
    GLINT_VK_CHECK(vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain_));
    GLINT_VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain_, &count, nullptr));
    swapchainImages_.resize(count);
    GLINT_VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain_, &count, swapchainImages_.data()));
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    presentReady_.assign(count, VK_NULL_HANDLE);
    for (VkSemaphore& semaphore : presentReady_)
        GLINT_VK_CHECK(vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &semaphore));

    VkImageCreateInfo imageInfo{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    imageInfo.imageType = VK_IMAGE_TYPE_2D;
    imageInfo.format = kWindowFormat;
    imageInfo.extent = {extent_.width, extent_.height, 1};
    imageInfo.mipLevels = 1;
    imageInfo.arrayLayers = 1;
    imageInfo.samples = VK_SAMPLE_COUNT_1_BIT;
    imageInfo.tiling = VK_IMAGE_TILING_OPTIMAL;
    imageInfo.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                      VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    GLINT_VK_CHECK(vkCreateImage(device_, &imageInfo, nullptr, &windowImage_));
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device_, windowImage_, &requirements);
    VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocateInfo.allocationSize = requirements.size;
    allocateInfo.memoryTypeIndex =
        vk::findMemoryType(context_.device, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (allocateInfo.memoryTypeIndex == UINT32_MAX)
        throw std::runtime_error("glint view: no device-local memory for the window image");
    GLINT_VK_CHECK(vkAllocateMemory(device_, &allocateInfo, nullptr, &windowMemory_));
    GLINT_VK_CHECK(vkBindImageMemory(device_, windowImage_, windowMemory_, 0));
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = windowImage_;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = kWindowFormat;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    GLINT_VK_CHECK(vkCreateImageView(device_, &viewInfo, nullptr, &windowView_));
    VkFramebufferCreateInfo framebufferInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    framebufferInfo.renderPass = renderPass_;
    framebufferInfo.attachmentCount = 1;
    framebufferInfo.pAttachments = &windowView_;
    framebufferInfo.width = extent_.width;
    framebufferInfo.height = extent_.height;
    framebufferInfo.layers = 1;
    GLINT_VK_CHECK(vkCreateFramebuffer(device_, &framebufferInfo, nullptr, &framebuffer_));
}

void Presenter::destroySwapchain() {
    if (!device_) return;
    if (framebuffer_) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
    if (windowView_) vkDestroyImageView(device_, windowView_, nullptr);
    if (windowImage_) vkDestroyImage(device_, windowImage_, nullptr);
    if (windowMemory_) vkFreeMemory(device_, windowMemory_, nullptr);
    for (VkSemaphore semaphore : presentReady_) vkDestroySemaphore(device_, semaphore, nullptr);
    if (swapchain_) vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    framebuffer_ = VK_NULL_HANDLE;
    windowView_ = VK_NULL_HANDLE;
    windowImage_ = VK_NULL_HANDLE;
    windowMemory_ = VK_NULL_HANDLE;
    presentReady_.clear();
    swapchainImages_.clear();
    swapchain_ = VK_NULL_HANDLE;
    extent_ = {};
}

void Presenter::ensurePictureImage(std::uint32_t width, std::uint32_t height) {
    if (pictureImage_.image && pictureImage_.width == width && pictureImage_.height == height) return;
    vk::destroyImage(context_.device, pictureImage_);
    vk::destroyBuffer(context_.device, pictureUpload_);
    pictureImage_ = vk::createImage2D(context_.device, width, height, kWindowFormat);
    pictureUpload_ = vk::createBuffer(context_.device, VkDeviceSize{width} * height * 4,
                                      VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::Upload);
}

void Presenter::beginUi() {
    if (uiFrameOpen_) return;
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    uiFrameOpen_ = true;
}

Presenter::Rect Presenter::pictureRect(std::uint32_t pictureWidth, std::uint32_t pictureHeight) const {
    const float windowWidth = static_cast<float>(extent_.width),
                windowHeight = static_cast<float>(extent_.height);
    if (pictureWidth == 0 || pictureHeight == 0 || windowWidth == 0 || windowHeight == 0) return {};
    const float scale = std::min(windowWidth / static_cast<float>(pictureWidth),
                                 windowHeight / static_cast<float>(pictureHeight));
    const float width = std::max(1.0f, std::floor(static_cast<float>(pictureWidth) * scale));
    const float height = std::max(1.0f, std::floor(static_cast<float>(pictureHeight) * scale));
    return {std::floor((windowWidth - width) / 2), std::floor((windowHeight - height) / 2), width, height};
}

void Presenter::present(const Picture& picture, bool drawUi, report::RgbImage* screenshot) {
    beginUi();
    ImGui::Render();
    uiFrameOpen_ = false;
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.handle(), &width, &height);
    if (!swapchain_ || static_cast<std::uint32_t>(width) != extent_.width ||
        static_cast<std::uint32_t>(height) != extent_.height) {
        GLINT_VK_CHECK(vkDeviceWaitIdle(device_));
        destroySwapchain();
        createSwapchain();
    }
    if (!swapchain_) {
        if (screenshot) throw std::runtime_error("glint view: no screenshot of a minimized window");
        return;
    }
    std::uint32_t index = 0;
    VkResult acquired =
        vkAcquireNextImageKHR(device_, swapchain_, UINT64_MAX, imageAcquired_, VK_NULL_HANDLE, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        GLINT_VK_CHECK(vkDeviceWaitIdle(device_));
        destroySwapchain();
        createSwapchain();
        if (!swapchain_) return;
        acquired =
            vkAcquireNextImageKHR(device_, swapchain_, UINT64_MAX, imageAcquired_, VK_NULL_HANDLE, &index);
    }
    if (acquired != VK_SUBOPTIMAL_KHR) GLINT_VK_CHECK(acquired);

    ensurePictureImage(picture.width, picture.height);
    std::memcpy(pictureUpload_.mapped, picture.rgba.data(), picture.rgba.size());
    vk::flushBuffer(context_.device, pictureUpload_);
    const VkDeviceSize screenshotBytes = VkDeviceSize{extent_.width} * extent_.height * 4;
    if (screenshot && screenshotReadback_.size < screenshotBytes) {
        vk::destroyBuffer(context_.device, screenshotReadback_);
        screenshotReadback_ = vk::createBuffer(context_.device, screenshotBytes,
                                               VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback);
    }

    const VkCommandBuffer cmd = commands_;
    GLINT_VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    GLINT_VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    const VkPipelineStageFlags transfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
    // The picture: uploaded, then the source of the blit into the window image.
    imageBarrier(cmd, pictureImage_.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 transfer, VK_ACCESS_TRANSFER_READ_BIT, transfer, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {picture.width, picture.height, 1};
    vkCmdCopyBufferToImage(cmd, pictureUpload_.buffer, pictureImage_.image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    imageBarrier(cmd, pictureImage_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, transfer, VK_ACCESS_TRANSFER_WRITE_BIT, transfer,
                 VK_ACCESS_TRANSFER_READ_BIT);
    // The window image: a dark background, the picture fitted into it, the controls over it.
    imageBarrier(cmd, windowImage_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer,
                 VK_ACCESS_TRANSFER_READ_BIT, transfer, VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkClearColorValue background{{0.08f, 0.08f, 0.08f, 1.0f}};
    const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, windowImage_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &background, 1, &whole);
    imageBarrier(cmd, windowImage_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer, VK_ACCESS_TRANSFER_WRITE_BIT, transfer,
                 VK_ACCESS_TRANSFER_WRITE_BIT);
    const Rect rect = pictureRect(picture.width, picture.height);
    const auto x0 = static_cast<std::int32_t>(rect.x), y0 = static_cast<std::int32_t>(rect.y);
    const auto x1 = static_cast<std::int32_t>(rect.x + rect.width),
               y1 = static_cast<std::int32_t>(rect.y + rect.height);
    // Whole multiples (1:1 included) stay sharp texels; other scales are filtered.
    const bool wholeScale = std::fmod(rect.width, static_cast<float>(picture.width)) == 0.0f &&
                            std::fmod(rect.height, static_cast<float>(picture.height)) == 0.0f;
    const VkImageBlit blit = fullBlit(static_cast<std::int32_t>(picture.width),
                                      static_cast<std::int32_t>(picture.height), x0, y0, x1, y1);
    vkCmdBlitImage(cmd, pictureImage_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, windowImage_,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                   wholeScale ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
    imageBarrier(cmd, windowImage_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, transfer, VK_ACCESS_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    pass.renderPass = renderPass_;
    pass.framebuffer = framebuffer_;
    pass.renderArea.extent = extent_;
    vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
    if (drawUi) ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
    vkCmdEndRenderPass(cmd);
    imageBarrier(cmd, windowImage_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, transfer, VK_ACCESS_TRANSFER_READ_BIT);
    if (screenshot) {
        VkBufferImageCopy back{};
        back.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        back.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyImageToBuffer(cmd, windowImage_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               screenshotReadback_.buffer, 1, &back);
        VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.buffer = screenshotReadback_.buffer;
        toHost.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(cmd, transfer, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0,
                             nullptr);
    }
    // The swapchain image: the window image copied in (the blit converts RGBA to its order).
    const VkImage target = swapchainImages_[index];
    imageBarrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer, 0,
                 transfer, VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkImageBlit toSwapchain =
        fullBlit(static_cast<std::int32_t>(extent_.width), static_cast<std::int32_t>(extent_.height), 0, 0,
                 static_cast<std::int32_t>(extent_.width), static_cast<std::int32_t>(extent_.height));
    vkCmdBlitImage(cmd, windowImage_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &toSwapchain, VK_FILTER_NEAREST);
    imageBarrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, transfer,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    GLINT_VK_CHECK(vkEndCommandBuffer(cmd));

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &imageAcquired_;
    submit.pWaitDstStageMask = &transfer;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &presentReady_[index];
    GLINT_VK_CHECK(vkResetFences(device_, 1, &done_));
    GLINT_VK_CHECK(vkQueueSubmit(context_.device.queue, 1, &submit, done_));
    VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    presentInfo.waitSemaphoreCount = 1;
    presentInfo.pWaitSemaphores = &presentReady_[index];
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &swapchain_;
    presentInfo.pImageIndices = &index;
    const VkResult presented = vkQueuePresentKHR(context_.device.queue, &presentInfo);
    GLINT_VK_CHECK(vkWaitForFences(device_, 1, &done_, VK_TRUE, UINT64_MAX));
    // Out of date or suboptimal: the next present() sees the new framebuffer size and recreates.
    if (presented != VK_ERROR_OUT_OF_DATE_KHR && presented != VK_SUBOPTIMAL_KHR) GLINT_VK_CHECK(presented);

    if (screenshot) {
        vk::invalidateBuffer(context_.device, screenshotReadback_);
        const auto* rgba = static_cast<const std::uint8_t*>(screenshotReadback_.mapped);
        const std::size_t pixels = std::size_t{extent_.width} * extent_.height;
        screenshot->width = extent_.width;
        screenshot->height = extent_.height;
        screenshot->rgb.resize(pixels * 3);
        for (std::size_t i = 0; i < pixels; ++i)
            for (std::size_t c = 0; c < 3; ++c) screenshot->rgb[i * 3 + c] = rgba[i * 4 + c];
    }
}

} // namespace glint::cli::view
