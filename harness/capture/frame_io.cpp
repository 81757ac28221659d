#include "capture/frame_io.h"

#include "capture/capture_error.h"
#include "capture/exr_file.h"
#include "capture/exr_layers.h"
#include "capture/frame_attributes.h"
#include "capture/frame_validation.h"
#include "capture/motion_convention.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <Imath/half.h>

#include <cstddef>
#include <vector>

namespace glint::capture {

namespace {
// A FLOAT slice over one channel of an interleaved layer; OpenEXR converts HALF file
// samples to and from float as it reads and writes.
Imf::Slice sliceOf(const Layer& layer, std::size_t channel, std::uint32_t width) {
    const std::size_t stride = layer.channels.size() * sizeof(float);
    const float* base = layer.pixels.data() + channel;
    return Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(base)), stride, stride * width);
}

Imf::Slice halfSliceOf(std::vector<Imath::half>& samples, std::size_t channels, std::size_t channel,
                       std::uint32_t width) {
    const std::size_t stride = channels * sizeof(Imath::half);
    return Imf::Slice(Imf::HALF, reinterpret_cast<char*>(samples.data() + channel), stride, stride * width);
}

FrameHeader parseHeader(const std::filesystem::path& file, const Imf::Header& exr, ExrSize size) {
    if (Imf::hasEnvmap(exr)) fail(file, "this is an environment map, not a frame capture");
    FrameHeader header;
    readFrameAttributes(exr, file, header);
    header.width = size.width;
    header.height = size.height;
    header.layers = layersFromChannels(exr.channels(), file);
    if (auto problem = checkHeader(header)) fail(file, *problem);
    return header;
}
} // namespace

FrameHeader readFrameHeader(const std::filesystem::path& file) {
    ExrSize size;
    const Imf::Header exr = readExrHeader(file, size);
    return parseHeader(file, exr, size);
}

FrameHeader checkFrameFile(const std::filesystem::path& file) {
    ExrSize size;
    ExrLayout layout;
    const Imf::Header exr = readExrHeader(file, size, &layout);
    FrameHeader header = parseHeader(file, exr, size);
    checkPixelData(file, exr, layout);
    return header;
}

Frame readFrame(const std::filesystem::path& file) {
    ExrSize size;
    ExrLayout layout;
    const Imf::Header exr = readExrHeader(file, size, &layout);
    const FrameHeader header = parseHeader(file, exr, size);
    // Before the layers are allocated: a header may declare far more than the file holds.
    checkPixelData(file, exr, layout);

    Frame frame = frameFromHeader(header);
    const std::size_t pixels = std::size_t{size.width} * size.height;
    for (const LayerInfo& info : header.layers) {
        Layer layer{info.name, info.channels, {}, 0, info.storage};
        layer.pixels.resize(pixels * info.channels.size());
        frame.layers.push_back(std::move(layer));
    }
    translateErrors(file, "cannot read pixel data", [&] {
        Imf::InputFile input(file.c_str());
        // The header was validated from our own read; a file that changed in between, or
        // that OpenEXR parses differently, must not be read into buffers sized for another.
        const Imath::Box2i& dw = input.header().dataWindow();
        if (dw.min.x != 0 || dw.min.y != 0 || dw.max.x + 1 != static_cast<int>(size.width) ||
            dw.max.y + 1 != static_cast<int>(size.height))
            fail(file, "data window changed while reading");
        if (!input.isComplete()) fail(file, "file is truncated or incomplete (some scanlines are missing)");
        Imf::FrameBuffer buffer;
        for (const Layer& layer : frame.layers) {
            for (std::size_t c = 0; c < layer.channels.size(); ++c) {
                const std::string name = exrChannelName(layer.name, layer.channels[c]);
                if (!input.header().channels().findChannel(name.c_str()))
                    fail(file, "channel '" + name + "' changed while reading");
                buffer.insert(name, sliceOf(layer, c, size.width));
            }
        }
        input.setFrameBuffer(buffer);
        input.readPixels(0, static_cast<int>(size.height) - 1);
    });
    convertMotionToConventionA(frame); // before counting: an extreme scale can overflow
    for (Layer& layer : frame.layers) layer.nonFinite = countNonFinite(layer.pixels);
    return frame;
}

void writeFrame(const std::filesystem::path& file, const Frame& frame) {
    if (auto problem = checkFrame(frame)) fail(file, *problem);
    translateErrors(file, "cannot write", [&] {
        writeAtomically(file, [&](const std::filesystem::path& partial) {
            Imf::Header header(static_cast<int>(frame.width), static_cast<int>(frame.height));
            header.compression() = Imf::ZIP_COMPRESSION;
            writeFrameAttributes(header, headerOf(frame));
            Imf::FrameBuffer buffer;
            // OutputFile does not convert between slice and file types (InputFile does), so
            // HALF layers are narrowed here, rounding to nearest as Imath::half does.
            std::vector<std::vector<Imath::half>> halves;
            halves.reserve(frame.layers.size());
            for (const Layer& layer : frame.layers) {
                const bool half = layer.storage == SampleType::Half;
                if (half) halves.emplace_back(layer.pixels.begin(), layer.pixels.end());
                for (std::size_t c = 0; c < layer.channels.size(); ++c) {
                    const std::string name = exrChannelName(layer.name, layer.channels[c]);
                    header.channels().insert(name, Imf::Channel(half ? Imf::HALF : Imf::FLOAT));
                    buffer.insert(name,
                                  half ? halfSliceOf(halves.back(), layer.channels.size(), c, frame.width)
                                       : sliceOf(layer, c, frame.width));
                }
            }
            Imf::OutputFile output(partial.c_str(), header);
            output.setFrameBuffer(buffer);
            output.writePixels(static_cast<int>(frame.height));
        });
    });
}

} // namespace glint::capture
