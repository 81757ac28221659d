// Presets (docs/accuracy-vs-time.md, "Presets"): named bundles of settings per effect, chosen
// from the study's Pareto fronts. `--preset NAME` applies, for each effect being run, that
// effect's bundle before the `--set` assignments, so `--set` overrides a preset. The built-in
// presets are harness/presets/presets.toml, embedded in the binary; `glint study` writes the
// same format for its own run, which `--preset-file FILE` reads back.
//
// The choice of points lives here too, as one rule: the most accurate point whose time fits a
// budget (ties in error go to the faster point). A point it returns is on the Pareto front
// (nothing is as fast and as accurate and better in one), and each preset is that rule at one
// budget, so no second Pareto test exists.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::cli {

// One effect's bundle within a preset.
struct PresetEntry {
    std::vector<std::string> settings; // "name=value", applied in order before --set
    std::string point;                 // the study point it was chosen from ("" when not given)
    std::optional<double> timeUs;      // that point's time and relative error (study output only)
    std::optional<double> error;
};

struct PresetTable {
    std::string source;             // "built-in presets" or the file, for messages
    std::vector<std::string> names; // in the file's order (cheapest first)
    std::map<std::string, std::map<std::string, PresetEntry>> presets; // preset -> effect -> entry
};

// Reads the TOML text of a presets file. Every setting must belong to its effect's settings
// table and parse there; any error is one line naming `source` and the key at fault.
PresetTable parsePresets(std::string_view text, const std::string& source);
// `file` empty: the built-in presets.
PresetTable loadPresets(const std::string& file);
// The presets file's text: the inverse of parsePresets. `header` lines become comments.
std::string formatPresets(const PresetTable& table, const std::string& header);

// --preset NAME [--preset-file FILE] as a verb was given them.
struct PresetChoice {
    std::string name; // empty: no preset
    std::string file; // empty: the built-in presets
};
// Checks a choice before any work: --preset-file needs --preset, the file must read, and the
// preset must exist ("unknown preset 'x' (low, medium, high, ultra)").
void checkPresetChoice(const PresetChoice& choice);
// The preset's bundles for `effects` (in that order), then `settings`. Two effects whose
// bundles give one shared setting different values are an error unless `settings` names it.
std::vector<std::string> presetThenSettings(const PresetChoice& choice,
                                            const std::vector<std::string>& effects,
                                            const std::vector<std::string>& settings);

// A measured point of one effect, its scenes already combined (cli_study_presets.cpp).
struct StudyPoint {
    std::string label;
    std::vector<std::string> settings;
    double timeUs = 0.0;
    double error = 0.0;
};
// The index of the most accurate point with timeUs <= budgetUs, the faster of equally accurate
// ones (then the earlier); none when no point fits.
std::optional<std::size_t> bestWithin(const std::vector<StudyPoint>& points, double budgetUs);
// The points on the Pareto front, fastest first: each point's own time as the budget.
std::vector<std::size_t> paretoFront(const std::vector<StudyPoint>& points);
// low: the fastest point (the most accurate of equally fast ones); high: the best within the
// time of the point labelled `base` (the effect as shipped; the median point's time when no
// point has that label); medium: the best within the midpoint of low's and high's times;
// ultra: the most accurate. Neighbours coincide when the front has fewer than four points.
// Empty when `points` is.
std::vector<std::pair<std::string, std::size_t>> choosePresets(const std::vector<StudyPoint>& points,
                                                               const std::string& base);

} // namespace glint::cli
