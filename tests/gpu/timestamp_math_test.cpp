// Tick differences to milliseconds, including a counter that wraps within its valid bits.
#include <gpu/gpu_timestamps.h>

#include <catch2/catch.hpp>

using glint::gpu::timestampMilliseconds;
using glint::gpu::TimestampPool;

TEST_CASE("timestamp differences scale by the period in nanoseconds", "[timestamps]") {
    TimestampPool pool;
    pool.periodNs = 2.5;
    pool.validBits = 64;
    CHECK(timestampMilliseconds(pool, 1000, 1000 + 400000) == Approx(1.0));
    CHECK(timestampMilliseconds(pool, 7, 7) == 0.0);
}

TEST_CASE("a timestamp counter wrapping within its valid bits still gives the short interval",
          "[timestamps]") {
    TimestampPool pool;
    pool.periodNs = 1.0;
    pool.validBits = 32;
    // 0x10 ticks before the wrap plus 0x20 after it.
    CHECK(timestampMilliseconds(pool, 0xfffffff0u, 0x20u) == Approx(48e-6));
    // Garbage above the valid bits is ignored.
    CHECK(timestampMilliseconds(pool, 0xabcd000000000100ull, 0x1234000000000200ull) == Approx(256e-6));
}
