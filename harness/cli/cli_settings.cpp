// glint settings [effect]: every setting of the effects' settings tables (glint_effect.h) with
// its type, default, range and help; the same rows --set parses and checks.
#include "cli_commands.h"

#include "glint/glint_effect.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <stdexcept>

namespace glint::cli {

std::string effectNames() {
    std::string names;
    for (const EffectDescriptor* effect : effectRegistry())
        names += (names.empty() ? "" : ", ") + effect->name;
    return names;
}

std::string settingsHelp() {
    return "Settings (--set name=value):\n" + describeSettings(allSettings());
}

std::string settingsSection(const EffectDescriptor& effect) {
    std::vector<const SettingDesc*> table;
    for (const SettingDesc& setting : effect.settings) table.push_back(&setting);
    return "## " + effect.name + "\n\n" + effect.help + ".\n\n" + settingsMarkdown(table);
}

void addPresetOptions(CLI::App& command, PresetChoice& preset) {
    command.add_option("--preset", preset.name,
                       "low | medium | high | ultra: settings per effect, applied before --set "
                       "(docs/accuracy-vs-time.md, Presets)");
    command.add_option("--preset-file", preset.file,
                       "read --preset from this file (presets.toml written by glint study)");
}

void addSettingsOptions(CLI::App& command, SettingsOptions& options) {
    command.add_option("effect", options.effect, effectNames());
    command.add_flag("--markdown", options.markdown, "as the Markdown tables of docs/settings.md");
}

int runSettings(SettingsOptions options, bool) {
    const std::string& effectName = options.effect;
    const bool markdown = options.markdown;
    for (const EffectDescriptor* effect : effectRegistry()) {
        if (!effectName.empty() && effect->name != effectName) continue;
        std::vector<const SettingDesc*> table;
        for (const SettingDesc& setting : effect->settings) table.push_back(&setting);
        if (markdown)
            std::printf("\n%s", settingsSection(*effect).c_str());
        else
            std::printf("%s: %s\n%s", effect->name.c_str(), effect->help.c_str(),
                        describeSettings(table).c_str());
        if (!effectName.empty()) return kExitOk;
    }
    if (!effectName.empty())
        throw std::invalid_argument("settings: unknown effect '" + effectName + "' (" + effectNames() + ")");
    return kExitOk;
}

} // namespace glint::cli
