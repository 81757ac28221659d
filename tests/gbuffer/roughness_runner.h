// Runs the roughness extraction plan on the test context: upload an RGBA32F material,
// execute through the Vulkan executor with a timestamp around the dispatch, read back alpha.
#pragma once

#include "glint/glint_gbuffer.h"

#include <gpu/gpu_context.h>

#include <vector>

namespace glint::test {

struct RoughnessRun {
    std::vector<float> alpha; // one value per pixel, row-major
    double dispatchMs = -1.0; // GPU time of the dispatch; < 0 when the queue has no timestamps
};

// material: 4 floats per pixel (RGBA).
RoughnessRun runRoughnessExtraction(gpu::Context& context, const std::vector<float>& material,
                                    const RoughnessExtractionDesc& desc);

} // namespace glint::test
