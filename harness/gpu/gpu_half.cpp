// Bit-level conversion, because going through float arithmetic would round twice (once to
// the float grid, once to the half grid) and break ties-to-even at the denormal boundary.
#include <gpu/gpu_half.h>

#include <bit>

namespace glint::gpu {

namespace {

constexpr uint32_t kFloatMantissaBits = 23;
constexpr uint32_t kHalfMantissaBits = 10;
constexpr uint32_t kDroppedBits = kFloatMantissaBits - kHalfMantissaBits; // 13
constexpr int kFloatBias = 127;
constexpr int kHalfBias = 15;
constexpr uint32_t kHalfInfinity = 0x7c00u;
constexpr uint32_t kHalfQuietBit = 0x0200u;

// Drops `shift` low bits of value, rounding to nearest with ties to even.
uint32_t shiftRightRoundEven(uint32_t value, uint32_t shift) {
    uint32_t kept = value >> shift;
    uint32_t remainder = value & ((1u << shift) - 1u);
    uint32_t halfway = 1u << (shift - 1u);
    if (remainder > halfway || (remainder == halfway && (kept & 1u) != 0)) ++kept;
    return kept;
}

} // namespace

uint16_t floatToHalf(float value) {
    const uint32_t bits = std::bit_cast<uint32_t>(value);
    const uint32_t sign = (bits >> 16) & 0x8000u;
    const uint32_t exponentField = (bits >> kFloatMantissaBits) & 0xffu;
    const uint32_t mantissa = bits & 0x7fffffu;

    if (exponentField == 0xffu) {
        if (mantissa == 0) return static_cast<uint16_t>(sign | kHalfInfinity);
        // The quiet bit keeps the mantissa non-zero, so a NaN never turns into Inf.
        return static_cast<uint16_t>(sign | kHalfInfinity | kHalfQuietBit | (mantissa >> kDroppedBits));
    }

    const int exponent = static_cast<int>(exponentField) - kFloatBias + kHalfBias;
    if (exponent >= 31) return static_cast<uint16_t>(sign | kHalfInfinity);

    if (exponent <= 0) {
        // Half denormal (or zero): the full significand, implicit one included, is shifted to
        // units of 2^-24. Below exponent -10 even the largest significand rounds to zero.
        if (exponent < -10) return static_cast<uint16_t>(sign);
        const uint32_t significand = mantissa | (1u << kFloatMantissaBits);
        const uint32_t shift = static_cast<uint32_t>(14 - exponent);
        // A carry out of the denormal range lands exactly on the smallest normal's encoding.
        return static_cast<uint16_t>(sign | shiftRightRoundEven(significand, shift));
    }

    // A carry out of the mantissa bumps the exponent, and out of the largest exponent gives
    // exactly the Inf encoding, which is the correct result of rounding there.
    const uint32_t rebiased = (static_cast<uint32_t>(exponent) << kFloatMantissaBits) | mantissa;
    const uint32_t rounded = shiftRightRoundEven(rebiased, kDroppedBits);
    return static_cast<uint16_t>(sign | rounded);
}

float halfToFloat(uint16_t half) {
    const uint32_t sign = static_cast<uint32_t>(half & 0x8000u) << 16;
    const uint32_t exponentField = (half >> kHalfMantissaBits) & 0x1fu;
    uint32_t mantissa = half & 0x3ffu;

    if (exponentField == 0x1fu) {
        return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << kDroppedBits));
    }
    if (exponentField == 0) {
        if (mantissa == 0) return std::bit_cast<float>(sign);
        // Denormal: normalise so the leading one becomes the implicit bit of a float.
        int exponent = 1 - kHalfBias;
        while ((mantissa & 0x400u) == 0) {
            mantissa <<= 1;
            --exponent;
        }
        mantissa &= 0x3ffu;
        const uint32_t floatExponent = static_cast<uint32_t>(exponent + kFloatBias);
        return std::bit_cast<float>(sign | (floatExponent << kFloatMantissaBits) |
                                    (mantissa << kDroppedBits));
    }
    const uint32_t floatExponent = exponentField + static_cast<uint32_t>(kFloatBias - kHalfBias);
    return std::bit_cast<float>(sign | (floatExponent << kFloatMantissaBits) | (mantissa << kDroppedBits));
}

} // namespace glint::gpu
