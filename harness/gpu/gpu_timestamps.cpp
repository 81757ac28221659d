// Timestamp query pool. Results are 64-bit with the WAIT bit: the harness reads them only
// after submitAndWait, so waiting costs nothing and an unwritten query is a bug, not a race.
#include <gpu/gpu_timestamps.h>

#include "glint/vulkan/vk_check.h"

#include <stdexcept>
#include <string>

namespace glint::gpu {

namespace {

uint64_t validMask(uint32_t validBits) {
    return validBits >= 64 ? ~uint64_t{0} : (uint64_t{1} << validBits) - 1;
}

} // namespace

TimestampPool createTimestampPool(const vk::Device& device, uint32_t capacity) {
    if (!device.timestamps || device.timestampValidBits == 0) {
        throw std::runtime_error("glint: the device's compute queue does not support timestamps");
    }
    if (capacity == 0) throw std::invalid_argument("glint::gpu::createTimestampPool: capacity must be > 0");
    TimestampPool pool;
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = capacity;
    GLINT_VK_CHECK(vkCreateQueryPool(device.device, &info, nullptr, &pool.pool));
    pool.capacity = capacity;
    pool.periodNs = static_cast<double>(device.properties.limits.timestampPeriod);
    pool.validBits = device.timestampValidBits;
    return pool;
}

void destroyTimestampPool(const vk::Device& device, TimestampPool& pool) {
    if (pool.pool) vkDestroyQueryPool(device.device, pool.pool, nullptr);
    pool = TimestampPool{};
}

void resetTimestamps(VkCommandBuffer cmd, TimestampPool& pool) {
    vkCmdResetQueryPool(cmd, pool.pool, 0, pool.capacity);
    pool.used = 0;
}

uint32_t writeTimestamp(VkCommandBuffer cmd, TimestampPool& pool, VkPipelineStageFlagBits stage) {
    if (pool.used >= pool.capacity) {
        throw std::out_of_range("glint::gpu::writeTimestamp: all " + std::to_string(pool.capacity) +
                                " timestamps of the pool are used");
    }
    const uint32_t query = pool.used++;
    vkCmdWriteTimestamp(cmd, stage, pool.pool, query);
    return query;
}

std::vector<uint64_t> readTimestamps(const vk::Device& device, const TimestampPool& pool) {
    std::vector<uint64_t> ticks(pool.used);
    if (pool.used == 0) return ticks;
    GLINT_VK_CHECK(vkGetQueryPoolResults(device.device, pool.pool, 0, pool.used,
                                         ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                         VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const uint64_t mask = validMask(pool.validBits);
    for (uint64_t& tick : ticks) tick &= mask;
    return ticks;
}

double timestampMilliseconds(const TimestampPool& pool, uint64_t begin, uint64_t end) {
    // Unsigned subtraction wraps modulo 2^64; masking reduces it to modulo 2^validBits.
    const uint64_t ticks = (end - begin) & validMask(pool.validBits);
    return static_cast<double>(ticks) * pool.periodNs * 1e-6;
}

} // namespace glint::gpu
