// Camera helpers shared by the effects' plans: view depth from device depth, 4x4 inverses
// and matrix rows for the constants (docs/conventions.md §2.1 and §6).
#pragma once

#include "glint/common/glint_shared_types.h"

#include <array>

namespace glint::core {

using Matrix4 = std::array<double, 16>; // row-major, column vectors (q = M p)

// (A, B, C, 0) with view depth z = A / (B + C d) for device depth d, computed in double:
// standard z = n f / (f - d (f - n)); reversed z = n f / (n + d (f - n)); reversed with
// farPlane <= 0 (infinite) z = n / d.
shared::float4 viewDepthCoefficients(bool reversed, double nearPlane, double farPlane);

// The inverse in double; false when the matrix is singular or not finite.
bool invert(const Matrix4& matrix, Matrix4& inverse);

bool isFinite(const Matrix4& matrix);

// a b (b applied first), in double.
Matrix4 multiply(const Matrix4& a, const Matrix4& b);

// Row i of the matrix as float4 (the layout the constants headers use).
void storeRows(const Matrix4& matrix, shared::float4 rows[4]);

} // namespace glint::core
