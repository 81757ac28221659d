// "name=value" settings for the effects, shared by `glint bench`, `glint run`, `glint dump`
// and `glint study`, so that one spelling sweeps the same option everywhere.
//   reflections: samplesPerQuad, maxTraversalIterations, mostDetailedMip, roughnessThreshold,
//                occupancyExitFraction, importanceSampleBias, thickness, thicknessAware,
//                halfResolution, previousFrameColor, halfPrecisionStorage, denoise, debugOutput,
//                composite, varianceGuided, varianceThreshold
//                (also accepted with a "reflections." prefix)
//   reflections denoiser: denoiser.historyClipScale, denoiser.maxHistoryLength,
//                         denoiser.spatialPath (prefilter | ratio), denoiser.reconstructionRadius,
//                         denoiser.cleanupSigma
//   shadows: shadows.filter, shadows.classify, shadows.skipClearedTiles, shadows.fusedFilter,
//            shadows.pairedFilter, shadows.splitClassify, shadows.outputFormat (r8 | r16f | rg32f),
//            shadows.antiLag, shadows.rebuildClearHistory, shadows.filterVarianceScale,
//            shadows.depthSigma, shadows.normalPower
#pragma once

#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_shadow_denoiser.h"
#include "glint/glint_sssr.h"

#include <string>
#include <vector>

namespace glint::replay {

struct EffectSettings {
    SssrDesc sssr;                        // only the tunables are read from it
    ReflectionsDenoiserDesc denoiser;     // the tunables copyDenoiserTunables copies
    ShadowDenoiserDesc shadows;           // the shadows.* tunables above
    std::vector<std::string> assignments; // as given, for reports
};

// Applies one "name=value"; throws std::invalid_argument naming the setting and listing the
// known ones.
void applySetting(EffectSettings& settings, const std::string& assignment);
EffectSettings parseSettings(const std::vector<std::string>& assignments);

// Copies the tunables (not the camera, size or decoding) of `from` onto `to`.
void copySssrTunables(const SssrDesc& from, SssrDesc& to);

// Copies the denoiser's tunables (history clip scale and length, spatial path, reconstruction
// radius, cleanup sigma) of `from` onto `to`.
void copyDenoiserTunables(const ReflectionsDenoiserDesc& from, ReflectionsDenoiserDesc& to);

// Whether SSSR must store its rays (SssrDesc::storeRays) for the denoiser these settings ask for.
bool needsSssrRays(const EffectSettings& settings);

} // namespace glint::replay
