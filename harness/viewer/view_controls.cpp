#include "view_controls.h"

#include "glint/glint_effect.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace glint::cli::view {
namespace {

void applySetting(Player& player, ViewerState& state, const SettingDesc& setting, double value) {
    const std::string error = player.setSetting(setting.name + "=" + formatSettingValue(setting, value));
    state.status = error.empty()
                       ? setting.name + " = " + formatSettingValue(setting, value) + " from the next frame"
                       : error;
}

void settingWidget(Player& player, ViewerState& state, const SettingDesc& setting) {
    const SettingValues& values = player.settings();
    const char* label = setting.name.c_str();
    switch (setting.type) {
    case SettingType::Bool: {
        bool on = values.flag(setting.name);
        if (ImGui::Checkbox(label, &on)) applySetting(player, state, setting, on ? 1.0 : 0.0);
        break;
    }
    case SettingType::Choice: {
        const std::size_t current = values.choice(setting.name);
        const char* preview = current < setting.choices.size() ? setting.choices[current].c_str() : "?";
        if (ImGui::BeginCombo(label, preview)) {
            for (std::size_t i = 0; i < setting.choices.size(); ++i)
                if (ImGui::Selectable(setting.choices[i].c_str(), i == current))
                    applySetting(player, state, setting, static_cast<double>(i));
            ImGui::EndCombo();
        }
        break;
    }
    case SettingType::Uint: {
        int value = static_cast<int>(values.count(setting.name));
        if (ImGui::InputInt(label, &value)) {
            const double clamped = std::clamp(static_cast<double>(value), setting.minimum, setting.maximum);
            applySetting(player, state, setting, clamped);
        }
        break;
    }
    case SettingType::Float: {
        float value = values.real(setting.name);
        const double span = setting.maximum - setting.minimum;
        const float speed = static_cast<float>(std::max(1e-4, std::min(span, 10.0) / 500.0));
        if (ImGui::DragFloat(label, &value, speed, static_cast<float>(setting.minimum),
                             static_cast<float>(setting.maximum), "%.4g", ImGuiSliderFlags_AlwaysClamp))
            applySetting(player, state, setting, value);
        break;
    }
    }
    if (ImGui::IsItemHovered() && !setting.help.empty()) ImGui::SetTooltip("%s", setting.help.c_str());
}

void viewCombo(const char* label, const std::vector<std::string>& names, std::string& chosen,
               bool allowNone) {
    if (!ImGui::BeginCombo(label, chosen.empty() ? "(none)" : chosen.c_str())) return;
    if (allowNone && ImGui::Selectable("(none)", chosen.empty())) chosen.clear();
    for (const std::string& name : names)
        if (ImGui::Selectable(name.c_str(), name == chosen)) chosen = name;
    ImGui::EndCombo();
}

void overlay(const Player& player, const gpu::Context& context, std::size_t frameCount) {
    ImGui::Text("frame %zu of 0..%zu (%llu run)", player.frameIndex(), frameCount - 1,
                static_cast<unsigned long long>(player.framesRun()));
    ImGui::Text("%s, subgroup %u", context.info.name.c_str(), context.device.subgroupSize);
    if (player.timings().empty()) {
        ImGui::TextUnformatted("no GPU timestamps on this queue");
    } else if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingStretchProp)) {
        double sum = 0;
        for (const replay::PassTime& time : player.timings()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(time.pass.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%8.1f us", 1000.0 * time.milliseconds);
            sum += time.milliseconds;
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("all passes");
        ImGui::TableNextColumn();
        ImGui::Text("%8.1f us", 1000.0 * sum);
        ImGui::EndTable();
    }
    for (const replay::Counter& counter : player.counters())
        ImGui::Text("%s: %.4g", counter.name.c_str(), counter.value);
    for (const auto& [effect, error] : player.errors()) {
        if (error.pixels == 0) {
            ImGui::Text("%s error: no pixels scored", effect.c_str());
        } else if (error.noisyMean >= 0) {
            ImGui::Text("%s error: %.4f (noisy input %.4f) over %zu pixels", effect.c_str(), error.mean,
                        error.noisyMean, error.pixels);
        } else {
            ImGui::Text("%s error: %.4f over %zu pixels", effect.c_str(), error.mean, error.pixels);
        }
    }
}

} // namespace

void drawControls(Player& player, ViewerState& state, const gpu::Context& context, std::size_t frameCount) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("glint view")) {
        ImGui::End();
        return;
    }
    if (ImGui::Button(state.playing ? "pause" : "play")) state.playing = !state.playing;
    ImGui::SameLine();
    if (ImGui::Button("step")) state.stepRequested = true;
    ImGui::SameLine();
    ImGui::Checkbox("loop", &state.loop);
    ImGui::SameLine();
    if (ImGui::Button("reset histories")) player.resetHistories();
    ImGui::SameLine();
    if (ImGui::Button("screenshot")) state.screenshotRequested = true;

    overlay(player, context, frameCount);

    if (ImGui::CollapsingHeader("view", ImGuiTreeNodeFlags_DefaultOpen)) {
        viewCombo("image", player.viewNames(), state.view, false);
        viewCombo("split with", player.viewNames(), state.split, true);
        if (!state.split.empty()) ImGui::SliderFloat("divider", &state.divider, 0.0f, 1.0f, "%.2f");
        ImGui::SliderFloat("exposure", &state.exposure, 1.0f / 64.0f, 64.0f, "%.3g",
                           ImGuiSliderFlags_Logarithmic);
    }
    if (ImGui::CollapsingHeader("effects", ImGuiTreeNodeFlags_DefaultOpen))
        for (const std::string& effect : player.allEffects()) {
            bool on = player.effectOn(effect);
            if (ImGui::Checkbox(effect.c_str(), &on)) {
                const std::string error = player.toggleEffect(effect);
                state.status =
                    error.empty() ? effect + (on ? " on" : " off") + " from the next frame" : error;
            }
        }
    std::set<std::string> shown; // a setting two effects share is one widget
    for (const std::string& effect : player.allEffects()) {
        const EffectDescriptor* descriptor = findEffect(effect);
        if (!descriptor || !ImGui::CollapsingHeader((effect + " settings").c_str())) continue;
        ImGui::PushID(effect.c_str());
        for (const SettingDesc& setting : descriptor->settings)
            if (setting.name != descriptor->debugSetting && shown.insert(setting.name).second)
                settingWidget(player, state, setting);
        ImGui::PopID();
    }
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
    ImGui::End();
}

} // namespace glint::cli::view
