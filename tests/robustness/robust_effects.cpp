#include "robustness/robust_effects.h"

#include <gpu/gpu_input_images.h>
#include <replay/replay_frame.h>
#include <scene/scene_buffers.h>
#include <scene/scene_shaders.h>

#include <stdexcept>

namespace glint::test {

std::vector<HistoryResource> effectHistories(const std::string& effect, const SettingValues& settings) {
    std::vector<HistoryResource> out;
    const bool denoised = (effect == "reflections" || effect == "hybrid") && settings.flag("denoise");
    if (denoised)
        for (const char* name : {"rd_radiance0", "rd_radiance1", "rd_variance0", "rd_variance1", "rd_length0",
                                 "rd_length1", "rd_guides0", "rd_guides1"})
            out.push_back({name, false, true});
    if (denoised)
        for (const char* name : {"rd_tile_mask0", "rd_tile_mask1"}) out.push_back({name, true, false});
    if (effect == "hybrid")
        for (const char* name : {"hybrid_feedback0", "hybrid_feedback1"}) out.push_back({name, false, false});
    if (effect == "shadows") {
        for (const char* name : {"shadow_moments0", "shadow_moments1"}) out.push_back({name, false, true});
        for (const char* name : {"shadow_tile_metadata0", "shadow_tile_metadata1"})
            out.push_back({name, true, false});
    }
    return out;
}

struct EffectSet::Running {
    const EffectDescriptor* descriptor = nullptr;
    EffectPlan plan;
    std::unique_ptr<gpu::EffectRunner> runner;
};

EffectSet::EffectSet(const gpu::Context& context, const capture::Frame& first,
                     const capture::Environment& environment, std::vector<std::string> effects,
                     SettingValues settings, const scene::Scene* geometry)
    : context_(context), environment_(environment), names_(std::move(effects)),
      settings_(std::move(settings)) {
    inputs_ = std::make_unique<gpu::InputImages>(context_, Extent2D{first.width, first.height}, false);
    for (const std::string& name : names_) {
        auto running = std::make_unique<Running>();
        running->descriptor = findEffect(name);
        if (!running->descriptor) throw std::invalid_argument("unknown effect " + name);
        for (const InputDesc& input : running->descriptor->inputs)
            if (input.kind == InputKind::SceneGeometry && !scene_) {
                if (!geometry) throw std::invalid_argument(name + " needs the scene's geometry");
                scene_ = std::make_unique<scene::SceneBuffers>(context_, *geometry);
            }
        running_.push_back(std::move(running));
    }
}

EffectSet::~EffectSet() = default;

void EffectSet::poisonEnvironment(std::vector<float> rgba) {
    poisonedEnvironment_ = std::move(rgba);
    environmentPoisoned_ = true;
}

gpu::EffectRunner& EffectSet::runner(const std::string& effect) {
    for (auto& running : running_)
        if (running->descriptor->name == effect && running->runner) return *running->runner;
    throw std::logic_error("no runner for " + effect);
}

bool EffectSet::ran(const std::string& effect) const {
    for (const auto& running : running_)
        if (running->descriptor->name == effect) return running->runner != nullptr;
    return false;
}

std::vector<EffectFrame> EffectSet::run(const capture::Frame& frame, bool cut, bool read) {
    const bool reset = frame_ == 0 || cut;
    const FrameInfo info = replay::frameInfo(frame, environment_, frame_, reset);
    // The inputs, each kind once (effects share them), as the session uploads them.
    std::vector<InputKind> done;
    gpu::TransferBatch batch(context_); // the frame's images in one submission
    const auto uploaded = [&](InputKind kind) {
        for (InputKind k : done)
            if (k == kind) return true;
        return false;
    };
    for (const auto& running : running_)
        for (const InputDesc& input : running->descriptor->inputs) {
            if ((!input.setting.empty() && !settings_.flag(input.setting)) || uploaded(input.kind)) continue;
            done.push_back(input.kind);
            if (input.kind == InputKind::Environment) {
                if (environmentPoisoned_)
                    inputs_->uploadEnvironment(environment_.width, environment_.height, poisonedEnvironment_);
                else if (environmentDirty_)
                    inputs_->uploadEnvironment(environment_.width, environment_.height,
                                               replay::environmentTexels(environment_));
                environmentDirty_ = environmentPoisoned_;
                continue;
            }
            if (input.kind == InputKind::PreviousDepth || input.kind == InputKind::SceneGeometry) continue;
            std::uint32_t channels = 0;
            std::vector<float> texels = replay::inputTexels(frame, input.kind, channels);
            if (hook_) hook_(input.kind, texels, channels);
            inputs_->upload(batch, input.kind, texels, channels);
            if (input.kind == InputKind::Depth) {
                // Last frame's depth as the application copied it (poisoned or not).
                bool wantsPrevious = false;
                for (const auto& r : running_)
                    for (const InputDesc& i : r->descriptor->inputs)
                        wantsPrevious = wantsPrevious || i.kind == InputKind::PreviousDepth;
                if (wantsPrevious) {
                    const bool usable = !reset && previousDepth_.size() == texels.size();
                    inputs_->upload(batch, InputKind::PreviousDepth, usable ? previousDepth_ : texels, 1);
                    previousDepth_ = std::move(texels);
                }
            }
        }
    batch.submit();
    environmentPoisoned_ = false;
    hook_ = nullptr;
    if (scene_) scene_->setFrame(frame.frameIndex);

    std::vector<EffectFrame> results;
    for (auto& running : running_) {
        EffectFrame result;
        result.effect = running->descriptor->name;
        std::string error;
        if (running->descriptor->plan(info, settings_, running->plan, &error) != Result::Ok) {
            result.refused = true;
            result.error = error;
            results.push_back(std::move(result));
            continue;
        }
        if (!running->runner) {
            running->runner = std::make_unique<gpu::EffectRunner>(context_, running->plan, scene::findShader);
            running->runner->initialize();
        }
        vk::ResourceTable table;
        for (const InputDesc& input : running->descriptor->inputs) {
            if (input.kind == InputKind::SceneGeometry && scene_) scene_->addTo(table);
            if (const vk::Image* image = inputs_->find(input.kind)) table.images[input.resource] = image;
        }
        running->runner->run(running->plan, table, read);
        if (read) result.outputs = running->runner->readOutputs(running->plan, false);
        results.push_back(std::move(result));
    }
    ++frame_;
    return results;
}

} // namespace glint::test
