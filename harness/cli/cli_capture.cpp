#include "cli_capture.h"

#include "cli_commands.h"

#include "capture/channel_map.h"
#include "capture/frame_io.h"
#include "capture/sequence_io.h"
#include "scene/scene_file.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <set>
#include <stdexcept>

namespace glint::cli {

namespace {

// The digits that end a frame's name, without ".exr": "0001.exr" -> 1, "frame_0000.exr" -> 0.
std::optional<std::size_t> trailingNumber(const std::string& path) {
    std::string name = std::filesystem::path(path).filename().string();
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower.ends_with(".exr")) name.resize(name.size() - 4);
    std::size_t start = name.size();
    while (start > 0 && std::isdigit(static_cast<unsigned char>(name[start - 1]))) --start;
    if (start == name.size() || name.size() - start > 9) return std::nullopt;
    return static_cast<std::size_t>(std::stoul(name.substr(start)));
}

// Frame numbers from the names when every name ends in a distinct one, else positions.
std::vector<std::size_t> frameNumbers(const std::vector<std::string>& paths) {
    std::vector<std::size_t> numbers;
    std::set<std::size_t> seen;
    for (const std::string& path : paths) {
        const std::optional<std::size_t> number = trailingNumber(path);
        if (!number || !seen.insert(*number).second) break;
        numbers.push_back(*number);
    }
    if (numbers.size() == paths.size()) return numbers;
    numbers.resize(paths.size());
    for (std::size_t i = 0; i < numbers.size(); ++i) numbers[i] = i;
    return numbers;
}

} // namespace

struct CaptureSource::Impl {
    std::optional<capture::Sequence> sequence;
    std::filesystem::path single; // one glint frame file
    std::optional<capture::ChannelMap> map;
    std::vector<std::string> mappedFiles; // foreign frames, in order
    std::vector<std::string> paths;       // every frame's file, in order
    std::vector<std::size_t> numbers;     // frameNumber()
};

CaptureSource::CaptureSource(const std::string& path, const std::string& mapPath) : impl_(new Impl) {
    try {
        const std::filesystem::path p(path);
        if (!std::filesystem::exists(p)) throw std::invalid_argument(path + ": no such file or folder");
        if (!mapPath.empty()) {
            impl_->map = capture::loadChannelMap(mapPath);
            std::vector<std::string> ignored;
            impl_->mappedFiles = capture::mappedSequenceFiles(path, *impl_->map, &ignored);
            if (!ignored.empty()) {
                std::string names;
                for (std::size_t i = 0; i < ignored.size() && i < 4; ++i)
                    names += (i ? ", " : "") + ignored[i];
                if (ignored.size() > 4) names += ", ...";
                std::fprintf(stderr,
                             "glint: %s: note: %zu file%s that the map's frames do not match left out (%s)\n",
                             path.c_str(), ignored.size(), ignored.size() == 1 ? "" : "s", names.c_str());
            }
            if (impl_->mappedFiles.empty())
                throw std::invalid_argument(path + ": no frames to read through " + mapPath);
            if (auto environment = capture::loadMappedEnvironment(*impl_->map, path)) {
                environment_ = std::move(*environment);
                environmentName_ = capture::mappedEnvironmentFile(*impl_->map, path).string();
            } else if (!impl_->map->environment.file.empty()) {
                environmentName_ = "none (the optional " +
                                   capture::mappedEnvironmentFile(*impl_->map, path).string() +
                                   " is not there)";
            }
            impl_->paths = impl_->mappedFiles;
            description_ =
                path + " through " + mapPath + " (" + std::to_string(impl_->mappedFiles.size()) + " frames)";
        } else if (std::filesystem::is_directory(p) || p.filename() == capture::kManifestName) {
            if (std::filesystem::is_directory(p)) requireManifest(p);
            impl_->sequence = capture::readSequence(p);
            if (auto environment = capture::loadEnvironment(*impl_->sequence)) {
                environment_ = std::move(*environment);
                environmentName_ = (impl_->sequence->directory / impl_->sequence->environment).string();
            }
            for (const std::string& name : impl_->sequence->frameFiles)
                impl_->paths.push_back((impl_->sequence->directory / name).string());
            description_ = path + " (" + std::to_string(impl_->sequence->frameFiles.size()) + " frames)";
        } else {
            impl_->single = p;
            impl_->paths.push_back(path);
            description_ = path;
        }
        impl_->numbers = frameNumbers(impl_->paths);
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
    return impl_->paths.size();
}

capture::Frame CaptureSource::frame(std::size_t index) const {
    if (impl_->map)
        return capture::readMappedFrame(impl_->mappedFiles.at(index), *impl_->map,
                                        static_cast<std::uint32_t>(index));
    if (impl_->sequence) return capture::loadFrame(*impl_->sequence, index);
    return capture::readFrame(impl_->single);
}

std::string CaptureSource::framePath(std::size_t index) const {
    return impl_->paths.at(index);
}

std::string CaptureSource::sceneFile() const {
    return impl_->sequence ? impl_->sequence->scene : std::string();
}

std::vector<std::string> CaptureSource::declaredEffects() const {
    if (impl_->map) return impl_->map->effects;
    return capture::readFrameHeader(impl_->paths.front()).effects;
}

std::vector<std::string> settingsWithPreset(const ReplayOptions& options, const CaptureSource& source) {
    if (options.preset.name.empty()) return options.settings;
    return presetThenSettings(options.preset,
                              options.effects.empty() ? source.declaredEffects() : options.effects,
                              options.settings);
}

std::size_t CaptureSource::frameNumber(std::size_t index) const {
    return impl_->numbers.at(index);
}

std::vector<std::string> CaptureSource::checkEffects(const capture::Frame& frame, std::size_t index,
                                                     const replay::SessionOptions& options) const {
    const std::vector<std::string>& wanted = options.effects.empty() ? frame.effects : options.effects;
    const std::vector<std::string> known = replay::knownEffects();
    const bool allKnown =
        !wanted.empty() && std::all_of(wanted.begin(), wanted.end(), [&](const std::string& e) {
            return std::find(known.begin(), known.end(), e) != known.end();
        });
    const std::optional<replay::MissingLayer> missing =
        allKnown ? replay::missingLayer(frame, wanted, options.settings) : std::nullopt;
    if (!missing) return replay::effectsToRun(frame, options.effects, options.settings);
    std::string message = framePath(index) + ": " + replay::missingLayerMessage(*missing);
    const std::string off = missing->setting.empty() ? "" : ", or leave " + missing->setting + " off";
    if (missing->layer == "material" && !impl_->map) {
        message += "; give the capture a 'material' layer with the base colour in R, G, B" + off;
    } else if (missing->layer == "material" && impl_->map->baseColor.empty()) {
        message += "; map the base colour with [material] base_color in " + impl_->map->path +
                   " (docs/replay.md)" + off;
    } else if (missing->layer == "material") {
        std::string channels;
        for (const std::string& channel : impl_->map->baseColor)
            channels += (channels.empty() ? "" : ", ") + channel;
        message += "; the file lacks " + channels + " (material.base_color in " + impl_->map->path +
                   "): render that pass (Blender: Diffuse Color, docs/replay.md)" + off;
    } else {
        message += impl_->map ? "; map it in " + impl_->map->path + " (docs/replay.md, \"The map file\")"
                              : "; the layers each effect reads: docs/capture-format.md, \"Required layers\"";
        if (missing->layer == "shadow")
            message += "; from Blender: docs/replay.md, \"Shadow visibility from Blender\"";
        message += off;
    }
    throw std::invalid_argument(message);
}

void CaptureSource::checkFrames(std::size_t first, std::size_t last,
                                const replay::SessionOptions& options) const {
    bool halfDepth = false;
    std::string halfDepthFile;
    for (std::size_t index = first; index <= last && index < frameCount(); ++index) {
        if (impl_->map) {
            if (capture::checkMappedFrame(impl_->mappedFiles.at(index), *impl_->map) && !halfDepth) {
                halfDepth = true;
                halfDepthFile = impl_->mappedFiles.at(index);
            }
            continue; // the map names the same layers for every frame: checkEffects saw them
        }
        const capture::FrameHeader header = capture::checkFrameFile(impl_->paths.at(index));
        // The layers' shapes without pixels are what checkEffects reads.
        capture::Frame shape = capture::frameFromHeader(header);
        for (const capture::LayerInfo& info : header.layers) {
            shape.layers.push_back({info.name, info.channels, {}, 0, info.storage});
            if (info.name == "depth" && info.storage == capture::SampleType::Half && !halfDepth) {
                halfDepth = true;
                halfDepthFile = impl_->paths.at(index);
            }
        }
        checkEffects(shape, index, options);
    }
    if (halfDepth)
        std::fprintf(stderr,
                     "glint: %s: warning: depth is stored as 16-bit float (HALF): it quantises geometry "
                     "(about 3 significant digits) and view depths beyond 65504 turn into Inf\n",
                     halfDepthFile.c_str());
}

std::string frameFolderName(std::size_t number) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04zu", number);
    return name;
}

void addReplayOptions(CLI::App& command, ReplayOptions& options) {
    command
        .add_option("capture", options.capture,
                    "frame .exr, sequence folder, or with --map one foreign EXR or a folder of them "
                    "(one path)")
        ->required();
    command.add_option("--map", options.mapPath, "channel map of a foreign capture (docs/replay.md)");
    command.add_option("--geometry", options.geometry,
                       "a glTF (.gltf/.glb, or anything assimp reads) of the capture's scene in its world "
                       "space, for the effects that ray trace (hybrid): its meshes with their materials "
                       "and its punctual lights; wins over the scene a manifest records (docs/replay.md)");
    command.add_option("--effects", options.effects, effectNames() + " (default: declared)")->delimiter(',');
    command.add_option("--set", options.settings, "a setting, name=value (repeatable; glint settings)");
    addPresetOptions(command, options.preset);
    command.footer(settingsHelp());
}

void requireManifest(const std::filesystem::path& folder) {
    std::error_code ec;
    if (std::filesystem::exists(folder / capture::kManifestName, ec)) return;
    throw std::invalid_argument(folder.string() + ": no " + capture::kManifestName +
                                "; for a folder of foreign EXR renders pass --map FILE "
                                "(harness/maps/blender.toml for Blender)");
}

capture::Environment blackEnvironment() {
    capture::Environment environment;
    environment.layout = capture::EnvironmentLayout::LatLong;
    environment.width = 16;
    environment.height = 8;
    environment.rgb.assign(16 * 8 * 3, 0.0f);
    return environment;
}

void setGeometry(replay::SessionOptions& options, const std::string& manifestScene,
                 const std::string& geometryPath) {
    options.scene = manifestScene;
    options.geometry.reset();
    if (geometryPath.empty()) return;
    std::vector<std::string> warnings;
    options.geometry = scene::loadGeometryScene(geometryPath, &warnings);
    for (const std::string& warning : warnings)
        std::fprintf(stderr, "glint: %s: warning: %s\n", geometryPath.c_str(), warning.c_str());
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

int withContext(bool validate, const std::function<int(const gpu::Context&)>& body,
                const std::function<void(gpu::ContextOptions&)>& configure) {
    gpu::ContextOptions options;
    options.validation = validate;
    options.synchronizationValidation = validate;
    if (configure) configure(options);
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
    source.checkFrames(0, last, options);
    const capture::Frame first = source.frame(0);
    source.checkEffects(first, 0, options);
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
