#include "cli_presets.h"

#include "glint/glint_effect.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace glint::cli {

// harness/presets/presets.toml, embedded at build time (cmake/GlintEmbedText.cmake).
std::string_view builtInPresetsText();

namespace {

constexpr const char* kBuiltInSource = "built-in presets (harness/presets/presets.toml)";

std::string settingName(const std::string& assignment) {
    return assignment.substr(0, assignment.find('='));
}

std::string settingValue(const std::string& assignment) {
    const std::size_t equals = assignment.find('=');
    return equals == std::string::npos ? std::string() : assignment.substr(equals + 1);
}

std::string joinedNames(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

[[noreturn]] void fail(const std::string& source, const std::string& key, const std::string& what) {
    throw std::invalid_argument(source + ": " + key + ": " + what);
}

PresetEntry parseEntry(const toml::node& node, const EffectDescriptor& effect, const std::string& source,
                       const std::string& key) {
    const toml::table* table = node.as_table();
    if (!table) fail(source, key, "must be a table with 'settings'");
    PresetEntry entry;
    for (const auto& [name, value] : *table) {
        const std::string field(name.str());
        if (field == "settings") {
            const toml::array* list = value.as_array();
            if (!list) fail(source, key + ".settings", "must be an array of \"name=value\" strings");
            // Each assignment is checked against the effect's own table, so that a bundle cannot
            // set another effect's setting or a value out of range.
            std::vector<const SettingDesc*> rows;
            for (const SettingDesc& setting : effect.settings) rows.push_back(&setting);
            SettingValues values(rows);
            for (const toml::node& item : *list) {
                const std::optional<std::string> assignment = item.value<std::string>();
                if (!assignment)
                    fail(source, key + ".settings", "must be an array of \"name=value\" strings");
                if (!values.has(settingName(*assignment)))
                    fail(source, key + ".settings",
                         "'" + settingName(*assignment) + "' is not a setting of " + effect.name);
                if (const std::string error = values.assign(*assignment); !error.empty())
                    fail(source, key + ".settings", error);
                entry.settings.push_back(*assignment);
            }
        } else if (field == "point") {
            const std::optional<std::string> point = value.value<std::string>();
            if (!point) fail(source, key + ".point", "must be a string");
            entry.point = *point;
        } else if (field == "time_us" || field == "error") {
            const std::optional<double> number = value.value<double>();
            if (!number || !std::isfinite(*number))
                fail(source, key + "." + field, "must be a finite number");
            (field == "time_us" ? entry.timeUs : entry.error) = *number;
        } else {
            fail(source, key + "." + field, "unknown key (settings, point, time_us, error)");
        }
    }
    if (!table->contains("settings")) fail(source, key, "has no 'settings'");
    return entry;
}

} // namespace

PresetTable parsePresets(std::string_view text, const std::string& source) {
    toml::table root;
    try {
        root = toml::parse(text, source);
    } catch (const toml::parse_error& error) {
        throw std::invalid_argument(source + ":" + std::to_string(error.source().begin.line) + ": " +
                                    std::string(error.description()));
    }
    PresetTable table;
    table.source = source;
    const toml::array* names = root["presets"].as_array();
    if (!names || names->empty())
        fail(source, "presets", "must list the preset names, e.g. [\"low\", \"high\"]");
    for (const toml::node& item : *names) {
        const std::optional<std::string> name = item.value<std::string>();
        if (!name || name->empty()) fail(source, "presets", "must be an array of names");
        if (std::find(table.names.begin(), table.names.end(), *name) != table.names.end())
            fail(source, "presets", "names '" + *name + "' twice");
        table.names.push_back(*name);
    }
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        if (name == "presets") continue;
        if (std::find(table.names.begin(), table.names.end(), name) == table.names.end())
            fail(source, name, "is not listed in 'presets'");
        const toml::table* effects = node.as_table();
        if (!effects) fail(source, name, "must be a table of effects");
        table.presets[name]; // a preset may list no effect: everything at its defaults
        for (const auto& [effectKey, entry] : *effects) {
            const std::string effectName(effectKey.str());
            const EffectDescriptor* effect = findEffect(effectName);
            if (!effect)
                fail(
                    source, name + "." + effectName, "unknown effect (" + [] {
                        std::vector<std::string> known;
                        for (const EffectDescriptor* e : effectRegistry()) known.push_back(e->name);
                        return joinedNames(known);
                    }() + ")");
            table.presets[name][effectName] = parseEntry(entry, *effect, source, name + "." + effectName);
        }
    }
    for (const std::string& name : table.names)
        if (!table.presets.contains(name)) fail(source, name, "is listed in 'presets' but has no table");
    return table;
}

PresetTable loadPresets(const std::string& file) {
    if (file.empty()) return parsePresets(builtInPresetsText(), kBuiltInSource);
    std::ifstream stream(file, std::ios::binary);
    if (!stream) throw std::invalid_argument(file + ": cannot read the presets file");
    std::ostringstream text;
    text << stream.rdbuf();
    return parsePresets(text.str(), file);
}

std::string formatPresets(const PresetTable& table, const std::string& header) {
    std::ostringstream out;
    std::istringstream lines(header);
    for (std::string line; std::getline(lines, line);) out << (line.empty() ? "#" : "# " + line) << "\n";
    toml::table root;
    toml::array names;
    for (const std::string& name : table.names) names.push_back(name);
    root.insert("presets", std::move(names));
    for (const std::string& name : table.names) {
        toml::table effects; // a preset may list no effect
        if (const auto found = table.presets.find(name); found != table.presets.end())
            for (const auto& [effect, entry] : found->second) {
                toml::table bundle;
                if (!entry.point.empty()) bundle.insert("point", entry.point);
                toml::array settings;
                for (const std::string& setting : entry.settings) settings.push_back(setting);
                bundle.insert("settings", std::move(settings));
                if (entry.timeUs) bundle.insert("time_us", *entry.timeUs);
                if (entry.error) bundle.insert("error", *entry.error);
                effects.insert(effect, std::move(bundle));
            }
        root.insert(name, std::move(effects));
    }
    out << root << "\n";
    return out.str();
}

void checkPresetChoice(const PresetChoice& choice) {
    if (choice.name.empty()) {
        if (!choice.file.empty())
            throw std::invalid_argument("--preset-file " + choice.file + " needs --preset NAME");
        return;
    }
    const PresetTable table = loadPresets(choice.file);
    if (!table.presets.contains(choice.name))
        throw std::invalid_argument("unknown preset '" + choice.name + "' (" + joinedNames(table.names) +
                                    (choice.file.empty() ? "" : ", from " + choice.file) + ")");
}

std::vector<std::string> presetThenSettings(const PresetChoice& choice,
                                            const std::vector<std::string>& effects,
                                            const std::vector<std::string>& settings) {
    if (choice.name.empty()) return settings;
    checkPresetChoice(choice);
    const PresetTable table = loadPresets(choice.file);
    const std::map<std::string, PresetEntry>& bundles = table.presets.at(choice.name);
    std::vector<std::string> all;
    std::map<std::string, std::pair<std::string, std::string>> given; // name -> (value, effect)
    for (const std::string& effect : effects) {
        const auto entry = bundles.find(effect);
        if (entry == bundles.end()) continue;
        for (const std::string& assignment : entry->second.settings) {
            const std::string name = settingName(assignment);
            const bool overridden = std::any_of(settings.begin(), settings.end(),
                                                [&](const std::string& s) { return settingName(s) == name; });
            const auto previous = given.find(name);
            if (previous != given.end() && previous->second.first != settingValue(assignment) && !overridden)
                throw std::invalid_argument("preset '" + choice.name + "' gives " + name + " the value " +
                                            previous->second.first + " for " + previous->second.second +
                                            " and " + settingValue(assignment) + " for " + effect +
                                            ", which share it: choose with --set " + name + "=VALUE");
            given.emplace(name, std::pair{settingValue(assignment), effect});
            all.push_back(assignment);
        }
    }
    all.insert(all.end(), settings.begin(), settings.end());
    return all;
}

std::optional<std::size_t> bestWithin(const std::vector<StudyPoint>& points, double budgetUs) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < points.size(); ++i) {
        // A point without a finite time and error is on no front and fits no budget.
        if (!std::isfinite(points[i].timeUs) || !std::isfinite(points[i].error) ||
            !(points[i].timeUs <= budgetUs))
            continue;
        if (!best || points[i].error < points[*best].error ||
            (points[i].error == points[*best].error && points[i].timeUs < points[*best].timeUs))
            best = i;
    }
    return best;
}

std::vector<std::size_t> paretoFront(const std::vector<StudyPoint>& points) {
    std::vector<std::size_t> front;
    for (const StudyPoint& point : points)
        if (const std::optional<std::size_t> best = bestWithin(points, point.timeUs);
            best && std::find(front.begin(), front.end(), *best) == front.end())
            front.push_back(*best);
    std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
        return points[a].timeUs < points[b].timeUs || (points[a].timeUs == points[b].timeUs && a < b);
    });
    return front;
}

std::vector<std::pair<std::string, std::size_t>> choosePresets(const std::vector<StudyPoint>& points,
                                                               const std::string& base) {
    const std::vector<std::size_t> front = paretoFront(points);
    if (front.empty()) return {};
    std::vector<double> times;
    for (const StudyPoint& point : points)
        if (std::isfinite(point.timeUs) && std::isfinite(point.error)) times.push_back(point.timeUs);
    std::sort(times.begin(), times.end());
    double baseTime = times[times.size() / 2];
    for (const StudyPoint& point : points)
        if (point.label == base && std::isfinite(point.timeUs) && std::isfinite(point.error))
            baseTime = point.timeUs;
    const std::size_t low = front.front(); // the fastest point, the most accurate of equally fast ones
    const std::size_t high = *bestWithin(points, baseTime);
    const std::size_t medium = *bestWithin(points, 0.5 * (points[low].timeUs + points[high].timeUs));
    const std::size_t ultra = *bestWithin(points, std::numeric_limits<double>::infinity());
    return {{"low", low}, {"medium", medium}, {"high", high}, {"ultra", ultra}};
}

} // namespace glint::cli
