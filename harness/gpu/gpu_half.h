// IEEE 754 binary16 <-> binary32 on the CPU, for uploading and reading back *16F images.
// Written here (not taken from Imath or the compiler's _Float16) so that the harness behaves
// the same with every toolchain; tests check it against an independent reference.
#pragma once

#include <cstdint>

namespace glint::gpu {

// Round to nearest, ties to even, like the GPU's float-to-half conversion. Values too large
// for half become +-Inf, values too small become signed zero or a half denormal; NaN stays
// NaN (quietened, sign and top payload bits kept).
uint16_t floatToHalf(float value);

// Exact: every half value, denormals included, is representable as a float.
float halfToFloat(uint16_t bits);

} // namespace glint::gpu
