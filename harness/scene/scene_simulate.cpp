#include "scene/scene_simulate.h"

#include "scene/scene_buffers.h"
#include "scene/scene_bvh.h"
#include "scene/scene_environment.h"
#include "scene/scene_geometry.h"
#include "scene/scene_shaders.h"

#include "capture/enum_names.h"
#include "capture/motion_convention.h"

#include <gpu/gpu_plan_runner.h>
#include <gpu/gpu_transfer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <sstream>

namespace glint::scene {
namespace {

using shaders::GLINT_SceneConstants;

// tan of the shadow light's angular radius for the denoiser's penumbra estimate
// (glint.shadowLightTanHalfAngle): a directional light's own (0 included: hard shadows); a
// sphere light's as seen from the eye, its blocker layer scaled to it; -1 (unknown) with the eye
// inside a sphere light.
double shadowLightTan(const LightDesc& light, const Vec3& eye) {
    if (light.kind == LightKind::Directional)
        return light.angularRadiusDegrees >= 0.0f
                   ? std::tan(static_cast<double>(light.angularRadiusDegrees) * std::numbers::pi / 180.0)
                   : -1.0;
    double squared = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double d = double(light.position[k]) - double(eye[k]);
        squared += d * d;
    }
    const double distance = std::sqrt(squared), radius = double(light.radius);
    return distance > radius * 1.0001 && radius > 0.0
               ? radius / std::sqrt(distance * distance - radius * radius)
               : -1.0;
}

struct OutputImage {
    const char* resource; // plan resource name
    const char* layer;    // capture layer
    Format format;
    std::vector<std::string> channels;
};

// A matrix as the four float4 rows the shader constants hold (scene_constants.h).
void storeRows(shaders::float4 (&rows)[4], const capture::Mat4& m) {
    for (std::size_t r = 0; r < 4; ++r)
        rows[r] = {static_cast<float>(m.m[r * 4 + 0]), static_cast<float>(m.m[r * 4 + 1]),
                   static_cast<float>(m.m[r * 4 + 2]), static_cast<float>(m.m[r * 4 + 3])};
}

std::vector<std::byte> pack(const GLINT_SceneConstants& constants) {
    std::vector<std::byte> bytes(sizeof constants);
    std::memcpy(bytes.data(), &constants, sizeof constants);
    return bytes;
}

Pass makePass(const char* name, const char* pipeline, std::vector<ResourceUse> uses,
              const GLINT_SceneConstants& constants, std::uint32_t width, std::uint32_t height) {
    Pass pass;
    pass.name = name;
    pass.pipeline = pipeline;
    pass.uses = std::move(uses);
    pass.constantsBinding = "g_scene";
    pass.constants = pack(constants);
    pass.dispatch = DirectDispatch{(width + 7) / 8, (height + 7) / 8, 1};
    return pass;
}

ResourceUse read(const char* binding) {
    return {binding, binding, Access::Read};
}
ResourceUse write(const char* binding, const char* resource) {
    return {binding, resource, Access::Write};
}

// Samples per reference dispatch. llvmpipe stops any invocation after 65535 loop iterations
// in all, which silently truncated the references at 64 spp and more (every ray's BVH walk is
// a loop). Chunks keep each invocation far below that; the shaders accumulate across chunks.
// A reflection sample traces 2 + lights rays: a chunk traces at most 64 of them.
std::uint32_t reflectionChunk(const Scene& scene) {
    return std::clamp<std::uint32_t>(64u / (2u + static_cast<std::uint32_t>(scene.lights.size())), 1u, 16u);
}
constexpr std::uint32_t kShadowChunk = 16;

// A reference pass as dispatches "name", "name#2", ... of at most `chunk` samples, covering
// [0, baseline) and then [baseline, total): each reads and updates the accumulating images,
// which also hold the samples of the run's earlier frames (sampleBase); their times add up
// under "name".
void addChunkedPasses(EffectPlan& plan, const char* name, const char* pipeline, std::vector<ResourceUse> uses,
                      GLINT_SceneConstants constants, std::uint32_t baseline, std::uint32_t total,
                      std::uint32_t chunk, std::uint32_t width, std::uint32_t height) {
    constants.sampleTotal = total;
    std::uint32_t count = 0;
    for (std::uint32_t start = 0; start < total; ++count) {
        const std::uint32_t end =
            start < baseline ? std::min(start + chunk, baseline) : std::min(start + chunk, total);
        constants.sampleStart = start;
        constants.samples = end - start;
        Pass pass = makePass(name, pipeline, uses, constants, width, height);
        if (count > 0) pass.name.append("#").append(std::to_string(count + 1));
        plan.passes.push_back(std::move(pass));
        start = end;
    }
}

template <typename T> void appendBytes(std::string& out, const T* values, std::size_t count) {
    out.append(reinterpret_cast<const char*>(values), sizeof(T) * count);
}

// Everything a frame's references depend on besides the frame's index, as bytes: the camera,
// the geometry as traced and the lights (not the objects' motion since the previous frame,
// which only the motion layer reads). Frames with the same state have references of the same
// mean, so the references accumulate over them.
std::string frameState(const capture::Mat4& viewProjection, const std::array<float, 3>& eye, const Bvh& bvh,
                       const std::vector<shaders::SceneLight>& lights) {
    std::string state;
    appendBytes(state, viewProjection.m.data(), viewProjection.m.size());
    appendBytes(state, eye.data(), eye.size());
    appendBytes(state, bvh.nodes.data(), bvh.nodes.size());
    appendBytes(state, bvh.primitives.data(), bvh.primitives.size());
    appendBytes(state, lights.data(), lights.size());
    return state;
}

// The passes of one frame and the images they write. Which passes exist depends only on
// the declared effects and reference settings, never on the frame.
EffectPlan planFrame(const Scene& scene, const GLINT_SceneConstants& base,
                     std::vector<OutputImage>& outputs) {
    const bool reflections = needsReflections(scene);
    const bool shadows = needsShadows(scene);
    const std::uint32_t w = scene.width, h = scene.height;
    EffectPlan plan;
    plan.effect = "scene";
    outputs = {{"depth", "depth", Format::R32Float, {"Z"}},
               {"normal", "normal", Format::RGBA32Float, {"X", "Y", "Z"}},
               {"motion", "motion", Format::RG32Float, {"X", "Y"}}};
    std::vector<ResourceUse> gbuffer = {read("g_scene_nodes"),       read("g_scene_primitives"),
                                        read("g_scene_objects"),     write("g_depth", "depth"),
                                        write("g_normal", "normal"), write("g_motion", "motion")};
    if (reflections) {
        gbuffer.push_back(read("g_scene_materials"));
        gbuffer.push_back(write("g_roughness", "roughness"));
        gbuffer.push_back(write("g_material", "material"));
        outputs.push_back({"roughness", "roughness", Format::R32Float, {"Y"}});
        outputs.push_back({"material", "material", Format::RGBA32Float, {"R", "G", "B", "A"}});
    }
    plan.passes.push_back(
        makePass("gbuffer", reflections ? "scene_gbuffer.material" : "scene_gbuffer", gbuffer, base, w, h));
    const std::vector<ResourceUse> shading = {read("g_scene_nodes"), read("g_scene_primitives"),
                                              read("g_scene_materials"), read("g_scene_lights"),
                                              read("g_scene_environment")};
    if (reflections) {
        std::vector<ResourceUse> uses = shading;
        uses.push_back(write("g_color", "color"));
        plan.passes.push_back(makePass("shade", "scene_shade", uses, base, w, h));
        outputs.push_back({"color", "color", Format::RGBA32Float, {"R", "G", "B"}});
        if (scene.reference.reflections) {
            GLINT_SceneConstants c = base;
            c.passSalt = 0x52454631u;
            uses = shading;
            uses.push_back(read("g_scene_environment_sampling"));
            uses.push_back(write("g_reflection", "reference.reflection"));
            uses.push_back({"g_reflection_sum", "reference.reflection_sum", Access::ReadWrite});
            uses.push_back({"g_reflection_moments", "reference.reflection_moments", Access::ReadWrite});
            uses.push_back({"g_roughness", "roughness", Access::Read});
            c.referenceFrameSamples = scene.reference.samplesPerPixel;
            c.referenceNoiseTarget = scene.reference.noiseTarget;
            // 1 means every pixel, alpha 1 included.
            c.referenceNoiseAlphaBelow =
                scene.reference.noiseTargetAlphaBelow >= 1.0f ? 2.0f : scene.reference.noiseTargetAlphaBelow;
            addChunkedPasses(plan, "reference.reflection", "scene_reflection", uses, c,
                             scene.reference.samplesPerPixel, maxReferenceSamples(scene.reference),
                             reflectionChunk(scene), w, h);
            outputs.push_back(
                {"reference.reflection", "reference.reflection", Format::RGBA32Float, {"R", "G", "B"}});
        }
    }
    if (shadows) {
        const std::vector<ResourceUse> common = {read("g_scene_nodes"), read("g_scene_primitives"),
                                                 read("g_scene_lights")};
        GLINT_SceneConstants c = base;
        c.samples = 1;
        c.passSalt = 0x53484431u;
        std::vector<ResourceUse> uses = common;
        uses.push_back(write("g_visibility", "shadow"));
        uses.push_back(write("g_blocker", "shadow_blocker"));
        plan.passes.push_back(makePass("shadow", "scene_shadow.blocker", uses, c, w, h));
        outputs.push_back({"shadow", "shadow", Format::R32Float, {"Y"}});
        outputs.push_back({"shadow_blocker", "shadow_blocker", Format::R32Float, {"Y"}});
        if (scene.reference.shadows) {
            c.passSalt = 0x53484432u;
            uses = common;
            uses.push_back({"g_visibility", "reference.shadow", Access::ReadWrite});
            addChunkedPasses(plan, "reference.shadow", "scene_shadow", uses, c,
                             scene.reference.samplesPerPixel, scene.reference.samplesPerPixel, kShadowChunk,
                             w, h);
            outputs.push_back({"reference.shadow", "reference.shadow", Format::R32Float, {"Y"}});
        }
    }
    for (const OutputImage& out : outputs) plan.images.push_back({out.resource, w, h, 1, out.format});
    if (reflections && scene.reference.reflections) {
        plan.images.push_back({"reference.reflection_sum", w, h, 1, Format::RGBA32Float});
        plan.images.push_back({"reference.reflection_moments", w, h, 1, Format::RG32Float});
    }
    return plan;
}

template <typename T> vk::Buffer uploadStorage(const gpu::Context& context, const std::vector<T>& values) {
    vk::Buffer buffer = vk::createBuffer(context.device, sizeof(T) * values.size(),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::DeviceLocal);
    gpu::uploadBuffer(context, buffer, std::span<const T>(values));
    return buffer;
}

capture::Layer toLayer(const OutputImage& out, const std::vector<float>& texels,
                       std::uint32_t texelChannels) {
    capture::Layer layer;
    layer.name = out.layer;
    layer.channels = out.channels;
    layer.storage = capture::SampleType::Float;
    const std::size_t n = out.channels.size();
    const std::size_t count = texels.size() / texelChannels;
    layer.pixels.resize(count * n);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < n; ++c) layer.pixels[i * n + c] = texels[i * texelChannels + c];
    return layer;
}

struct Resources {
    const gpu::Context& context;
    std::vector<vk::Buffer> buffers;
    vk::Image environment;
    gpu::PlanResources owned;
    vk::Executor executor;
    ~Resources() {
        vk::destroyExecutor(executor);
        gpu::destroyPlanResources(context, owned);
        for (vk::Buffer& b : buffers) vk::destroyBuffer(context.device, b);
        vk::destroyImage(context.device, environment);
    }
};

// The passes' background test (docs/conventions.md §2.2): depth within 1e-6 of the far value,
// outside [0, 1] or not finite.
constexpr float kBackgroundEpsilon = 1e-6f;
bool backgroundDepth(float d, bool reversed) {
    if (!std::isfinite(d)) return true;
    return reversed ? (d <= kBackgroundEpsilon || d > 1.0f) : (d >= 1.0f - kBackgroundEpsilon || d < 0.0f);
}

// Surface pixels whose device depth the background test takes for the sky. A surface at view
// depth z has depth n(f - z) / (z (f - n)) from the far value in both conventions (standard:
// 1 - d; reversed: d), so a small near plane puts distant surfaces within 1e-6 of it (near
// 0.001: everything beyond about 1000), whichever the convention; standard depth also rounds to
// exactly 1.0f there. The ray caster draws a surface at such a pixel (its normal faces the ray
// instead of being -view, its roughness and material are the surface's) that every consumer of
// the depth reads as sky. A surface facing the ray head-on with roughness 1 and no material
// layers cannot be told from the sky and is not counted.
std::size_t surfacesAtBackgroundDepth(const capture::Frame& f, const capture::Mat4& viewProjection,
                                      const Vec3& eye, bool reversed, bool ndcYDown) {
    const capture::Layer* depth = capture::findLayer(f, "depth");
    const capture::Layer* normal = capture::findLayer(f, "normal");
    const capture::Layer* roughness = capture::findLayer(f, "roughness");
    const capture::Layer* material = capture::findLayer(f, "material");
    const std::optional<capture::Mat4> inverse = capture::inverse(viewProjection);
    if (!depth || !normal || !inverse) return 0;
    const capture::Mat4& m = *inverse;
    std::size_t count = 0;
    for (std::uint32_t y = 0; y < f.height; ++y)
        for (std::uint32_t x = 0; x < f.width; ++x) {
            const std::size_t i = std::size_t{y} * f.width + x;
            if (!backgroundDepth(depth->pixels[i], reversed)) continue;
            bool surface = (roughness && roughness->pixels[i] != 1.0f);
            if (material)
                for (std::size_t c = 0; c < 4; ++c) surface = surface || material->pixels[i * 4 + c] != 0.0f;
            if (!surface) {
                // The primary ray of scene_trace.hlsli (ScenePrimaryRay), in double: the pixel
                // centre unprojected at NDC depth 0.5, from the eye. The sky's normal is -dir to
                // float rounding (about 1e-6); a surface's differs unless it faces the ray.
                const double u = (x + 0.5) / f.width, v = (y + 0.5) / f.height;
                const double ndc[4] = {2.0 * u - 1.0, ndcYDown ? 2.0 * v - 1.0 : 1.0 - 2.0 * v, 0.5, 1.0};
                double q[4] = {};
                for (std::size_t r = 0; r < 4; ++r)
                    for (std::size_t c = 0; c < 4; ++c) q[r] += m.m[r * 4 + c] * ndc[c];
                double dir[3], length = 0.0;
                for (std::size_t c = 0; c < 3; ++c) {
                    dir[c] = q[c] / q[3] - static_cast<double>(eye[c]);
                    length += dir[c] * dir[c];
                }
                length = std::sqrt(length);
                double gap = 0.0;
                for (std::size_t c = 0; c < 3; ++c) {
                    const double d = static_cast<double>(normal->pixels[i * 3 + c]) + dir[c] / length;
                    gap += d * d;
                }
                surface = std::sqrt(gap) > 1e-3;
            }
            count += surface;
        }
    return count;
}

} // namespace

std::string backgroundDepthWarning(const Scene& scene, std::size_t pixels, std::uint32_t frames) {
    if (pixels == 0) return {};
    const CameraDesc& c = scene.camera;
    const bool infinite = c.depth == capture::DepthConvention::ReversedInfinite;
    std::ostringstream s;
    s << scene.file.string() << ": warning: " << pixels << " surface pixel" << (pixels == 1 ? "" : "s")
      << " on " << frames << " of " << scene.frameCount << " frame" << (scene.frameCount == 1 ? "" : "s")
      << (pixels == 1 ? " has" : " have") << " device depth within 1e-6 of the background's "
      << (c.depth == capture::DepthConvention::Standard ? 1 : 0) << " (" << capture::toString(c.depth)
      << " depth, near " << c.nearZ;
    if (!infinite) s << ", far " << c.farZ;
    s << "), so they replay as sky while their other layers show a surface; ";
    // The depth's distance from the far value, n (f - z) / (z (f - n)) (n / z without a far
    // plane), is the same in both conventions: only the near plane, and a far plane well beyond
    // the surfaces, move it. With f >= 2z it is at least n / (2z).
    if (infinite)
        s << "a surface at view depth z keeps its depth above 1e-6 only while near / z > 1e-6: raise "
             "camera.near above 1e-6 times the farthest surface's view depth";
    else
        s << "a surface at view depth z keeps its depth apart only while near * (far - z) / (z * (far - "
             "near)) "
             "> 1e-6, in either depth convention: raise camera.near above 2e-6 times the farthest surface's "
             "view depth, with camera.far at least twice that depth";
    return s.str();
}

std::vector<std::string> captureEffects(const Scene& scene) {
    std::vector<std::string> effects;
    if (hasEffect(scene, Effect::Reflections)) effects.push_back("reflections");
    if (hasEffect(scene, Effect::Hybrid)) effects.push_back("hybrid");
    if (needsShadows(scene)) effects.push_back("shadows");
    return effects;
}

Simulation simulate(const gpu::Context& context, const Scene& scene) {
    Simulation sim;
    const std::vector<Mesh> meshes = loadMeshes(scene);
    const capture::Environment environment = bakeEnvironment(scene);
    const bool reflections = needsReflections(scene);
    if (reflections) sim.environment = environment;

    Resources res{context, {}, {}, {}, vk::createExecutor(context.device)};
    res.executor.findShader = findShader;
    res.environment = vk::createImage2D(context.device, environment.width, environment.height,
                                        VK_FORMAT_R32G32B32A32_SFLOAT);
    gpu::uploadImage(context, res.environment, environment.rgb, 3);
    const vk::Buffer materials = uploadStorage(context, packMaterials(scene));
    std::vector<shaders::SceneEnvironmentSample> sampling;
    if (reflections && scene.reference.reflections && scene.reference.environmentSampling)
        sampling = environmentSamplingTable(environment);
    const bool environmentSampling = !sampling.empty();
    if (!environmentSampling) sampling.resize(1); // never read, but a binding needs a buffer
    const vk::Buffer environmentTexels = uploadStorage(context, sampling);
    res.buffers = {materials, environmentTexels};

    std::vector<OutputImage> outputs;
    std::vector<std::size_t> passSlot; // plan pass -> sim.passes entry (chunks share one)
    std::uint32_t framesWithLostSurfaces = 0;
    // The run of unchanged frames the references accumulate over: its first frame, the samples
    // per pixel its earlier frames traced, and the state of the previous frame.
    std::uint32_t runFirstFrame = 0, runSamples = 0;
    std::string previousState;
    for (std::uint32_t frame = 0; frame < scene.frameCount; ++frame) {
        const FrameCamera cam = cameraAt(scene, frame);
        FrameGeometry geometry = buildGeometry(scene, meshes, frame);
        if (frame == 0) sim.primitives = geometry.primitives.size();
        Bvh bvh = buildBvh(std::move(geometry.primitives));
        if (bvh.primitives.empty()) bvh.primitives.push_back({}); // never read: the root is an empty leaf
        if (geometry.objects.empty()) geometry.objects.push_back({});
        const std::vector<shaders::SceneLight> packedLights = packLights(lightsAt(scene, frame));
        const capture::Mat4 vp = capture::viewProjection(cam.camera);
        std::string state = frameState(vp, cam.eye, bvh, packedLights);
        if (frame == 0 || !scene.reference.accumulate || state != previousState) {
            runFirstFrame = frame;
            runSamples = 0;
        }
        previousState = std::move(state);
        sim.referenceSamples.push_back(runSamples + scene.reference.samplesPerPixel);

        GLINT_SceneConstants c{};
        storeRows(c.viewProjection, vp);
        storeRows(c.invViewProjection, *capture::inverse(vp));
        storeRows(c.prevViewProjection, cam.camera.prevViewProjection);
        c.eye = {cam.eye[0], cam.eye[1], cam.eye[2], 1.0f};
        c.size = {scene.width, scene.height};
        c.frameIndex = frame;
        c.sampleBase = runSamples;
        c.sequenceFrame = runFirstFrame;
        c.seed = scene.seed;
        c.lightCount = static_cast<std::uint32_t>(scene.lights.size());
        c.samples = 1;
        c.shadowSamples = scene.shadowSamples;
        c.shadowLight = scene.shadowLight;
        c.backgroundDepth = scene.camera.depth == capture::DepthConvention::Standard ? 1.0f : 0.0f;
        c.ndcYDown = scene.camera.ndcYDown ? 1u : 0u;
        c.environmentIntensity = 1.0f;
        c.environmentSampling = environmentSampling ? 1u : 0u;
        double shadowTan = -1.0;
        c.shadowLightTanReference = 0.0f;
        if (needsShadows(scene)) {
            const LightDesc shadowLight = lightsAt(scene, frame).at(scene.shadowLight);
            shadowTan = shadowLightTan(shadowLight, cam.eye);
            if (shadowLight.kind == LightKind::Sphere && shadowTan > 0.0)
                c.shadowLightTanReference = static_cast<float>(shadowTan);
        }
        const EffectPlan plan = planFrame(scene, c, outputs);
        if (frame == 0) {
            res.owned = gpu::createPlanResources(context, plan);
            for (const Pass& pass : plan.passes) {
                // Chunks of a reference pass ("name#k") share the entry of "name".
                const std::string name = pass.name.substr(0, pass.name.find('#'));
                auto entry = std::find_if(sim.passes.begin(), sim.passes.end(),
                                          [&](const PassTime& t) { return t.pass == name; });
                if (entry == sim.passes.end()) {
                    passSlot.push_back(sim.passes.size());
                    sim.passes.push_back({name, 0.0});
                } else {
                    passSlot.push_back(static_cast<std::size_t>(entry - sim.passes.begin()));
                }
            }
            for (const OutputImage& out : outputs) sim.layers.push_back(out.layer);
        }

        vk::Buffer nodes = uploadStorage(context, bvh.nodes);
        res.buffers.push_back(nodes);
        vk::Buffer primitives = uploadStorage(context, bvh.primitives);
        res.buffers.push_back(primitives);
        vk::Buffer objects = uploadStorage(context, geometry.objects);
        res.buffers.push_back(objects);
        // Keyframed lights move: the shadow layers, references and shading all read this frame's.
        vk::Buffer lights = uploadStorage(context, packedLights);
        res.buffers.push_back(lights);
        vk::ResourceTable table = gpu::resourceTable(res.owned, {{"g_scene_environment", &res.environment}});
        table.buffers["g_scene_nodes"] = &nodes;
        table.buffers["g_scene_primitives"] = &primitives;
        table.buffers["g_scene_objects"] = &objects;
        table.buffers["g_scene_materials"] = &materials;
        table.buffers["g_scene_lights"] = &lights;
        table.buffers["g_scene_environment_sampling"] = &environmentTexels;

        const gpu::PlanTimings timings = gpu::executePlan(context, res.executor, plan, table, 1);
        for (std::size_t p = 0; p < passSlot.size(); ++p) {
            const double ms = timings.times.empty() ? -1.0 : timings.times[0].at(p);
            PassTime& entry = sim.passes[passSlot[p]];
            entry.milliseconds = ms < 0.0 || entry.milliseconds < 0.0 ? -1.0 : entry.milliseconds + ms;
        }

        capture::Frame f;
        f.width = scene.width;
        f.height = scene.height;
        f.frameIndex = frame;
        f.camera = cam.camera;
        f.normalEncoding = capture::NormalEncoding::WorldUnit;
        f.motion = capture::kConventionA;
        if (reflections) f.roughness = {"roughness", "Y", true};
        f.effects = captureEffects(scene);
        if (needsShadows(scene)) {
            // The light the shadow layers sample: its angular radius for the denoiser's
            // penumbra estimate (0 included: hard shadows; a sphere light's as the camera sees
            // it, the blocker layer scaled to it: scene_shadow.cs.hlsl).
            f.shadowLightTanHalfAngle = shadowTan;
        }
        for (const OutputImage& out : outputs) {
            const vk::Image& image = res.owned.images.at(out.resource);
            f.layers.push_back(
                toLayer(out, gpu::readbackImage(context, image), vk::formatChannelCount(image.format)));
        }
        const std::size_t lost = surfacesAtBackgroundDepth(
            f, vp, cam.eye, scene.camera.depth != capture::DepthConvention::Standard, scene.camera.ndcYDown);
        sim.surfacesAtBackgroundDepth += lost;
        framesWithLostSurfaces += lost > 0;
        sim.frames.push_back(std::move(f));
        runSamples += scene.reference.samplesPerPixel;
        // This frame's geometry and lights are done with; the executor waited in executePlan.
        for (int i = 0; i < 4; ++i) {
            vk::destroyBuffer(context.device, res.buffers.back());
            res.buffers.pop_back();
        }
    }
    if (sim.surfacesAtBackgroundDepth > 0)
        sim.warnings.push_back(
            backgroundDepthWarning(scene, sim.surfacesAtBackgroundDepth, framesWithLostSurfaces));
    return sim;
}

} // namespace glint::scene
