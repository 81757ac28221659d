// replay::referenceErrors and replay::referenceNoise on hand-made frames: the clamped MAE and
// RMSE (radiance clamped to [0, kMaeClamp]), the mask (glossy surface pixels for reflections,
// receivers for shadows), and the floor of two references, each checked against values worked
// out by hand from the definitions in replay_error.h.
#include "replay/replay_error.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace glint;

namespace {

// The run's settings: the defaults with the reflections' mask threshold at 0.2.
SettingValues settings() {
    SettingValues values = defaultSettings(effectRegistry());
    values.set("roughnessThreshold", 0.2);
    return values;
}

// Four pixels in a row: three surfaces (roughness 0.1, 0.1, 0.9) and one background pixel.
capture::Frame fourPixels() {
    capture::Frame frame;
    frame.width = 4;
    frame.height = 1;
    frame.camera.depth = capture::DepthConvention::Standard;
    frame.roughness = {"material", "roughness", false}; // stored as GGX alpha
    frame.layers.push_back({"depth", {"Z"}, {0.5f, 0.5f, 0.5f, 1.0f}});
    frame.layers.push_back({"material", {"roughness"}, {0.1f, 0.1f, 0.9f, 0.1f}});
    return frame;
}

report::Image grey(std::initializer_list<float> values) {
    report::Image image{static_cast<std::uint32_t>(values.size()), 1, 3, {}};
    for (float v : values) image.pixels.insert(image.pixels.end(), {v, v, v});
    return image;
}

replay::FrameResult reflections(const report::Image& output, const report::Image& reference) {
    return {{{"reflections/denoised", "reflections/resolve", output},
             {"reflections/reference", "reflections/input", reference}},
            {},
            {}};
}

} // namespace

TEST_CASE("clamped MAE and RMSE clamp both images to [0, 16] and score only glossy surface pixels") {
    const capture::Frame frame = fourPixels();
    // Glossy surface pixels are 0 and 1 (alpha 0.1 < 0.2); pixel 2 is rough, pixel 3 is sky.
    // Pixel 0: out 20 -> 16, ref 4: |16 - 4| = 12. Pixel 1: out 1, ref 3: 2.
    const replay::FrameResult result =
        reflections(grey({20.0f, 1.0f, 100.0f, 50.0f}), grey({4.0f, 3.0f, 0.0f, 0.0f}));
    const std::vector<replay::ReferenceError> errors = replay::referenceErrors(frame, result, settings());
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].pixels == 2);
    CHECK(errors[0].maeClamped == Approx((12.0 + 2.0) / 2.0));
    CHECK(errors[0].rmseClamped == Approx(std::sqrt((144.0 + 4.0) / 2.0)));
    // The unclamped RMSE sees the 16 -> 20 difference: sqrt((256 + 4) / 2).
    CHECK(errors[0].rmse == Approx(std::sqrt((256.0 + 4.0) / 2.0)));
}

TEST_CASE("a non-finite output pixel counts as the largest clamped difference") {
    const capture::Frame frame = fourPixels();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const replay::FrameResult result =
        reflections(grey({nan, 3.0f, 0.0f, 0.0f}), grey({4.0f, 3.0f, 0.0f, 0.0f}));
    const std::vector<replay::ReferenceError> errors = replay::referenceErrors(frame, result, settings());
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].maeClamped == Approx(replay::kMaeClamp / 2.0));
    CHECK(errors[0].rmseClamped == Approx(replay::kMaeClamp / std::sqrt(2.0)));
    CHECK(errors[0].nonFinite == Approx(0.25));
}

TEST_CASE("the reference noise floor is the two references' difference over the same mask") {
    capture::Frame second = fourPixels();
    // The second reference differs by 1 on pixel 0 and by 30 (clamped: 12) on the rough pixel 2.
    second.layers.push_back({"reference.reflection", {"R", "G", "B"}, {}});
    for (float v : {5.0f, 3.0f, 30.0f, 0.0f})
        second.layers.back().pixels.insert(second.layers.back().pixels.end(), {v, v, v});
    const replay::FrameResult result =
        reflections(grey({0.0f, 0.0f, 0.0f, 0.0f}), grey({4.0f, 3.0f, 0.0f, 0.0f}));
    const std::vector<replay::ReferenceError> noise =
        replay::referenceNoise(fourPixels(), result, second, settings());
    REQUIRE(noise.size() == 1);
    CHECK(noise[0].effect == "reflections");
    CHECK(noise[0].pixels == 2); // the rough pixel's difference is outside the mask
    CHECK(noise[0].maeClamped == Approx(0.5));
    CHECK(noise[0].rmseClamped == Approx(std::sqrt(0.5)));
    // Identical references have no floor.
    capture::Frame same = fourPixels();
    same.layers.push_back({"reference.reflection", {"R", "G", "B"}, {}});
    for (float v : {4.0f, 3.0f, 0.0f, 0.0f})
        same.layers.back().pixels.insert(same.layers.back().pixels.end(), {v, v, v});
    const std::vector<replay::ReferenceError> none =
        replay::referenceNoise(fourPixels(), result, same, settings());
    REQUIRE(none.size() == 1);
    CHECK(none[0].maeClamped == 0.0);
    CHECK(none[0].mean == 0.0);
}
