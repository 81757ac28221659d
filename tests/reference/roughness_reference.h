// Independent CPU reference for roughness extraction, written from docs/conventions.md §4
// (alpha = r^2, convert once) and the header's stated policy for bad input, not from the HLSL.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace glint::reference {

inline float alphaFromStoredRoughness(float stored, bool inputIsPerceptual) {
    float value;
    if (std::isnan(stored) || stored == -INFINITY)
        value = 1.0f; // undefined roughness is treated as fully rough
    else
        value = std::fmin(std::fmax(stored, 0.0f), 1.0f);
    return inputIsPerceptual ? value * value : value;
}

// material: interleaved channels per pixel; returns one alpha per pixel.
inline std::vector<float> extractRoughness(const std::vector<float>& material, std::size_t channels,
                                           std::size_t channel, bool inputIsPerceptual) {
    std::vector<float> alpha(material.size() / channels);
    for (std::size_t i = 0; i < alpha.size(); ++i)
        alpha[i] = alphaFromStoredRoughness(material[i * channels + channel], inputIsPerceptual);
    return alpha;
}

} // namespace glint::reference
