// Cameras of mapped captures: from a JSON side file or from the frame's OpenEXR header,
// turned into glint's camera (docs/replay.md, "Camera").
#include "capture/channel_map.h"

#include "capture/capture_error.h"
#include "capture/enum_names.h"
#include "capture/exr_file.h"
#include "capture/frame_validation.h"
#include "capture/json_text.h"

#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>

namespace glint::capture {

namespace {
using Json = nlohmann::json;

enum class ProjectionKind { Given, OpenGl, FovY };

// A camera as the source describes it, in the source's world axes.
struct SourceCamera {
    Mat4 view; // world -> view, column vectors, right-handed, looking down -z
    ProjectionKind kind = ProjectionKind::FovY;
    Mat4 projection; // Given: used as is; OpenGl: its x, y and w rows are kept
    double fovYDegrees = 0.0;
    double nearZ = 0.0, farZ = 0.0;
    std::optional<Mat4> prevViewProjection; // glint clip space, source world axes
};

// glint world = A · source world.
Mat4 axisMatrix(const AxisMap& axes) {
    Mat4 a;
    for (std::size_t i = 0; i < 3; ++i) a.m[i * 4 + static_cast<std::size_t>(axes.axis[i])] = axes.sign[i];
    a.m[15] = 1.0;
    return a;
}

// The projection's depth row for the produced frame's convention; the x and y rows (field of
// view, aspect, lens shift) come from the source unchanged.
Mat4 buildProjection(const SourceCamera& s, const CameraMapping& mapping, std::uint32_t width,
                     std::uint32_t height, const std::string& where) {
    if (s.kind == ProjectionKind::Given) return s.projection;
    Mat4 p;
    if (s.kind == ProjectionKind::FovY) {
        const double fy = 1.0 / std::tan(0.5 * s.fovYDegrees * std::numbers::pi / 180.0);
        p.m[0] = fy * static_cast<double>(height) / static_cast<double>(width);
        p.m[5] = fy;
        p.m[14] = -1.0;
    } else {
        p = s.projection;
    }
    const bool perspective = p.m[12] == 0.0 && p.m[13] == 0.0 && p.m[14] == -1.0 && p.m[15] == 0.0;
    const bool orthographic = p.m[12] == 0.0 && p.m[13] == 0.0 && p.m[14] == 0.0 && p.m[15] == 1.0;
    if (!perspective && !orthographic)
        throw CaptureError(where, "projection_gl: the last row must be (0,0,-1,0) or (0,0,0,1)");
    const double n = s.nearZ, f = s.farZ;
    double c = 0.0, e = 0.0; // depth row (0, 0, c, e)
    switch (mapping.depth) {
    case DepthConvention::Standard: // near -> 0, far -> 1
        c = perspective ? f / (n - f) : -1.0 / (f - n);
        e = perspective ? n * f / (n - f) : -n / (f - n);
        break;
    case DepthConvention::Reversed: // near -> 1, far -> 0
        c = perspective ? n / (f - n) : 1.0 / (f - n);
        e = perspective ? n * f / (f - n) : f / (f - n);
        break;
    case DepthConvention::ReversedInfinite:
        if (!perspective) throw CaptureError(where, "an orthographic camera has no reversed_infinite depth");
        c = 0.0;
        e = n;
        break;
    }
    p.m[8] = 0.0;
    p.m[9] = 0.0;
    p.m[10] = c;
    p.m[11] = e;
    if (mapping.ndcYDown)
        for (std::size_t i = 4; i < 8; ++i) p.m[i] = -p.m[i];
    return p;
}

Camera toGlint(const SourceCamera& current, const SourceCamera* previous, const ChannelMap& map,
               std::uint32_t width, std::uint32_t height, const std::string& where) {
    const Mat4 toSource = transpose(axisMatrix(map.worldAxes)); // inverse of a signed permutation
    Camera c;
    c.depth = map.camera.depth;
    c.ndcYDown = map.camera.ndcYDown;
    c.nearZ = current.nearZ;
    c.farZ =
        c.depth == DepthConvention::ReversedInfinite ? std::numeric_limits<double>::infinity() : current.farZ;
    c.view = multiply(current.view, toSource);
    c.projection = buildProjection(current, map.camera, width, height, where);
    if (current.prevViewProjection) {
        c.prevViewProjection = multiply(*current.prevViewProjection, toSource);
    } else if (previous) {
        const Mat4 prevProjection = buildProjection(*previous, map.camera, width, height, where);
        c.prevViewProjection = multiply(prevProjection, multiply(previous->view, toSource));
    } else {
        c.prevViewProjection = viewProjection(c); // first frame: no camera motion
    }
    if (auto problem = checkCamera(c)) throw CaptureError(where, *problem);
    return c;
}

std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", v);
    return text;
}

// Device depth of the view-space point (0, 0, -t) under p, and the clip w it has there.
double clipW(const Mat4& p, double t) {
    return -p.m[14] * t + p.m[15];
}
double depthAt(const Mat4& p, double t) {
    return (-p.m[10] * t + p.m[11]) / clipW(p, t);
}

// What depthAt can be off by when the matrix was computed and stored in float (as exporters
// such as Blender's do): 8 float ulps (2^-24 relative) on each term of the quotient.
double depthTolerance(const Mat4& p, double t) {
    const double numerator = std::abs(p.m[10] * t) + std::abs(p.m[11]);
    const double denominator = std::abs(p.m[14] * t) + std::abs(p.m[15]);
    return 8.0 * 0x1p-24 * (numerator + std::abs(depthAt(p, t)) * denominator) / std::abs(clipW(p, t));
}

// How the matrix maps the view-space +y axis at the centre of the near plane: +1 up, -1 down,
// 0 not at all.
int yDirection(const Mat4& p, double t) {
    const double w = clipW(p, t), y = -p.m[6] * t + p.m[7];
    const double slope = p.m[5] * w - y * p.m[13]; // d(y / w)/dy times w^2
    return slope > 0.0 ? 1 : slope < 0.0 ? -1 : 0;
}

// The depths a projection must give the near and far planes (far: at infinity for
// reversed_infinite), checked to float precision; the reason it does not, or nothing.
std::optional<std::string> depthRowProblem(const Mat4& p, double nearZ, double farZ, bool infinite,
                                           double nearDepth, double farDepth) {
    if (!(clipW(p, nearZ) > 0.0) || (!infinite && !(clipW(p, farZ) > 0.0)))
        return std::string("gives the near or far plane a clip w <= 0 (the view looks down -z: is the "
                           "matrix transposed? \"vectors\" says how matrices are stored)");
    const double atNear = depthAt(p, nearZ);
    double atFar = 0.0, farTolerance = 0.0;
    if (infinite) {
        if (p.m[14] == 0.0) return std::string("is orthographic: reversed_infinite needs a perspective");
        atFar = p.m[10] / p.m[14]; // the limit of depthAt as t grows
        farTolerance = 8.0 * 0x1p-24 * (std::abs(p.m[10]) + std::abs(atFar * p.m[14])) / std::abs(p.m[14]);
    } else {
        atFar = depthAt(p, farZ);
        farTolerance = depthTolerance(p, farZ);
    }
    if (std::abs(atNear - nearDepth) <= depthTolerance(p, nearZ) &&
        std::abs(atFar - farDepth) <= farTolerance)
        return std::nullopt;
    const std::string farName = infinite ? "infinity" : "far " + shortNumber(farZ);
    return "maps near " + shortNumber(nearZ) + " to depth " + shortNumber(atNear) + " and " + farName +
           " to " + shortNumber(atFar) + ", expected " + shortNumber(nearDepth) + " and " +
           shortNumber(farDepth);
}

// A side file's projection against the frame's declared near/far, depth convention and NDC y
// direction: a matrix in another convention would replay without error and be wrong.
std::optional<std::string> projectionProblem(const SourceCamera& s, const ChannelMap& map) {
    const CameraMapping& c = map.camera;
    const bool infinite = c.depth == DepthConvention::ReversedInfinite;
    const std::string mapName = std::filesystem::path(map.path).filename().string();
    if (s.kind == ProjectionKind::OpenGl) {
        if (yDirection(s.projection, s.nearZ) <= 0)
            return std::string("its y row (m[1][1] = ") + shortNumber(s.projection.m[5]) +
                   ") sends view +y down; an OpenGL projection sends it up (glint flips it when "
                   "camera.ndc_y_down is true), so this looks like a Vulkan-style matrix: give it as "
                   "projection with camera.ndc_y_down = true";
        // Without a far plane (reversed_infinite) the entry has no far to check the row against.
        const double atNear = depthAt(s.projection, s.nearZ);
        if (infinite && (!(clipW(s.projection, s.nearZ) > 0.0) ||
                         std::abs(atNear + 1.0) > depthTolerance(s.projection, s.nearZ)))
            return "an OpenGL projection's depth row maps near " + shortNumber(s.nearZ) + " to depth " +
                   shortNumber(atNear) + ", expected -1";
        if (auto p = infinite ? std::optional<std::string>{}
                              : depthRowProblem(s.projection, s.nearZ, s.farZ, false, -1.0, 1.0))
            return "an OpenGL projection's depth row " + *p +
                   " from the entry's near and far; give the near and far the matrix was made with, or "
                   "give a matrix already in glint's convention as projection";
        return std::nullopt;
    }
    if (s.kind != ProjectionKind::Given) return std::nullopt;
    const bool reversed = c.depth != DepthConvention::Standard;
    const std::string convention =
        "camera.depth_convention = \"" + std::string(toString(c.depth)) + "\" in " + mapName;
    if (auto p = depthRowProblem(s.projection, s.nearZ, s.farZ, infinite, reversed ? 1.0 : 0.0,
                                 reversed ? 0.0 : 1.0))
        return "used as is, it " + *p + " for " + convention +
               " (an OpenGL projection, depth -1 to 1, goes in projection_gl)";
    const int y = yDirection(s.projection, s.nearZ);
    if (y != (c.ndcYDown ? -1 : 1))
        return std::string("used as is, it sends view +y ") +
               (y > 0   ? "up"
                : y < 0 ? "down"
                        : "nowhere") +
               " in NDC (m[1][1] = " + shortNumber(s.projection.m[5]) + "), expected " +
               (c.ndcYDown ? "down" : "up") + " for camera.ndc_y_down = " + (c.ndcYDown ? "true" : "false") +
               " in " + mapName;
    return std::nullopt;
}

// Index of the frame among its capture folder's frames, matched by name.
std::size_t positionInSequence(const std::string& framePath, const ChannelMap& map) {
    const std::string name = std::filesystem::path(framePath).filename().string();
    const std::vector<std::string> frames = mappedSequenceFiles(mappedCaptureFolder(framePath, map), map);
    for (std::size_t i = 0; i < frames.size(); ++i)
        if (std::filesystem::path(frames[i]).filename().string() == name) return i;
    fail(framePath, "is not among the frames of its folder");
}

struct SideFileReader {
    std::filesystem::path file;
    const ChannelMap& map;
    bool rowVectors = false;

    [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
        capture::fail(file, key + ": " + problem);
    }

    double number(const Json& entry, const std::string& prefix, const char* key) const {
        const Json* v = entry.contains(key) ? &entry.at(key) : nullptr;
        if (!v) fail(prefix + "." + key, "missing (required)");
        if (!v->is_number() || !std::isfinite(v->get<double>()))
            fail(prefix + "." + key, "expected a number");
        return v->get<double>();
    }

    // 16 numbers row by row (m[row][col] of M·p), flat or as 4 rows of 4.
    Mat4 matrix(const Json& value, const std::string& key) const {
        std::vector<double> flat;
        auto take = [&](const Json& v) {
            if (!v.is_number() || !std::isfinite(v.get<double>())) fail(key, "expected 16 finite numbers");
            flat.push_back(v.get<double>());
        };
        if (!value.is_array()) fail(key, "expected 16 numbers (or 4 rows of 4)");
        for (const Json& element : value) {
            if (element.is_array()) {
                if (element.size() != 4) fail(key, "expected 4 rows of 4 numbers");
                for (const Json& x : element) take(x);
            } else {
                take(element);
            }
        }
        if (flat.size() != 16)
            fail(key, "expected 16 numbers (or 4 rows of 4), got " + std::to_string(flat.size()));
        Mat4 m;
        for (std::size_t i = 0; i < 16; ++i) m.m[i] = flat[i];
        return rowVectors ? transpose(m) : m;
    }

    SourceCamera camera(const Json& entry, const std::string& prefix, const CameraMapping& mapping) const {
        if (!entry.is_object()) fail(prefix, "expected an object");
        for (const auto& [key, value] : entry.items()) {
            static const std::array<std::string_view, 8> kKeys{
                "file",          "view", "projection", "projection_gl",
                "fov_y_degrees", "near", "far",        "prev_view_projection"};
            if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
                fail(prefix + "." + key, "unknown key");
        }
        SourceCamera s;
        if (!entry.contains("view")) fail(prefix + ".view", "missing (required)");
        s.view = matrix(entry.at("view"), prefix + ".view");
        const int given = (entry.contains("projection") ? 1 : 0) + (entry.contains("projection_gl") ? 1 : 0) +
                          (entry.contains("fov_y_degrees") ? 1 : 0);
        if (given != 1) fail(prefix, "give exactly one of projection, projection_gl, fov_y_degrees");
        if (entry.contains("projection")) {
            s.kind = ProjectionKind::Given;
            s.projection = matrix(entry.at("projection"), prefix + ".projection");
        } else if (entry.contains("projection_gl")) {
            s.kind = ProjectionKind::OpenGl;
            s.projection = matrix(entry.at("projection_gl"), prefix + ".projection_gl");
        } else {
            s.kind = ProjectionKind::FovY;
            s.fovYDegrees = number(entry, prefix, "fov_y_degrees");
            if (!(s.fovYDegrees > 0.0 && s.fovYDegrees < 180.0))
                fail(prefix + ".fov_y_degrees", "expected a value in (0, 180)");
        }
        s.nearZ = number(entry, prefix, "near");
        if (mapping.depth != DepthConvention::ReversedInfinite) s.farZ = number(entry, prefix, "far");
        if (entry.contains("prev_view_projection"))
            s.prevViewProjection = matrix(entry.at("prev_view_projection"), prefix + ".prev_view_projection");
        if (s.nearZ > 0.0 && (mapping.depth == DepthConvention::ReversedInfinite || s.farZ > s.nearZ))
            if (auto problem = projectionProblem(s, map))
                fail(prefix + (s.kind == ProjectionKind::OpenGl ? ".projection_gl" : ".projection"),
                     *problem);
        return s;
    }

    // "previous": the camera of the frame before the first, an entry without "file".
    SourceCamera previousCamera(const Json& entry, const CameraMapping& mapping) const {
        for (const char* key : {"file", "prev_view_projection"})
            if (entry.is_object() && entry.contains(key))
                fail(std::string("previous.") + key, "not for the camera of the frame before the first");
        return camera(entry, "previous", mapping);
    }
};

// Whether the frame matched to frames[0] is the capture's first: always, except for a single
// static entry without "file", which serves every frame of the folder.
bool isFirstFrame(const std::string& framePath, const ChannelMap& map, std::size_t entries, bool named) {
    return named || entries > 1 || positionInSequence(framePath, map) == 0;
}

Json parseJsonFile(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        fail(file, "camera side file does not exist (camera.file in the map names it; its format: "
                   "docs/replay.md, \"The camera side file\")");
    std::ifstream in(file, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in && !in.eof()) fail(file, "cannot read the camera side file");
    return parseJson(text, file, "invalid JSON");
}

Camera sideFileCamera(const std::string& framePath, const ChannelMap& map, std::uint32_t width,
                      std::uint32_t height) {
    std::filesystem::path file(map.camera.file);
    if (file.is_relative()) file = std::filesystem::path(mappedCaptureFolder(framePath, map)) / file;
    const Json root = parseJsonFile(file);
    SideFileReader r{file, map};
    if (!root.is_object()) r.fail("(top level)", "expected an object with \"frames\"");
    for (const auto& [key, value] : root.items()) {
        if (key == "format" && value != "glint-camera") r.fail("format", "expected \"glint-camera\"");
        if (key == "version" && value != 1) r.fail("version", "unsupported (this reader knows version 1)");
        if (key == "vectors" && value != "column" && value != "row")
            r.fail("vectors", "expected \"column\" (M·p) or \"row\" (p·M)");
        if (key != "format" && key != "version" && key != "vectors" && key != "frames" && key != "previous")
            r.fail(key, "unknown key");
    }
    r.rowVectors = root.contains("vectors") && root.at("vectors") == "row";
    if (!root.contains("frames") || !root.at("frames").is_array() || root.at("frames").empty())
        r.fail("frames", "expected a non-empty array of cameras");
    const Json& frames = root.at("frames");

    // Entries are matched by file name when they carry one, otherwise by position.
    std::size_t named = 0;
    for (const Json& entry : frames) named += entry.is_object() && entry.contains("file") ? 1u : 0u;
    if (named != 0 && named != frames.size()) r.fail("frames", "either every entry has \"file\" or none has");
    std::size_t index = 0;
    if (named != 0) {
        const std::string name = std::filesystem::path(framePath).filename().string();
        index = frames.size();
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const Json& f = frames[i].at("file");
            if (!f.is_string()) r.fail("frames[" + std::to_string(i) + "].file", "expected a string");
            if (f.get<std::string>() == name) index = i;
        }
        if (index == frames.size())
            r.fail("frames", "no entry for frame '" + name + "' (a file beside the frames that is not one: " +
                                 "list the frames with frames = \"...\" in " + map.path +
                                 ", docs/replay.md, \"Top level\")");
    } else if (frames.size() > 1) {
        index = positionInSequence(framePath, map);
        if (index >= frames.size())
            r.fail("frames", "has " + std::to_string(frames.size()) + " entries but '" + framePath +
                                 "' is frame " + std::to_string(index) + " of its folder");
    }
    const std::string prefix = "frames[" + std::to_string(index) + "]";
    const SourceCamera current = r.camera(frames[index], prefix, map.camera);
    std::optional<SourceCamera> previous;
    if (index > 0)
        previous = r.camera(frames[index - 1], "frames[" + std::to_string(index - 1) + "]", map.camera);
    else if (root.contains("previous") && isFirstFrame(framePath, map, frames.size(), named != 0))
        previous = r.previousCamera(root.at("previous"), map.camera);
    return toGlint(current, previous ? &*previous : nullptr, map, width, height,
                   file.string() + ": " + prefix);
}

// Header cameras: a 4x4 view attribute plus fov/near/far from attributes or the map.
SourceCamera headerCamera(const std::string& framePath, const CameraMapping& m) {
    ExrSize size;
    const Imf::Header header = readExrHeader(framePath, size);
    auto scalar = [&](const std::string& attribute, double fixed, const char* key) {
        if (attribute.empty()) return fixed;
        if (const auto* f = header.findTypedAttribute<Imf::FloatAttribute>(attribute))
            return static_cast<double>(f->value());
        if (const auto* d = header.findTypedAttribute<Imf::DoubleAttribute>(attribute)) return d->value();
        fail(framePath,
             "attribute '" + attribute + "' (camera." + key + " in the map) is missing or not a number");
    };
    Mat4 rows;
    if (const auto* f = header.findTypedAttribute<Imf::M44fAttribute>(m.viewAttribute)) {
        for (int i = 0; i < 16; ++i)
            rows.m[static_cast<std::size_t>(i)] = static_cast<double>(f->value()[i / 4][i % 4]);
    } else if (const auto* d = header.findTypedAttribute<Imf::M44dAttribute>(m.viewAttribute)) {
        for (int i = 0; i < 16; ++i) rows.m[static_cast<std::size_t>(i)] = d->value()[i / 4][i % 4];
    } else {
        fail(framePath, "attribute '" + m.viewAttribute +
                            "' (camera.view_attribute in the map) is missing or not a 4x4 matrix");
    }
    SourceCamera s;
    s.view = transpose(rows); // Imath stores row-vector matrices
    if (m.viewSpace == HeaderViewSpace::OpenExr)
        for (std::size_t i = 8; i < 12; ++i) s.view.m[i] = -s.view.m[i]; // +z forward -> -z forward
    s.kind = ProjectionKind::FovY;
    s.fovYDegrees = scalar(m.fovYAttribute, m.fovYDegrees, "fov_y_attribute");
    s.nearZ = scalar(m.nearAttribute, m.nearZ, "near_attribute");
    s.farZ = scalar(m.farAttribute, m.farZ, "far_attribute");
    if (!(s.fovYDegrees > 0.0 && s.fovYDegrees < 180.0))
        fail(framePath, "camera field of view is not in (0, 180)");
    return s;
}
} // namespace

Camera mappedCamera(const std::string& framePath, const ChannelMap& map, std::uint32_t width,
                    std::uint32_t height) {
    if (map.camera.source == CameraSource::SideFile) return sideFileCamera(framePath, map, width, height);
    const SourceCamera current = headerCamera(framePath, map.camera);
    std::optional<SourceCamera> previous;
    const std::size_t index = positionInSequence(framePath, map);
    if (index > 0) {
        const std::vector<std::string> frames = mappedSequenceFiles(mappedCaptureFolder(framePath, map), map);
        previous = headerCamera(frames[index - 1], map.camera);
    }
    return toGlint(current, previous ? &*previous : nullptr, map, width, height, framePath);
}

} // namespace glint::capture
