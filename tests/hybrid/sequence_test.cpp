// Hybrid reflections over simulated sequences (harness/scene), frame after frame with every
// history carried as the replay carries them (4 rays per quad, so every glossy pixel traces).
//
// 1. A camera moving down the mirror corridor while it pans: tiles change between screen space
//    and ray tracing on every frame. The hybrid must not produce fireflies where they change.
// 2. A static camera over a glossy floor that reflects only the sky (screen space misses, the
//    tiles go FULL_HW); then a wall appears behind the floor, which screen space can see in
//    the floor's reflection. The tiles must come back to screen space within a number of
//    frames derived from the spawn rate and the safe band (docs/hybrid.md, "Classification").
//
// `glint_tests_hybrid "[.measure-sequence]"` prints the per-frame numbers of both.
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include "glint/hybrid/glint_hybrid_constants.h"

#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_transfer.h>
#include <replay/replay_frame.h>
#include <scene/scene_buffers.h>
#include <scene/scene_file.h>
#include <scene/scene_shaders.h>
#include <scene/scene_simulate.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace glint;

namespace {

constexpr std::uint32_t kWidth = 160, kHeight = 90, kTile = 8;
constexpr std::uint32_t kTilesX = (kWidth + kTile - 1) / kTile, kTilesY = (kHeight + kTile - 1) / kTile;

double luminance(const float* rgb) {
    return 0.2126 * double(rgb[0]) + 0.7152 * double(rgb[1]) + 0.0722 * double(rgb[2]); // Rec. 709
}

std::size_t tileOf(std::size_t pixel) {
    const std::size_t x = pixel % kWidth, y = pixel / kWidth;
    return (y / kTile) * kTilesX + x / kTile;
}

// The largest luminance over `mask` of an image with `channels` floats per pixel, and where.
struct Peak {
    double value = 0.0;
    std::size_t pixel = 0;
};
Peak peakLuminance(const std::vector<float>& pixels, std::size_t channels, const std::vector<bool>& mask) {
    Peak peak;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i] && luminance(&pixels[channels * i]) > peak.value)
            peak = {luminance(&pixels[channels * i]), i};
    return peak;
}

// One configuration of the composed effect (planHybridReflections) with its own resources and
// histories.
struct Path {
    HybridDesc desc;
    EffectPlan plan;
    std::unique_ptr<gpu::EffectRunner> runner;
};

struct PathFrame {
    std::vector<float> noisy, denoised;   // RGB
    std::vector<std::uint32_t> tileClass; // per tile
};

// Every frame of a simulation through several configurations of the composed hybrid effect:
// the inputs and the scene's geometry of each frame are uploaded once and each configuration
// runs on them, carrying its feedback and denoiser histories from frame to frame.
class Sequence {
  public:
    Sequence(const scene::Scene& scene, const scene::Simulation& sim, std::vector<HybridDesc> configurations)
        : sim_(sim), buffers_(test::testContext(), scene),
          inputs_(test::testContext(), Extent2D{scene.width, scene.height}, false) {
        for (HybridDesc& desc : configurations) paths_.push_back(Path{desc, {}, nullptr});
    }

    // Runs frame `index` through every configuration; `view` gets the frame's SSSR view.
    std::vector<PathFrame> run(std::uint32_t index, test::SssrTestView& view) {
        const gpu::Context& context = test::testContext();
        const capture::Frame& frame = sim_.frames.at(index);
        view.desc = paths_.front().desc.sssr;
        replay::sssrFromFrame(frame, *sim_.environment, view.desc, view.inputs);
        vk::ResourceTable table = test::uploadInputs(inputs_, view);
        buffers_.setFrame(index); // the previous frame's work has finished
        buffers_.addTo(table);
        std::vector<PathFrame> out;
        for (Path& path : paths_) {
            HybridDesc desc = path.desc;
            const SssrDesc tunables = desc.sssr;
            desc.sssr = view.desc;
            desc.sssr.samplesPerQuad = tunables.samplesPerQuad;
            desc.sssr.denoise = tunables.denoise;
            desc.sssr.frameIndex = index;
            const ReflectionsDenoiserDesc denoiser =
                replay::denoiserFromFrame(frame, desc.sssr, index, index == 0);
            std::string error;
            REQUIRE(planHybridReflections(desc, desc.sssr.denoise ? &denoiser : nullptr, path.plan, &error) ==
                    Result::Ok);
            if (!path.runner) {
                path.runner = std::make_unique<gpu::EffectRunner>(context, path.plan, scene::findShader);
                path.runner->initialize();
            }
            path.runner->run(path.plan, table, true); // snapshots: "noisy" before the denoiser
            PathFrame result;
            for (gpu::DecodedOutput& output : path.runner->readOutputs(path.plan, false)) {
                if (output.name == "noisy" || output.name == "denoised")
                    REQUIRE(output.pixels.size() == std::size_t{3} * kWidth * kHeight);
                if (output.name == "noisy") result.noisy = std::move(output.pixels);
                if (output.name == "denoised") result.denoised = std::move(output.pixels);
            }
            const std::vector<std::byte> bytes =
                gpu::readbackImageBytes(context, path.runner->image("hybrid_tile_class"));
            result.tileClass.resize(bytes.size() / 4);
            std::memcpy(result.tileClass.data(), bytes.data(), bytes.size());
            REQUIRE(result.tileClass.size() == std::size_t{kTilesX} * kTilesY);
            out.push_back(std::move(result));
        }
        return out;
    }

  private:
    const scene::Simulation& sim_;
    scene::SceneBuffers buffers_;
    gpu::InputImages inputs_;
    std::vector<Path> paths_;
};

// The pixels SSSR traces (GGX alpha below its roughness threshold), from the capture's roughness.
std::vector<bool> glossyPixels(const test::SssrTestView& view) {
    std::vector<bool> glossy(std::size_t{kWidth} * kHeight);
    for (std::size_t i = 0; i < glossy.size(); ++i) {
        const float r = view.inputs.material[4 * i];
        const float alpha = view.desc.roughnessIsPerceptual ? r * r : r;
        glossy[i] = std::isfinite(alpha) && alpha < view.desc.roughnessThreshold;
    }
    return glossy;
}

std::size_t countClass(const std::vector<std::uint32_t>& classes, std::uint32_t c) {
    return static_cast<std::size_t>(std::count(classes.begin(), classes.end(), c));
}

// ---- 1. Camera move -------------------------------------------------------------------------

constexpr std::uint32_t kMoveFrames = 12;

// The mirror corridor with the camera walking 1.5 units down it while it pans from the left
// mirror to the right one (about 18 degrees each side of the corridor's axis): on every frame
// content enters and leaves the screen and the tiles' statistics move with it. The reference
// has 4 samples per pixel (lavapipe's time): a noisier reference only raises its maximum, which
// loosens the bound below where the reference is the largest term.
scene::Scene panningCorridor() {
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/mirror_corridor.toml");
    scene.width = kWidth;
    scene.height = kHeight;
    scene.frameCount = kMoveFrames;
    scene::CameraKey start, end;
    start.frame = 0.0f;
    start.position = {0.0f, 1.2f, 7.0f};
    start.target = {-2.0f, 1.0f, 1.0f};
    end.frame = static_cast<float>(kMoveFrames - 1);
    end.position = {0.0f, 1.2f, 5.5f};
    end.target = {2.0f, 1.0f, -0.5f};
    scene.camera.keys = {start, end};
    scene.reference.reflections = true;
    scene.reference.samplesPerPixel = 4;
    return scene;
}

constexpr std::size_t kHybrid = 0, kRayTracedOnly = 1, kScreenSpaceOnly = 2, kPaths = 3;
const char* const kPathNames[kPaths] = {"hybrid", "RT-only", "SS-only"};

// The firefly bound. Each of the hybrid's rays is either a screen-space ray or a ray-traced ray
// for the same blue-noise GGX sample that the SS-only path (hybrid.rayTracing off) or the
// RT-only path (hybrid.screenSpace off) traces for that pixel on that frame; neither path ever
// switches. Their maxima already contain the one-sample noise (a single GGX sample that finds
// the sphere light's highlight in a mirror is far above the converged reference's maximum), and
// screen space's maximum may exceed the ray tracer's (its hit points are the screen's), so
// the bound is the largest of the reference's and the two paths' maxima on the same frame, with
// 5 % for the rays the hybrid's classification routes differently (the denoiser's variance that
// guides it is the hybrid's own). A value above that can only come from the switching itself:
// the firefly this test is about. The denoised outputs are bounded the same way by the
// reference and the two paths' denoised maxima.
constexpr double kBoundFactor = 1.05;
// A firefly confined to one tile: the tile of the hybrid's brightest glossy pixel at twice its
// value. The noisy bound must reject it on every frame, so the check is not vacuous.
constexpr double kPoison = 2.0;

// Maxima over one set of pixels, and the bound they give.
struct Maxima {
    std::size_t pixels = 0;
    double reference = 0.0; // max luminance of reference.reflection
    double noisy[kPaths] = {}, denoised[kPaths] = {};
    double poisonedNoisy = 0.0; // the hybrid's noisy maximum with kPoison applied

    double noisyBound() const {
        return kBoundFactor * std::max({reference, noisy[kRayTracedOnly], noisy[kScreenSpaceOnly]});
    }
    double denoisedBound() const {
        return kBoundFactor * std::max({reference, denoised[kRayTracedOnly], denoised[kScreenSpaceOnly]});
    }
};

Maxima maxima(const std::vector<PathFrame>& paths, const std::vector<float>& reference,
              const std::vector<bool>& mask) {
    Maxima m;
    m.pixels = static_cast<std::size_t>(std::count(mask.begin(), mask.end(), true));
    m.reference = peakLuminance(reference, 3, mask).value;
    for (std::size_t p = 0; p < kPaths; ++p) {
        m.noisy[p] = peakLuminance(paths[p].noisy, 3, mask).value;
        m.denoised[p] = peakLuminance(paths[p].denoised, 3, mask).value;
    }
    std::vector<float> poisoned = paths[kHybrid].noisy;
    const std::size_t brightest = tileOf(peakLuminance(poisoned, 3, mask).pixel);
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (tileOf(i) == brightest)
            for (std::size_t c = 0; c < 3; ++c) poisoned[3 * i + c] *= static_cast<float>(kPoison);
    m.poisonedNoisy = peakLuminance(poisoned, 3, mask).value;
    return m;
}

std::string describe(const Maxima& m) {
    std::ostringstream s;
    s << m.pixels << " pixels, max luminance: reference " << m.reference;
    for (std::size_t p = 0; p < kPaths; ++p)
        s << ", " << kPathNames[p] << " " << m.noisy[p] << " (denoised " << m.denoised[p] << ")";
    s << "; noisy: bound " << m.noisyBound() << ", hybrid/bound " << m.noisy[kHybrid] / m.noisyBound()
      << ", poisoned/bound " << m.poisonedNoisy / m.noisyBound() << "; denoised: bound " << m.denoisedBound()
      << ", hybrid/bound " << m.denoised[kHybrid] / m.denoisedBound();
    return s.str();
}

struct MoveFrame {
    std::size_t changedTiles = 0, classes[3] = {};
    bool finite = true;
    Maxima glossy;     // every glossy pixel
    Maxima transition; // the glossy pixels of the tiles that changed class this frame or are HALF_SW
};

std::vector<MoveFrame> measureCameraMove() {
    const scene::Scene scene = panningCorridor();
    const scene::Simulation sim = scene::simulate(test::testContext(), scene);
    REQUIRE(sim.environment.has_value());
    std::vector<HybridDesc> configurations(kPaths);
    for (HybridDesc& desc : configurations) {
        desc.sssr.samplesPerQuad = 4;
        desc.sssr.denoise = true;
    }
    configurations[kRayTracedOnly].screenSpace = false;
    configurations[kScreenSpaceOnly].rayTracing = false;
    Sequence sequence(scene, sim, configurations);

    std::vector<MoveFrame> frames;
    std::vector<std::uint32_t> previousClasses;
    for (std::uint32_t index = 0; index < kMoveFrames; ++index) {
        test::SssrTestView view;
        const std::vector<PathFrame> paths = sequence.run(index, view);
        const std::vector<bool> glossy = glossyPixels(view);
        const std::vector<float> reference =
            replay::layerChannels(sim.frames[index], "reference.reflection", 3);
        MoveFrame m;
        for (const PathFrame& path : paths)
            for (const auto* image : {&path.noisy, &path.denoised})
                for (const float value : *image) m.finite = m.finite && std::isfinite(value);
        const std::vector<std::uint32_t>& classes = paths[kHybrid].tileClass;
        for (std::uint32_t c = 0; c < 3; ++c) m.classes[c] = countClass(classes, c);
        std::vector<bool> switching(classes.size());
        for (std::size_t t = 0; t < classes.size(); ++t) {
            const bool changed = !previousClasses.empty() && previousClasses[t] != classes[t];
            m.changedTiles += changed;
            switching[t] = changed || classes[t] == GLINT_HYBRID_TILE_HALF_SW;
        }
        previousClasses = classes;
        std::vector<bool> transition = glossy;
        for (std::size_t i = 0; i < transition.size(); ++i)
            transition[i] = transition[i] && switching[tileOf(i)];
        m.glossy = maxima(paths, reference, glossy);
        m.transition = maxima(paths, reference, transition);
        frames.push_back(m);
    }
    return frames;
}

std::string describe(std::size_t index, const MoveFrame& m) {
    std::ostringstream s;
    s << "frame " << index << ": tiles FULL_SW/HALF_SW/FULL_HW " << m.classes[0] << "/" << m.classes[1] << "/"
      << m.classes[2] << ", " << m.changedTiles << " changed class\n  glossy: " << describe(m.glossy)
      << "\n  switching tiles: " << describe(m.transition);
    return s.str();
}

// ---- 2. Latency back to screen space --------------------------------------------------------

constexpr std::uint32_t kAppearFrame = 8;    // the first frame with the wall in view
constexpr std::uint32_t kLatencyFrames = 24; // frames measured from kAppearFrame on

// A glossy floor seen from above that reflects only the sky: every screen-space ray escapes, a
// miss, so the tiles stay ray traced. On frame kAppearFrame a wall appears across the floor's
// far end (before, it stands far off to the side, outside the view and the floor's
// reflections); screen space can then see it in most of the floor's reflection.
scene::Scene appearingWall() {
    scene::Scene scene;
    scene.width = kWidth;
    scene.height = kHeight;
    scene.frameCount = kAppearFrame + kLatencyFrames;
    scene.effects = {scene::Effect::Hybrid};
    scene.camera.keys.front().position = {0.0f, 1.4f, 4.0f};
    scene.camera.keys.front().target = {0.0f, 0.4f, 0.0f};
    scene.camera.fovYDegrees = 55.0;
    scene::LightDesc sun;
    sun.direction = {0.3f, 1.0f, 0.5f};
    sun.intensity = 3.0f;
    scene.lights = {sun};
    scene::MaterialDesc floor, wall;
    floor.name = "floor";
    floor.baseColor = {0.5f, 0.5f, 0.55f};
    floor.roughness = 0.3f; // alpha 0.09: traced, below the ray-tracing threshold
    wall.name = "wall";
    wall.baseColor = {0.8f, 0.4f, 0.15f};
    wall.roughness = 0.7f;
    scene.materials = {floor, wall};
    scene::ObjectDesc plane;
    plane.name = "floor";
    plane.shape = scene::ShapeKind::Plane;
    plane.material = 0;
    plane.size = {30.0f, 1.0f, 30.0f};
    scene::ObjectDesc box;
    box.name = "wall";
    box.shape = scene::ShapeKind::Box;
    box.material = 1;
    box.size = {10.0f, 4.0f, 0.3f};
    scene::ObjectKey away, here;
    away.frame = static_cast<float>(kAppearFrame - 1);
    away.position = {60.0f, 2.0f, -2.0f};
    here.frame = static_cast<float>(kAppearFrame);
    here.position = {0.0f, 2.0f, -2.0f};
    box.keys = {away, here};
    scene.objects = {plane, box};
    return scene;
}

struct Latency {
    std::vector<bool> affected;        // per tile: screen space can answer it once the wall is there
    std::vector<std::uint32_t> before; // per tile: its class on the last frame without the wall
    std::vector<int> back;             // per tile: frames after kAppearFrame until not FULL_HW (-1: never)
    std::vector<std::uint32_t> last;   // per tile: its class on the last frame
    std::vector<std::array<std::size_t, 3>> affectedClasses; // per frame from kAppearFrame - 1
    std::vector<std::array<std::size_t, 3>> allClasses;      // per frame from 0

    // The affected tiles that were FULL_HW before the wall appeared: the ones whose return is measured.
    std::vector<std::size_t> measured() const {
        std::vector<std::size_t> tiles;
        for (std::size_t t = 0; t < affected.size(); ++t)
            if (affected[t] && before[t] == GLINT_HYBRID_TILE_FULL_HW) tiles.push_back(t);
        return tiles;
    }
};

Latency measureLatency() {
    const scene::Scene scene = appearingWall();
    const scene::Simulation sim = scene::simulate(test::testContext(), scene);
    REQUIRE(sim.environment.has_value());
    HybridDesc hybrid;
    hybrid.sssr.samplesPerQuad = 4;
    Sequence sequence(scene, sim, {hybrid});

    Latency l;
    // Where screen space can see the reflected wall: SSSR alone (its own runner, none of the
    // hybrid's code) on the first frame with the wall, confident on at least half of a tile's
    // glossy pixels (and the tile has at least 16).
    l.affected.assign(std::size_t{kTilesX} * kTilesY, false);
    {
        test::SssrTestView view;
        view.desc.samplesPerQuad = 4;
        replay::sssrFromFrame(sim.frames[kAppearFrame], *sim.environment, view.desc, view.inputs);
        gpu::SssrRunner sssr(test::testContext(), view.desc);
        sssr.upload(view.inputs);
        sssr.run(view.desc);
        const gpu::SssrFrameOutputs out = sssr.readback();
        const std::vector<bool> glossy = glossyPixels(view);
        std::vector<std::size_t> glossyCount(l.affected.size()), confident(l.affected.size());
        for (std::size_t i = 0; i < glossy.size(); ++i) {
            if (!glossy[i]) continue;
            ++glossyCount[tileOf(i)];
            confident[tileOf(i)] += out.confidence[i] >= hybrid.confidenceThreshold;
        }
        for (std::size_t t = 0; t < l.affected.size(); ++t)
            l.affected[t] = glossyCount[t] >= 16 && 2 * confident[t] >= glossyCount[t];
    }

    l.back.assign(l.affected.size(), -1);
    for (std::uint32_t index = 0; index < scene.frameCount; ++index) {
        test::SssrTestView view;
        const std::vector<std::uint32_t> classes = sequence.run(index, view).front().tileClass;
        l.allClasses.push_back({countClass(classes, 0), countClass(classes, 1), countClass(classes, 2)});
        l.last = classes;
        if (index + 1 == kAppearFrame) l.before = classes;
        if (index + 1 < kAppearFrame) continue;
        std::array<std::size_t, 3> perClass{};
        for (std::size_t t = 0; t < classes.size(); ++t) {
            if (!l.affected[t]) continue;
            ++perClass[std::min(classes[t], 2u)];
            if (index >= kAppearFrame && l.back[t] < 0 && classes[t] != GLINT_HYBRID_TILE_FULL_HW)
                l.back[t] = static_cast<int>(index - kAppearFrame);
        }
        l.affectedClasses.push_back(perClass);
    }
    return l;
}

// The number of frames after kAppearFrame by which at least `fraction` of the measured tiles
// had left FULL_HW (-1: not within the measured frames).
int framesUntil(const Latency& l, double fraction) {
    std::vector<int> back;
    for (const std::size_t t : l.measured()) back.push_back(l.back[t] < 0 ? INT32_MAX : l.back[t]);
    std::sort(back.begin(), back.end());
    const auto needed = static_cast<std::size_t>(std::ceil(fraction * double(back.size())));
    if (needed == 0) return 0;
    return back[needed - 1] == INT32_MAX ? -1 : back[needed - 1];
}

// The latency bounds, from the spawn rate and the safe band (docs/hybrid.md, "Classification").
//
// Lottery: a FULL_HW tile has no screen-space rays, so its statistics are empty and it turns
// HALF_SW when this frame's or last frame's lottery number is at most the spawn rate s:
// probability q = 1 - (1 - s)^2 (about 4 % with s = 0.02). Such a seed traces half its rays in
// screen space; on an affected tile they hit. Among A measured tiles, no seed appears in n frames
// with probability (1 - q)^(A n); `seedFrames` is the smallest n that makes this at most 1e-3,
// so the first seed is on relative frame seedFrames - 1 at the latest.
//
// Safe band: a tile takes the 3x3 neighbour counter with the most fresh hits, and with the
// default miss weight a neighbour with more hits than twice its misses (every affected tile:
// at least half its rays are confident) makes it screen space on the next frame. So the
// screen-space region grows by one ring of tiles (8-connected, through affected tiles: others
// have no hits to pass on) per frame. From the worst-placed single seed, `majorityRings` rings
// reach half the measured tiles and `allRings` reach all of them (-1: not connected). Later seeds
// only make it faster. Hence: half the tiles back within seedFrames - 1 + majorityRings frames,
// all within seedFrames - 1 + allRings.
struct LatencyBound {
    double q = 0.0;
    int seedFrames = 0, majorityRings = 0, allRings = 0;
    int majority() const { return seedFrames - 1 + majorityRings; }
    int all() const { return allRings < 0 ? -1 : seedFrames - 1 + allRings; }
};

LatencyBound latencyBound(const Latency& l, float spawnRate) {
    LatencyBound b;
    const std::vector<std::size_t> measured = l.measured();
    const double s = spawnRate;
    b.q = 1.0 - (1.0 - s) * (1.0 - s);
    if (measured.empty()) return b;
    while (std::pow(1.0 - b.q, double(measured.size()) * double(b.seedFrames)) > 1e-3) ++b.seedFrames;
    const std::size_t half = (measured.size() + 1) / 2;
    for (std::size_t seed = 0; seed < l.affected.size(); ++seed) {
        if (!l.affected[seed]) continue;
        std::vector<int> distance(l.affected.size(), -1);
        std::vector<std::size_t> queue{seed};
        distance[seed] = 0;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const std::size_t t = queue[head];
            const int tx = static_cast<int>(t % kTilesX), ty = static_cast<int>(t / kTilesX);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = tx + dx, ny = ty + dy;
                    if (nx < 0 || ny < 0 || nx >= int(kTilesX) || ny >= int(kTilesY)) continue;
                    const auto n = static_cast<std::size_t>(ny) * kTilesX + static_cast<std::size_t>(nx);
                    if (!l.affected[n] || distance[n] >= 0) continue;
                    distance[n] = distance[t] + 1;
                    queue.push_back(n);
                }
        }
        std::vector<int> reached;
        for (const std::size_t t : measured) reached.push_back(distance[t] < 0 ? INT32_MAX : distance[t]);
        std::sort(reached.begin(), reached.end());
        b.majorityRings =
            std::max(b.majorityRings, reached[half - 1] == INT32_MAX ? 1 << 20 : reached[half - 1]);
        if (b.allRings >= 0)
            b.allRings = reached.back() == INT32_MAX ? -1 : std::max(b.allRings, reached.back());
    }
    return b;
}

std::string describe(const Latency& l, const LatencyBound& b) {
    std::ostringstream s;
    std::size_t affected = 0, before[3] = {}, back[3] = {};
    for (std::size_t t = 0; t < l.affected.size(); ++t)
        if (l.affected[t]) ++affected, ++before[std::min(l.before[t], 2u)], ++back[std::min(l.last[t], 2u)];
    s << affected << " affected tiles (FULL_SW/HALF_SW/FULL_HW before the wall " << before[0] << "/"
      << before[1] << "/" << before[2] << ", on the last frame " << back[0] << "/" << back[1] << "/"
      << back[2] << "); " << l.measured().size() << " measured, frames until the first is back "
      << framesUntil(l, 1e-9) << ", half " << framesUntil(l, 0.5) << ", 90 % " << framesUntil(l, 0.9)
      << ", all " << framesUntil(l, 1.0) << "; bound: q " << b.q << ", first seed within " << b.seedFrames
      << " frames, rings to half " << b.majorityRings << ", to all " << b.allRings << ": half within "
      << b.majority() << ", all within " << b.all() << " (lottery alone would bring back "
      << 1.0 - std::pow(1.0 - b.q, b.majority() + 1.0) << " by then)";
    return s.str();
}

} // namespace

TEST_CASE(
    "a camera moving down the mirror corridor: no fireflies where tiles change between screen space and "
    "ray tracing",
    "[hybrid][scene][sequence]") {
    const std::vector<MoveFrame> frames = measureCameraMove();
    std::size_t changed = 0;
    for (std::size_t index = 0; index < frames.size(); ++index) {
        const MoveFrame& m = frames[index];
        INFO(describe(index, m));
        CHECK(m.finite);
        REQUIRE(m.glossy.pixels > 1000);
        REQUIRE(m.transition.pixels > 0);
        for (const Maxima* set : {&m.glossy, &m.transition}) {
            CHECK(set->noisy[kHybrid] <= set->noisyBound());
            CHECK(set->denoised[kHybrid] <= set->denoisedBound());
        }
        // The bound sees a firefly of twice the hybrid's maximum in one tile. (On the switching
        // tiles alone the reference's maximum can be the larger term by more than 2x, e.g. on
        // frame 0's few HALF_SW tiles: there the margins are in the message.)
        CHECK(m.glossy.poisonedNoisy > m.glossy.noisyBound());
        if (index > 0) CHECK(m.changedTiles > 0); // the camera's move keeps changing tiles
        changed += m.changedTiles;
        CHECK(m.classes[GLINT_HYBRID_TILE_FULL_HW] > 0);
    }
    // Screen space was adopted while the camera moved: both paths are in use at the end.
    CHECK(frames.back().classes[GLINT_HYBRID_TILE_FULL_SW] >
          frames.back().classes[GLINT_HYBRID_TILE_FULL_HW]);
    CHECK(changed >= 100);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE(
    "content that appears on screen later: ray-traced tiles return to screen space within the frames the "
    "spawn rate and the safe band allow",
    "[hybrid][scene][sequence][feedback]") {
    const Latency l = measureLatency();
    const LatencyBound b = latencyBound(l, HybridDesc{}.spawnRate);
    INFO(describe(l, b));
    const std::vector<std::size_t> measured = l.measured();
    std::size_t affected = 0;
    for (const bool a : l.affected) affected += a;
    // The setup: the wall is seen in much of the floor, and those tiles were ray traced before.
    REQUIRE(affected >= 30);
    REQUIRE(measured.size() * 10 >= affected * 8);
    // Nothing returns before the wall is there to be seen (the lottery's seeds miss the sky).
    CHECK(l.affectedClasses.front()[GLINT_HYBRID_TILE_FULL_SW] == 0);
    REQUIRE(b.majority() < int(kLatencyFrames));
    const int half = framesUntil(l, 0.5);
    CHECK(half >= 0);
    CHECK(half <= b.majority());
    if (b.all() >= 0 && b.all() < int(kLatencyFrames)) {
        const int all = framesUntil(l, 1.0);
        CHECK(all >= 0);
        CHECK(all <= b.all());
    }
    // Back for good: on the last frame every affected tile uses screen space.
    for (std::size_t t = 0; t < l.affected.size(); ++t)
        if (l.affected[t]) CHECK(l.last[t] != GLINT_HYBRID_TILE_FULL_HW);
    // The bound needs the safe band: the lottery alone would bring back less than half by then.
    CHECK(1.0 - std::pow(1.0 - b.q, b.majority() + 1.0) < 0.5);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("sequence: per-frame measurements", "[.measure-sequence]") {
    const std::vector<MoveFrame> frames = measureCameraMove();
    for (std::size_t index = 0; index < frames.size(); ++index)
        std::printf("%s\n", describe(index, frames[index]).c_str());
    const Latency l = measureLatency();
    std::printf("%s\n", describe(l, latencyBound(l, HybridDesc{}.spawnRate)).c_str());
    for (std::size_t f = 0; f < l.allClasses.size(); ++f) {
        std::printf("frame %zu: all tiles %zu/%zu/%zu", f, l.allClasses[f][0], l.allClasses[f][1],
                    l.allClasses[f][2]);
        if (f + 1 >= kAppearFrame) {
            const auto& a = l.affectedClasses[f + 1 - kAppearFrame];
            std::printf(", affected %zu/%zu/%zu", a[0], a[1], a[2]);
        }
        std::printf("\n");
    }
    for (std::size_t y = 0; y < kTilesY; ++y) {
        for (std::size_t x = 0; x < kTilesX; ++x) {
            const std::size_t t = y * kTilesX + x;
            if (!l.affected[t])
                std::printf("  .");
            else
                std::printf(" %2d", l.back[t]);
        }
        std::printf("\n");
    }
}
