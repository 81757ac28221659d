// glint check: each pass's outputs against expected ones laid out as glint dump writes them
// (<dir>/<effect>/<pass>/<image>.exr, e.g. exported from an engine's own integration of the
// headers), with per-pass tolerances, and a verdict table. Exit 1 when a pass differs.
//
// Default tolerances (absolute, relative, fraction of pixels allowed to differ) are each
// effect's (EffectEvaluation::tolerances, glint_effect.h) and follow what each pass computes:
// reductions, packing, lists and classes are exact on every GPU; float filters differ in the
// last bits between compilers; the intersection's hit or miss may flip on a few pixels where a
// ray grazes a depth edge and the GPUs round differently. A pass no row names is exact.
#include "cli_capture.h"
#include "cli_commands.h"

#include "report/report_metrics.h"

#include <CLI/CLI.hpp>
#include <glint/glint_effect.h>

#include <cstdio>
#include <map>
#include <stdexcept>

namespace glint::cli {
namespace {

struct Tolerance {
    double absolute = 0.0, relative = 0.0, fraction = 0.0;
};

// The first of the effect's tolerance rows that names `pass` ("<effect>/<pass>"); exact
// without one.
Tolerance defaultTolerance(const std::string& pass) {
    const std::size_t slash = pass.find('/');
    const EffectDescriptor* effect = slash == std::string::npos ? nullptr : findEffect(pass.substr(0, slash));
    if (!effect) return {};
    const std::string name = pass.substr(slash + 1);
    for (const PassTolerance& row : effect->evaluation.tolerances) {
        const bool prefix = !row.pass.empty() && row.pass.back() == '*';
        const bool matches = prefix
                                 ? name.compare(0, row.pass.size() - 1, row.pass, 0, row.pass.size() - 1) == 0
                                 : name == row.pass;
        if (matches) return {row.absolute, row.relative, row.fraction};
    }
    return {};
}

std::map<std::string, Tolerance> parseTolerances(const std::vector<std::string>& texts) {
    std::map<std::string, Tolerance> overrides;
    for (const std::string& text : texts) {
        Tolerance t;
        char pass[128] = {};
        const int read =
            std::sscanf(text.c_str(), "%127[^=]=%lf,%lf,%lf", pass, &t.absolute, &t.relative, &t.fraction);
        if (read < 3 || t.absolute < 0.0 || t.relative < 0.0 || t.fraction < 0.0)
            throw std::invalid_argument("check: --tolerance must read effect/pass=abs,rel[,fraction], got '" +
                                        text + "'");
        overrides[pass] = t;
    }
    return overrides;
}

} // namespace

void addCheckOptions(CLI::App& command, ReplayOptions& options) {
    addReplayOptions(command, options);
    command.add_option("--expected", options.expectedDir, "folder laid out as glint dump writes")->required();
    command.add_option("--pass", options.pass, "pass name, effect/pass or all")->capture_default_str();
    command.add_option("--frame", options.frames, "the frame to compare (default: the last)");
    command.add_option("--tolerance", options.tolerances, "effect/pass=abs,rel[,fraction] (repeatable)");
}

int runCheck(ReplayOptions options, bool validate) {
    // An unknown preset or an unreadable preset file fails before any capture is read.
    checkPresetChoice(options.preset);
    options.validate = validate;
    if (options.expectedDir.empty()) throw std::invalid_argument("check: --expected DIR is required");
    const std::filesystem::path expectedDir(options.expectedDir);
    if (!std::filesystem::is_directory(expectedDir))
        throw std::invalid_argument("check: " + options.expectedDir + ": no such folder");
    const std::map<std::string, Tolerance> overrides = parseTolerances(options.tolerances);
    const CaptureSource source(options.capture, options.mapPath);
    replay::SessionOptions sessionOptions;
    sessionOptions.effects = options.effects;
    setGeometry(sessionOptions, source.sceneFile(), options.geometry);
    const std::vector<std::string> settings = settingsWithPreset(options, source);
    sessionOptions.settings = replay::parseSettings(settings);
    return withContext(options.validate, [&](const gpu::Context& context) {
        std::size_t frame = 0;
        const replay::FrameResult result =
            replayUntil(context, source, options.frames, sessionOptions, &frame);
        std::printf("check of frame %zu of %s against %s\n", frame, source.description().c_str(),
                    options.expectedDir.c_str());
        std::printf("%-26s %-16s %12s %12s %10s %8s  %s\n", "pass", "image", "max |diff|", "rmse", "differ %",
                    "allowed", "verdict");
        std::size_t compared = 0, failed = 0;
        for (const replay::NamedImage& image : result.images) {
            if (!passSelected(options.pass, image.pass)) continue;
            const std::filesystem::path file = expectedDir / (dumpPath(image).string() + ".exr");
            if (!std::filesystem::exists(file)) continue;
            const report::Image expected = report::readExr(file.string());
            const Tolerance tolerance =
                overrides.contains(image.pass) ? overrides.at(image.pass) : defaultTolerance(image.pass);
            const std::string shortName = image.name.substr(image.name.find('/') + 1);
            ++compared;
            if (expected.width != image.image.width || expected.height != image.image.height ||
                expected.channels != image.image.channels) {
                std::printf("%-26s %-16s expected %ux%u x%u, got %ux%u x%u  FAIL\n", image.pass.c_str(),
                            shortName.c_str(), expected.width, expected.height, expected.channels,
                            image.image.width, image.image.height, image.image.channels);
                ++failed;
                continue;
            }
            const report::ImageDiff diff =
                report::diffImages(image.image, expected, tolerance.absolute, tolerance.relative);
            const double pixels = static_cast<double>(expected.width) * expected.height;
            const double fraction = static_cast<double>(diff.differing) / pixels;
            const bool pass = fraction <= tolerance.fraction;
            if (!pass) ++failed;
            std::printf("%-26s %-16s %12.4g %12.4g %10.3f %8.3f  %s\n", image.pass.c_str(), shortName.c_str(),
                        diff.maxAbs, diff.rmse, 100.0 * fraction, 100.0 * tolerance.fraction,
                        pass ? "ok" : "FAIL");
        }
        if (compared == 0)
            throw std::invalid_argument("check: " + options.expectedDir +
                                        " holds no expected image for pass '" + options.pass +
                                        "' (lay it out as glint dump writes it)");
        std::printf("%zu image(s) compared, %zu differ\n", compared, failed);
        return failed > 0 ? kExitCheckFailed : kExitOk;
    });
}

} // namespace glint::cli
