// What glint bench on captures and glint study share: timing a replay Session over a capture's
// frames (warm-up, then measured runs, readback off) and writing the result as a table or JSON.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "replay/replay_session.h"

#include <gpu/gpu_context.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace glint::cli {

// One pass's GPU time over the measured runs, microseconds.
struct PassStats {
    std::string pass; // "reflections/intersect", or "total" for the per-run sum of every pass
    double medianUs = 0.0, minUs = 0.0, maxUs = 0.0;
};

struct Measurement {
    std::vector<PassStats> passes;         // in the order they ran; empty without timestamps
    PassStats total{"total"};              // statistics of the per-run sums
    std::vector<replay::Counter> counters; // of the last run
    std::uint32_t warmup = 0, runs = 0;
    double wallPerRunUs = 0.0;   // wall time of the sustained runs over their count
    gpu::DeviceMemoryUse memory; // held while the runs were measured
};

// Every frame once, then min(runs, 10) warm-up runs and `runs` measured ones, of a Session
// created with options.readback = false: the last frame repeated (Session::repeatSustained),
// so that every run does the work of a running sequence at the clocks a frame loop keeps.
Measurement measureFrames(const gpu::Context& context, const std::vector<capture::Frame>& frames,
                          const capture::Environment& environment, replay::SessionOptions options,
                          std::uint32_t runs);

nlohmann::json deviceJson(const gpu::Context& context);
nlohmann::json measurementJson(const Measurement& measurement);
void printMeasurement(std::FILE* out, const Measurement& measurement);

} // namespace glint::cli
