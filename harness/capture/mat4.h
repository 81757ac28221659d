// 4x4 matrices for camera data in the capture format.
//
// Storage is row-major (m[row * 4 + col]) and the convention is column vectors: a matrix
// transforms a point p as M·p, so the translation of a view matrix sits in m[3], m[7], m[11].
// Everything is double: camera matrices are stored bit-exactly in the files and inverses are
// computed on the host in double (docs/conventions.md §6).
#pragma once

#include <array>
#include <optional>

namespace glint::capture {

struct Mat4 {
    std::array<double, 16> m{};
};

struct Vec4 {
    double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
};

Mat4 identity();
Mat4 multiply(const Mat4& a, const Mat4& b); // a·b: b is applied first
Mat4 transpose(const Mat4& a);
// Empty when the matrix is singular (or too close to it for double precision to help).
std::optional<Mat4> inverse(const Mat4& a);
Vec4 transform(const Mat4& a, const Vec4& p);
bool operator==(const Mat4& a, const Mat4& b);
bool isFinite(const Mat4& a);

} // namespace glint::capture
