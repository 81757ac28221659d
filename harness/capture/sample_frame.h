// An analytic, self-consistent sample capture: a perspective camera (standard depth, near
// 0.1, far 100, D3D-style NDC) moving slightly between frames over a ground plane (y = 0)
// and a sphere. Depth, normals and motion are exact per pixel, so tests and the demo can
// check the whole chain against an independent computation.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"

#include <array>
#include <cstdint>

namespace glint::capture {

struct SampleScene {
    std::array<double, 3> sphereCenter{0.0, 0.6, 0.0};
    double sphereRadius = 0.6;
    double groundY = 0.0;
};

inline constexpr SampleScene kSampleScene{};

// The camera of frame `frameIndex` (its prevViewProjection is that of frame index - 1).
Camera sampleCamera(std::uint32_t width, std::uint32_t height, std::uint32_t frameIndex);

// Layers: color (R,G,B, HALF), depth (Z, FLOAT, device depth, 1 on the sky), normal
// (X,Y,Z, FLOAT, unit world normals; the sky gets the direction towards the camera),
// material (R = metalness, G = perceptual roughness varying with x, HALF), motion (X,Y,
// FLOAT, convention A; the sky moves as a point at infinity). Effects {"reflections"}.
Frame makeSampleFrame(std::uint32_t width, std::uint32_t height, std::uint32_t frameIndex);

// A lat-long sky matching the sample's background colour.
Environment makeSampleEnvironment(std::uint32_t width, std::uint32_t height);

} // namespace glint::capture
