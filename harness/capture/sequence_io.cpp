#include "capture/sequence_io.h"

#include "capture/capture_error.h"
#include "capture/exr_file.h"
#include "capture/frame_io.h"
#include "capture/json_text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

namespace glint::capture {

namespace {
constexpr const char* kFormat = "glint-sequence";
constexpr int kManifestVersion = 1;
constexpr std::uintmax_t kMaxManifestBytes = 16u << 20; // far beyond any real sequence

std::string sizeText(const FrameHeader& h) {
    return std::to_string(h.width) + "x" + std::to_string(h.height);
}

// Manifest entries must stay inside the sequence folder: a bare relative path without "..".
bool isInsideFolder(const std::string& name) {
    const std::filesystem::path p(name);
    if (name.empty() || p.is_absolute() || p.has_root_name()) return false;
    for (const auto& part : p)
        if (part == "..") return false;
    return true;
}

nlohmann::json parseManifest(const std::filesystem::path& manifest) {
    std::error_code ec;
    if (!std::filesystem::exists(manifest, ec)) fail(manifest, "file does not exist");
    if (!std::filesystem::is_regular_file(manifest, ec)) fail(manifest, "not a regular file");
    const std::uintmax_t bytes = std::filesystem::file_size(manifest, ec);
    if (ec || bytes > kMaxManifestBytes) fail(manifest, "manifest is unreadable or larger than 16 MiB");
    std::string text(static_cast<std::size_t>(bytes), '\0');
    std::ifstream in(manifest, std::ios::binary);
    if (!in.read(text.data(), static_cast<std::streamsize>(text.size())))
        fail(manifest, "cannot read the manifest");
    return parseJson(text, manifest, "malformed JSON");
}

std::string requiredString(const nlohmann::json& j, const char* key, const std::filesystem::path& manifest) {
    if (!j.contains(key)) fail(manifest, std::string("missing key '") + key + "'");
    if (!j[key].is_string()) fail(manifest, std::string("key '") + key + "' must be a string");
    return j[key].get<std::string>();
}

std::string frameName(std::size_t index) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04zu.exr", index);
    return name;
}
} // namespace

Sequence readSequence(const std::filesystem::path& path) {
    const bool isManifest = path.filename() == kManifestName;
    const std::filesystem::path manifest = isManifest ? path : path / kManifestName;
    Sequence seq;
    seq.directory = manifest.parent_path();

    const nlohmann::json j = parseManifest(manifest);
    if (!j.is_object()) fail(manifest, "the manifest must be a JSON object");
    if (requiredString(j, "format", manifest) != kFormat)
        fail(manifest, std::string("key 'format' must be \"") + kFormat + "\"");
    if (!j.contains("version") || !j["version"].is_number_integer())
        fail(manifest, "missing or non-integer key 'version'");
    if (j["version"].get<long long>() != kManifestVersion)
        fail(manifest,
             "unsupported manifest version " + j["version"].dump() + " (this reader knows version 1)");
    if (!j.contains("frameRate") || !j["frameRate"].is_number())
        fail(manifest, "missing or non-numeric key 'frameRate'");
    seq.frameRate = j["frameRate"].get<double>();
    if (!std::isfinite(seq.frameRate) || !(seq.frameRate > 0.0))
        fail(manifest, "key 'frameRate' must be a positive number");
    if (!j.contains("frames") || !j["frames"].is_array() || j["frames"].empty())
        fail(manifest, "key 'frames' must be a non-empty array of file names");

    std::set<std::string, std::less<>> seen;
    for (const nlohmann::json& entry : j["frames"]) {
        if (!entry.is_string()) fail(manifest, "key 'frames' must hold only strings");
        const std::string name = entry.get<std::string>();
        if (!isInsideFolder(name))
            fail(manifest, "frame '" + name + "' is not a relative path inside the sequence folder");
        if (!seen.insert(name).second) fail(manifest, "frame '" + name + "' is listed twice");
        std::error_code ec;
        if (!std::filesystem::exists(seq.directory / name, ec))
            fail(manifest, "frame '" + name + "' does not exist");
        seq.frameFiles.push_back(name);
    }
    if (j.contains("environment")) {
        seq.environment = requiredString(j, "environment", manifest);
        std::error_code ec;
        if (!isInsideFolder(seq.environment))
            fail(manifest,
                 "environment '" + seq.environment + "' is not a relative path inside the sequence folder");
        if (!std::filesystem::exists(seq.directory / seq.environment, ec))
            fail(manifest, "environment '" + seq.environment + "' does not exist");
    }

    if (j.contains("scene")) seq.scene = requiredString(j, "scene", manifest);

    for (const std::string& name : seq.frameFiles) {
        FrameHeader header = readFrameHeader(seq.directory / name);
        if (!seq.headers.empty() &&
            (header.width != seq.headers[0].width || header.height != seq.headers[0].height))
            fail(seq.directory / name, "size " + sizeText(header) + " differs from the sequence's " +
                                           sizeText(seq.headers[0]) + " (" + seq.frameFiles[0] + ")");
        seq.headers.push_back(std::move(header));
    }
    return seq;
}

Frame loadFrame(const Sequence& sequence, std::size_t index) {
    if (index >= sequence.frameFiles.size())
        fail(sequence.directory / kManifestName, "frame " + std::to_string(index) + " requested of " +
                                                     std::to_string(sequence.frameFiles.size()));
    Frame frame = readFrame(sequence.directory / sequence.frameFiles[index]);
    if (frame.width != sequence.headers[index].width || frame.height != sequence.headers[index].height)
        fail(sequence.directory / sequence.frameFiles[index], "size changed since the sequence was opened");
    return frame;
}

std::optional<Environment> loadEnvironment(const Sequence& sequence) {
    if (sequence.environment.empty()) return std::nullopt;
    return readEnvironment(sequence.directory / sequence.environment);
}

void writeSequence(const std::filesystem::path& directory, const std::vector<Frame>& frames, double frameRate,
                   const Environment* environment, const std::filesystem::path& scene) {
    const std::filesystem::path manifest = directory / kManifestName;
    if (frames.empty()) fail(manifest, "a sequence needs at least one frame");
    if (!std::isfinite(frameRate) || !(frameRate > 0.0))
        fail(manifest, "frame rate must be a positive number");
    for (std::size_t i = 1; i < frames.size(); ++i) {
        if (frames[i].width != frames[0].width || frames[i].height != frames[0].height)
            fail(directory / frameName(i), "size " + sizeText(headerOf(frames[i])) +
                                               " differs from the sequence's " +
                                               sizeText(headerOf(frames[0])));
    }
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (ec) fail(directory, "cannot create the sequence folder: " + ec.message());

    nlohmann::ordered_json j;
    j["format"] = kFormat;
    j["version"] = kManifestVersion;
    j["frames"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < frames.size(); ++i) {
        writeFrame(directory / frameName(i), frames[i]);
        j["frames"].push_back(frameName(i));
    }
    j["frameRate"] = frameRate;
    if (environment) {
        writeEnvironment(directory / "environment.exr", *environment);
        j["environment"] = "environment.exr";
    }
    if (!scene.empty()) {
        std::error_code absoluteError;
        const std::filesystem::path absolute = std::filesystem::absolute(scene, absoluteError);
        j["scene"] = (absoluteError ? scene : absolute).lexically_normal().string();
    }
    translateErrors(manifest, "cannot write", [&] {
        writeAtomically(manifest, [&](const std::filesystem::path& partial) {
            std::ofstream out(partial, std::ios::binary | std::ios::trunc);
            out << j.dump(2) << '\n';
            out.close();
            if (!out) fail(manifest, "cannot write the manifest");
        });
    });
}

} // namespace glint::capture
