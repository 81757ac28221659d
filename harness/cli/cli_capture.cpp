#include "cli_capture.h"

#include "cli_commands.h"

#include "capture/channel_map.h"
#include "capture/frame_io.h"
#include "capture/sequence_io.h"

#include <cstdio>
#include <optional>
#include <stdexcept>

namespace glint::cli {

struct CaptureSource::Impl {
    std::optional<capture::Sequence> sequence;
    std::filesystem::path single; // one glint frame file
    std::optional<capture::ChannelMap> map;
    std::vector<std::string> mappedFiles; // foreign frames, in order
};

CaptureSource::CaptureSource(const std::string& path, const std::string& mapPath) : impl_(new Impl) {
    try {
        const std::filesystem::path p(path);
        if (!std::filesystem::exists(p)) throw std::invalid_argument(path + ": no such file or folder");
        if (!mapPath.empty()) {
            impl_->map = capture::loadChannelMap(mapPath);
            impl_->mappedFiles = capture::mappedSequenceFiles(path, *impl_->map);
            if (impl_->mappedFiles.empty())
                throw std::invalid_argument(path + ": no frames to read through " + mapPath);
            if (auto environment = capture::loadMappedEnvironment(*impl_->map, path))
                environment_ = std::move(*environment);
            description_ =
                path + " through " + mapPath + " (" + std::to_string(impl_->mappedFiles.size()) + " frames)";
        } else if (std::filesystem::is_directory(p) || p.filename() == capture::kManifestName) {
            impl_->sequence = capture::readSequence(p);
            if (auto environment = capture::loadEnvironment(*impl_->sequence))
                environment_ = std::move(*environment);
            description_ = path + " (" + std::to_string(impl_->sequence->frameFiles.size()) + " frames)";
        } else {
            impl_->single = p;
            description_ = path;
        }
    } catch (...) {
        delete impl_;
        throw;
    }
    if (environment_.width == 0) environment_ = blackEnvironment();
}

CaptureSource::~CaptureSource() {
    delete impl_;
}

std::size_t CaptureSource::frameCount() const {
    if (impl_->map) return impl_->mappedFiles.size();
    return impl_->sequence ? impl_->sequence->frameFiles.size() : 1;
}

capture::Frame CaptureSource::frame(std::size_t index) const {
    if (impl_->map)
        return capture::readMappedFrame(impl_->mappedFiles.at(index), *impl_->map,
                                        static_cast<std::uint32_t>(index));
    if (impl_->sequence) return capture::loadFrame(*impl_->sequence, index);
    return capture::readFrame(impl_->single);
}

capture::Environment blackEnvironment() {
    capture::Environment environment;
    environment.layout = capture::EnvironmentLayout::LatLong;
    environment.width = 16;
    environment.height = 8;
    environment.rgb.assign(16 * 8 * 3, 0.0f);
    return environment;
}

FrameRange parseFrames(const std::string& text, std::size_t count) {
    FrameRange range{0, count - 1};
    if (text.empty()) return range;
    const std::size_t dots = text.find("..");
    auto number = [&](const std::string& part) {
        std::size_t used = 0;
        unsigned long value = 0;
        try {
            value = std::stoul(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (part.empty() || used != part.size())
            throw std::invalid_argument("--frames must read a..b, a.. or a (frame indices), got '" + text +
                                        "'");
        return static_cast<std::size_t>(value);
    };
    if (dots == std::string::npos) {
        range.first = range.last = number(text);
    } else {
        range.first = number(text.substr(0, dots));
        if (dots + 2 < text.size()) range.last = number(text.substr(dots + 2));
    }
    if (range.first > range.last || range.last >= count)
        throw std::invalid_argument("--frames " + text + " is outside the capture's " +
                                    std::to_string(count) + " frame(s) (0.." + std::to_string(count - 1) +
                                    ")");
    return range;
}

int withContext(bool validate, const std::function<int(const gpu::Context&)>& body) {
    gpu::ContextOptions options;
    options.validation = validate;
    options.synchronizationValidation = validate;
    gpu::Context context = gpu::createContext(options);
    int code = kExitUsage;
    try {
        code = body(context);
    } catch (...) {
        gpu::destroyContext(context);
        throw;
    }
    gpu::destroyContext(context);
    const std::uint32_t errors = context.validation ? context.validation->errors.load() : 0u;
    if (errors > 0) {
        std::fprintf(stderr, "glint: %u validation errors\n", errors);
        return kExitCheckFailed;
    }
    return code;
}

replay::FrameResult replayUntil(const gpu::Context& context, const CaptureSource& source,
                                const std::string& frameText, replay::SessionOptions options,
                                std::size_t* frameIndex) {
    const std::size_t last =
        frameText.empty() ? source.frameCount() - 1 : parseFrames(frameText, source.frameCount()).first;
    if (frameIndex) *frameIndex = last;
    options.intermediates = true;
    const capture::Frame first = source.frame(0);
    replay::Session session(context, first, source.environment(), options);
    replay::FrameResult result;
    for (std::size_t index = 0; index <= last; ++index) {
        result = session.run(index == 0 ? first : source.frame(index));
    }
    return result;
}

bool passSelected(const std::string& selection, const std::string& pass) {
    if (selection == "all" || selection == pass) return true;
    const std::size_t slash = pass.find('/');
    return slash != std::string::npos && pass.substr(slash + 1) == selection;
}

std::filesystem::path dumpPath(const replay::NamedImage& image) {
    const std::size_t slash = image.name.find('/');
    return std::filesystem::path(image.pass) / image.name.substr(slash + 1);
}

std::string fileStem(const std::string& imageName) {
    std::string stem = imageName;
    for (char& c : stem)
        if (c == '/') c = '_';
    return stem;
}

} // namespace glint::cli
