// Reading one mapped frame: the source channels of one EXR file (or a folder of them),
// converted to glint's conventions and validated like every other capture.
#include "capture/channel_map.h"

#include "capture/capture_error.h"
#include "capture/exr_file.h"
#include "capture/frame_validation.h"
#include "capture/motion_convention.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

namespace glint::capture {

namespace {
// One source channel, read as float whatever its file type.
struct Plane {
    std::vector<float> samples;
    bool half = false;
};

struct Request {
    std::string ref;       // as written in the map
    std::string key;       // the map key naming it, for messages
    bool optional = false; // a file without it is not an error; the plane is then left out
};

struct Location {
    std::filesystem::path file;
    std::string channel;
};

Location locate(const std::string& framePath, const std::string& ref, bool folders) {
    if (!folders) return {framePath, ref};
    const ChannelRef split = splitChannelRef(ref);
    return {std::filesystem::path(framePath) / split.file, split.channel};
}

std::string channelList(const Imf::ChannelList& channels) {
    std::string out;
    std::size_t count = 0;
    for (auto it = channels.begin(); it != channels.end(); ++it, ++count)
        if (count < 8) out += (count ? ", " : "") + std::string(it.name());
    if (count > 8) out += ", ... (" + std::to_string(count) + " channels)";
    return count ? out : "no channels";
}

// Reads every requested channel, one InputFile per source file; all files must have one size.
// With readPixels false, everything but the pixels: headers, channels, sizes, file lengths.
std::map<std::string, Plane> readPlanes(const std::string& framePath, const ChannelMap& map,
                                        const std::vector<Request>& requests, ExrSize& size,
                                        bool readPixels = true) {
    std::map<std::filesystem::path, std::vector<const Request*>> byFile;
    for (const Request& r : requests)
        byFile[locate(framePath, r.ref, map.framesAreFolders).file].push_back(&r);
    std::map<std::string, Plane> planes;
    std::filesystem::path first;
    for (const auto& entry : byFile) {
        // Named references rather than a structured binding: the lambda below captures them
        // (clang before 16 cannot capture structured bindings).
        const std::filesystem::path& file = entry.first;
        const std::vector<const Request*>& wanted = entry.second;
        const bool allOptional =
            std::all_of(wanted.begin(), wanted.end(), [](const Request* r) { return r->optional; });
        std::error_code ec;
        if (allOptional && !std::filesystem::exists(file, ec)) continue; // a texture not exported
        ExrSize fileSize;
        ExrLayout layout;
        const Imf::Header header = readExrHeader(file, fileSize, &layout);
        if (first.empty()) {
            first = file;
            size = fileSize;
        } else if (fileSize.width != size.width || fileSize.height != size.height) {
            fail(file, "size " + std::to_string(fileSize.width) + "x" + std::to_string(fileSize.height) +
                           " differs from " + first.filename().string() + "'s " + std::to_string(size.width) +
                           "x" + std::to_string(size.height));
        }
        std::vector<const Request*> present;
        for (const Request* r : wanted) {
            const std::string channel = locate(framePath, r->ref, map.framesAreFolders).channel;
            const Imf::Channel* c = header.channels().findChannel(channel);
            if (!c && r->optional) continue;
            if (!c)
                fail(file, "missing channel '" + channel + "' (" + r->key + " in " + map.path +
                               "); the file has " + channelList(header.channels()));
            if (c->xSampling != 1 || c->ySampling != 1) fail(file, "channel '" + channel + "' is subsampled");
            planes[r->ref].half = c->type == Imf::HALF;
            present.push_back(r);
        }
        checkPixelData(file, header, layout); // before the planes are allocated
        if (!readPixels) continue;
        const std::size_t pixels = std::size_t{size.width} * size.height;
        translateErrors(file, "cannot read pixel data", [&] {
            Imf::InputFile input(file.c_str());
            const Imath::Box2i& dw = input.header().dataWindow();
            if (dw.min.x != 0 || dw.min.y != 0 || dw.max.x + 1 != static_cast<int>(size.width) ||
                dw.max.y + 1 != static_cast<int>(size.height))
                fail(file, "data window changed while reading");
            if (!input.isComplete())
                fail(file, "file is truncated or incomplete (some scanlines are missing)");
            Imf::FrameBuffer buffer;
            for (const Request* r : present) {
                Plane& plane = planes[r->ref];
                if (!plane.samples.empty()) continue; // the same channel named by two keys
                plane.samples.resize(pixels);
                const std::string channel = locate(framePath, r->ref, map.framesAreFolders).channel;
                buffer.insert(channel, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(plane.samples.data()),
                                                  sizeof(float), sizeof(float) * size.width));
            }
            input.setFrameBuffer(buffer);
            input.readPixels(0, static_cast<int>(size.height) - 1);
        });
    }
    if (map.flipVertical && readPixels) {
        for (auto& [ref, plane] : planes)
            for (std::size_t y = 0; y < size.height / 2; ++y)
                std::swap_ranges(plane.samples.begin() + static_cast<std::ptrdiff_t>(y * size.width),
                                 plane.samples.begin() + static_cast<std::ptrdiff_t>((y + 1) * size.width),
                                 plane.samples.end() - static_cast<std::ptrdiff_t>((y + 1) * size.width));
    }
    return planes;
}

struct Builder {
    const std::map<std::string, Plane>& planes;
    std::size_t pixels;

    // A layer whose channels are copied from the named sources; HALF only when all of them are.
    Layer copied(const std::string& name, const std::vector<std::string>& channels,
                 const std::vector<std::string>& refs) const {
        Layer layer{name, channels, std::vector<float>(pixels * refs.size()), 0, SampleType::Half};
        for (std::size_t c = 0; c < refs.size(); ++c) {
            const Plane& plane = planes.at(refs[c]);
            if (!plane.half) layer.storage = SampleType::Float;
            for (std::size_t i = 0; i < pixels; ++i) layer.pixels[i * refs.size() + c] = plane.samples[i];
        }
        return layer;
    }
};

struct Pixel {
    double xn = 0.0, yn = 0.0; // NDC of the pixel centre
    double u = 0.0, v = 0.0;   // screen UV
};

Pixel pixelAt(std::size_t i, std::uint32_t width, std::uint32_t height, bool ndcYDown) {
    Pixel p;
    p.u = (static_cast<double>(i % width) + 0.5) / width;
    p.v = (static_cast<double>(i / width) + 0.5) / height;
    p.xn = 2.0 * p.u - 1.0;
    p.yn = ndcYDown ? 2.0 * p.v - 1.0 : 1.0 - 2.0 * p.v;
    return p;
}

Vec4 unproject(const Mat4& inv, double xn, double yn, double d) {
    const Vec4 q = transform(inv, {xn, yn, d, 1.0});
    return {q.x / q.w, q.y / q.w, q.z / q.w, 1.0};
}

float backgroundDepth(DepthConvention c) {
    return c == DepthConvention::Standard ? 1.0f : 0.0f;
}

bool isBackground(float d, DepthConvention c) {
    return !std::isfinite(d) || (c == DepthConvention::Standard ? d >= 1.0f : d <= 0.0f);
}

// Linear depth to device depth: the view-space point on the pixel's ray at that depth,
// projected with the camera, so any projection (off-centre, reversed, orthographic) works.
Layer deviceDepth(const Plane& source, const DepthMapping& mapping, const Camera& camera, std::uint32_t width,
                  std::uint32_t height, const std::string& framePath) {
    const std::size_t pixels = std::size_t{width} * height;
    Layer layer{"depth", {"Z"}, source.samples, 0, SampleType::Float};
    if (mapping.kind == DepthKind::Device) return layer;
    const bool perspective = camera.projection.m[15] == 0.0;
    if (mapping.kind == DepthKind::Distance && !perspective)
        fail(framePath, "depth.kind = \"distance\" needs a perspective camera");
    const Mat4 inv = *inverse(camera.projection);
    for (std::size_t i = 0; i < pixels; ++i) {
        const double z = static_cast<double>(source.samples[i]);
        if (!std::isfinite(z) || z <= 0.0 || z >= mapping.backgroundFrom || z >= camera.farZ) {
            layer.pixels[i] = backgroundDepth(camera.depth);
            continue;
        }
        const Pixel px = pixelAt(i, width, height, camera.ndcYDown);
        // Two points on the ray, both finite in every depth convention.
        const Vec4 a = unproject(inv, px.xn, px.yn, 0.25);
        const Vec4 b = unproject(inv, px.xn, px.yn, 0.75);
        Vec4 p{0.0, 0.0, 0.0, 1.0};
        if (mapping.kind == DepthKind::ViewZ) {
            const double target = a.z < 0.0 ? -z : z; // points in front share a.z's sign
            const double s = (target - a.z) / (b.z - a.z);
            p = {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), target, 1.0};
        } else { // the eye is the view-space origin
            const double k = z / std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
            p = {a.x * k, a.y * k, a.z * k, 1.0};
        }
        const Vec4 clip = transform(camera.projection, p);
        layer.pixels[i] = static_cast<float>(clip.z / clip.w);
    }
    return layer;
}

std::array<double, 3> applyAxes(const AxisMap& m, const std::array<double, 3>& v) {
    return {m.sign[0] * v[static_cast<std::size_t>(m.axis[0])],
            m.sign[1] * v[static_cast<std::size_t>(m.axis[1])],
            m.sign[2] * v[static_cast<std::size_t>(m.axis[2])]};
}

// docs/conventions.md §5, with the stored [0,1] values mapped back to [-1,1] first.
std::array<double, 3> decodeOctahedral(double sx, double sy) {
    const double px = 2.0 * sx - 1.0, py = 2.0 * sy - 1.0;
    double x = px, y = py;
    const double z = 1.0 - std::abs(px) - std::abs(py);
    const double t = std::max(-z, 0.0);
    x -= x >= 0.0 ? t : -t;
    y -= y >= 0.0 ? t : -t;
    return {x, y, z};
}

Layer worldNormals(const Builder& b, const NormalMapping& mapping, const AxisMap& worldAxes,
                   const Camera& camera) {
    Layer layer{"normal", {"X", "Y", "Z"}, std::vector<float>(b.pixels * 3), 0, SampleType::Float};
    std::vector<const Plane*> src;
    for (const std::string& ref : mapping.channels) src.push_back(&b.planes.at(ref));
    for (std::size_t i = 0; i < b.pixels; ++i) {
        auto s = [&](std::size_t c) { return static_cast<double>(src[c]->samples[i]); };
        std::array<double, 3> n{};
        switch (mapping.storage) {
        case NormalStorage::Unit:
            n = {s(0), s(1), s(2)};
            break;
        case NormalStorage::Unorm:
            n = {2.0 * s(0) - 1.0, 2.0 * s(1) - 1.0, 2.0 * s(2) - 1.0};
            break;
        case NormalStorage::Octahedral:
            n = decodeOctahedral(s(0), s(1));
            break;
        }
        n = applyAxes(mapping.axes, n);
        if (mapping.space == NormalSpace::View) {
            // Normals go back to world space with the transpose of the view matrix's 3x3
            // (exact for rigid views, and the right normal transform for any other). glint's
            // view already includes the world-axis change.
            const auto& v = camera.view.m;
            n = {v[0] * n[0] + v[4] * n[1] + v[8] * n[2], v[1] * n[0] + v[5] * n[1] + v[9] * n[2],
                 v[2] * n[0] + v[6] * n[1] + v[10] * n[2]};
        } else {
            n = applyAxes(worldAxes, n);
        }
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        // Background normals are often zero; they stay zero (undefined in glint, never NaN).
        const double k = length > 0.0 && std::isfinite(length) ? 1.0 / length : 1.0;
        for (std::size_t c = 0; c < 3; ++c) layer.pixels[i * 3 + c] = static_cast<float>(n[c] * k);
    }
    return layer;
}

Layer motionConventionA(const Builder& b, const MotionMapping& mapping, const Layer* depth,
                        const Camera& camera, std::uint32_t width, std::uint32_t height) {
    Layer layer{"motion", {"X", "Y"}, std::vector<float>(b.pixels * 2), 0, SampleType::Float};
    const Plane& sx = b.planes.at(mapping.channels[0]);
    const Plane& sy = b.planes.at(mapping.channels[1]);
    // Direction and y sign fold into the scale, so the one conversion in motion_convention.h
    // does the rest.
    const float direction = mapping.direction == MotionDirection::FromPrevious ? -1.0f : 1.0f;
    const MotionConvention convention{
        mapping.units,
        {mapping.scale.x * direction, mapping.scale.y * direction * (mapping.yUp ? -1.0f : 1.0f)}};
    for (std::size_t i = 0; i < b.pixels; ++i) {
        const Float2 a =
            toConventionA({sx.samples[i], sy.samples[i]}, convention, width, height, camera.ndcYDown);
        layer.pixels[2 * i] = a.x;
        layer.pixels[2 * i + 1] = a.y;
    }
    if (mapping.background == BackgroundMotion::Keep || !depth) return layer;

    // Background: a point at infinity along the pixel's ray (the far-plane point for an
    // orthographic camera), reprojected into the previous frame.
    const Mat4 invVp = *inverse(viewProjection(camera));
    const Vec4 eye = transform(*inverse(camera.view), {0.0, 0.0, 0.0, 1.0});
    const bool perspective = camera.projection.m[15] == 0.0;
    for (std::size_t i = 0; i < b.pixels; ++i) {
        if (!isBackground(depth->pixels[i], camera.depth)) continue;
        const Pixel px = pixelAt(i, width, height, camera.ndcYDown);
        Vec4 clip;
        if (perspective) {
            const Vec4 q = unproject(invVp, px.xn, px.yn, 0.5);
            clip = transform(camera.prevViewProjection, {q.x - eye.x, q.y - eye.y, q.z - eye.z, 0.0});
        } else {
            const double far = static_cast<double>(backgroundDepth(camera.depth));
            clip = transform(camera.prevViewProjection, unproject(invVp, px.xn, px.yn, far));
        }
        const double yn = clip.y / clip.w;
        const double du = 0.5 * clip.x / clip.w + 0.5 - px.u;
        const double dv = (camera.ndcYDown ? 0.5 + 0.5 * yn : 0.5 - 0.5 * yn) - px.v;
        if (!std::isfinite(du) || !std::isfinite(dv)) continue;
        layer.pixels[2 * i] = static_cast<float>(du);
        layer.pixels[2 * i + 1] = static_cast<float>(dv);
    }
    return layer;
}

std::vector<Request> requestsOf(const ChannelMap& map) {
    std::vector<Request> out;
    auto add = [&](const std::vector<std::string>& refs, const std::string& key, bool optional = false) {
        for (const std::string& ref : refs) out.push_back({ref, key, optional});
    };
    add(map.color, "color.channels");
    if (map.depth) add({map.depth->channel}, "depth.channel");
    if (map.normal) add(map.normal->channels, "normal.channels");
    if (map.roughness) add({map.roughness->channel}, "roughness.channel");
    if (map.motion) add(map.motion->channels, "motion.channels");
    if (!map.shadow.empty()) add({map.shadow}, "shadow.channel");
    add(map.referenceReflection, "reference.reflection.channels");
    if (!map.referenceShadow.empty()) add({map.referenceShadow}, "reference.shadow.channel");
    add(map.baseColor, "material.base_color", map.materialOptional);
    if (!map.metallic.empty()) add({map.metallic}, "material.metallic", map.materialOptional);
    return out;
}
} // namespace

bool checkMappedFrame(const std::string& framePath, const ChannelMap& map) {
    ExrSize size;
    const std::map<std::string, Plane> planes = readPlanes(framePath, map, requestsOf(map), size, false);
    mappedCamera(framePath, map, size.width, size.height);
    if (!map.depth) return false;
    const auto depth = planes.find(map.depth->channel);
    return depth != planes.end() && depth->second.half;
}

Frame readMappedFrame(const std::string& framePath, const ChannelMap& map, std::uint32_t frameIndex) {
    ExrSize size;
    const std::map<std::string, Plane> planes = readPlanes(framePath, map, requestsOf(map), size);
    Frame frame;
    frame.width = size.width;
    frame.height = size.height;
    frame.frameIndex = frameIndex;
    frame.camera = mappedCamera(framePath, map, size.width, size.height);
    frame.normalEncoding = NormalEncoding::WorldUnit;
    frame.motion = kConventionA;
    frame.effects = map.effects;

    // Layers in the canonical order of readFrame (exr_layers.h).
    const Builder b{planes, std::size_t{size.width} * size.height};
    if (!map.color.empty()) {
        const std::vector<std::string> names{"R", "G", "B", "A"};
        frame.layers.push_back(
            b.copied("color", {names.begin(), names.begin() + static_cast<std::ptrdiff_t>(map.color.size())},
                     map.color));
    }
    if (map.depth)
        frame.layers.push_back(deviceDepth(planes.at(map.depth->channel), *map.depth, frame.camera,
                                           size.width, size.height, framePath));
    if (map.normal) frame.layers.push_back(worldNormals(b, *map.normal, map.worldAxes, frame.camera));
    if (map.roughness) {
        frame.layers.push_back(b.copied("roughness", {"Y"}, {map.roughness->channel}));
        frame.roughness = {"roughness", "Y", map.roughness->perceptual};
    }
    // An optional material whose base colour the file lacks is left out (only composite needs it).
    const bool hasBaseColor = std::all_of(map.baseColor.begin(), map.baseColor.end(),
                                          [&](const std::string& ref) { return planes.contains(ref); });
    if (!map.baseColor.empty() && hasBaseColor) {
        std::vector<std::string> refs = map.baseColor;
        std::vector<std::string> names{"R", "G", "B"};
        if (!map.metallic.empty() && planes.contains(map.metallic)) {
            refs.push_back(map.metallic);
            names.push_back("A");
        }
        frame.layers.push_back(b.copied("material", names, refs));
    }
    if (map.motion) {
        // The map loader made sure that background = "camera" comes with a depth layer.
        const Layer* depth = findLayer(frame, "depth");
        Layer motion = motionConventionA(b, *map.motion, depth, frame.camera, size.width, size.height);
        frame.layers.push_back(std::move(motion));
    }
    if (!map.shadow.empty()) frame.layers.push_back(b.copied("shadow", {"Y"}, {map.shadow}));
    if (!map.referenceReflection.empty())
        frame.layers.push_back(b.copied("reference.reflection", {"R", "G", "B"}, map.referenceReflection));
    if (!map.referenceShadow.empty())
        frame.layers.push_back(b.copied("reference.shadow", {"Y"}, {map.referenceShadow}));

    for (Layer& layer : frame.layers) layer.nonFinite = countNonFinite(layer.pixels);
    if (auto problem = checkFrame(frame)) fail(framePath, *problem + " (read through " + map.path + ")");
    return frame;
}

} // namespace glint::capture
