// CPU references of the reflections denoiser's ratio-estimator path
// (docs/reflections_denoiser.md, "Ratio-estimator path"): the reconstruction and the bilateral
// cleanup of one pixel, in double precision, written from the documented formulas and
// independent of the shaders.
#pragma once

#include "reference/reflections_denoiser_reference.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace glint::reference {

// A sample's ray as SSSR stores it: world direction (unit, or zero when empty) and pdf.
struct StoredRay {
    Rgb direction{};
    double pdf = 0.0;
};

struct ReconstructInputs {
    const DenoiserSurface* surface = nullptr;
    std::vector<Rgb> view;        // per pixel: unit world direction toward the camera
    std::vector<Rgb> radiance;    // reproject's clamped sample
    std::vector<StoredRay> rays;  // SSSR's rays
    std::vector<double> variance; // reproject's temporal variance
    double mirrorThreshold = 1e-4;
    double radius = 4.0; // reconstructionRadius
    std::uint32_t frameIndex = 0;
};

struct ReconstructResult {
    RadianceVariance value;
    // A tap's pixel offset lies within 1e-3 of a rounding boundary (x.5), where float32 and
    // double may pick different pixels: not comparable.
    bool ambiguous = false;
};

// The reconstruction of one in-image pixel: rgb 0 and variance kNotGlossyVariance for pixels
// that are not glossy (the prefilter's marking), the sample and its temporal variance for
// mirrors, the ratio estimate otherwise.
ReconstructResult reconstructPixel(const ReconstructInputs& inputs, std::uint32_t x, std::uint32_t y);

// The reconstruction's 8 disk taps: the Vogel spiral r_k = sqrt((k + 0.5) / 8),
// theta_k = k pi (3 - sqrt 5).
std::array<std::array<double, 2>, 8> reconstructionTaps();

struct CleanupInputs {
    const DenoiserSurface* surface = nullptr;
    std::vector<Rgb> resolved;    // the resolve's radiance
    std::vector<double> variance; // the resolve's variance
    double sigma = 0.9;
};

// The cleanup's result for one glossy pixel, or nothing when the pixel is not filtered (its
// output stays the resolve's).
std::optional<Rgb> cleanupPixel(const CleanupInputs& inputs, std::uint32_t x, std::uint32_t y);

} // namespace glint::reference
