#include "capture/frame_attributes.h"

#include "capture/capture_error.h"
#include "capture/enum_names.h"

#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfStringVectorAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace glint::capture {

namespace {
constexpr const char* kVersion = "glint.formatVersion";
constexpr const char* kFrameIndex = "glint.frameIndex";
constexpr const char* kView = "glint.view";
constexpr const char* kProjection = "glint.projection";
constexpr const char* kPrevViewProjection = "glint.prevViewProjection";
constexpr const char* kDepthConvention = "glint.depthConvention";
constexpr const char* kNear = "glint.near";
constexpr const char* kFar = "glint.far";
constexpr const char* kNdcYDown = "glint.ndcYDown";
constexpr const char* kNormalEncoding = "glint.normalEncoding";
constexpr const char* kMotionUnits = "glint.motionUnits";
constexpr const char* kMotionScale = "glint.motionScale";
constexpr const char* kRoughnessSource = "glint.roughnessSource";
constexpr const char* kRoughnessPerceptual = "glint.roughnessPerceptual";
constexpr const char* kEffects = "glint.effects";
// Optional: written only when known (> 0).
constexpr const char* kShadowLightTanHalfAngle = "glint.shadowLightTanHalfAngle";

double signOr1(double v) {
    return v < 0.0 ? -1.0 : 1.0;
}

// The value of a required attribute of type A, or a one-line failure saying what is wrong.
template <typename A>
const auto& required(const Imf::Header& header, const char* name, const std::filesystem::path& file) {
    if (const A* attr = header.findTypedAttribute<A>(name)) return attr->value();
    auto it = header.find(name);
    if (it != header.end())
        fail(file, std::string("attribute '") + name + "' has type " + it.attribute().typeName() +
                       ", expected " + A::staticTypeName());
    fail(file, std::string("missing attribute '") + name + "'");
}

bool requiredFlag(const Imf::Header& header, const char* name, const std::filesystem::path& file) {
    const int v = required<Imf::IntAttribute>(header, name, file);
    if (v != 0 && v != 1)
        fail(file, std::string("attribute '") + name + "' is " + std::to_string(v) + ", expected 0 or 1");
    return v == 1;
}

template <typename E, typename Parse>
E requiredEnum(const Imf::Header& header, const char* name, const std::filesystem::path& file, Parse parse) {
    const std::string& text = required<Imf::StringAttribute>(header, name, file);
    if (auto v = parse(text)) return *v;
    fail(file, std::string("attribute '") + name + "' has unknown value '" + text + "'");
}
} // namespace

Imath::M44d toImath(const Mat4& m) {
    Imath::M44d r;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) r[col][row] = m.m[static_cast<std::size_t>(row * 4 + col)];
    return r;
}

Mat4 fromImath(const Imath::M44d& m) {
    Mat4 r;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) r.m[static_cast<std::size_t>(row * 4 + col)] = m[col][row];
    return r;
}

Imath::M44f worldToCameraOf(const Camera& camera) {
    // Only axis signs separate an API's view space from OpenEXR's camera space, and the
    // projection reveals them: NDC +x is right; NDC +y is up unless ndcYDown; points in
    // front of a perspective camera have w > 0, and for an orthographic one depth grows
    // away from the camera (or shrinks, when reversed).
    const auto& p = camera.projection.m;
    const double sx = signOr1(p[0]);
    const double sy = signOr1(p[5]) * (camera.ndcYDown ? -1.0 : 1.0);
    double sz = signOr1(p[14]);
    if (p[14] == 0.0) sz = signOr1(p[10]) * (camera.depth == DepthConvention::Standard ? 1.0 : -1.0);
    Mat4 flip = identity();
    flip.m[0] = sx;
    flip.m[5] = sy;
    flip.m[10] = sz;
    return Imath::M44f(toImath(multiply(flip, camera.view)));
}

Imath::M44f worldToNdcOf(const Camera& camera) {
    // clip -> RenderMan NDC in homogeneous form: u·w = (x + w)/2, v·w = (w -/+ y)/2.
    Mat4 toNdc = identity();
    toNdc.m[0] = 0.5;
    toNdc.m[3] = 0.5;
    toNdc.m[5] = camera.ndcYDown ? 0.5 : -0.5;
    toNdc.m[7] = 0.5;
    return Imath::M44f(toImath(multiply(toNdc, viewProjection(camera))));
}

void writeFrameAttributes(Imf::Header& header, const FrameHeader& f) {
    const Camera& c = f.camera;
    header.insert(kVersion, Imf::IntAttribute(static_cast<int>(f.formatVersion)));
    header.insert(kFrameIndex, Imf::IntAttribute(static_cast<int>(f.frameIndex)));
    header.insert(kView, Imf::M44dAttribute(toImath(c.view)));
    header.insert(kProjection, Imf::M44dAttribute(toImath(c.projection)));
    header.insert(kPrevViewProjection, Imf::M44dAttribute(toImath(c.prevViewProjection)));
    header.insert(kDepthConvention, Imf::StringAttribute(std::string(toString(c.depth))));
    header.insert(kNear, Imf::DoubleAttribute(c.nearZ));
    header.insert(kFar, Imf::DoubleAttribute(c.farZ));
    header.insert(kNdcYDown, Imf::IntAttribute(c.ndcYDown ? 1 : 0));
    header.insert(kNormalEncoding, Imf::StringAttribute(std::string(toString(f.normalEncoding))));
    header.insert(kMotionUnits, Imf::StringAttribute(std::string(toString(f.motion.units))));
    header.insert(kMotionScale, Imf::V2fAttribute(Imath::V2f(f.motion.scale.x, f.motion.scale.y)));
    const std::string source = f.roughness.layer.empty() ? "" : f.roughness.layer + "." + f.roughness.channel;
    header.insert(kRoughnessSource, Imf::StringAttribute(source));
    header.insert(kRoughnessPerceptual, Imf::IntAttribute(f.roughness.perceptual ? 1 : 0));
    header.insert(kEffects, Imf::StringVectorAttribute(f.effects));
    if (f.shadowLightTanHalfAngle >= 0.0)
        header.insert(kShadowLightTanHalfAngle, Imf::DoubleAttribute(f.shadowLightTanHalfAngle));
    Imf::addWorldToCamera(header, worldToCameraOf(c));
    Imf::addWorldToNDC(header, worldToNdcOf(c));
}

void readFrameAttributes(const Imf::Header& header, const std::filesystem::path& file, FrameHeader& f) {
    if (header.find(kVersion) == header.end())
        fail(file, std::string("missing attribute '") + kVersion + "' (not a glint frame capture)");
    const int version = required<Imf::IntAttribute>(header, kVersion, file);
    if (version != static_cast<int>(kFormatVersion))
        fail(file, "unsupported format version " + std::to_string(version) + " (this reader knows version " +
                       std::to_string(kFormatVersion) + ")");
    f.formatVersion = static_cast<std::uint32_t>(version);
    const int frameIndex = required<Imf::IntAttribute>(header, kFrameIndex, file);
    if (frameIndex < 0)
        fail(file, "attribute 'glint.frameIndex' is negative (" + std::to_string(frameIndex) + ")");
    f.frameIndex = static_cast<std::uint32_t>(frameIndex);

    Camera& c = f.camera;
    c.view = fromImath(required<Imf::M44dAttribute>(header, kView, file));
    c.projection = fromImath(required<Imf::M44dAttribute>(header, kProjection, file));
    c.prevViewProjection = fromImath(required<Imf::M44dAttribute>(header, kPrevViewProjection, file));
    c.depth = requiredEnum<DepthConvention>(header, kDepthConvention, file, parseDepthConvention);
    c.nearZ = required<Imf::DoubleAttribute>(header, kNear, file);
    c.farZ = required<Imf::DoubleAttribute>(header, kFar, file);
    c.ndcYDown = requiredFlag(header, kNdcYDown, file);

    f.normalEncoding = requiredEnum<NormalEncoding>(header, kNormalEncoding, file, parseNormalEncoding);
    f.motion.units = requiredEnum<MotionUnits>(header, kMotionUnits, file, parseMotionUnits);
    const Imath::V2f scale = required<Imf::V2fAttribute>(header, kMotionScale, file);
    if (!std::isfinite(scale.x) || !std::isfinite(scale.y) || scale.x == 0.0f || scale.y == 0.0f)
        fail(file, "attribute 'glint.motionScale' must be finite and non-zero");
    f.motion.scale = {scale.x, scale.y};

    const std::string& source = required<Imf::StringAttribute>(header, kRoughnessSource, file);
    const std::size_t dot = source.rfind('.');
    if (!source.empty() && (dot == std::string::npos || dot == 0 || dot + 1 == source.size()))
        fail(file, "attribute 'glint.roughnessSource' is '" + source + "', expected <layer>.<channel>");
    f.roughness.layer = source.empty() ? "" : source.substr(0, dot);
    f.roughness.channel = source.empty() ? "" : source.substr(dot + 1);
    f.roughness.perceptual = requiredFlag(header, kRoughnessPerceptual, file);
    f.effects = required<Imf::StringVectorAttribute>(header, kEffects, file);
    f.shadowLightTanHalfAngle = -1.0;
    if (header.find(kShadowLightTanHalfAngle) != header.end()) {
        const double t = required<Imf::DoubleAttribute>(header, kShadowLightTanHalfAngle, file);
        if (!(std::isfinite(t) && t >= 0.0))
            fail(file, "attribute 'glint.shadowLightTanHalfAngle' must be finite and >= 0");
        f.shadowLightTanHalfAngle = t;
    }
}

} // namespace glint::capture
