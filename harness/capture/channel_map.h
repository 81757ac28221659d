// Foreign captures through a channel map (docs/replay.md): a TOML file that says which
// channels of another tool's OpenEXR files hold glint's layers, and in which conventions, so
// that a Blender render or a RenderDoc texture dump becomes a capture::Frame.
//
// Typical use:
//   const ChannelMap map = loadChannelMap("harness/maps/blender.toml");
//   const std::vector<std::string> frames = mappedSequenceFiles("renders/", map);
//   for (std::size_t i = 0; i < frames.size(); ++i)
//       Frame frame = readMappedFrame(frames[i], map, static_cast<std::uint32_t>(i));
//   std::optional<Environment> sky = loadMappedEnvironment(map, "renders/");
//
// Every failure throws CaptureError (a std::runtime_error) whose what() is one line naming
// the file (map, frame, side file) and the problem.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::capture {

// A source channel is named as in the file ("ViewLayer.Depth.Z"). When each frame is a
// folder of files (one texture per file, e.g. from RenderDoc), it is "<file>.exr:<channel>"
// with the file relative to the frame's folder ("depth.exr:R").
struct ChannelRef {
    std::string file; // empty: the frame's own file
    std::string channel;
};
// Splits at the first ".exr:" (any case); a name without one is a plain channel name.
ChannelRef splitChannelRef(const std::string& ref);

// A signed axis permutation: out[i] = sign[i] * in[axis[i]], written in the map as three
// names such as ["x", "z", "-y"].
struct AxisMap {
    std::array<int, 3> axis{0, 1, 2};
    std::array<double, 3> sign{1.0, 1.0, 1.0};
};

// One signed axis ("-y": axis 1, sign -1).
struct AxisDirection {
    int axis = 0;
    double sign = 1.0;
};

enum class DepthKind {
    Device,   // device depth in camera.depth_convention, copied as is
    ViewZ,    // positive distance along the view axis (Blender's Z pass: distance to the camera plane)
    Distance, // Euclidean distance from the eye (perspective cameras only)
};

struct DepthMapping {
    std::string channel;
    DepthKind kind = DepthKind::Device;
    // Linear depth at or beyond this (or beyond the far plane, non-finite or <= 0) is background.
    double backgroundFrom = std::numeric_limits<double>::infinity();
};

enum class NormalSpace { World, View };
enum class NormalStorage { Unit, Unorm, Octahedral };

struct NormalMapping {
    std::vector<std::string> channels; // x, y, z (unit, unorm) or x, y (octahedral)
    NormalSpace space = NormalSpace::World;
    NormalStorage storage = NormalStorage::Unit;
    AxisMap axes; // applied to the decoded vector in its own space, before anything else
};

struct RoughnessMapping {
    std::string channel;
    bool perceptual = true; // false: the channel holds GGX alpha = r^2
};

enum class MotionDirection {
    ToPrevious,   // stored vector = previous - current position (glint's convention A direction)
    FromPrevious, // stored vector = current - previous position
};
enum class BackgroundMotion {
    Keep,   // use what the file holds
    Camera, // replace background pixels by the reprojection of a point at infinity
};

struct MotionMapping {
    std::vector<std::string> channels; // x, y
    MotionUnits units = MotionUnits::Uv;
    MotionDirection direction = MotionDirection::ToPrevious;
    Float2 scale{1.0f, 1.0f}; // applied to the stored vector first
    bool yUp = false;         // pixels/uv: the stored +y points up the image (glint's points down)
    BackgroundMotion background = BackgroundMotion::Keep;
};

enum class CameraSource { SideFile, Header };
enum class HeaderViewSpace {
    OpenExr, // OpenEXR's worldToCamera: row vectors, +x right, +y up, +z forward
    OpenGl,  // row vectors (as Imath stores them), +x right, +y up, looking down -z
};

struct CameraMapping {
    CameraSource source = CameraSource::SideFile;
    std::string file = "camera.json"; // side file, relative to the capture folder
    // Header source: attribute names, or fixed numbers where the attribute name is empty.
    std::string viewAttribute;
    HeaderViewSpace viewSpace = HeaderViewSpace::OpenExr;
    std::string fovYAttribute, nearAttribute, farAttribute;
    double fovYDegrees = 0.0, nearZ = 0.0, farZ = 0.0;
    // The produced frame's conventions.
    DepthConvention depth = DepthConvention::Standard;
    bool ndcYDown = false;
};

// The environment map of a mapped capture (docs/replay.md, "[environment]").
struct EnvironmentMapping {
    std::string file;      // relative to the capture folder; empty: no environment
    bool optional = false; // a missing file means no environment rather than an error
    // A lat-long file's orientation in the source world, as signed source axes: the direction
    // at the image centre (`center`, from the map, horizontal) and at its top row (`up`, always
    // the source axis that [world] axes turns into glint's +y). The default centre is the one
    // that becomes glint's +z: the file is then a glint environment map.
    AxisDirection center{2, 1.0}, up{1, 1.0};
};

struct ChannelMap {
    std::string path; // the map file, for messages
    std::vector<std::string> effects;
    bool framesAreFolders = false;  // channels name files: one folder of textures per frame
    bool flipVertical = false;      // the files store the bottom row first
    AxisMap worldAxes;              // glint world axis i = sign[i] * source world axis[axis[i]]
    std::vector<std::string> color; // R, G, B (+ A); empty when not mapped
    std::optional<DepthMapping> depth;
    std::optional<NormalMapping> normal;
    std::optional<RoughnessMapping> roughness;
    std::optional<MotionMapping> motion;
    std::string shadow;                           // -> shadow.Y
    std::vector<std::string> referenceReflection; // -> reference.reflection.R,G,B
    std::string referenceShadow;                  // -> reference.shadow.Y
    std::vector<std::string> baseColor;           // -> material.R,G,B
    std::string metallic;                         // -> material.A
    bool materialOptional = false;                // frames may lack the material channels
    CameraMapping camera;
    EnvironmentMapping environment;
    // Name patterns of the capture folder's frames (`*` any run of characters, `?` one
    // character, `#` one digit); empty: every .exr file (every folder for folder frames).
    std::vector<std::string> frames;
};

// Whether a frame's file (or folder) name matches one of the map's `frames` patterns.
bool matchesFramePattern(std::string_view name, std::string_view pattern);

// Reads and checks a map file: unknown keys, missing fields, bad values and layers the
// declared effects need but the map lacks are errors naming the file, line and key.
ChannelMap loadChannelMap(const std::string& path);

// Frames of a mapped capture in playback order. `dirOrFile` is one frame (a file, or a
// folder when map.framesAreFolders) or a folder of them: its .exr files (or, for folder
// frames, its sub-folders) in natural name order ("2.exr" before "10.exr"), leaving out the
// map's environment file. With map.frames, only the names that match one of its patterns;
// the other candidates' names go into `ignored` (when given), for a note to the user.
std::vector<std::string> mappedSequenceFiles(const std::string& dirOrFile, const ChannelMap& map,
                                             std::vector<std::string>* ignored = nullptr);

// The capture folder that the map's side files (camera.file, environment) are relative to:
// `dirOrFile` itself when it is a folder of frames, the folder holding it when it is a frame.
std::string mappedCaptureFolder(const std::string& dirOrFile, const ChannelMap& map);

// The camera of one frame in glint's conventions, from the side file or the frame's header.
// When the source gives no previous view-projection, it is that of the previous frame (the
// previous side-file entry or, for header cameras, the previous file of the folder); the
// first frame gets its own (no camera motion).
Camera mappedCamera(const std::string& framePath, const ChannelMap& map, std::uint32_t width,
                    std::uint32_t height);

// Reads the mapped channels of one frame, converts them to glint's conventions (device depth,
// unit world normals, motion convention A), validates the result as writeFrame would and
// returns it with frame index `frameIndex`.
Frame readMappedFrame(const std::string& framePath, const ChannelMap& map, std::uint32_t frameIndex);

// Everything readMappedFrame checks before it reads pixels: every source file's header and
// mapped channels, that the files agree in size and can hold their pixel data, and the frame's
// camera. Returns whether the mapped depth channel is stored as HALF.
bool checkMappedFrame(const std::string& framePath, const ChannelMap& map);

// The environment file the map names, resolved in the capture folder of `dirOrFile` (a
// sequence folder or one of its frames); empty when the map names none.
std::filesystem::path mappedEnvironmentFile(const ChannelMap& map, const std::string& dirOrFile);

// The environment the map names, read from the capture folder of `dirOrFile` and turned into
// glint's world axes (a lat-long file in another orientation is re-indexed, texel for texel);
// empty when the map names none, or names an optional one that is not there. A file without
// OpenEXR's `envmap` attribute (as other tools write them) is read as lat-long.
std::optional<Environment> loadMappedEnvironment(const ChannelMap& map, const std::string& dirOrFile);

} // namespace glint::capture
