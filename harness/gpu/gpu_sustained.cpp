#include <gpu/gpu_sustained.h>

#include <chrono>
#include <stdexcept>

namespace glint::gpu {

namespace {

struct SustainedBuffer {
    RecordedCommands commands;
    TimestampPool timestamps;
};

} // namespace

SustainedTimes timeSustained(const Context& context, std::uint32_t framesPerBuffer, std::uint32_t submissions,
                             std::uint32_t queriesPerFrame, const RecordFrame& recordFrame,
                             double warmupMilliseconds) {
    if (framesPerBuffer == 0 || submissions < 2 || queriesPerFrame == 0 || queriesPerFrame % 2 != 0)
        throw std::invalid_argument(
            "glint::gpu::timeSustained: needs frames, two submissions and timestamp pairs");
    std::vector<SustainedBuffer> buffers(2);
    const auto release = [&] {
        for (SustainedBuffer& buffer : buffers) {
            destroyRecorded(context, buffer.commands);
            destroyTimestampPool(context.device, buffer.timestamps);
        }
    };
    SustainedTimes times;
    try {
        std::uint32_t recorded = 0;
        for (SustainedBuffer& buffer : buffers) {
            buffer.timestamps = createTimestampPool(context.device, framesPerBuffer * queriesPerFrame);
            buffer.commands = recordCommands(context, [&](VkCommandBuffer cmd) {
                resetTimestamps(cmd, buffer.timestamps);
                for (std::uint32_t k = 0; k < framesPerBuffer; ++k)
                    recordFrame(cmd, buffer.timestamps, recorded++);
            });
            if (buffer.timestamps.used != framesPerBuffer * queriesPerFrame)
                throw std::logic_error(
                    "glint::gpu::timeSustained: a frame wrote other than queriesPerFrame timestamps");
        }
        submitRecorded(context, buffers[0].commands);
        submitRecorded(context, buffers[1].commands);
        auto start = std::chrono::steady_clock::now();
        bool warm = warmupMilliseconds <= 0.0;
        std::uint32_t remaining = submissions; // measured waits still to come
        for (std::uint32_t wait = 0;; ++wait) {
            SustainedBuffer& buffer = buffers[wait % 2];
            waitRecorded(context, buffer.commands);
            if (warm) {
                const std::vector<std::uint64_t> ticks = readTimestamps(context.device, buffer.timestamps);
                for (std::size_t first = 0; first < ticks.size(); first += queriesPerFrame) {
                    std::vector<double>& frame = times.frames.emplace_back();
                    for (std::size_t query = first; query < first + queriesPerFrame; query += 2)
                        frame.push_back(
                            timestampMilliseconds(buffer.timestamps, ticks[query], ticks[query + 1]));
                }
                --remaining;
            } else {
                const std::chrono::duration<double, std::milli> elapsed =
                    std::chrono::steady_clock::now() - start;
                warm = elapsed.count() >= warmupMilliseconds;
                if (warm) start = std::chrono::steady_clock::now();
            }
            if (warm && remaining == 0) {
                const std::chrono::duration<double, std::milli> wall =
                    std::chrono::steady_clock::now() - start;
                times.wallMilliseconds = wall.count();
                break;
            }
            // The other buffer is queued; this one again only if two more waits are to come.
            if (!warm || remaining >= 2) submitRecorded(context, buffer.commands);
        }
    } catch (...) {
        release();
        throw;
    }
    release();
    return times;
}

} // namespace glint::gpu
