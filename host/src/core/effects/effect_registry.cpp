// The registry of effect descriptors (glint_effect.h), built from effect_list.h.
#include "glint/glint_effect.h"

#include <algorithm>

namespace glint {

#define GLINT_EFFECT(function) const EffectDescriptor& function();
#include "core/effects/effect_list.h"
#undef GLINT_EFFECT

const std::vector<const EffectDescriptor*>& effectRegistry() {
    static const std::vector<const EffectDescriptor*> effects{
#define GLINT_EFFECT(function) &function(),
#include "core/effects/effect_list.h"
#undef GLINT_EFFECT
    };
    return effects;
}

const EffectDescriptor* findEffect(std::string_view name) {
    for (const EffectDescriptor* effect : effectRegistry())
        if (effect->name == name) return effect;
    return nullptr;
}

namespace {
void addSettings(const EffectDescriptor& effect, std::vector<const SettingDesc*>& table) {
    for (const SettingDesc& setting : effect.settings) {
        const bool known = std::any_of(table.begin(), table.end(),
                                       [&](const SettingDesc* row) { return row->name == setting.name; });
        if (!known) table.push_back(&setting);
    }
}
} // namespace

std::vector<const SettingDesc*> allSettings() {
    std::vector<const SettingDesc*> table;
    for (const EffectDescriptor* effect : effectRegistry()) addSettings(*effect, table);
    return table;
}

SettingValues defaultSettings(const std::vector<const EffectDescriptor*>& effects) {
    std::vector<const SettingDesc*> table;
    for (const EffectDescriptor* effect : effects) addSettings(*effect, table);
    return SettingValues(table);
}

} // namespace glint
