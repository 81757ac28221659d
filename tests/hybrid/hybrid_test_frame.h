// One frame of the hybrid plan (glint_hybrid.h) on the test device from a synthetic SSSR view,
// with a chosen feedback history, everything the tests compare read back.
#pragma once

#include "glint/glint_hybrid.h"
#include "sssr/sssr_test_scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::test {

struct HybridFrame {
    std::vector<std::uint32_t> tileClass, feedback; // per tile: this frame's class and counter
    std::vector<std::uint32_t> counters, arguments; // all words
    std::vector<std::uint32_t> swList;              // counter 1 entries
    std::vector<std::uint32_t> hwList;              // counter 5 entries (counter 4 without hw_args)
    std::vector<std::uint32_t> tileList;            // counter 3 entries
    std::vector<float> radiance, confidence;        // RGBA, R
};

// Runs frame desc.sssr.frameIndex with `history` as last frame's feedback counters, leaving out
// the passes named in `skipPasses`.
HybridFrame runHybridFrame(const HybridDesc& desc, const SssrTestView& view,
                           const std::vector<std::uint32_t>& history,
                           const std::vector<std::string>& skipPasses = {});

} // namespace glint::test
