#include "replay/replay_settings.h"

#include <stdexcept>

namespace glint::replay {
namespace {

float parseFloat(const std::string& name, const std::string& value) {
    try {
        std::size_t used = 0;
        const float parsed = std::stof(value, &used);
        if (used == value.size()) return parsed;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument("--set " + name + " needs a number, got '" + value + "'");
}

bool parseBool(const std::string& name, const std::string& value) {
    if (value == "1" || value == "true" || value == "on") return true;
    if (value == "0" || value == "false" || value == "off") return false;
    throw std::invalid_argument("--set " + name + " needs true or false, got '" + value + "'");
}

std::uint32_t parseUint(const std::string& name, const std::string& value) {
    const float parsed = parseFloat(name, value);
    if (parsed < 0.0f || parsed != static_cast<float>(static_cast<std::uint32_t>(parsed)))
        throw std::invalid_argument("--set " + name + " needs a whole number, got '" + value + "'");
    return static_cast<std::uint32_t>(parsed);
}

SpatialPath parseSpatialPath(const std::string& name, const std::string& value) {
    if (value == "prefilter") return SpatialPath::Prefilter;
    if (value == "ratio" || value == "ratioEstimator") return SpatialPath::RatioEstimator;
    throw std::invalid_argument("--set denoiser." + name + " needs prefilter or ratio, got '" + value + "'");
}

Format parseShadowOutputFormat(const std::string& name, const std::string& value) {
    if (value == "r8") return Format::R8Unorm;
    if (value == "r16f") return Format::R16Float;
    if (value == "rg32f") return Format::RG32Float;
    throw std::invalid_argument("--set shadows." + name + " needs r8, r16f or rg32f, got '" + value + "'");
}

bool applySssr(SssrDesc& desc, const std::string& name, const std::string& value) {
    if (name == "samplesPerQuad")
        desc.samplesPerQuad = parseUint(name, value);
    else if (name == "maxTraversalIterations")
        desc.maxTraversalIterations = parseUint(name, value);
    else if (name == "mostDetailedMip")
        desc.mostDetailedMip = parseUint(name, value);
    else if (name == "roughnessThreshold")
        desc.roughnessThreshold = parseFloat(name, value);
    else if (name == "occupancyExitFraction")
        desc.occupancyExitFraction = parseFloat(name, value);
    else if (name == "importanceSampleBias")
        desc.importanceSampleBias = parseFloat(name, value);
    else if (name == "thickness")
        desc.thickness = parseFloat(name, value);
    else if (name == "thicknessAware")
        desc.thicknessAware = parseBool(name, value);
    else if (name == "halfResolution")
        desc.halfResolution = parseBool(name, value);
    else if (name == "previousFrameColor")
        desc.previousFrameColor = parseBool(name, value);
    else if (name == "halfPrecisionStorage")
        desc.halfPrecisionStorage = parseBool(name, value);
    else if (name == "denoise")
        desc.denoise = parseBool(name, value);
    else if (name == "debugOutput")
        desc.debugOutput = parseBool(name, value);
    else if (name == "composite")
        desc.composite = parseBool(name, value);
    else if (name == "varianceGuided")
        desc.varianceGuided = parseBool(name, value);
    else if (name == "varianceThreshold")
        desc.varianceThreshold = parseFloat(name, value);
    else
        return false;
    return true;
}

bool applyShadow(ShadowDenoiserDesc& desc, const std::string& name, const std::string& value) {
    if (name == "filter")
        desc.filter = parseBool(name, value);
    else if (name == "classify")
        desc.classify = parseBool(name, value);
    else if (name == "skipClearedTiles")
        desc.skipClearedTiles = parseBool(name, value);
    else if (name == "fusedFilter")
        desc.fusedFilter = parseBool(name, value);
    else if (name == "antiLag")
        desc.antiLag = parseBool(name, value);
    else if (name == "pairedFilter")
        desc.pairedFilter = parseBool(name, value);
    else if (name == "splitClassify")
        desc.splitClassify = parseBool(name, value);
    else if (name == "outputFormat")
        desc.outputFormat = parseShadowOutputFormat(name, value);
    else if (name == "rebuildClearHistory")
        desc.rebuildClearHistory = parseBool(name, value);
    else if (name == "depthSigma")
        desc.depthSigma = parseFloat(name, value);
    else if (name == "normalPower")
        desc.normalPower = parseFloat(name, value);
    else if (name == "filterVarianceScale")
        desc.filterVarianceScale = parseFloat(name, value);
    else
        return false;
    return true;
}

bool applyDenoiser(ReflectionsDenoiserDesc& desc, const std::string& name, const std::string& value) {
    if (name == "historyClipScale")
        desc.historyClipScale = parseFloat(name, value);
    else if (name == "maxHistoryLength")
        desc.maxHistoryLength = parseUint(name, value);
    else if (name == "spatialPath")
        desc.spatialPath = parseSpatialPath(name, value);
    else if (name == "reconstructionRadius")
        desc.reconstructionRadius = parseFloat(name, value);
    else if (name == "cleanupSigma")
        desc.cleanupSigma = parseFloat(name, value);
    else
        return false;
    return true;
}

bool startsWith(const std::string& text, const std::string& prefix) {
    return text.rfind(prefix, 0) == 0;
}

} // namespace

void applySetting(EffectSettings& settings, const std::string& assignment) {
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos)
        throw std::invalid_argument("--set wants name=value, got '" + assignment + "'");
    std::string name = assignment.substr(0, equals);
    const std::string value = assignment.substr(equals + 1);
    bool known = false;
    if (startsWith(name, "shadows."))
        known = applyShadow(settings.shadows, name.substr(8), value);
    else if (startsWith(name, "denoiser."))
        known = applyDenoiser(settings.denoiser, name.substr(9), value);
    else
        known = applySssr(settings.sssr, startsWith(name, "reflections.") ? name.substr(12) : name, value);
    if (!known)
        throw std::invalid_argument(
            "unknown setting '" + name +
            "' (samplesPerQuad, maxTraversalIterations, mostDetailedMip, roughnessThreshold, "
            "occupancyExitFraction, importanceSampleBias, thickness, thicknessAware, halfResolution, "
            "previousFrameColor, halfPrecisionStorage, denoise, debugOutput, composite, varianceGuided, "
            "varianceThreshold, denoiser.historyClipScale, denoiser.maxHistoryLength, denoiser.spatialPath, "
            "denoiser.reconstructionRadius, denoiser.cleanupSigma, shadows.filter, shadows.classify, "
            "shadows.skipClearedTiles, "
            "shadows.fusedFilter, shadows.pairedFilter, shadows.splitClassify, shadows.outputFormat, "
            "shadows.antiLag, "
            "shadows.rebuildClearHistory, shadows.filterVarianceScale, "
            "shadows.depthSigma, shadows.normalPower)");
    settings.assignments.push_back(assignment);
}

EffectSettings parseSettings(const std::vector<std::string>& assignments) {
    EffectSettings settings;
    for (const std::string& assignment : assignments) applySetting(settings, assignment);
    return settings;
}

void copySssrTunables(const SssrDesc& from, SssrDesc& to) {
    to.samplesPerQuad = from.samplesPerQuad;
    to.maxTraversalIterations = from.maxTraversalIterations;
    to.mostDetailedMip = from.mostDetailedMip;
    to.roughnessThreshold = from.roughnessThreshold;
    to.occupancyExitFraction = from.occupancyExitFraction;
    to.importanceSampleBias = from.importanceSampleBias;
    to.thickness = from.thickness;
    to.thicknessAware = from.thicknessAware;
    to.halfResolution = from.halfResolution;
    to.previousFrameColor = from.previousFrameColor;
    to.halfPrecisionStorage = from.halfPrecisionStorage;
    to.denoise = from.denoise;
    to.debugOutput = from.debugOutput;
    to.composite = from.composite;
    to.varianceGuided = from.varianceGuided;
    to.varianceThreshold = from.varianceThreshold;
}

void copyDenoiserTunables(const ReflectionsDenoiserDesc& from, ReflectionsDenoiserDesc& to) {
    to.historyClipScale = from.historyClipScale;
    to.maxHistoryLength = from.maxHistoryLength;
    to.spatialPath = from.spatialPath;
    to.reconstructionRadius = from.reconstructionRadius;
    to.cleanupSigma = from.cleanupSigma;
}

bool needsSssrRays(const EffectSettings& settings) {
    return settings.sssr.denoise && settings.denoiser.spatialPath == SpatialPath::RatioEstimator;
}

} // namespace glint::replay
