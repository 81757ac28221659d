// The viewer's frame loop pieces (glint view, harness/cli/cli_view.cpp): keys, scripts, the
// picture shown and the window's first size.
#include "view_loop.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace glint::cli::view {

// Keys: space play/pause, right arrow step, R reset histories, H the controls, P a
// screenshot, + and - exposure, Escape quit (none while the controls take the keyboard).
void handleInput(Window& window, Player& player, ViewerState& state, const Presenter& presenter,
                 std::uint32_t width, std::uint32_t height) {
    const ImGuiIO& io = ImGui::GetIO();
    for (const int key : window.takePressedKeys()) {
        if (io.WantCaptureKeyboard) continue;
        switch (key) {
        case GLFW_KEY_SPACE:
            state.playing = !state.playing;
            break;
        case GLFW_KEY_RIGHT:
            state.stepRequested = true;
            break;
        case GLFW_KEY_R:
            player.resetHistories();
            break;
        case GLFW_KEY_H:
            state.showUi = !state.showUi;
            break;
        case GLFW_KEY_P:
            state.screenshotRequested = true;
            break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD:
            state.exposure *= 2;
            break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            state.exposure /= 2;
            break;
        case GLFW_KEY_ESCAPE:
            state.quit = true;
            break;
        default:
            break;
        }
    }
    GLFWwindow* handle = window.handle();
    // Dragging on the picture moves the split's divider.
    if (!state.split.empty() && !io.WantCaptureMouse &&
        glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
        double x = 0, y = 0;
        glfwGetCursorPos(handle, &x, &y);
        int windowWidth = 0, windowHeight = 0, framebufferWidth = 0, framebufferHeight = 0;
        glfwGetWindowSize(handle, &windowWidth, &windowHeight);
        glfwGetFramebufferSize(handle, &framebufferWidth, &framebufferHeight);
        const double toPixels = windowWidth > 0 ? static_cast<double>(framebufferWidth) / windowWidth : 1.0;
        const Presenter::Rect rect = presenter.pictureRect(width, height);
        if (rect.width > 0)
            state.divider = std::clamp(static_cast<float>((x * toPixels - static_cast<double>(rect.x)) /
                                                          static_cast<double>(rect.width)),
                                       0.0f, 1.0f);
    }
}

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

} // namespace

// Runs the script's commands from `next` on until one needs a frame to be shown first (step,
// screenshot); returns the screenshot's file when that was the one.
std::string runScript(const std::vector<ScriptCommand>& commands, std::size_t& next, std::uint64_t& steps,
                      Player& player, ViewerState& state) {
    using Kind = ScriptCommand::Kind;
    while (next < commands.size() && steps == 0) {
        const ScriptCommand& command = commands[next++];
        const auto fail = [&](const std::string& problem) {
            throw std::invalid_argument(command.where + ": " + problem);
        };
        const auto requireView = [&](const std::string& name) {
            const std::vector<std::string>& names = player.viewNames();
            if (std::find(names.begin(), names.end(), name) == names.end())
                fail("no image '" + name + "' in this replay (" + joined(names) + ")");
        };
        switch (command.kind) {
        case Kind::Set:
            if (const std::string error = player.setSetting(command.text); !error.empty()) fail(error);
            break;
        case Kind::Toggle:
            if (const std::string error = player.toggleEffect(command.text); !error.empty()) fail(error);
            break;
        case Kind::View:
            requireView(command.text);
            state.view = command.text;
            break;
        case Kind::Split:
            if (!command.text.empty()) requireView(command.text);
            state.split = command.text;
            break;
        case Kind::Divider:
            state.divider = static_cast<float>(command.number);
            break;
        case Kind::Exposure:
            state.exposure = static_cast<float>(command.number);
            break;
        case Kind::Step:
            steps = static_cast<std::uint64_t>(command.number);
            break;
        case Kind::Play:
        case Kind::Pause:
            state.playing = command.kind == Kind::Play;
            break;
        case Kind::Loop:
            state.loop = command.number != 0;
            break;
        case Kind::Reset:
            player.resetHistories();
            break;
        case Kind::Ui:
            state.showUi = command.number != 0;
            break;
        case Kind::Screenshot:
            return command.text;
        case Kind::Quit:
            state.quit = true;
            return {};
        }
    }
    return {};
}

Picture picture(Player& player, ViewerState& state) {
    const capture::Frame& frame = player.frame();
    std::optional<report::Image> left = player.image(state.view);
    if (!left) { // the view went away with an effect or setting: back to the default
        state.view = player.defaultView();
        left = player.image(state.view);
    }
    std::optional<report::Image> right = state.split.empty() ? std::nullopt : player.image(state.split);
    if (!state.split.empty() && !right) state.split.clear();
    if (!left) {
        const report::RgbImage black{1, 1, {0, 0, 0}};
        return composePicture(frame.width, frame.height, black, nullptr, 0.5f);
    }
    const report::RgbImage leftRgb = mapView(state.view, *left, state.exposure);
    if (!right) return composePicture(frame.width, frame.height, leftRgb, nullptr, state.divider);
    const report::RgbImage rightRgb = mapView(state.split, *right, state.exposure);
    return composePicture(frame.width, frame.height, leftRgb, &rightRgb, state.divider);
}

// The window's first size: the capture's own when scripted (so a screenshot is the picture at
// 1:1), else a whole multiple of it near 1280 pixels wide, shrunk to fit the screen.
void initialWindowSize(std::uint32_t width, std::uint32_t height, bool scripted, std::uint32_t& windowWidth,
                       std::uint32_t& windowHeight) {
    windowWidth = width;
    windowHeight = height;
    if (scripted) return;
    const std::uint32_t factor = std::max(1u, 1280u / std::max(width, 1u));
    windowWidth = width * factor;
    windowHeight = height * factor;
    std::uint32_t screenWidth = 0, screenHeight = 0;
    Window::screenSize(screenWidth, screenHeight);
    if (screenWidth == 0 || screenHeight == 0) return;
    const double fit = std::min({1.0, 0.9 * screenWidth / windowWidth, 0.9 * screenHeight / windowHeight});
    windowWidth = std::max(1u, static_cast<std::uint32_t>(windowWidth * fit));
    windowHeight = std::max(1u, static_cast<std::uint32_t>(windowHeight * fit));
}

} // namespace glint::cli::view
