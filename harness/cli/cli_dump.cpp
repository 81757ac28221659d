// glint dump: every intermediate of the named passes of one frame (after replaying the frames
// before it, so that histories are what they would be) as EXR and PNG, laid out
// <out>/<effect>/<pass>/<image>.exr, plus counters.json (ray counts, filtered tiles). glint
// check reads the same layout (docs/replay.md).
#include "cli_capture.h"
#include "cli_commands.h"
#include "cli_images.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>

namespace glint::cli {

void addDumpOptions(CLI::App& command, ReplayOptions& options) {
    addReplayOptions(command, options);
    command.add_option("--out", options.outDir, "output folder")->required();
    command.add_option("--pass", options.pass, "pass name, effect/pass, input or all")->capture_default_str();
    command.add_option("--frame", options.frames, "the frame to dump (default: the last)");
}

int runDump(ReplayOptions options, bool validate) {
    // An unknown preset or an unreadable preset file fails before any capture is read.
    checkPresetChoice(options.preset);
    options.validate = validate;
    if (options.outDir.empty()) throw std::invalid_argument("dump: --out DIR is required");
    const CaptureSource source(options.capture, options.mapPath);
    replay::SessionOptions sessionOptions;
    sessionOptions.effects = options.effects;
    setGeometry(sessionOptions, source.sceneFile(), options.geometry);
    const std::vector<std::string> settings = settingsWithPreset(options, source);
    sessionOptions.settings = replay::parseSettings(settings);
    const std::filesystem::path out(options.outDir);
    return withContext(options.validate, [&](const gpu::Context& context) {
        std::size_t frame = 0;
        const replay::FrameResult result =
            replayUntil(context, source, options.frames, sessionOptions, &frame);
        nlohmann::json index{{"capture", source.description()}, {"frame", frame}, {"settings", settings}};
        std::size_t written = 0;
        for (const replay::NamedImage& image : result.images) {
            if (!passSelected(options.pass, image.pass)) continue;
            const std::filesystem::path relative = dumpPath(image);
            writeImageFiles(out / relative.parent_path(), relative.filename().string(), image.name,
                            image.image, true);
            index["images"][image.name] = {{"pass", image.pass},
                                           {"file", relative.string() + ".exr"},
                                           {"size", {image.image.width, image.image.height}},
                                           {"channels", image.image.channels}};
            std::printf("  %-36s %-28s %ux%u x%u\n", image.name.c_str(), image.pass.c_str(),
                        image.image.width, image.image.height, image.image.channels);
            ++written;
        }
        if (written == 0)
            throw std::invalid_argument("dump: no pass named '" + options.pass +
                                        "' in this replay (try --pass all to list them)");
        for (const replay::Counter& counter : result.counters)
            index["counters"][counter.name] = counter.value;
        for (const replay::PassTime& time : result.timings) index["timings"][time.pass] = time.milliseconds;
        std::filesystem::create_directories(out);
        std::ofstream(out / "index.json") << index.dump(2) << "\n";
        std::printf("dumped %zu image(s) of frame %zu to %s\n", written, frame, out.string().c_str());
        return kExitOk;
    });
}

} // namespace glint::cli
