// glint check: each pass's outputs against expected ones laid out as glint dump writes them
// (<dir>/<effect>/<pass>/<image>.exr, e.g. exported from an engine's own integration of the
// headers), with per-pass tolerances, and a verdict table. Exit 1 when a pass differs.
//
// Default tolerances (absolute, relative, fraction of pixels allowed to differ) follow what
// each pass computes: reductions, packing, lists and classes are exact on every GPU; float
// filters differ in the last bits between compilers; the intersection's hit or miss may flip
// on a few pixels where a ray grazes a depth edge and the GPUs round differently.
#include "cli_capture.h"
#include "cli_commands.h"

#include "report/report_metrics.h"

#include <cstdio>
#include <map>
#include <stdexcept>

namespace glint::cli {
namespace {

struct Tolerance {
    double absolute = 0.0, relative = 0.0, fraction = 0.0;
};

// The float passes of the reflections and of the hybrid (intersection, ray tracing, shading,
// the denoiser): a hit may flip where a ray grazes a depth edge, and the flip carries into the
// passes after it. Their classifications, lists, inputs and pyramid are exact.
bool reflectionFloatPass(const std::string& pass) {
    for (const std::string effect : {"reflections/", "hybrid/"})
        if (pass.rfind(effect, 0) == 0)
            return pass != effect + "classify" && pass != effect + "input" &&
                   pass != effect + "depth_pyramid";
    return false;
}

Tolerance defaultTolerance(const std::string& pass) {
    if (reflectionFloatPass(pass)) return {1e-3, 1e-2, 0.01};
    if (pass == "shadows/classify" || pass.rfind("shadows/filter", 0) == 0) return {1e-4, 1e-3, 0.001};
    if (pass == "reflections/classify") return {1e-6, 1e-6, 0.0};
    return {}; // inputs, the depth pyramid, shadow prepare, the hybrid's classification: exact
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

int runCheck(const ReplayOptions& options) {
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
