// glint view: a window that replays a capture (or a scene simulated in memory) frame after
// frame through its effects, histories carried, with controls for playback, effects,
// settings, views, split screen and exposure, and the per-pass GPU times over it
// (docs/viewer.md). Scripts (--script) and --screenshot FILE --after N drive it unattended.
#include "cli_capture.h"
#include "cli_commands.h"
#include "view_controls.h"
#include "view_loop.h"
#include "view_player.h"
#include "view_script.h"
#include "view_window.h"

#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <CLI/CLI.hpp>
#include <GLFW/glfw3.h>

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

} // namespace

void addViewOptions(CLI::App& command, ViewOptions& options) {
    command
        .add_option(
            "capture", options.capture,
            "frame .exr, sequence folder, with --map one foreign EXR or a folder of them, or scene .toml")
        ->required();
    command.add_option("--map", options.mapPath, "channel map of a foreign capture (docs/replay.md)");
    command.add_option("--geometry", options.geometry,
                       "a glTF of the capture's scene, for the effects that ray trace");
    command.add_option("--effects", options.effects, effectNames() + " (default: declared)")->delimiter(',');
    command.add_option("--set", options.settings, "a setting, name=value (repeatable; glint settings)");
    addPresetOptions(command, options.preset);
    command.add_option("--script", options.script, "commands to run, one a line (docs/viewer.md)");
    command.add_option("--screenshot", options.screenshot,
                       "write the window's image as PNG after frame --after, then exit");
    command.add_option("--after", options.after, "the frame (0-based) --screenshot waits for");
    command.add_flag("--ui", options.ui, "show the controls in scripted runs and screenshots too");
    command.footer(settingsHelp());
}

int runView(ViewOptions options, bool validate) {
    // An unknown preset or an unreadable preset file fails before any capture is read.
    checkPresetChoice(options.preset);
    options.validate = validate;
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
    view::initialWindowSize(width, height, scripted, windowWidth, windowHeight);
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
            view::PictureCache cache;
            while (!state.quit) {
                window.pollEvents();
                if (window.closeRequested()) break;
                std::string screenshot = view::runScript(commands, next, steps, player, state);
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
                view::handleInput(window, player, state, presenter, width, height);
                if (state.screenshotRequested && screenshot.empty()) {
                    char name[64];
                    std::snprintf(name, sizeof name, "glint_view_frame%04zu_%u.png", player.frameIndex(),
                                  screenshots++);
                    screenshot = name;
                }
                state.screenshotRequested = false;
                report::RgbImage shot;
                if (!cache.matches(player, state)) {
                    cache.picture = view::picture(player, state); // may fall back to the default view
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
