// The moving-edge error of replay::referenceErrors (replay_error.h) on hand-made four-pixel
// frames: the receivers where the shadow reference changed by more than 0.25 since the previous
// frame, the output's and the noisy input's mean |out - ref| over them, and what is left empty
// (no previous frame, nothing moved, effects scored by a relative error). Every expected value
// is worked out by hand from those definitions.
#include "replay/replay_error.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace glint;

namespace {

// The run's settings: the defaults with the reflections' mask threshold at 0.2.
SettingValues settings() {
    SettingValues values = defaultSettings(effectRegistry());
    values.set("roughnessThreshold", 0.2);
    return values;
}

// Four pixels in a row: three receivers and one background pixel (standard depth 1).
capture::Frame receivers(std::initializer_list<float> reference) {
    capture::Frame frame;
    frame.width = 4;
    frame.height = 1;
    frame.camera.depth = capture::DepthConvention::Standard;
    frame.layers.push_back({"depth", {"Z"}, {0.5f, 0.5f, 0.5f, 1.0f}});
    frame.layers.push_back({"reference.shadow", {"Y"}, reference});
    return frame;
}

report::Image row(std::initializer_list<float> values) {
    return {static_cast<std::uint32_t>(values.size()), 1, 1, values};
}

replay::FrameResult shadows(const report::Image& denoised, const report::Image& noisy,
                            const report::Image& reference) {
    return {{{"shadows/noisy", "shadows/input", noisy},
             {"shadows/denoised", "shadows/filter2", denoised},
             {"shadows/reference", "shadows/input", reference}},
            {},
            {}};
}

// The reference of `current` (what the replay hands back as shadows/reference).
report::Image referenceOf(const capture::Frame& frame) {
    return row({frame.layers[1].pixels[0], frame.layers[1].pixels[1], frame.layers[1].pixels[2],
                frame.layers[1].pixels[3]});
}

} // namespace

TEST_CASE(
    "the moving-edge error is the mean error over receivers whose reference changed by more than 0.25") {
    // Changes since the previous frame: pixel 0 |0 - 1| = 1 (moving), pixel 1 |0.75 - 0.5| =
    // 0.25 exactly (not more than 0.25: still), pixel 2 |0.8 - 0.5| = 0.3 (moving), pixel 3
    // changes by 1 but is background (not a receiver).
    const capture::Frame previous = receivers({1.0f, 0.5f, 0.5f, 1.0f});
    const capture::Frame current = receivers({0.0f, 0.75f, 0.8f, 0.0f});
    const replay::FrameResult result =
        shadows(row({0.5f, 0.75f, 0.6f, 0.3f}), row({1.0f, 0.0f, 1.0f, 1.0f}), referenceOf(current));
    const std::vector<replay::ReferenceError> errors =
        replay::referenceErrors(current, result, settings(), &previous);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].movingEdgePixels == 2);
    // Denoised: |0.5 - 0| = 0.5 and |0.6 - 0.8| = 0.2, mean 0.35. Noisy: 1 and 0.2, mean 0.6.
    REQUIRE(errors[0].movingEdge.has_value());
    CHECK(*errors[0].movingEdge == Approx(0.35));
    REQUIRE(errors[0].noisyMovingEdge.has_value());
    CHECK(*errors[0].noisyMovingEdge == Approx(0.6));
    // The error over every receiver is unchanged by it: (0.5 + 0 + 0.2) / 3, RMSE
    // sqrt((0.25 + 0 + 0.04) / 3); the noisy input's (1 + 0.75 + 0.2) / 3 and
    // sqrt((1 + 0.5625 + 0.04) / 3).
    CHECK(errors[0].pixels == 3);
    CHECK(errors[0].mean == Approx(0.7 / 3.0));
    CHECK(errors[0].rmse == Approx(std::sqrt(0.29 / 3.0)));
    CHECK(errors[0].noisyMean == Approx(1.95 / 3.0));
    CHECK(errors[0].noisyRmse == Approx(std::sqrt(1.6025 / 3.0)));
}

TEST_CASE(
    "without a previous frame or with no receiver changed, no pixel is a moving edge and nothing is scored") {
    const capture::Frame current = receivers({0.0f, 0.75f, 0.8f, 0.0f});
    const replay::FrameResult result =
        shadows(row({0.5f, 0.75f, 0.6f, 0.3f}), row({1.0f, 0.0f, 1.0f, 1.0f}), referenceOf(current));
    // A sequence's first frame has no previous frame.
    const std::vector<replay::ReferenceError> first = replay::referenceErrors(current, result, settings());
    REQUIRE(first.size() == 1);
    CHECK(first[0].movingEdgePixels == 0);
    CHECK_FALSE(first[0].movingEdge.has_value());
    CHECK_FALSE(first[0].noisyMovingEdge.has_value());
    // The same reference on the frame before: nothing moved, although the output is wrong.
    const capture::Frame still = receivers({0.0f, 0.75f, 0.8f, 0.0f});
    const std::vector<replay::ReferenceError> unmoved =
        replay::referenceErrors(current, result, settings(), &still);
    REQUIRE(unmoved.size() == 1);
    CHECK(unmoved[0].movingEdgePixels == 0);
    CHECK_FALSE(unmoved[0].movingEdge.has_value());
    CHECK_FALSE(unmoved[0].noisyMovingEdge.has_value());
    // A previous frame without a shadow reference cannot tell what moved.
    capture::Frame unreferenced = receivers({1.0f, 1.0f, 1.0f, 1.0f});
    unreferenced.layers.pop_back();
    CHECK(replay::referenceErrors(current, result, settings(), &unreferenced)[0].movingEdgePixels == 0);
}

TEST_CASE("the moving-edge mask keeps masked pixels whose first channel changed by more than the threshold") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    // Pixel 0 changes by 0.5 (kept), pixel 1 by 0.5 outside the mask, pixel 2 to NaN, pixel 3
    // from infinity (neither finite: not moving edges).
    const std::vector<std::uint8_t> mask{1, 0, 1, 1};
    const std::vector<std::uint8_t> moving =
        replay::movingEdgeMask(row({0.0f, 0.0f, nan, 0.0f}), row({0.5f, 0.5f, 0.0f, inf}), mask);
    CHECK(moving == std::vector<std::uint8_t>{1, 0, 0, 0});
    // A threshold of 0.6 keeps none of them.
    CHECK(replay::movingEdgeMask(row({0.0f, 0.0f, 0.0f, 0.0f}), row({0.5f, 0.5f, 0.5f, 0.5f}), mask, 0.6f) ==
          std::vector<std::uint8_t>{0, 0, 0, 0});
    CHECK_THROWS_AS(replay::movingEdgeMask(row({0.0f, 0.0f}), row({0.0f, 0.0f, 0.0f, 0.0f}), mask),
                    std::invalid_argument);
}

TEST_CASE("a previous frame of another size is refused, naming both sizes") {
    const capture::Frame current = receivers({0.0f, 0.75f, 0.8f, 0.0f});
    capture::Frame smaller = receivers({0.0f, 0.0f, 0.0f, 0.0f});
    smaller.width = 2;
    smaller.height = 2;
    const replay::FrameResult result =
        shadows(row({0.5f, 0.75f, 0.6f, 0.3f}), row({1.0f, 0.0f, 1.0f, 1.0f}), referenceOf(current));
    CHECK_THROWS_WITH(replay::referenceErrors(current, result, settings(), &smaller),
                      Catch::Contains("2x2") && Catch::Contains("4x1"));
}

TEST_CASE("reflections, scored by a relative error, get no moving edges") {
    // A glossy surface in every pixel (GGX alpha 0.1 below the threshold 0.2) whose reflection
    // reference changed from 0 to 1 on every pixel.
    const auto glossy = [](float reference) {
        capture::Frame frame;
        frame.width = 4;
        frame.height = 1;
        frame.camera.depth = capture::DepthConvention::Standard;
        frame.roughness = {"material", "roughness", false};
        frame.layers.push_back({"depth", {"Z"}, {0.5f, 0.5f, 0.5f, 0.5f}});
        frame.layers.push_back({"material", {"roughness"}, {0.1f, 0.1f, 0.1f, 0.1f}});
        frame.layers.push_back({"reference.reflection", {"R", "G", "B"}, std::vector<float>(12, reference)});
        return frame;
    };
    const capture::Frame previous = glossy(0.0f), current = glossy(1.0f);
    const report::Image ones{4, 1, 3, std::vector<float>(12, 1.0f)};
    const replay::FrameResult result{{{"reflections/denoised", "reflections/resolve", ones},
                                      {"reflections/reference", "reflections/input", ones}},
                                     {},
                                     {}};
    const std::vector<replay::ReferenceError> errors =
        replay::referenceErrors(current, result, settings(), &previous);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].movingEdgePixels == 0);
    CHECK_FALSE(errors[0].movingEdge.has_value());
}
