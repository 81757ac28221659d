// glint view's scripts (--script FILE): one command a line, run in order before the window
// takes input, so that a test or a documentation run can drive the viewer and take pictures.
//   set NAME=VALUE     a setting (glint settings), applied from the next frame on
//   toggle EFFECT      an effect on or off
//   view NAME          the image shown ("reflections/denoised", "depth_pyramid/mip3", ...)
//   split NAME | off   a second image right of a divider, or none
//   divider F          the divider's place, a fraction of the width in [0, 1]
//   exposure F         linear factor on tone-mapped colour, > 0
//   step [N]           run N frames (default 1)
//   play | pause       playback
//   loop on | off      back to the first frame after the last (with histories reset)
//   reset              the next frame starts every history again
//   ui on | off        the controls and the overlay
//   screenshot FILE    the window's image as PNG
//   quit               close the window, exit 0
// Blank lines and lines starting with '#' are skipped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace glint::cli::view {

struct ScriptCommand {
    enum class Kind {
        Set,
        Toggle,
        View,
        Split,
        Divider,
        Exposure,
        Step,
        Play,
        Pause,
        Loop,
        Reset,
        Ui,
        Screenshot,
        Quit
    };
    Kind kind = Kind::Quit;
    std::string
        text; // Set: "name=value"; Toggle: effect; View/Split: image ("" = split off); Screenshot: file
    double number = 0; // Divider, Exposure, Step (count), Loop/Ui (1 on, 0 off)
    std::string where; // "<script>:<line>", for errors found when the command runs
};

// One line; throws std::invalid_argument "<where>: <problem>" for a line it cannot read.
// Returns false (nothing to run) for blank and comment lines.
bool parseScriptLine(std::string_view line, const std::string& where, ScriptCommand& command);

// The whole file; throws std::invalid_argument naming the file (and line) on any problem.
std::vector<ScriptCommand> readScript(const std::string& path);

} // namespace glint::cli::view
