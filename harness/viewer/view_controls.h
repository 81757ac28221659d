// glint view's controls and overlay (Dear ImGui): playback, effects on and off, every setting
// of the running effects' settings tables as a widget, the views, split and exposure, and the
// per-pass GPU times, counters, frame and device.
#pragma once

#include "view_player.h"

#include <gpu/gpu_context.h>

#include <string>

namespace glint::cli::view {

// What the viewer shows and does, changed by the controls, the keys and scripts alike.
struct ViewerState {
    std::string view;      // the image shown ("" until the first frame names the default)
    std::string split;     // a second image right of the divider, "" for none
    float divider = 0.5f;  // fraction of the picture's width
    float exposure = 1.0f; // linear factor on tone-mapped colour
    bool playing = true;
    bool loop = true;
    bool showUi = true;
    bool stepRequested = false;
    bool screenshotRequested = false;
    bool quit = false;
    std::string status; // the last message (a refused setting, a screenshot written)
};

// Draws the controls window between Presenter::beginUi and present; acts on `player` and `state`.
void drawControls(Player& player, ViewerState& state, const gpu::Context& context, std::size_t frameCount);

} // namespace glint::cli::view
