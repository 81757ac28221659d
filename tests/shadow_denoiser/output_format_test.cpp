// The final output's formats (ShadowDenoiserDesc::outputFormat): R16F and R8 hold the shadow the
// RG32F output holds, rounded to their format, in clear tiles (classification's store or the
// filter's, without tile skipping) and filtered ones alike, in every plan variant that writes
// the output.
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"
#include "shadow_denoiser/shadow_runner.h"
#include "support/gpu_test_context.h"

#include <gpu/gpu_half.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace glint;

namespace {

// Whether `stored` is what storing x in `format` may give. R8: one of the two 8-bit steps
// next to clamp(x, 0, 1) (Vulkan's float-to-normalized conversion returns either of the two
// closest values and only recommends the nearer, and devices differ: docs/shadow_denoiser.md,
// "Validation"); the 1e-4 step of slack covers the CPU's float arithmetic. R16F: Vulkan leaves
// the rounding mode of float conversions undefined ("rounded to one or the other",
// fundamentals-fp-conversion), so either half next to x.
bool storedAs(Format format, float x, float stored) {
    if (format == Format::R8Unorm) {
        const float steps = std::clamp(x, 0.0f, 1.0f) * 255.0f;
        const float step = std::round(stored * 255.0f);
        return std::abs(stored * 255.0f - step) <= 1e-3f && step >= std::floor(steps - 1e-4f) &&
               step <= std::ceil(steps + 1e-4f);
    }
    const std::uint16_t nearest = gpu::floatToHalf(x);
    const float rounded = gpu::halfToFloat(nearest);
    if (stored == rounded) return true;
    if (rounded == x || std::isnan(x) || std::isinf(rounded)) return false;
    // The other neighbour: one step from the nearest towards x (magnitude bits, sign kept).
    const auto other =
        static_cast<std::uint16_t>(std::abs(x) > std::abs(rounded) ? nearest + 1 : nearest - 1);
    return stored == gpu::halfToFloat(other);
}

struct Variant {
    const char* what;
    bool skipClearedTiles, splitClassify, pairedFilter;
};

} // namespace

TEST_CASE("output formats: R16F and R8 hold the RG32F output's shadow, rounded",
          "[classify][tiles][format]") {
    // Odd size (partial tiles and groups), motion and history over three frames, lit and
    // shadowed bands so that clear and filtered tiles meet.
    constexpr std::uint32_t width = 53, height = 37;
    test::ShadowInputs inputs = test::movingShadowInputs(width, height, 31);
    test::addUniformBands(inputs, width, height);
    const Variant variants[] = {
        {"default: split classification, paired filter", true, true, true},
        {"one classification dispatch, three filter dispatches", true, false, false},
        {"paired filter without tile skipping", false, true, true},
    };
    for (const Variant& variant : variants) {
        ShadowDenoiserDesc desc;
        desc.size = {width, height};
        desc.skipClearedTiles = variant.skipClearedTiles;
        desc.splitClassify = variant.splitClassify;
        desc.pairedFilter = variant.pairedFilter;
        desc.outputFormat = Format::RG32Float;
        const test::ShadowOutputs wide = test::runThreeFrames(desc, inputs);
        const std::size_t count = std::size_t{width} * height;
        REQUIRE(wide.filtered.size() == 2 * count);
        for (Format format : {Format::R16Float, Format::R8Unorm}) {
            INFO(variant.what << (format == Format::R8Unorm ? ", R8" : ", R16F"));
            desc.outputFormat = format;
            const test::ShadowOutputs narrow = test::runThreeFrames(desc, inputs);
            REQUIRE(narrow.filtered.size() == 2 * count);
            CHECK(narrow.metadata == wide.metadata);
            std::size_t clearPixels = 0, filteredPixels = 0, fractional = 0, mismatches = 0;
            for (std::size_t i = 0; i < count; ++i) {
                const std::size_t tile = (i / width / 8) * ((width + 7) / 8) + (i % width) / 8;
                ++(wide.metadata.at(tile) & GLINT_SHADOW_DENOISER_TILE_CLEAR ? clearPixels : filteredPixels);
                const float x = wide.filtered[2 * i];
                fractional += x > 0.01f && x < 0.99f ? 1u : 0u;
                const float stored = narrow.filtered[2 * i];
                const bool same = storedAs(format, x, stored);
                // One channel: no variance (ShadowOutputs::filtered).
                if (!same || narrow.filtered[2 * i + 1] != 0.0f) {
                    if (mismatches < 6)
                        UNSCOPED_INFO("pixel " << i << ": rg32f " << x << ", stored " << stored
                                               << ", variance " << narrow.filtered[2 * i + 1]);
                    ++mismatches;
                }
            }
            CHECK(mismatches == 0u);
            // Not vacuous: both kinds of tile, and penumbra values that must be rounded.
            CHECK(clearPixels >= 2u * 64u);
            CHECK(filteredPixels > count / 8);
            CHECK(fractional > count / 8);
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
