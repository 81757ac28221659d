#include "replay/replay_session.h"

#include "replay/replay_frame.h"

#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_sustained.h>
#include <gpu/gpu_transfer.h>
#include <scene/scene_buffers.h>
#include <scene/scene_file.h>
#include <scene/scene_shaders.h>

#include <algorithm>
#include <stdexcept>

namespace glint::replay {
namespace {

bool hasLayer(const capture::Frame& frame, const std::string& name) {
    return !name.empty() && capture::findLayer(frame, name) != nullptr;
}

// A capture layer's first `keep` channels, or nothing when the capture lacks it.
std::optional<report::Image> layerImage(const capture::Frame& frame, const std::string& name,
                                        std::uint32_t keep) {
    const capture::Layer* layer = capture::findLayer(frame, name);
    if (!layer) return std::nullopt;
    const auto stride = static_cast<std::uint32_t>(layer->channels.size());
    const std::uint32_t channels = std::min(keep, stride);
    return report::Image{frame.width, frame.height, channels, layerChannels(frame, name, channels)};
}

bool inputUsed(const InputDesc& input, const SettingValues& settings) {
    return input.setting.empty() || settings.flag(input.setting);
}

std::string joinedEffectNames() {
    std::string names;
    for (const EffectDescriptor* effect : effectRegistry())
        names += (names.empty() ? "" : ", ") + effect->name;
    return names;
}

EffectPlan planOrThrow(const EffectDescriptor& descriptor, const FrameInfo& info,
                       const SettingValues& settings) {
    EffectPlan plan;
    std::string error;
    if (descriptor.plan(info, settings, plan, &error) != Result::Ok) throw std::invalid_argument(error);
    return plan;
}

} // namespace

struct Session::Running {
    const EffectDescriptor* descriptor = nullptr;
    // The session's settings, plus the effect's own debug setting when intermediates are kept:
    // effects share setting names (the hybrid refuses the reflections' debugOutput), so one
    // effect's debug switch must not reach another's plan.
    SettingValues settings;
    EffectPlan plan;
    std::unique_ptr<gpu::EffectRunner> runner;
};

const NamedImage* FrameResult::find(const std::string& name) const {
    for (const NamedImage& image : images)
        if (image.name == name) return &image;
    return nullptr;
}

std::vector<std::string> knownEffects() {
    std::vector<std::string> names;
    for (const EffectDescriptor* effect : effectRegistry()) names.push_back(effect->name);
    return names;
}

std::optional<MissingLayer> missingLayer(const capture::Frame& frame, const std::vector<std::string>& effects,
                                         const SettingValues& settings) {
    for (const EffectDescriptor* effect : effectRegistry()) {
        if (std::find(effects.begin(), effects.end(), effect->name) == effects.end()) continue;
        for (const InputDesc& input : effect->inputs) {
            if (!inputUsed(input, settings) || input.kind == InputKind::Environment ||
                input.kind == InputKind::PreviousDepth || input.kind == InputKind::SceneGeometry ||
                input.kind == InputKind::SceneAccelerationStructure ||
                input.kind == InputKind::ShadowBlockerDistance) // optional (inputTexels)
                continue;
            const std::string layer = inputLayer(frame, input.kind);
            if (input.kind == InputKind::Material && !hasLayer(frame, layer))
                return MissingLayer{effect->name, "", input.setting};
            if (!hasLayer(frame, layer)) return MissingLayer{effect->name, layer, input.setting};
        }
    }
    return std::nullopt;
}

std::string missingLayerMessage(const MissingLayer& missing) {
    if (missing.layer.empty())
        return "effect '" + missing.effect + "' needs a roughness source, which this capture does not have";
    return "effect '" + missing.effect + "' needs the capture layer '" + missing.layer + "'" +
           (missing.setting.empty() ? "" : " (for " + missing.setting + ")") +
           ", which this capture does not have";
}

std::vector<std::string> effectsToRun(const capture::Frame& frame, const std::vector<std::string>& requested,
                                      const SettingValues& settings) {
    const std::vector<std::string>& wanted = requested.empty() ? frame.effects : requested;
    if (wanted.empty())
        throw std::invalid_argument("the capture declares no effects; name them with --effects");
    for (const std::string& name : wanted)
        if (!findEffect(name))
            throw std::invalid_argument("unknown effect '" + name + "' (" + joinedEffectNames() + ")");
    if (const std::optional<MissingLayer> missing = missingLayer(frame, wanted, settings))
        throw std::invalid_argument(missingLayerMessage(*missing));
    std::vector<std::string> effects;
    for (const EffectDescriptor* effect : effectRegistry())
        if (std::find(wanted.begin(), wanted.end(), effect->name) != wanted.end())
            effects.push_back(effect->name);
    return effects;
}

Session::Session(const gpu::Context& context, const capture::Frame& first,
                 const capture::Environment& environment, SessionOptions options)
    : context_(context), environment_(environment), options_(std::move(options)), width_(first.width),
      height_(first.height) {
    effects_ = effectsToRun(first, options_.effects, options_.settings);
    // Without readback (benchmarks) the inputs take the formats an engine would bind.
    inputs_ =
        std::make_unique<gpu::InputImages>(context_, Extent2D{first.width, first.height}, !options_.readback);
    const FrameInfo info = frameInfo(first, environment_, 0, true);
    // One scene serves every effect; it carries an acceleration structure when one of them
    // traces with RayQuery.
    bool acceleration = false;
    for (const std::string& name : effects_)
        for (const InputDesc& input : findEffect(name)->inputs)
            acceleration |=
                input.kind == InputKind::SceneAccelerationStructure && inputUsed(input, options_.settings);
    for (const std::string& name : effects_) {
        auto running = std::make_unique<Running>();
        running->descriptor = findEffect(name);
        for (const InputDesc& input : running->descriptor->inputs)
            if (input.kind == InputKind::SceneGeometry && !scene_) {
                if (options_.geometry)
                    scene_ =
                        std::make_unique<scene::SceneBuffers>(context_, *options_.geometry, acceleration);
                else if (options_.scene.empty())
                    throw std::invalid_argument(
                        "effect '" + name +
                        "' ray traces the scene's geometry, which this capture does not name: give it with "
                        "--geometry FILE (a glTF of the scene in the capture's world space), or replay a "
                        "capture written by glint simulate (its manifest records the scene file)");
                else
                    scene_ = std::make_unique<scene::SceneBuffers>(context_, scene::loadScene(options_.scene),
                                                                   acceleration);
            }
        running->settings = options_.settings;
        if (options_.intermediates && !running->descriptor->debugSetting.empty())
            running->settings.set(running->descriptor->debugSetting, 1.0);
        running->plan = planOrThrow(*running->descriptor, info, running->settings);
        // The harness's modules for the application's passes (the hybrid effect's ray tracing).
        running->runner = std::make_unique<gpu::EffectRunner>(context_, running->plan, scene::findShader);
        running_.push_back(std::move(running));
    }
}

Session::~Session() = default;

void Session::uploadInputs(const capture::Frame& frame, bool reset) {
    uploaded_.clear();
    gpu::TransferBatch batch(context_); // the frame's images in one submission
    for (const auto& running : running_)
        for (const InputDesc& input : running->descriptor->inputs) {
            if (!inputUsed(input, running->settings) || uploaded_.contains(input.kind)) continue;
            if (input.kind == InputKind::Environment) {
                if (frame_ == 0) // the same map for the whole sequence
                    inputs_->uploadEnvironment(environment_.width, environment_.height,
                                               environmentTexels(environment_));
                uploaded_[input.kind] = {};
                continue;
            }
            if (input.kind == InputKind::PreviousDepth) continue; // after this frame's depth
            if (input.kind == InputKind::SceneGeometry || input.kind == InputKind::SceneAccelerationStructure)
                continue; // buffers and structures, set per frame in run()
            std::uint32_t channels = 0;
            std::vector<float> texels = inputTexels(frame, input.kind, channels);
            inputs_->upload(batch, input.kind, texels, channels);
            uploaded_[input.kind] = std::move(texels);
        }
    for (const auto& running : running_)
        for (const InputDesc& input : running->descriptor->inputs)
            if (input.kind == InputKind::PreviousDepth && !uploaded_.contains(input.kind)) {
                std::uint32_t channels = 1;
                std::vector<float> depth = inputTexels(frame, InputKind::Depth, channels);
                const bool usable = !reset && previousDepth_.size() == depth.size();
                inputs_->upload(batch, InputKind::PreviousDepth, usable ? previousDepth_ : depth, 1);
                previousDepth_ = std::move(depth);
                uploaded_[input.kind] = {};
            }
    batch.submit();
}

namespace {

// The application's images (and the scene, for effects that ray trace) by the effect's names.
vk::ResourceTable inputsOf(const Session::Running& effect, const gpu::InputImages& images,
                           const scene::SceneBuffers* scene) {
    vk::ResourceTable inputs;
    for (const InputDesc& input : effect.descriptor->inputs) {
        if (input.kind == InputKind::SceneGeometry && scene) scene->addTo(inputs);
        if (const vk::Image* image = images.find(input.kind)) inputs.images[input.resource] = image;
    }
    return inputs;
}

} // namespace

void Session::dispatch(Running& effect, const FrameInfo& info, FrameResult& result) {
    effect.plan = planOrThrow(*effect.descriptor, info, effect.settings);
    const vk::ResourceTable inputs = inputsOf(effect, *inputs_, scene_.get());
    const std::string& name = effect.descriptor->name;
    const gpu::FrameRun run = effect.runner->run(effect.plan, inputs, options_.readback);
    for (std::size_t i = 0; i < std::min(run.passes.size(), run.milliseconds.size()); ++i)
        result.timings.push_back({name + "/" + run.passes[i], run.milliseconds[i]});
    for (const auto& [counter, value] : effect.runner->readCounters(effect.plan))
        result.counters.push_back({name + "/" + counter, value});
}

FrameResult Session::repeat() {
    if (frame_ == 0) throw std::logic_error("replay: repeat() needs a frame run first");
    FrameResult result;
    const FrameInfo info = nextRepeat();
    for (const auto& running : running_) dispatch(*running, info, result);
    return result;
}

FrameInfo Session::nextRepeat() {
    FrameInfo info = last_;
    info.frameIndex = options_.firstFrameIndex + frame_;
    info.resetHistory = false;
    holdCamera(info);
    last_ = info;
    ++frame_;
    return info;
}

SustainedResult Session::repeatSustained(std::uint32_t framesPerBuffer, std::uint32_t submissions) {
    if (frame_ == 0) throw std::logic_error("replay: repeatSustained() needs a frame run first");
    SustainedResult result;
    std::vector<FrameResult>& results = result.frames;
    if (!context_.device.timestamps) {
        for (std::uint32_t run = 0; run < framesPerBuffer * submissions; ++run) results.push_back(repeat());
        return result;
    }
    // Pass names of one frame, effect by effect, in recording order; the plans of the last run
    // say how many there are.
    std::vector<std::string> names;
    for (const auto& running : running_)
        for (const std::string& pass : gpu::passNames(running->plan))
            names.push_back(running->descriptor->name + "/" + pass);
    for (const auto& running : running_) running->runner->beginFrames();
    const auto recordFrame = [&](VkCommandBuffer cmd, gpu::TimestampPool& timestamps, std::uint32_t) {
        const FrameInfo info = nextRepeat();
        for (const auto& running : running_) {
            running->plan = planOrThrow(*running->descriptor, info, running->settings);
            running->runner->record(cmd, running->plan, inputsOf(*running, *inputs_, scene_.get()),
                                    &timestamps);
        }
    };
    const gpu::SustainedTimes times = gpu::timeSustained(
        context_, framesPerBuffer, submissions, static_cast<std::uint32_t>(2 * names.size()), recordFrame);
    result.wallMilliseconds = times.wallMilliseconds;
    for (const std::vector<double>& frame : times.frames) {
        FrameResult& measured = results.emplace_back();
        for (std::size_t pass = 0; pass < names.size(); ++pass)
            measured.timings.push_back({names[pass], frame[pass]});
    }
    for (const auto& running : running_)
        for (const auto& [counter, value] : running->runner->readCounters(running->plan))
            results.back().counters.push_back({running->descriptor->name + "/" + counter, value});
    return result;
}

FrameResult Session::run(const capture::Frame& frame, bool cut) {
    if (frame.width != width_ || frame.height != height_)
        throw std::invalid_argument("frame " + std::to_string(frame.frameIndex) + " is " +
                                    std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                    ", the sequence started at " + std::to_string(width_) + "x" +
                                    std::to_string(height_));
    effectsToRun(frame, effects_, options_.settings); // every frame must still feed every effect
    FrameResult result;
    const bool reset = frame_ == 0 || cut;
    const FrameInfo info = frameInfo(frame, environment_, options_.firstFrameIndex + frame_, reset);
    uploadInputs(frame, reset);
    if (scene_) scene_->setFrame(frame.frameIndex); // the previous frame's work has finished
    for (const auto& running : running_) {
        try {
            dispatch(*running, info, result);
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument("frame " + std::to_string(frame.frameIndex) + ": " + error.what());
        }
        if (options_.readback) readImages(*running, frame, options_.readbackFilter, result);
    }
    last_ = info;
    ++frame_;
    return result;
}

void Session::readImages(const Running& running, const capture::Frame& frame,
                         const std::function<bool(const std::string&)>& wanted, FrameResult& result) const {
    const EffectDescriptor& descriptor = *running.descriptor;
    const std::string& name = descriptor.name;
    const auto shown = [&](const std::string& image) { return !wanted || wanted(image); };
    for (const InputDesc& input : descriptor.inputs) {
        if (input.shownAs.empty() || !uploaded_.contains(input.kind)) continue;
        if (!shown(name + "/" + input.shownAs)) continue;
        if (auto image = layerImage(frame, inputLayer(frame, input.kind), 3))
            result.images.push_back({name + "/" + input.shownAs, name + "/input", *image});
    }
    // Final outputs first, then (for dump) the inputs and the intermediates.
    std::vector<gpu::DecodedOutput> outputs =
        running.runner->readOutputs(running.plan, options_.intermediates,
                                    [&](const std::string& output) { return shown(name + "/" + output); });
    const auto add = [&](gpu::DecodedOutput& out) {
        result.images.push_back({name + "/" + out.name, name + "/" + out.pass,
                                 report::Image{out.width, out.height, out.channels, std::move(out.pixels)}});
    };
    for (gpu::DecodedOutput& out : outputs)
        if (!out.intermediate) add(out);
    if (!descriptor.reference.empty() && shown(name + "/reference"))
        if (auto reference = layerImage(frame, "reference." + descriptor.reference, 3))
            result.images.push_back({name + "/reference", name + "/input", *reference});
    if (!options_.intermediates) return;
    // The inputs as the effect read them (decoded normals, motion in convention A, roughness in
    // channel 0), so an import can be checked against what the capture meant.
    for (const InputDesc& input : descriptor.inputs) {
        const vk::Image* image = input.kind == InputKind::Environment ? nullptr : inputs_->find(input.kind);
        // Named by what it holds: the material input carries roughness (channel 0) alone.
        const std::string imageName =
            name + "/" +
            (input.kind == InputKind::Material ? std::string("input_roughness") : "input_" + input.resource);
        if (!image || !shown(imageName)) continue;
        std::vector<float> texels = gpu::readbackImage(context_, *image);
        const auto channels = static_cast<std::uint32_t>(texels.size() / (std::size_t{width_} * height_));
        result.images.push_back(
            {imageName, name + "/input", report::Image{width_, height_, channels, std::move(texels)}});
    }
    for (gpu::DecodedOutput& out : outputs)
        if (out.intermediate) add(out);
}

FrameResult Session::read(const capture::Frame& frame,
                          const std::function<bool(const std::string&)>& wanted) const {
    if (frame_ == 0) throw std::logic_error("replay: read() needs a frame run first");
    if (!options_.readback) throw std::logic_error("replay: read() needs a session with readback");
    FrameResult result;
    for (const auto& running : running_) readImages(*running, frame, wanted, result);
    return result;
}

bool Session::changeSettings(const SettingValues& settings) {
    for (const auto& running : running_)
        for (const std::string& fixed : running->descriptor->resourceSettings)
            if (settings.has(fixed) && running->settings.has(fixed) &&
                settings.real(fixed) != running->settings.real(fixed) &&
                fixed != running->descriptor->debugSetting)
                return false;
    options_.settings = settings;
    for (const auto& running : running_) {
        running->settings = settings;
        if (options_.intermediates && !running->descriptor->debugSetting.empty())
            running->settings.set(running->descriptor->debugSetting, 1.0);
    }
    return true;
}

} // namespace glint::replay
