#include "replay/replay_session.h"

#include "core/camera.h"
#include "replay/replay_shadow.h"
#include "replay/replay_sssr.h"

#include <gpu/gpu_plan_runner.h>
#include <gpu/gpu_shadow_runner.h>
#include <gpu/gpu_snapshot.h>
#include <gpu/gpu_sssr_runner.h>
#include <gpu/gpu_transfer.h>

#include "glint/glint_depth_pyramid.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace glint::replay {
namespace {

report::Image makeImage(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                        std::vector<float> pixels) {
    return report::Image{width, height, channels, std::move(pixels)};
}

// The first `keep` channels of an interleaved image with `stride` channels.
report::Image channelsOf(std::uint32_t width, std::uint32_t height, const std::vector<float>& pixels,
                         std::uint32_t stride, std::uint32_t keep, std::uint32_t first = 0) {
    std::vector<float> out(std::size_t{width} * height * keep);
    for (std::size_t i = 0; i < std::size_t{width} * height; ++i)
        for (std::uint32_t c = 0; c < keep; ++c) out[i * keep + c] = pixels[i * stride + first + c];
    return makeImage(width, height, keep, std::move(out));
}

// A capture layer's first `keep` channels, or nothing when the capture lacks it.
std::optional<report::Image> layerImage(const capture::Frame& frame, const std::string& name,
                                        std::uint32_t keep) {
    const capture::Layer* layer = capture::findLayer(frame, name);
    if (!layer) return std::nullopt;
    const auto stride = static_cast<std::uint32_t>(layer->channels.size());
    return channelsOf(frame.width, frame.height, layer->pixels, stride, std::min(keep, stride));
}

void addTimings(FrameResult& result, const std::string& effect, const std::vector<std::string>& passes,
                const std::vector<double>& milliseconds) {
    for (std::size_t i = 0; i < std::min(passes.size(), milliseconds.size()); ++i)
        result.timings.push_back({effect + "/" + passes[i], milliseconds[i]});
}

bool hasLayer(const capture::Frame& frame, const char* name) {
    return capture::findLayer(frame, name) != nullptr;
}

DepthConvention depthOf(const capture::Frame& frame) {
    return frame.camera.depth == capture::DepthConvention::Standard ? DepthConvention::Standard
                                                                    : DepthConvention::Reversed;
}

} // namespace

const NamedImage* FrameResult::find(const std::string& name) const {
    for (const NamedImage& image : images)
        if (image.name == name) return &image;
    return nullptr;
}

const std::vector<std::string>& knownEffects() {
    static const std::vector<std::string> effects{"depth_pyramid", "reflections", "shadows"};
    return effects;
}

std::vector<std::string> effectsToRun(const capture::Frame& frame,
                                      const std::vector<std::string>& requested) {
    const std::vector<std::string>& wanted = requested.empty() ? frame.effects : requested;
    if (wanted.empty())
        throw std::invalid_argument("the capture declares no effects; name them with --effects");
    std::vector<std::string> effects;
    for (const std::string& known : knownEffects()) {
        if (std::find(wanted.begin(), wanted.end(), known) == wanted.end()) continue;
        std::vector<const char*> needs{"depth"};
        if (known == "reflections") needs = {"depth", "normal", "color", "motion"};
        if (known == "shadows") needs = {"depth", "normal", "motion", "shadow"};
        for (const char* layer : needs)
            if (!hasLayer(frame, layer))
                throw std::invalid_argument("effect '" + known + "' needs the capture layer '" + layer +
                                            "', which this capture does not have");
        if (known == "reflections" &&
            (frame.roughness.layer.empty() || !capture::findLayer(frame, frame.roughness.layer)))
            throw std::invalid_argument(
                "effect 'reflections' needs a roughness source, which this capture does not have");
        effects.push_back(known);
    }
    for (const std::string& name : wanted)
        if (std::find(knownEffects().begin(), knownEffects().end(), name) == knownEffects().end())
            throw std::invalid_argument("unknown effect '" + name +
                                        "' (depth_pyramid, reflections, shadows)");
    return effects;
}

// ---- depth pyramid: the closest-depth chain SSSR builds, on its own -------------------------

struct Session::Pyramid {
    const gpu::Context& context;
    DepthPyramidDesc desc;
    EffectPlan plan;
    gpu::PlanResources owned;
    vk::Image depth;
    vk::Executor executor;

    Pyramid(const gpu::Context& c, const capture::Frame& frame) : context(c) {
        desc.size = {frame.width, frame.height};
        desc.depth = depthOf(frame);
        std::string error;
        if (planDepthPyramid(desc, plan, &error) != Result::Ok)
            throw std::invalid_argument("depth_pyramid: " + error);
        owned = gpu::createPlanResources(context, plan);
        depth = vk::createImage2D(context.device, frame.width, frame.height, VK_FORMAT_R32_SFLOAT);
        executor = vk::createExecutor(context.device);
    }
    ~Pyramid() {
        vk::destroyExecutor(executor);
        vk::destroyImage(context.device, depth);
        gpu::destroyPlanResources(context, owned);
    }

    void repeat(FrameResult& result) {
        const gpu::PlanTimings timings =
            gpu::executePlan(context, executor, plan, gpu::resourceTable(owned, {{"depth", &depth}}));
        if (!timings.times.empty())
            addTimings(result, "depth_pyramid", timings.passes, timings.times.front());
    }

    void run(const capture::Frame& frame, bool readback, FrameResult& result) {
        gpu::uploadImage(context, depth, layerChannels(frame, "depth", 1), 1);
        repeat(result);
        if (!readback) return;
        const vk::Image& pyramid = owned.images.at("depth_pyramid");
        for (std::uint32_t level = 0; level < pyramid.mipLevels; ++level) {
            const std::uint32_t w = gpu::mipWidth(pyramid, level), h = gpu::mipHeight(pyramid, level);
            result.images.push_back({"depth_pyramid/mip" + std::to_string(level), "depth_pyramid/build",
                                     makeImage(w, h, 1, gpu::readbackImage(context, pyramid, level))});
        }
    }
};

// ---- reflections: SSSR, then the denoiser and the composite when asked for -------------------

struct Session::Reflections {
    const gpu::Context& context;
    const capture::Environment& environment;
    SssrDesc tunables;
    ReflectionsDenoiserDesc denoiserTunables;
    std::optional<gpu::SssrRunner> runner;
    std::optional<gpu::Snapshot> noisy;

    Reflections(const gpu::Context& c, const capture::Frame& frame, const capture::Environment& env,
                const EffectSettings& settings, bool intermediates, bool readback)
        : context(c), environment(env), tunables(settings.sssr), denoiserTunables(settings.denoiser) {
        if (intermediates) tunables.debugOutput = true;
        SssrDesc desc = describe(frame, nullptr);
        if (desc.composite && !hasLayer(frame, "material"))
            throw std::invalid_argument(
                "reflections: composite needs the capture layer 'material' (base colour)");
        // Without readback (benchmarks) the inputs take the formats an engine would use (16-bit
        // normals, colour, roughness and motion) and no copy of the noisy radiance is taken.
        runner.emplace(context, desc, /*compactInputs=*/!readback);
        if (desc.denoise && readback)
            noisy.emplace(context, frame.width, frame.height,
                          desc.halfPrecisionStorage ? VK_FORMAT_R16G16B16A16_SFLOAT
                                                    : VK_FORMAT_R32G32B32A32_SFLOAT);
    }

    SssrDesc describe(const capture::Frame& frame, gpu::SssrFrameInputs* inputs) const {
        SssrDesc desc;
        gpu::SssrFrameInputs scratch;
        sssrFromFrame(frame, environment, desc, inputs ? *inputs : scratch);
        copySssrTunables(tunables, desc);
        desc.mirrorThreshold = tunables.mirrorThreshold;
        desc.storeRays = desc.denoise && denoiserTunables.spatialPath == SpatialPath::RatioEstimator;
        return desc;
    }

    // The last frame's descs, for repeat().
    SssrDesc last;
    std::optional<ReflectionsDenoiserDesc> lastDenoiser;

    void dispatch(const SssrDesc& desc, const std::optional<ReflectionsDenoiserDesc>& denoiser,
                  FrameResult& result) {
        const std::vector<std::string> passes =
            runner->passNames(desc, desc.denoise, denoiser ? denoiser->spatialPath : SpatialPath::Prefilter);
        const std::size_t intersect =
            static_cast<std::size_t>(std::find(passes.begin(), passes.end(), "intersect") - passes.begin());
        vk::PassHooks hooks;
        hooks.afterDispatch = [&](VkCommandBuffer cmd, std::size_t pass) {
            if (noisy && pass == intersect) noisy->record(cmd, runner->ownedImage("sssr_radiance"));
        };
        std::vector<double> timings;
        runner->run(desc, &timings, denoiser ? &*denoiser : nullptr, &hooks);
        addTimings(result, "reflections", passes, timings);
        const std::array<std::uint32_t, 4> counters = runner->counters();
        const double pixels = static_cast<double>(desc.size.width) * desc.size.height;
        result.counters.push_back({"reflections/traced_pixels", static_cast<double>(counters[1])});
        result.counters.push_back({"reflections/traced_fraction", counters[1] / pixels});
        result.counters.push_back({"reflections/listed_tiles", static_cast<double>(counters[3])});
    }

    // The last frame again as frame `index`, with the inputs already on the GPU (benchmarks).
    void repeat(std::uint32_t index, FrameResult& result) {
        last.frameIndex = index;
        if (lastDenoiser) {
            lastDenoiser->frameIndex = index;
            lastDenoiser->resetHistory = false;
            lastDenoiser->previousClipFromWorld = core::multiply(last.projection, last.viewFromWorld);
        }
        dispatch(last, lastDenoiser, result);
    }

    void run(const capture::Frame& frame, std::uint32_t index, bool reset, const SessionOptions& options,
             FrameResult& result) {
        gpu::SssrFrameInputs inputs;
        SssrDesc desc = describe(frame, &inputs);
        desc.frameIndex = index;
        if (index > 0) inputs.environment.clear(); // uploaded with the first frame's mips
        runner->upload(inputs);
        std::optional<ReflectionsDenoiserDesc> denoiser;
        if (desc.denoise) {
            denoiser = denoiserFromFrame(frame, desc, index, reset);
            copyDenoiserTunables(denoiserTunables, *denoiser);
        }
        last = desc;
        lastDenoiser = denoiser;
        dispatch(desc, denoiser, result);
        if (!options.readback) return;
        const gpu::SssrFrameOutputs out = runner->readback();
        const std::uint32_t w = frame.width, h = frame.height;
        auto add = [&](const std::string& name, const std::string& pass, report::Image image) {
            result.images.push_back({"reflections/" + name, "reflections/" + pass, std::move(image)});
        };
        add("input", "input", *layerImage(frame, "color", 3));
        // The denoiser pass that writes the output last.
        const char* denoisedBy =
            denoiser && denoiser->spatialPath == SpatialPath::RatioEstimator ? "cleanup" : "resolve";
        if (noisy) {
            add("noisy", "intersect", channelsOf(w, h, gpu::readbackImage(context, noisy->image), 4, 3));
            add("denoised", denoisedBy, channelsOf(w, h, out.radiance, 4, 3));
        } else {
            add("noisy", "intersect", channelsOf(w, h, out.radiance, 4, 3));
        }
        if (!out.composite.empty()) add("composite", "composite", channelsOf(w, h, out.composite, 4, 3));
        add("confidence", "intersect", makeImage(w, h, 1, out.confidence));
        if (auto reference = layerImage(frame, "reference.reflection", 3))
            add("reference", "input", *reference);
        if (!options.intermediates) return;

        add("hit_distance", noisy ? denoisedBy : "intersect", channelsOf(w, h, out.radiance, 4, 1, 3));
        add("roughness", "classify", makeImage(w, h, 1, out.roughness));
        std::vector<float> rays(std::size_t{w} * h, 0.0f), tiles(std::size_t{w} * h, 0.0f);
        for (std::uint32_t entry : out.rayList) {
            const std::size_t x = entry & 0x7FFFu, y = (entry >> 15) & 0x3FFFu;
            if (x < w && y < h) rays[y * w + x] = 1.0f;
        }
        for (std::uint32_t tile : out.tileList) {
            const std::uint32_t x0 = tile & 0xFFFFu, y0 = tile >> 16;
            for (std::uint32_t y = y0; y < std::min(h, y0 + 8); ++y)
                for (std::uint32_t x = x0; x < std::min(w, x0 + 8); ++x) tiles[std::size_t{y} * w + x] = 1.0f;
        }
        add("ray_list", "classify", makeImage(w, h, 1, std::move(rays)));
        add("tile_list", "classify", makeImage(w, h, 1, std::move(tiles)));
        if (!out.rayInfo.empty()) {
            add("ray_class", "intersect", channelsOf(w, h, out.rayInfo, 4, 1, 2));
            add("iterations", "intersect", channelsOf(w, h, out.rayInfo, 4, 1, 3));
        }
        if (denoiser)
            add("variance", "resolve",
                makeImage(
                    w, h, 1,
                    gpu::readbackImage(context, runner->ownedImage(reflectionsDenoiserVariance(index)))));
        const vk::Image& pyramid = runner->ownedImage("depth_pyramid");
        for (std::uint32_t level = 1; level < pyramid.mipLevels; ++level) {
            const std::vector<float> texels = gpu::readbackImage(context, pyramid, level);
            const std::uint32_t pw = gpu::mipWidth(pyramid, level), ph = gpu::mipHeight(pyramid, level);
            const auto stride = static_cast<std::uint32_t>(texels.size() / (std::size_t{pw} * ph));
            add("pyramid_mip" + std::to_string(level), "depth_pyramid",
                channelsOf(pw, ph, texels, stride, 1));
        }
    }
};

// ---- shadows: prepare, classification, three a-trous passes --------------------------------

struct Session::Shadows {
    const gpu::Context& context;
    ShadowDenoiserDesc tunables;
    std::optional<gpu::ShadowRunner> runner;
    std::vector<float> previousDepth;

    Shadows(const gpu::Context& c, const capture::Frame& frame, const EffectSettings& settings, bool readback)
        : context(c), tunables(settings.shadows) {
        if (!tunables.classify)
            throw std::invalid_argument(
                "shadows: replay needs shadows.classify=true (the filter alone reads a "
                "(mean, variance) image a capture does not carry)");
        ShadowDenoiserDesc desc = tunables;
        shadowDescFromFrame(frame, 0, true, desc);
        // Without readback (benchmarks) the inputs take the formats an engine would bind.
        runner.emplace(context, desc, /*compactInputs=*/!readback);
    }

    ShadowDenoiserDesc last; // for repeat()

    gpu::ShadowOutputs dispatch(const ShadowDenoiserDesc& desc, const gpu::ShadowInputs& inputs,
                                bool readback, FrameResult& result) {
        gpu::PlanTimings timings;
        gpu::ShadowOutputs out = runner->run(desc, inputs, &timings, readback);
        if (!timings.times.empty()) addTimings(result, "shadows", timings.passes, timings.times.front());
        if (desc.filter && desc.skipClearedTiles)
            result.counters.push_back({"shadows/filtered_tiles", static_cast<double>(out.filteredTiles)});
        return out;
    }

    // The last frame again as frame `index` with the inputs already on the GPU: its depth
    // doubles as the previous depth, a static camera (benchmarks).
    void repeat(std::uint32_t index, FrameResult& result) {
        last.frameIndex = index;
        last.resetHistory = false;
        last.reprojection = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        dispatch(last, gpu::ShadowInputs{}, false, result);
    }

    void run(const capture::Frame& frame, std::uint32_t index, bool reset, const SessionOptions& options,
             FrameResult& result) {
        ShadowDenoiserDesc desc = tunables;
        shadowDescFromFrame(frame, index, reset, desc);
        const gpu::ShadowInputs inputs =
            shadowInputsFromFrame(frame, reset ? std::vector<float>{} : previousDepth);
        last = desc;
        const gpu::ShadowOutputs out = dispatch(desc, inputs, options.readback, result);
        previousDepth = inputs.depth;
        if (!options.readback) return;
        const std::uint32_t w = frame.width, h = frame.height;
        auto add = [&](const std::string& name, const std::string& pass, report::Image image) {
            result.images.push_back({"shadows/" + name, "shadows/" + pass, std::move(image)});
        };
        add("noisy", "input", makeImage(w, h, 1, inputs.visibility));
        const std::vector<float>& final = desc.filter ? out.filtered : out.classified;
        const std::string pass = !desc.filter ? "classify" : desc.fusedFilter ? "filter" : "filter2";
        add("denoised", pass, channelsOf(w, h, final, 2, 1));
        // One-channel output formats carry no variance (ShadowOutputs::filtered).
        if (!desc.filter || desc.outputFormat == Format::RG32Float)
            add("variance", pass, channelsOf(w, h, final, 2, 1, 1));
        if (auto reference = layerImage(frame, "reference.shadow", 1)) add("reference", "input", *reference);
        if (!options.intermediates) return;

        const Extent2D words = shadowMaskTiles(desc.size);
        std::vector<float> mask(std::size_t{w} * h, 0.0f), classes(std::size_t{w} * h, 0.0f);
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                const std::uint32_t word = out.mask.at(std::size_t{y / 4} * words.width + x / 8);
                mask[std::size_t{y} * w + x] = static_cast<float>((word >> ((y % 4) * 8 + x % 8)) & 1u);
                const std::uint32_t tilesX = (w + 7) / 8;
                const std::uint32_t meta = out.metadata.at(std::size_t{y / 8} * tilesX + x / 8);
                classes[std::size_t{y} * w + x] = static_cast<float>(meta & 3u);
            }
        add("mask", "prepare", makeImage(w, h, 1, std::move(mask)));
        add("tile_class", "classify", makeImage(w, h, 1, std::move(classes)));
        add("moments", "classify", channelsOf(w, h, out.moments, 4, 3));
    }
};

Session::Session(const gpu::Context& context, const capture::Frame& first,
                 const capture::Environment& environment, SessionOptions options)
    : context_(context), options_(std::move(options)), width_(first.width), height_(first.height) {
    effects_ = effectsToRun(first, options_.effects);
    for (const std::string& effect : effects_) {
        if (effect == "depth_pyramid") pyramid_ = std::make_unique<Pyramid>(context_, first);
        if (effect == "reflections")
            reflections_ = std::make_unique<Reflections>(context_, first, environment, options_.settings,
                                                         options_.intermediates, options_.readback);
        if (effect == "shadows")
            shadows_ = std::make_unique<Shadows>(context_, first, options_.settings, options_.readback);
    }
}

Session::~Session() = default;

FrameResult Session::repeat() {
    if (frame_ == 0) throw std::logic_error("replay: repeat() needs a frame run first");
    FrameResult result;
    if (pyramid_) pyramid_->repeat(result);
    if (reflections_) reflections_->repeat(frame_, result);
    if (shadows_) shadows_->repeat(frame_, result);
    ++frame_;
    return result;
}

FrameResult Session::run(const capture::Frame& frame, bool cut) {
    if (frame.width != width_ || frame.height != height_)
        throw std::invalid_argument("frame " + std::to_string(frame.frameIndex) + " is " +
                                    std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                    ", the sequence started at " + std::to_string(width_) + "x" +
                                    std::to_string(height_));
    effectsToRun(frame, effects_); // every frame must still feed every effect
    FrameResult result;
    const bool reset = frame_ == 0 || cut;
    if (pyramid_) pyramid_->run(frame, options_.readback, result);
    if (reflections_) reflections_->run(frame, frame_, reset, options_, result);
    if (shadows_) shadows_->run(frame, frame_, reset, options_, result);
    ++frame_;
    return result;
}

} // namespace glint::replay
