#include "capture/environment_io.h"

#include "capture/capture_error.h"
#include "capture/capture_frame.h"
#include "capture/exr_file.h"
#include "capture/frame_validation.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <array>
#include <optional>
#include <string>

namespace glint::capture {

namespace {
constexpr std::array<const char*, 3> kChannels{"R", "G", "B"};

Imf::FrameBuffer bufferOf(const Environment& env) {
    Imf::FrameBuffer buffer;
    const std::size_t stride = 3 * sizeof(float);
    for (std::size_t c = 0; c < kChannels.size(); ++c) {
        char* base = reinterpret_cast<char*>(const_cast<float*>(env.rgb.data() + c));
        buffer.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base, stride, stride * env.width));
    }
    return buffer;
}

std::optional<std::string> checkEnvironment(const Environment& env) {
    if (auto problem = checkDimensions(env.width, env.height)) return problem;
    if (env.layout == EnvironmentLayout::Cube && env.height != 6 * std::uint64_t{env.width})
        return "cube environment map is " + std::to_string(env.width) + "x" + std::to_string(env.height) +
               "; a cube map must be W x 6W";
    if (env.rgb.size() != std::size_t{env.width} * env.height * 3)
        return "environment map holds " + std::to_string(env.rgb.size()) + " samples, expected " +
               std::to_string(std::size_t{env.width} * env.height * 3);
    return std::nullopt;
}
} // namespace

Environment readEnvironment(const std::filesystem::path& file, std::optional<EnvironmentLayout> unmarked) {
    ExrSize size;
    ExrLayout exrLayout;
    const Imf::Header exr = readExrHeader(file, size, &exrLayout);
    if (const auto* version = exr.findTypedAttribute<Imf::IntAttribute>("glint.formatVersion");
        version && version->value() != static_cast<int>(kFormatVersion))
        fail(file, "unsupported format version " + std::to_string(version->value()));
    Environment env;
    if (Imf::hasEnvmap(exr)) {
        const Imf::Envmap layout = Imf::envmap(exr);
        if (layout != Imf::ENVMAP_LATLONG && layout != Imf::ENVMAP_CUBE)
            fail(file, "attribute 'envmap' has unknown value " + std::to_string(static_cast<int>(layout)));
        env.layout = layout == Imf::ENVMAP_CUBE ? EnvironmentLayout::Cube : EnvironmentLayout::LatLong;
    } else if (unmarked) {
        env.layout = *unmarked;
    } else {
        fail(file, "missing attribute 'envmap' (lat-long or cube) of an environment map");
    }
    for (const char* name : kChannels) {
        const Imf::Channel* ch = exr.channels().findChannel(name);
        if (!ch) fail(file, std::string("environment map lacks channel '") + name + "'");
        if (ch->type != Imf::HALF && ch->type != Imf::FLOAT)
            fail(file, std::string("channel '") + name + "' must be HALF or FLOAT");
        if (ch->xSampling != 1 || ch->ySampling != 1)
            fail(file, std::string("channel '") + name + "' is subsampled");
    }
    checkPixelData(file, exr, exrLayout); // before the allocation the header asks for
    env.width = size.width;
    env.height = size.height;
    env.rgb.resize(std::size_t{size.width} * size.height * 3);
    if (auto problem = checkEnvironment(env)) fail(file, *problem);
    translateErrors(file, "cannot read pixel data", [&] {
        Imf::InputFile input(file.c_str());
        const Imath::Box2i& dw = input.header().dataWindow();
        if (dw.min.x != 0 || dw.min.y != 0 || dw.max.x + 1 != static_cast<int>(size.width) ||
            dw.max.y + 1 != static_cast<int>(size.height))
            fail(file, "data window changed while reading");
        if (!input.isComplete()) fail(file, "file is truncated or incomplete (some scanlines are missing)");
        input.setFrameBuffer(bufferOf(env));
        input.readPixels(0, static_cast<int>(size.height) - 1);
    });
    env.nonFinite = countNonFinite(env.rgb);
    return env;
}

void writeEnvironment(const std::filesystem::path& file, const Environment& env) {
    if (auto problem = checkEnvironment(env)) fail(file, *problem);
    translateErrors(file, "cannot write", [&] {
        writeAtomically(file, [&](const std::filesystem::path& partial) {
            Imf::Header header(static_cast<int>(env.width), static_cast<int>(env.height));
            header.compression() = Imf::ZIP_COMPRESSION;
            header.insert("glint.formatVersion", Imf::IntAttribute(static_cast<int>(kFormatVersion)));
            Imf::addEnvmap(header,
                           env.layout == EnvironmentLayout::Cube ? Imf::ENVMAP_CUBE : Imf::ENVMAP_LATLONG);
            for (const char* name : kChannels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
            Imf::OutputFile output(partial.c_str(), header);
            output.setFrameBuffer(bufferOf(env));
            output.writePixels(static_cast<int>(env.height));
        });
    });
}

} // namespace glint::capture
