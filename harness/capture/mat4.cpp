#include "capture/mat4.h"

#include <cmath>
#include <cstddef>
#include <utility>

namespace glint::capture {

Mat4 identity() {
    Mat4 r;
    for (std::size_t i = 0; i < 4; ++i) r.m[i * 5] = 1.0;
    return r;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 r;
    for (std::size_t row = 0; row < 4; ++row) {
        for (std::size_t col = 0; col < 4; ++col) {
            double sum = 0.0;
            for (std::size_t k = 0; k < 4; ++k) sum += a.m[row * 4 + k] * b.m[k * 4 + col];
            r.m[row * 4 + col] = sum;
        }
    }
    return r;
}

Mat4 transpose(const Mat4& a) {
    Mat4 r;
    for (std::size_t row = 0; row < 4; ++row)
        for (std::size_t col = 0; col < 4; ++col) r.m[col * 4 + row] = a.m[row * 4 + col];
    return r;
}

std::optional<Mat4> inverse(const Mat4& a) {
    // Gauss-Jordan with partial pivoting: projection matrices have zeros on the diagonal
    // (m[15] == 0 for perspective), so pivoting is required, and it keeps the double
    // result accurate for the near/far ratios real cameras use.
    std::array<double, 16> l = a.m;
    Mat4 r = identity();
    double largest = 0.0;
    for (double v : a.m) largest = std::fmax(largest, std::fabs(v));
    if (!(largest > 0.0) || !std::isfinite(largest)) return std::nullopt;
    for (std::size_t col = 0; col < 4; ++col) {
        std::size_t pivot = col;
        for (std::size_t row = col + 1; row < 4; ++row)
            if (std::fabs(l[row * 4 + col]) > std::fabs(l[pivot * 4 + col])) pivot = row;
        const double p = l[pivot * 4 + col];
        if (std::fabs(p) <= largest * 1e-14) return std::nullopt;
        if (pivot != col) {
            for (std::size_t k = 0; k < 4; ++k) {
                std::swap(l[pivot * 4 + k], l[col * 4 + k]);
                std::swap(r.m[pivot * 4 + k], r.m[col * 4 + k]);
            }
        }
        for (std::size_t k = 0; k < 4; ++k) {
            l[col * 4 + k] /= p;
            r.m[col * 4 + k] /= p;
        }
        for (std::size_t row = 0; row < 4; ++row) {
            if (row == col) continue;
            const double f = l[row * 4 + col];
            if (f == 0.0) continue;
            for (std::size_t k = 0; k < 4; ++k) {
                l[row * 4 + k] -= f * l[col * 4 + k];
                r.m[row * 4 + k] -= f * r.m[col * 4 + k];
            }
        }
    }
    return r;
}

Vec4 transform(const Mat4& a, const Vec4& p) {
    const auto& m = a.m;
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3] * p.w,
            m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7] * p.w,
            m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11] * p.w,
            m[12] * p.x + m[13] * p.y + m[14] * p.z + m[15] * p.w};
}

bool operator==(const Mat4& a, const Mat4& b) {
    return a.m == b.m;
}

bool isFinite(const Mat4& a) {
    for (double v : a.m)
        if (!std::isfinite(v)) return false;
    return true;
}

} // namespace glint::capture
