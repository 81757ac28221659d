// A moving occluder and a moving light (issue 7): the history converges on the static
// courtyard for 12 frames, then the ball jumps sideways or the sun turns, and everything holds
// still again. The denoised shadow must follow the new reference within a stated number of
// frames. The receivers do not move, so motion vectors never reset their history: only the
// anti-lag test in classification (this frame's 5x5 mask bits against last frame's accumulated
// shadow of the same window, docs/shadow_denoiser.md "Convergence"), the neighbourhood clamp
// (17x17 mean +- 2 sigma) and the history-length damping let it follow.
//
// The numbers of frames K and the ghost ratios asserted below are the values of the scene at
// 160x90 with small margins; the values themselves, frame by frame, are in
// docs/shadow_denoiser.md ("Motion: the anti-lag test"), and
// `glint_tests_shadow_denoiser_scene "[.measure-tracking]"` prints them. "ghost" is the error
// over the pixels whose reference changed by more than 0.5 with the move (the shadow left or
// arrived there) and whose penumbra is wider than a pixel (narrower ones pass their sample
// through: docs/shadow_denoiser.md, "Hard shadows pass through"), "switched" the fraction of those pixels
// whose output is already nearer the new reference than the old one.
#include "shadow_denoiser/scene_replay.h"
#include "support/gpu_test_context.h"

#include "replay/replay_frame.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <sstream>

using namespace glint;

namespace {

// Frames 0 .. kLastStatic are static (the history converges); the motion runs from the key at
// kLastStatic to the key at kLastStatic + moveFrames, then everything holds still. With a step
// (moveFrames = 1), frame kMoveFrame is the first in the new pose.
constexpr std::uint32_t kLastStatic = 11;
constexpr std::uint32_t kMoveFrame = kLastStatic + 1;

scene::Scene courtyard(std::uint32_t frames) {
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/courtyard_penumbra.toml");
    scene.frameCount = frames;
    scene.reference.shadows = true;
    scene.reference.samplesPerPixel = 64;
    // GLINT_TRACK_SIZE=WxH: for measurements at other sizes (the asserted bounds are the
    // scene's 160x90 ones).
    if (const char* size = std::getenv("GLINT_TRACK_SIZE")) {
        unsigned width = 0, height = 0;
        REQUIRE(std::sscanf(size, "%ux%u", &width, &height) == 2);
        scene.width = width;
        scene.height = height;
    }
    return scene;
}

// The ball (radius 0.6) moves 0.6 units along +x: its shadow shifts by about 7 pixels.
scene::Scene movingBall(std::uint32_t moveFrames, std::uint32_t frames) {
    scene::Scene scene = courtyard(frames);
    for (scene::ObjectDesc& ball : scene.objects) {
        if (ball.name != "ball") continue;
        scene::ObjectKey start = ball.keys.front(), end = start;
        start.frame = static_cast<float>(kLastStatic);
        end.frame = static_cast<float>(kLastStatic + moveFrames);
        end.position[0] += 0.6f;
        ball.keys = {start, end};
        return scene;
    }
    FAIL("the courtyard has no object named 'ball'");
    return scene;
}

// Turns a direction about the vertical axis.
scene::Vec3 turned(const scene::Vec3& d, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    return {static_cast<float>(c * static_cast<double>(d[0]) + s * static_cast<double>(d[2])), d[1],
            static_cast<float>(-s * static_cast<double>(d[0]) + c * static_cast<double>(d[2]))};
}

// The sun (3 degree disc) turns 5 degrees about the vertical: the shadow edges of the walls, the
// post and the ball sweep sideways by 1-3 pixels, the post's tip by more.
scene::Scene turningSun(std::uint32_t moveFrames, std::uint32_t frames) {
    scene::Scene scene = courtyard(frames);
    scene::LightDesc& sun = scene.lights.at(scene.shadowLight);
    scene::LightKey start{static_cast<float>(kLastStatic), sun.direction, sun.position};
    scene::LightKey end = start;
    end.frame = static_cast<float>(kLastStatic + moveFrames);
    end.direction = turned(sun.direction, 5.0);
    sun.keys = {start, end};
    return scene;
}

// Mean absolute error of `value` (every `stride`-th float) against `reference` over the pixels
// `select` accepts; -1 when it accepts none.
template <typename Select>
double meanError(const std::vector<float>& value, std::size_t stride, const std::vector<float>& reference,
                 Select select) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (!select(i)) continue;
        sum += std::abs(static_cast<double>(value[i * stride]) - static_cast<double>(reference[i]));
        ++count;
    }
    return count == 0 ? -1.0 : sum / static_cast<double>(count);
}

struct FrameErrors {
    double penumbra = 0.0;     // denoised, over this frame's penumbra (reference in (0.05, 0.95))
    double ghost = -1.0;       // denoised, over the pixels whose reference changed since kLastStatic
    double ghostAverage = -1.; // the plain running average of the input since frame 0, same pixels
    double stale = -1.0;       // denoised against the reference of frame kLastStatic, same pixels
    double settled = -1.0;     // frame kLastStatic's denoised output against its reference, same pixels
    std::size_t changed = 0;   // pixels with |reference - reference before the move| > 0.5
    double switched = 0.0;     // fraction of those where the output is nearer the new reference
};

// The scene with every keyframe `offset` frames earlier.
scene::Scene shifted(scene::Scene scene, float offset) {
    for (scene::CameraKey& k : scene.camera.keys) k.frame -= offset;
    for (scene::ObjectDesc& o : scene.objects)
        for (scene::ObjectKey& k : o.keys) k.frame -= offset;
    for (scene::LightDesc& l : scene.lights)
        for (scene::LightKey& k : l.keys) k.frame -= offset;
    return scene;
}

// `scene` is static except for keys between kLastStatic and kLastStatic + moveFrames. The
// noisy frames are simulated without references; the references are simulated once per pose
// (the scene shifted so that kLastStatic is frame 0): the static frames share one, so the
// reference, the dearest part of the simulation, is rendered twice instead of every frame.
std::vector<FrameErrors> track(const scene::Scene& scene, std::uint32_t moveFrames) {
    scene::Scene noisy = scene;
    noisy.reference.shadows = false;
    const scene::Simulation sim = scene::simulate(test::testContext(), noisy);
    REQUIRE(sim.frames.size() == scene.frameCount);
    scene::Scene poses = shifted(scene, static_cast<float>(kLastStatic));
    poses.frameCount = moveFrames + 1;
    poses.reference.shadows = true;
    const scene::Simulation referenceSim = scene::simulate(test::testContext(), poses);
    std::vector<std::vector<float>> references;
    for (const capture::Frame& frame : referenceSim.frames)
        references.push_back(replay::layerChannels(frame, "reference.shadow", 1));
    test::SceneShadowReplay replayer;
    std::vector<float> sum, before, settledOutput;
    std::vector<FrameErrors> errors;
    for (std::uint32_t index = 0; index < scene.frameCount; ++index) {
        const auto [inputs, outputs, hard] = replayer.run(sim.frames[index], index);
        const std::vector<float>& reference =
            references[std::min(index, kLastStatic + moveFrames) - std::min(index, kLastStatic)];
        if (sum.empty()) sum.assign(inputs.visibility.size(), 0.0f);
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += inputs.visibility[i];
        if (index == kLastStatic) {
            before = reference;
            settledOutput = outputs.filtered;
        }

        FrameErrors e;
        e.penumbra = meanError(outputs.filtered, 2, reference,
                               [&](std::size_t i) { return reference[i] > 0.05f && reference[i] < 0.95f; });
        REQUIRE(e.penumbra >= 0.0);
        if (index > kLastStatic) {
            // Pixels under a penumbra of at most a pixel pass their sample through (checked by
            // convergence_test): the tracking is measured where the denoiser accumulates.
            const auto changed = [&](std::size_t i) {
                return std::abs(reference[i] - before[i]) > 0.5f && !hard[i];
            };
            for (std::size_t i = 0; i < reference.size(); ++i) e.changed += changed(i) ? 1u : 0u;
            std::vector<float> average(sum.size());
            for (std::size_t i = 0; i < sum.size(); ++i) average[i] = sum[i] / static_cast<float>(index + 1);
            e.ghost = meanError(outputs.filtered, 2, reference, changed);
            e.ghostAverage = meanError(average, 1, reference, changed);
            e.stale = meanError(outputs.filtered, 2, before, changed);
            e.settled = meanError(settledOutput, 2, before, changed);
            std::size_t nearer = 0;
            for (std::size_t i = 0; i < reference.size(); ++i)
                if (changed(i) && std::abs(outputs.filtered[2 * i] - reference[i]) <
                                      std::abs(outputs.filtered[2 * i] - before[i]))
                    ++nearer;
            e.switched =
                static_cast<double>(nearer) / static_cast<double>(std::max<std::size_t>(e.changed, 1));
        }
        errors.push_back(e);
    }
    return errors;
}

std::string table(const std::vector<FrameErrors>& errors) {
    std::ostringstream s;
    s.precision(4);
    s << "frame penumbra ghost ghost(plain average) stale settled changed switched\n";
    for (std::size_t f = 0; f < errors.size(); ++f)
        s << f << " " << errors[f].penumbra << " " << errors[f].ghost << " " << errors[f].ghostAverage << " "
          << errors[f].stale << " " << errors[f].settled << " " << errors[f].changed << " "
          << errors[f].switched << "\n";
    return s.str();
}

// The first frame from which `holds` is true up to the last frame (errors.size() if none).
template <typename Holds> std::size_t holdsFrom(const std::vector<FrameErrors>& errors, Holds holds) {
    std::size_t first = errors.size();
    for (std::size_t f = errors.size(); f-- > kMoveFrame && holds(errors[f]);) first = f;
    return first;
}

// GLINT_TRACK_MOVE: frames the motion takes (1 = a step); GLINT_TRACK_HOLD: frames after it.
std::uint32_t environmentCount(const char* name, std::uint32_t fallback) {
    const char* value = std::getenv(name);
    return value ? static_cast<std::uint32_t>(std::strtoul(value, nullptr, 10)) : fallback;
}

} // namespace

// A step of 0.6 units, then 47 still frames. The moved shadow is followed on the move frame
// itself: around it the 5x5 window's bits contradict the converged histories by far more than
// their binomial noise, so the anti-lag test cuts the history to one frame and the spatial
// filter (boosted for young histories) fills in. Without the test the 17x17 neighbourhood at a
// moved edge holds lit and shadowed pixels (sigma ~ 0.5), the 2-sigma clamp spans [0, 1] and
// the history follows only at the pace of its accumulation. The ghost bound, 0.1, is the
// whole-penumbra error of the static frames before the move.
TEST_CASE("moving occluder: the moved penumbra is followed within a stated number of frames", "[tracking]") {
    const std::vector<FrameErrors> errors = track(movingBall(1, kMoveFrame + 48), 1);
    INFO(table(errors));
    const FrameErrors& moved = errors[kMoveFrame];
    // The pixels the move changed cover both crescents of the ball's shadow, and the history
    // had converged there before the move: a ghost is the move's, not a slow start's.
    REQUIRE(moved.changed > 150u);
    CHECK(moved.settled < 0.05);
    // Lag: 90 % of the changed pixels nearer the new reference than the old one, from then on,
    // within 2 frames of the move (the value plus 2 frames of margin).
    const std::size_t switched = holdsFrom(errors, [](const FrameErrors& e) { return e.switched >= 0.9; });
    CHECK(switched - kMoveFrame <= 2u);
    // Recovery: the ghost under 0.1 and staying there, within 2 frames (the value plus 2).
    const std::size_t recovered = holdsFrom(errors, [](const FrameErrors& e) { return e.ghost < 0.1; });
    CHECK(recovered - kMoveFrame <= 2u);
    // The plain running average of the input over all frames (an independent baseline that
    // never forgets) ghosts over ten times as much on every frame, and at the last frame it is
    // still far from recovered.
    for (std::size_t f = kMoveFrame; f < errors.size(); ++f) {
        INFO("frame " << f);
        CHECK(errors[f].ghost < 0.11 * errors[f].ghostAverage);
    }
    CHECK(errors.back().ghostAverage > 0.15);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

// A 5 degree turn in one step, then 47 still frames. The shadow edges move by one to three
// pixels, well inside the 17x17 neighbourhood, whose mean and sigma hardly change, so the
// clamp never bites. The anti-lag test sees most of them at once (the edge pixels' bits
// contradict confident histories), but not the pixels whose history was near 0.5 (one bit per
// frame cannot contradict it) and not all of a thin shadow that shifted sideways, so a tail of
// a few pixels follows at the pace of the accumulation. The ghost bound, 0.15, is about twice
// these pixels' error before the move.
TEST_CASE("moving light: the turned penumbra is followed within a stated number of frames", "[tracking]") {
    const std::vector<FrameErrors> errors = track(turningSun(1, kMoveFrame + 48), 1);
    INFO(table(errors));
    const FrameErrors& moved = errors[kMoveFrame];
    REQUIRE(moved.changed > 40u);
    CHECK(moved.settled < 0.1);
    // Lag: the value plus 3 frames of margin (the fraction hovers near 0.9 for a few frames: one
    // pixel is 1.6 %).
    const std::size_t switched = holdsFrom(errors, [](const FrameErrors& e) { return e.switched >= 0.9; });
    CHECK(switched - kMoveFrame <= 18u);
    // Recovery: the ghost under 0.15 and staying there; the value plus 3 frames of margin.
    const std::size_t recovered = holdsFrom(errors, [](const FrameErrors& e) { return e.ghost < 0.15; });
    CHECK(recovered - kMoveFrame <= 15u);
    // Against the plain running average: clearly below it on the move frame and the next seven,
    // and further below from 8 frames after it (the values plus margins).
    for (std::size_t f = kMoveFrame; f < errors.size(); ++f) {
        INFO("frame " << f);
        CHECK(errors[f].ghost < (f < kMoveFrame + 8 ? 0.78 : 0.62) * errors[f].ghostAverage);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

// Prints the per-frame table, e.g. for a motion over 4 frames held for 30:
//   GLINT_TRACK_MOVE=4 GLINT_TRACK_HOLD=30 glint_tests_shadow_denoiser_scene "[.measure-tracking]"
TEST_CASE("tracking: per-frame errors of a moving occluder and a moving light", "[.measure-tracking]") {
    const std::uint32_t moveFrames = std::max(environmentCount("GLINT_TRACK_MOVE", 1), 1u);
    const std::uint32_t frames = kLastStatic + moveFrames + environmentCount("GLINT_TRACK_HOLD", 40) + 1;
    WARN("moving occluder\n" << table(track(movingBall(moveFrames, frames), moveFrames)));
    WARN("moving light\n" << table(track(turningSun(moveFrames, frames), moveFrames)));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
