// The parts of glint report that read across runs or pixels: the convergence verdict, the
// summary table over every run (one row per run and scored effect) and the zoom on the region
// of a frame where the output's error is largest.
#pragma once

#include "report/report_html.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace glint::cli {

// `value` with `decimals` digits after the point (four for errors, one for microseconds).
std::string fixedDecimals(double value, int decimals);

// A number of a JSON object, NaN where it is absent or not a number (null: nothing scored).
double valueOr(const nlohmann::json& object, const char* key);

// Whether the references resolve what the report says of an effect on the last frame (the
// study's rule, docs/accuracy-vs-time.md): "yes" when the two references' own difference (the
// floor, same metric) is below a quarter of |output error - noisy input's error|. Where the two
// errors are equal (the output is its noisy input over the mask, as the shadow denoiser leaves
// hard shadows) there is no difference to resolve, and the floor must be below a quarter of the
// error itself: "yes (output = input)". "-" without a floor or a noisy error; otherwise "no",
// with the numbers in `reason`.
struct Convergence {
    std::string verdict;
    std::string reason; // why not, for a "no"
    // The verdict with its reason, "no: floor ... is not below a quarter of ...".
    std::string withReason() const { return reason.empty() ? verdict : verdict + ": " + reason; }
};
Convergence convergence(double floor, double output, double noisy);

// One row per run and scored effect: the noisy input's and the output's error on the last frame,
// the reference noise floor, the convergence verdict, the difference of the two errors against
// the capture's reference and against the second one and whether they agree (same sign, apart
// by less than a quarter), FLIP of both, the error over moving edges
// of both (visibility effects), the effect's GPU time per frame (the sum of its passes' medians)
// and the reference's samples per pixel on the last frame.
report::Table summaryTable(const std::vector<std::pair<std::filesystem::path, nlohmann::json>>& runs);

// Side by side, the noisy input, the output and the reference of `effect` on the frame in
// `frameDir`, cropped to the window a quarter of the frame wide and high whose summed output
// error (<effect>_error.exr) is largest and scaled up with nearest filtering; none when a file
// is missing or the error is 0 everywhere. `finalImage` is the scored image ("effect/denoised").
std::vector<report::Figure> zoomFigures(const std::filesystem::path& frameDir, const std::string& effect,
                                        const std::string& finalImage, const std::string& noisyImage);

} // namespace glint::cli
