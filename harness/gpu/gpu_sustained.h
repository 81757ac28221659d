// Sustained timing: frames recorded into two command buffers that are submitted alternately,
// the other one always queued, so that the GPU never waits for the host. A GPU left idle
// between frames lowers its clocks and runs the next frames several times slower than a frame
// loop would (docs/performance.md), so benchmarks time frames this way.
#pragma once

#include <gpu/gpu_context.h>
#include <gpu/gpu_timestamps.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace glint::gpu {

// Called 2 * framesPerBuffer times, frame 0 to 2 * framesPerBuffer - 1, to record one frame
// into `cmd`, with its timestamps written to `timestamps`.
using RecordFrame = std::function<void(VkCommandBuffer cmd, TimestampPool& timestamps, std::uint32_t frame)>;

// Frames a benchmark records into each buffer, and the submissions that run at least `frames`.
constexpr std::uint32_t kSustainedFramesPerBuffer = 8;
constexpr std::uint32_t sustainedSubmissions(std::uint32_t frames) {
    const std::uint32_t submissions = (frames + kSustainedFramesPerBuffer - 1) / kSustainedFramesPerBuffer;
    return submissions < 2 ? 2 : submissions;
}
// Sustained load before anything is measured. An idle GPU's clocks take up to about 0.2 s of
// full load to reach their top (docs/performance.md); this leaves a margin over that.
constexpr double kSustainedWarmupMilliseconds = 500.0;

struct SustainedTimes {
    std::vector<std::vector<double>> frames; // per measured frame, per timestamp pair
    double wallMilliseconds = 0.0;           // from the end of the warm-up to the last frame's end
};

// First submits the two buffers alternately until `warmupMilliseconds` of wall time have
// passed, discarding those frames; then `submissions` (at least 2) more submissions are
// measured: the milliseconds between the timestamp pairs of every measured frame, in execution
// order (framesPerBuffer * submissions frames). `queriesPerFrame` (even) is how many
// timestamps one frame writes. Throws std::invalid_argument for zero counts or odd queries.
SustainedTimes timeSustained(const Context& context, std::uint32_t framesPerBuffer, std::uint32_t submissions,
                             std::uint32_t queriesPerFrame, const RecordFrame& recordFrame,
                             double warmupMilliseconds = kSustainedWarmupMilliseconds);

} // namespace glint::gpu
