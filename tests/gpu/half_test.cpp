// floatToHalf/halfToFloat against an independent reference: halves decoded with ldexp and
// the nearest one found by search, ties to even, rather than by re-deriving the bit tricks.
#include <gpu/gpu_half.h>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

using glint::gpu::floatToHalf;
using glint::gpu::halfToFloat;

namespace {

// Decodes a half from the IEEE definition, in double, without bit manipulation of floats.
double referenceDecode(uint16_t half) {
    const int exponent = (half >> 10) & 0x1f;
    const int mantissa = half & 0x3ff;
    const double sign = (half & 0x8000) ? -1.0 : 1.0;
    if (exponent == 31) {
        return mantissa == 0 ? sign * std::numeric_limits<double>::infinity()
                             : std::numeric_limits<double>::quiet_NaN();
    }
    if (exponent == 0) return sign * std::ldexp(static_cast<double>(mantissa), -24);
    return sign * std::ldexp(1.0 + static_cast<double>(mantissa) / 1024.0, exponent - 15);
}

// The correctly rounded half of a finite float: nearest by value, ties to the even encoding,
// magnitudes at or beyond 65520 (halfway to 2^16) to infinity.
uint16_t referenceEncode(float value) {
    const double magnitude = std::fabs(static_cast<double>(value));
    const uint16_t sign = std::signbit(value) ? 0x8000 : 0;
    if (magnitude >= 65520.0) return static_cast<uint16_t>(sign | 0x7c00);
    // Largest positive finite encoding whose value does not exceed the magnitude.
    uint16_t low = 0;
    uint16_t high = 0x7bff;
    while (low < high) {
        const uint16_t middle = static_cast<uint16_t>((low + high + 1) / 2);
        if (referenceDecode(middle) <= magnitude) {
            low = middle;
        } else {
            high = static_cast<uint16_t>(middle - 1);
        }
    }
    uint16_t chosen = low;
    if (low < 0x7bff) {
        const double below = magnitude - referenceDecode(low);
        const double above = referenceDecode(static_cast<uint16_t>(low + 1)) - magnitude;
        if (above < below || (above == below && (low & 1) != 0)) chosen = static_cast<uint16_t>(low + 1);
    }
    return static_cast<uint16_t>(sign | chosen);
}

// Asserts only on a mismatch: a Catch assertion per sample would dominate the run time.
void requireMatchesReference(float value) {
    const uint16_t expected = referenceEncode(value);
    if (floatToHalf(value) == expected) return;
    INFO("float bits 0x" << std::hex << std::bit_cast<uint32_t>(value) << " = " << value);
    REQUIRE(floatToHalf(value) == expected);
}

// True when a half decodes to the reference value and encodes back to itself (NaN: stays NaN
// with its payload, a signalling NaN coming back quietened).
bool roundTrips(uint16_t half) {
    const float value = halfToFloat(half);
    const double expected = referenceDecode(half);
    if (std::isnan(expected)) return std::isnan(value) && (floatToHalf(value) | 0x0200) == (half | 0x0200);
    return static_cast<double>(value) == expected && std::signbit(value) == ((half & 0x8000) != 0) &&
           floatToHalf(value) == half;
}

} // namespace

TEST_CASE("every half value survives a round trip through float", "[half]") {
    for (uint32_t bits = 0; bits <= 0xffff; ++bits) {
        if (roundTrips(static_cast<uint16_t>(bits))) continue;
        INFO("half 0x" << std::hex << bits << " decodes to " << halfToFloat(static_cast<uint16_t>(bits)));
        FAIL("round trip failed");
    }
    SUCCEED("all 65536 halves round-trip");
}

TEST_CASE("well-known half values convert exactly", "[half]") {
    CHECK(floatToHalf(1.0f) == 0x3c00);
    CHECK(floatToHalf(-2.0f) == 0xc000);
    CHECK(floatToHalf(65504.0f) == 0x7bff);               // largest finite half
    CHECK(floatToHalf(6.103515625e-5f) == 0x0400);        // smallest normal, 2^-14
    CHECK(floatToHalf(5.9604644775390625e-8f) == 0x0001); // smallest denormal, 2^-24
    CHECK(floatToHalf(0.1f) == 0x2e66);
    CHECK(floatToHalf(0.0f) == 0x0000);
    CHECK(floatToHalf(-0.0f) == 0x8000);
    CHECK(halfToFloat(0x7bff) == 65504.0f);
    CHECK(halfToFloat(0x0001) == 5.9604644775390625e-8f);
    CHECK(halfToFloat(0x03ff) == 6.097555160522461e-5f); // largest denormal
}

TEST_CASE("float to half rounds ties to even", "[half]") {
    // Halfway between 1 and the next half (1 + 2^-10): the even neighbour is 1.
    CHECK(floatToHalf(1.0f + 0x1p-11f) == 0x3c00);
    // Halfway between 0x3c01 and 0x3c02: the even one is 0x3c02.
    CHECK(floatToHalf(1.0f + 3 * 0x1p-11f) == 0x3c02);
    // Just above a tie rounds up regardless of evenness.
    CHECK(floatToHalf(std::nextafter(1.0f + 0x1p-11f, 2.0f)) == 0x3c01);
    // Denormal ties: half of the smallest denormal goes to zero, 1.5 of it to 2 units.
    CHECK(floatToHalf(0x1p-25f) == 0x0000);
    CHECK(floatToHalf(3 * 0x1p-25f) == 0x0002);
    CHECK(floatToHalf(std::nextafter(0x1p-25f, 1.0f)) == 0x0001);
    // Rounding up out of the denormal range lands on the smallest normal.
    CHECK(floatToHalf(0x1p-14f - 0x1p-26f) == 0x0400);
}

TEST_CASE("float to half saturates to infinity and keeps NaN and infinity", "[half]") {
    CHECK(floatToHalf(65519.996f) == 0x7bff);
    CHECK(floatToHalf(65520.0f) == 0x7c00); // the tie goes to the even encoding, infinity
    CHECK(floatToHalf(1e10f) == 0x7c00);
    CHECK(floatToHalf(-1e10f) == 0xfc00);
    CHECK(floatToHalf(std::numeric_limits<float>::infinity()) == 0x7c00);
    CHECK(floatToHalf(-std::numeric_limits<float>::infinity()) == 0xfc00);
    const uint16_t nan = floatToHalf(std::numeric_limits<float>::quiet_NaN());
    CHECK((nan & 0x7c00) == 0x7c00);
    CHECK((nan & 0x03ff) != 0);
    // A NaN whose payload sits only in bits that do not fit a half must not become infinity.
    const uint16_t lowPayloadNaN = floatToHalf(std::bit_cast<float>(0x7f800001u));
    CHECK((lowPayloadNaN & 0x03ff) != 0);
    CHECK(floatToHalf(1e-30f) == 0x0000);
    CHECK(floatToHalf(-1e-30f) == 0x8000);
    CHECK(floatToHalf(std::numeric_limits<float>::denorm_min()) == 0x0000);
}

TEST_CASE("float to half matches correct rounding across the float range", "[half]") {
    // A sparse sweep of every float exponent...
    for (uint64_t bits = 0; bits <= 0xffffffffull; bits += 65521) {
        const float value = std::bit_cast<float>(static_cast<uint32_t>(bits));
        if (std::isfinite(value)) requireMatchesReference(value);
    }
    // ...and, densely, the values where rounding decides: every midpoint between neighbouring
    // halves and the floats right next to it.
    for (uint16_t half = 0; half < 0x7bff; ++half) {
        const double midpoint =
            (referenceDecode(half) + referenceDecode(static_cast<uint16_t>(half + 1))) / 2;
        const auto exact = static_cast<float>(midpoint);
        REQUIRE(static_cast<double>(exact) == midpoint); // 12 significant bits fit a float
        for (float value : {exact, std::nextafter(exact, 0.0f), std::nextafter(exact, 1e9f)}) {
            requireMatchesReference(value);
            requireMatchesReference(-value);
        }
    }
}
