#include "view_script.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace glint::cli::view {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
    throw std::invalid_argument(where + ": " + problem);
}

// The number in `text`, whole (no trailing characters) and finite, else a failure naming `what`.
double number(const std::string& text, const std::string& where, const std::string& what) {
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(value))
        fail(where, what + " needs a finite number, got '" + text + "'");
    return value;
}

bool onOff(const std::string& text, const std::string& where, const std::string& verb) {
    if (text == "on") return true;
    if (text == "off") return false;
    fail(where, verb + " takes 'on' or 'off', got '" + text + "'");
}

} // namespace

bool parseScriptLine(std::string_view line, const std::string& where, ScriptCommand& command) {
    std::istringstream words{std::string(line)};
    std::string verb;
    if (!(words >> verb) || verb.front() == '#') return false;
    std::vector<std::string> arguments;
    for (std::string word; words >> word;) arguments.push_back(word);
    using Kind = ScriptCommand::Kind;
    struct Verb {
        const char* name;
        Kind kind;
        std::size_t minimum, maximum; // argument counts
    };
    static const Verb verbs[] = {
        {"set", Kind::Set, 1, 1},
        {"toggle", Kind::Toggle, 1, 1},
        {"view", Kind::View, 1, 1},
        {"split", Kind::Split, 1, 1},
        {"divider", Kind::Divider, 1, 1},
        {"exposure", Kind::Exposure, 1, 1},
        {"step", Kind::Step, 0, 1},
        {"play", Kind::Play, 0, 0},
        {"pause", Kind::Pause, 0, 0},
        {"loop", Kind::Loop, 1, 1},
        {"reset", Kind::Reset, 0, 0},
        {"ui", Kind::Ui, 1, 1},
        {"screenshot", Kind::Screenshot, 1, 1},
        {"quit", Kind::Quit, 0, 0},
    };
    const Verb* found = nullptr;
    for (const Verb& candidate : verbs)
        if (verb == candidate.name) found = &candidate;
    if (!found)
        fail(where, "unknown command '" + verb +
                        "' (set, toggle, view, split, divider, exposure, step, play, pause, loop, reset, ui, "
                        "screenshot, quit)");
    if (arguments.size() < found->minimum || arguments.size() > found->maximum)
        fail(where, verb + " takes " +
                        (found->minimum == found->maximum
                             ? std::to_string(found->minimum)
                             : std::to_string(found->minimum) + " or " + std::to_string(found->maximum)) +
                        " argument(s), got " + std::to_string(arguments.size()));
    command = ScriptCommand{found->kind, arguments.empty() ? "" : arguments.front(), 0, where};
    switch (found->kind) {
    case Kind::Set:
        if (command.text.find('=') == std::string::npos)
            fail(where, "set needs NAME=VALUE, got '" + command.text + "'");
        break;
    case Kind::Split:
        if (command.text == "off") command.text.clear();
        break;
    case Kind::Divider:
        command.number = number(command.text, where, "divider");
        if (command.number < 0 || command.number > 1)
            fail(where, "divider needs a fraction in [0, 1], got " + command.text);
        break;
    case Kind::Exposure:
        command.number = number(command.text, where, "exposure");
        if (!(command.number > 0)) fail(where, "exposure needs a factor above 0, got " + command.text);
        break;
    case Kind::Step:
        command.number = arguments.empty() ? 1 : number(command.text, where, "step");
        if (command.number < 1 || command.number > 1e6 || command.number != std::floor(command.number))
            fail(where, "step needs a whole number of frames from 1 to 1000000, got " + command.text);
        break;
    case Kind::Loop:
        command.number = onOff(command.text, where, "loop") ? 1 : 0;
        break;
    case Kind::Ui:
        command.number = onOff(command.text, where, "ui") ? 1 : 0;
        break;
    default:
        break;
    }
    return true;
}

std::vector<ScriptCommand> readScript(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw std::invalid_argument(path + ": cannot open the script");
    std::vector<ScriptCommand> commands;
    std::string line;
    for (int number = 1; std::getline(file, line); ++number) {
        ScriptCommand command;
        if (parseScriptLine(line, path + ":" + std::to_string(number), command)) commands.push_back(command);
    }
    if (file.bad()) throw std::invalid_argument(path + ": cannot read the script");
    return commands;
}

} // namespace glint::cli::view
