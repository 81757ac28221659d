#include "core/dispatch.h"

#include <catch2/catch.hpp>

using glint::core::divideRoundUp;
using glint::core::gridFor;

TEST_CASE("a grid covers every pixel with the fewest groups", "[dispatch]") {
    const std::uint32_t group[3] = {8, 8, 1};
    // Brute force over small sizes: groups * 8 must reach the size, one group fewer must not.
    for (std::uint32_t width = 1; width <= 40; ++width) {
        for (std::uint32_t height = 1; height <= 40; height += 3) {
            const glint::DirectDispatch grid = gridFor(width, height, 1, group);
            CHECK(grid.groupsX * 8 >= width);
            CHECK((grid.groupsX - 1) * 8 < width);
            CHECK(grid.groupsY * 8 >= height);
            CHECK((grid.groupsY - 1) * 8 < height);
            CHECK(grid.groupsZ == 1);
        }
    }
}

TEST_CASE("exact multiples of the group size get no extra group", "[dispatch]") {
    const std::uint32_t group[3] = {8, 4, 2};
    const glint::DirectDispatch grid = gridFor(64, 32, 8, group);
    CHECK(grid.groupsX == 8);
    CHECK(grid.groupsY == 8);
    CHECK(grid.groupsZ == 4);
}

TEST_CASE("a zero-sized grid dispatches zero groups", "[dispatch]") {
    const std::uint32_t group[3] = {8, 8, 1};
    const glint::DirectDispatch grid = gridFor(0, 5, 1, group);
    CHECK(grid.groupsX == 0);
}

TEST_CASE("rounding up division does not overflow near the top of uint32", "[dispatch]") {
    CHECK(divideRoundUp(0xFFFFFFFFu, 8) == 0x20000000u);
    CHECK(divideRoundUp(0xFFFFFFF8u, 8) == 0x1FFFFFFFu);
    CHECK(divideRoundUp(1, 64) == 1);
}

TEST_CASE("constants are copied byte for byte", "[dispatch]") {
    struct alignas(16) Block {
        float a;
        std::uint32_t b;
        float c[2];
    };
    const Block block{1.5f, 7u, {-2.0f, 3.0f}};
    const std::vector<std::byte> bytes = glint::core::packConstants(block);
    REQUIRE(bytes.size() == 16);
    float a = 0;
    std::uint32_t b = 0;
    std::memcpy(&a, bytes.data(), 4);
    std::memcpy(&b, bytes.data() + 4, 4);
    CHECK(a == 1.5f);
    CHECK(b == 7u);
}
