// The in-memory form of one glint frame capture (format v1, docs/capture-format.md).
//
// Plain data: the readers fill it, the writers serialize it, and validation lives in
// frame_validation.h so that both directions apply the same rules.
#pragma once

#include "capture/mat4.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glint::capture {

inline constexpr std::uint32_t kFormatVersion = 1;

enum class DepthConvention { Standard, Reversed, ReversedInfinite };

struct Camera {
    Mat4 view;               // world -> view
    Mat4 projection;         // view -> clip, unjittered
    Mat4 prevViewProjection; // world -> previous frame's clip, unjittered
    DepthConvention depth = DepthConvention::Standard;
    double nearZ = 0.1;
    double farZ = 100.0; // +infinity is allowed (and expected) for ReversedInfinite
    // true: Vulkan-style NDC (+y down, top row at y = -1); false: D3D-style (+y up).
    bool ndcYDown = false;
};

enum class NormalEncoding {
    WorldUnit,  // X,Y,Z: unit world-space normal
    WorldUnorm, // X,Y,Z: n * 0.5 + 0.5
    Octahedral, // X,Y: octahedral encoding in [0,1] (docs/conventions.md §5)
};

// How the stored motion layer is to be read. The stored vector multiplied component-wise
// by `scale` is (previous - current) position in `units`; see motion_convention.h, the one
// place that turns it into the package's convention A.
enum class MotionUnits { Uv, Pixels, Ndc };

struct Float2 {
    float x = 0.0f, y = 0.0f;
};

struct MotionConvention {
    MotionUnits units = MotionUnits::Uv;
    Float2 scale{1.0f, 1.0f};
};

// Where perceptual roughness or GGX alpha comes from: a channel of a layer, e.g.
// {"roughness", "Y"} or {"material", "G"}. Empty when no declared effect needs it.
struct RoughnessSource {
    std::string layer;
    std::string channel;
    bool perceptual = true; // true: stored value is r; false: stored value is alpha = r^2
};

// How a layer's channels are stored in the file. In memory every sample is a float.
enum class SampleType { Half, Float };

struct Layer {
    std::string name;                  // "color", "depth", "reference.reflection", ...
    std::vector<std::string> channels; // e.g. {"R","G","B"}
    std::vector<float> pixels;         // interleaved, row-major, origin top-left, w*h*channels
    std::size_t nonFinite = 0;         // NaN/Inf samples, counted when the layer is read
    SampleType storage = SampleType::Float;
};

// A layer's shape without its pixels, for header-only inspection.
struct LayerInfo {
    std::string name;
    std::vector<std::string> channels;
    SampleType storage = SampleType::Float;
};

// Everything in a frame file except pixel data: what `glint info` needs, cheaply.
struct FrameHeader {
    std::uint32_t width = 0, height = 0;
    std::uint32_t formatVersion = kFormatVersion;
    std::uint32_t frameIndex = 0;
    Camera camera;
    NormalEncoding normalEncoding = NormalEncoding::WorldUnit;
    MotionConvention motion;
    RoughnessSource roughness;
    // tan of the angular radius of the light the `shadow` layer samples (a directional light);
    // 0 for a light of angular radius 0 (hard shadows); negative when unknown (attribute
    // glint.shadowLightTanHalfAngle absent).
    double shadowLightTanHalfAngle = -1.0;
    std::vector<std::string> effects; // "reflections", "shadows", "depth_pyramid"
    std::vector<LayerInfo> layers;
};

struct Frame {
    std::uint32_t width = 0, height = 0;
    std::uint32_t formatVersion = kFormatVersion;
    std::uint32_t frameIndex = 0;
    Camera camera;
    NormalEncoding normalEncoding = NormalEncoding::WorldUnit;
    MotionConvention motion;
    RoughnessSource roughness;
    double shadowLightTanHalfAngle = -1.0; // as FrameHeader's
    std::vector<std::string> effects;
    std::vector<Layer> layers;
};

struct NonFiniteCount {
    std::string layer;
    std::size_t count = 0;
};

// Non-finite samples of a frame, per layer (only layers with at least one) and in total.
struct NonFiniteSummary {
    std::vector<NonFiniteCount> layers;
    std::size_t total = 0;
};

const Layer* findLayer(const Frame& frame, std::string_view name);
Layer* findLayer(Frame& frame, std::string_view name);
const LayerInfo* findLayer(const FrameHeader& header, std::string_view name);
// Index of `channel` in layer.channels, or -1.
int channelIndex(const std::vector<std::string>& channels, std::string_view channel);

std::size_t countNonFinite(const std::vector<float>& samples);
NonFiniteSummary summarizeNonFinite(const Frame& frame);

FrameHeader headerOf(const Frame& frame);
// A frame carrying `header`'s metadata and no layers yet.
Frame frameFromHeader(const FrameHeader& header);

// P·V of the current frame (unjittered).
Mat4 viewProjection(const Camera& camera);

} // namespace glint::capture
