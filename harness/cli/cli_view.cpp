// glint view: a window that replays a capture (or a scene simulated in memory) frame after
// frame through its effects, histories carried, with controls for playback, effects,
// settings, views, split screen and exposure, and the per-pass GPU times over it
// (docs/viewer.md). Scripts (--script) and --screenshot FILE --after N drive it unattended.
#include "cli_capture.h"
#include "cli_commands.h"
#include "view_controls.h"
#include "view_player.h"
#include "view_script.h"
#include "view_window.h"

#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace glint::cli {
namespace {

// The frames of `path`: a capture (through `map` when given) or a scene .toml, simulated once
// the device exists (`simulate` is then set and the frames come from it).
struct OpenedSource {
    std::unique_ptr<CaptureSource> capture;
    std::optional<scene::Scene> scene;
    std::vector<capture::Frame> simulated;
    view::FrameSource frames;
};

// Keys: space play/pause, right arrow step, R reset histories, H the controls, P a
// screenshot, + and - exposure, Escape quit (none while the controls take the keyboard).
void handleInput(view::Window& window, view::Player& player, view::ViewerState& state,
                 const view::Presenter& presenter, std::uint32_t width, std::uint32_t height) {
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
        const view::Presenter::Rect rect = presenter.pictureRect(width, height);
        if (rect.width > 0)
            state.divider = std::clamp(static_cast<float>((x * toPixels - static_cast<double>(rect.x)) /
                                                          static_cast<double>(rect.width)),
                                       0.0f, 1.0f);
    }
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// Runs the script's commands from `next` on until one needs a frame to be shown first (step,
// screenshot); returns the screenshot's file when that was the one.
std::string runScript(const std::vector<view::ScriptCommand>& commands, std::size_t& next,
                      std::uint64_t& steps, view::Player& player, view::ViewerState& state) {
    using Kind = view::ScriptCommand::Kind;
    while (next < commands.size() && steps == 0) {
        const view::ScriptCommand& command = commands[next++];
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

// The picture is mapped on the CPU; while nothing it depends on changes (paused, or the
// controls moving), the last one is shown again.
struct PictureCache {
    std::uint64_t framesRun = 0;
    std::string view, split;
    float divider = 0, exposure = 0;
    view::Picture picture;

    bool matches(const view::Player& player, const view::ViewerState& state) const {
        return !picture.rgba.empty() && framesRun == player.framesRun() && view == state.view &&
               split == state.split && (split.empty() || divider == state.divider) &&
               exposure == state.exposure;
    }
};

view::Picture picture(view::Player& player, view::ViewerState& state) {
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
        return view::composePicture(frame.width, frame.height, black, nullptr, 0.5f);
    }
    const report::RgbImage leftRgb = view::mapView(state.view, *left, state.exposure);
    if (!right) return view::composePicture(frame.width, frame.height, leftRgb, nullptr, state.divider);
    const report::RgbImage rightRgb = view::mapView(state.split, *right, state.exposure);
    return view::composePicture(frame.width, frame.height, leftRgb, &rightRgb, state.divider);
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
    view::Window::screenSize(screenWidth, screenHeight);
    if (screenWidth == 0 || screenHeight == 0) return;
    const double fit = std::min({1.0, 0.9 * screenWidth / windowWidth, 0.9 * screenHeight / windowHeight});
    windowWidth = std::max(1u, static_cast<std::uint32_t>(windowWidth * fit));
    windowHeight = std::max(1u, static_cast<std::uint32_t>(windowHeight * fit));
}

} // namespace

int runView(const ViewOptions& options) {
    if (const std::string missing = view::missingDisplayMessage(); !missing.empty()) {
        std::fprintf(stderr, "%s\n", missing.c_str());
        return kExitUsage;
    }
    std::vector<view::ScriptCommand> commands;
    if (!options.script.empty()) commands = view::readScript(options.script);
    if (!options.screenshot.empty()) {
        if (!options.script.empty())
            throw std::invalid_argument("view: --screenshot and --script do not go together (a script takes "
                                        "screenshots with its own 'screenshot FILE')");
        if (options.after > 0)
            commands.push_back({view::ScriptCommand::Kind::Step, "", double(options.after), "--after"});
        commands.push_back({view::ScriptCommand::Kind::Screenshot, options.screenshot, 0, "--screenshot"});
        commands.push_back({view::ScriptCommand::Kind::Quit, "", 0, "--screenshot"});
    } else if (options.after > 0) {
        throw std::invalid_argument("view: --after N goes with --screenshot FILE");
    }
    const bool scripted = !commands.empty();

    // Everything about the input is checked before a window opens.
    replay::SessionOptions sessionOptions;
    sessionOptions.effects = options.effects;
    sessionOptions.settings = replay::parseSettings(options.settings);
    OpenedSource opened;
    std::uint32_t width = 0, height = 0;
    if (std::filesystem::path(options.capture).extension() == ".toml") {
        opened.scene = scene::loadScene(options.capture);
        width = opened.scene->width;
        height = opened.scene->height;
        opened.frames.description = options.capture;
        setGeometry(sessionOptions, options.capture, options.geometry);
    } else {
        opened.capture = std::make_unique<CaptureSource>(options.capture, options.mapPath);
        const CaptureSource& source = *opened.capture;
        setGeometry(sessionOptions, source.sceneFile(), options.geometry);
        sessionOptions.settings = replay::parseSettings(presetThenSettings(
            options.preset, options.effects.empty() ? source.declaredEffects() : options.effects,
            options.settings));
        source.checkFrames(0, source.frameCount() - 1, sessionOptions);
        const capture::Frame first = source.frame(0);
        source.checkEffects(first, 0, sessionOptions);
        width = first.width;
        height = first.height;
        opened.frames.count = source.frameCount();
        opened.frames.frame = [&source](std::size_t index) { return source.frame(index); };
        opened.frames.environment = source.environment();
        opened.frames.description = source.description();
    }

    std::uint32_t windowWidth = width, windowHeight = height;
    view::Window window(width, height, "glint view: " + opened.frames.description);
    initialWindowSize(width, height, scripted, windowWidth, windowHeight);
    if (windowWidth != width || windowHeight != height)
        glfwSetWindowSize(window.handle(), static_cast<int>(windowWidth), static_cast<int>(windowHeight));

    return withContext(
        options.validate,
        [&](const gpu::Context& context) {
            if (opened.scene) {
                scene::Simulation simulation = scene::simulate(context, *opened.scene);
                for (const std::string& warning : simulation.warnings)
                    std::fprintf(stderr, "glint: %s\n", warning.c_str());
                opened.simulated = std::move(simulation.frames);
                opened.frames.count = opened.simulated.size();
                opened.frames.frame = [&opened](std::size_t index) { return opened.simulated.at(index); };
                opened.frames.environment = simulation.environment.value_or(blackEnvironment());
                // A scene's effects are known once simulated: --preset follows them.
                if (!options.preset.name.empty() && !opened.simulated.empty())
                    sessionOptions.settings = replay::parseSettings(presetThenSettings(
                        options.preset,
                        options.effects.empty() ? opened.simulated.front().effects : options.effects,
                        options.settings));
            }
            view::Player player(context, opened.frames, sessionOptions);
            view::Presenter presenter(context, window);
            view::ViewerState state;
            state.playing = !scripted;
            state.showUi = !scripted || options.ui;
            state.view = player.defaultView();
            std::size_t next = 0;
            std::uint64_t steps = 0;
            std::uint32_t screenshots = 0;
            PictureCache cache;
            while (!state.quit) {
                window.pollEvents();
                if (window.closeRequested()) break;
                std::string screenshot = runScript(commands, next, steps, player, state);
                const bool scriptRunning = next < commands.size() || steps > 0;
                if (steps > 0) {
                    player.advance(true);
                    --steps;
                } else if (screenshot.empty() && !state.quit &&
                           (state.stepRequested || (state.playing && !scriptRunning))) {
                    // A change from the controls that the effects refuse is undone and shown;
                    // a script's is an error.
                    try {
                        if (!player.advance(state.loop)) state.playing = false;
                    } catch (const std::invalid_argument& error) {
                        if (scripted) throw;
                        state.status = std::string(error.what()) + " (the change is undone)";
                        player.revertChanges();
                    }
                }
                state.stepRequested = false;
                if (state.quit) break;
                presenter.beginUi();
                if (state.showUi) drawControls(player, state, context, opened.frames.count);
                handleInput(window, player, state, presenter, width, height);
                if (state.screenshotRequested && screenshot.empty()) {
                    char name[64];
                    std::snprintf(name, sizeof name, "glint_view_frame%04zu_%u.png", player.frameIndex(),
                                  screenshots++);
                    screenshot = name;
                }
                state.screenshotRequested = false;
                report::RgbImage shot;
                if (!cache.matches(player, state)) {
                    cache.picture = picture(player, state); // may fall back to the default view
                    cache = {player.framesRun(), state.view,     state.split,
                             state.divider,      state.exposure, std::move(cache.picture)};
                }
                presenter.present(cache.picture, state.showUi, screenshot.empty() ? nullptr : &shot);
                if (!screenshot.empty()) {
                    report::writeRgbPng(screenshot, shot.width, shot.height, shot.rgb);
                    std::printf("wrote %s (frame %zu, %s)\n", screenshot.c_str(), player.frameIndex(),
                                state.view.c_str());
                    std::fflush(stdout);
                }
                if (!scripted && !state.playing) glfwWaitEventsTimeout(0.05); // idle without spinning
            }
            return kExitOk;
        },
        [&](gpu::ContextOptions& contextOptions) {
            contextOptions.surfaceExtensions = window.instanceExtensions();
            contextOptions.createSurface = [&window](VkInstance instance) {
                return window.createSurface(instance);
            };
        });
}

} // namespace glint::cli
