// Blender (Cycles) renders made from glint's analytic sample frames, written the way Cycles
// and the recipe of docs/replay.md write them: multilayer EXR frames named by frame number
// with Cycles' layer names and conventions, camera.json as the export script writes it, and a
// world panorama in Blender's orientation. The channel-map tests and glint_make_blender_sample
// (the CLI tests' fixture) use them. No test framework here: failures throw.
#pragma once

#include <capture/capture_frame.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace glint::capture::test {

inline constexpr std::uint32_t kForeignWidth = 64, kForeignHeight = 48;

struct ExrChannel {
    std::string name;
    std::vector<float> samples;
    bool half = false;
};

// A plain single-part file with arbitrary channel names, as other tools write them (no glint
// attributes).
void writeForeignExr(const std::filesystem::path& file, std::vector<ExrChannel> channels,
                     std::uint32_t width = kForeignWidth, std::uint32_t height = kForeignHeight);

const std::vector<float>& layerSamples(const Frame& frame, const char* layer); // throws when absent
bool isSky(const Frame& sample, std::size_t pixel);

// Blender's world is Z-up: Blender (x, y, z) = glint (x, -z, y).
std::array<double, 3> toBlender(double x, double y, double z);
// The view matrix over Blender's world axes: V_b · p_b = V · p for p = (p_b.x, p_b.z, -p_b.y).
Mat4 blenderView(const Mat4& view);
// The camera's projection as OpenGL writes it (and Blender's calc_matrix_camera returns it).
Mat4 openGlProjection(const Camera& camera);
// View depth of a standard device depth, docs/conventions.md §2.
double viewDepth(double deviceDepth, double nearZ, double farZ);
// 4 rows of 4, as camera.json holds matrices.
nlohmann::json jsonRows(const Mat4& m);

// Passes of a written frame beyond Combined, Depth, Normal and Vector.
struct BlenderPasses {
    bool roughness = true;     // the roughness AOV (ViewLayer.roughness.X)
    bool diffuseColor = false; // Cycles' Diffuse Color pass (ViewLayer.DiffCol.R,G,B)
};

// The Diffuse Color pass written for pixel `i`: a ramp over the image, R,G,B in [0, 1].
std::array<float, 3> diffuseColorAt(std::size_t pixel);

// Sample frame `index` as Cycles writes it, as dir/name.
void writeBlenderFrame(const std::filesystem::path& dir, const std::string& name, std::uint32_t index,
                       BlenderPasses passes = {});

// camera.json for 0001.exr (sample frame 0, field of view) and 0002.exr (sample frame 1,
// OpenGL projection matrix), as the export script in docs/replay.md writes it.
nlohmann::json blenderCameras();

// 0001.exr, 0002.exr and camera.json in dir.
void writeBlenderCapture(const std::filesystem::path& dir, BlenderPasses passes = {});

// The value written for a Blender world direction: 0.5 + 0.5 · direction, so that the texel
// says which direction it was rendered for.
std::array<float, 3> worldValue(const std::array<double, 3>& blenderDirection);

// A world panorama as Cycles renders it with a panoramic equirectangular camera pointed along
// +X (Blender's environment-texture orientation): centre column +X, top row +Z, +Y left of
// the centre; R,G,B(,A) FLOAT without OpenEXR's envmap attribute, as Blender saves it.
void writeBlenderWorld(const std::filesystem::path& file, std::uint32_t width, std::uint32_t height);

} // namespace glint::capture::test
