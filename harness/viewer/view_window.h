// glint view's window: GLFW for the window and input, a Vulkan swapchain on the harness's
// device, Dear ImGui for the controls. Each frame the picture (the capture's size) is
// uploaded, scaled into the window keeping its aspect, the controls drawn over it, and the
// result copied to the swapchain; the same window image can be read back as a screenshot.
#pragma once

#include "view_picture.h"

#include <gpu/gpu_context.h>

#include "glint/vulkan/vk_resources.h"

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace glint::cli::view {

// Where the display is missing, the one line to print (empty when a display is named).
std::string missingDisplayMessage();

class Window {
  public:
    // Opens a window of width x height pixels (not resizable below 1x1). Throws
    // std::runtime_error with one line when GLFW cannot reach the display or Vulkan.
    Window(std::uint32_t width, std::uint32_t height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // What the context needs to present here (gpu::ContextOptions::surfaceExtensions, createSurface).
    std::vector<std::string> instanceExtensions() const;
    VkSurfaceKHR createSurface(VkInstance instance) const;

    GLFWwindow* handle() const { return window_; }
    bool closeRequested() const;
    void pollEvents() const;
    // The size of the largest monitor's mode, for the initial window size (0 when unknown).
    static void screenSize(std::uint32_t& width, std::uint32_t& height);
    // The keys pressed since the last call (GLFW key codes, in order). Kept from the key
    // events themselves: a tap shorter than a frame is pressed and released between two polls.
    std::vector<int> takePressedKeys();

  private:
    GLFWwindow* window_ = nullptr;
    std::vector<int> pressedKeys_;
};

// The swapchain, the window image the controls are drawn into, and Dear ImGui's Vulkan and
// GLFW backends. One frame is in flight at a time: present() waits for its own work.
class Presenter {
  public:
    Presenter(const gpu::Context& context, Window& window);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // Starts the controls' frame (ImGui::NewFrame); call before any ImGui widget.
    void beginUi();
    // Where the picture lands in the window (pixels, top left origin), for mouse input.
    struct Rect {
        float x = 0, y = 0, width = 0, height = 0;
    };
    Rect pictureRect(std::uint32_t pictureWidth, std::uint32_t pictureHeight) const;
    // Shows `picture` fitted into the window with the controls over it (when `drawUi`; the
    // ImGui frame is ended either way). With `screenshot`, the window's image is read back
    // into it as RGB.
    void present(const Picture& picture, bool drawUi, report::RgbImage* screenshot);

  private:
    void release(); // everything, whatever was made (the destructor, a failed constructor)
    void createSwapchain();
    void destroySwapchain();
    void ensurePictureImage(std::uint32_t width, std::uint32_t height);
    const gpu::Context& context_;
    Window& window_;
    VkDevice device_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat swapchainFormat_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    std::vector<VkImage> swapchainImages_;
    std::vector<VkSemaphore> presentReady_; // one per swapchain image: signalled for its present
    VkSemaphore imageAcquired_ = VK_NULL_HANDLE;
    // The window image: the picture and the controls, read back for screenshots.
    VkImage windowImage_ = VK_NULL_HANDLE;
    VkDeviceMemory windowMemory_ = VK_NULL_HANDLE;
    VkImageView windowView_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkDescriptorPool uiPool_ = VK_NULL_HANDLE;
    vk::Image pictureImage_;
    vk::Buffer pictureUpload_;
    vk::Buffer screenshotReadback_;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence done_ = VK_NULL_HANDLE;
    bool uiFrameOpen_ = false;
};

} // namespace glint::cli::view
