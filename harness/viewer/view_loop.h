// The pieces of glint view's frame loop (harness/cli/cli_view.cpp runs them): the keys, the
// script's commands, the picture shown and the window's first size.
#pragma once

#include "view_controls.h"
#include "view_picture.h"
#include "view_player.h"
#include "view_script.h"
#include "view_window.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace glint::cli::view {

// Keys: space play/pause, right arrow step, R reset histories, H the controls, P a
// screenshot, + and - exposure, Escape quit (none while the controls take the keyboard).
void handleInput(Window& window, Player& player, ViewerState& state, const Presenter& presenter,
                 std::uint32_t width, std::uint32_t height);

// Runs the script's commands from `next` on until one needs a frame to be shown first (step,
// screenshot); returns the screenshot's file when that was the one.
std::string runScript(const std::vector<ScriptCommand>& commands, std::size_t& next, std::uint64_t& steps,
                      Player& player, ViewerState& state);

// The picture is mapped on the CPU; while nothing it depends on changes (paused, or the
// controls moving), the last one is shown again.
struct PictureCache {
    std::uint64_t framesRun = 0;
    std::string view, split;
    float divider = 0, exposure = 0;
    Picture picture;

    bool matches(const Player& player, const ViewerState& state) const {
        return !picture.rgba.empty() && framesRun == player.framesRun() && view == state.view &&
               split == state.split && (split.empty() || divider == state.divider) &&
               exposure == state.exposure;
    }
};

// The picture of the state's view (and split), falling back to the default view when the view
// went away with an effect or setting.
Picture picture(Player& player, ViewerState& state);

// The window's first size: the capture's own when scripted (so a screenshot is the picture at
// 1:1), else a whole multiple of it near 1280 pixels wide, shrunk to fit the screen.
void initialWindowSize(std::uint32_t width, std::uint32_t height, bool scripted, std::uint32_t& windowWidth,
                       std::uint32_t& windowHeight);

} // namespace glint::cli::view
