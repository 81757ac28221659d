// Camera helpers shared by the effects' plans.
#include "core/camera.h"

#include "glint/common/glint_view_depth.h"

#include <cmath>

namespace glint::core {

shared::float4 viewDepthCoefficients(bool reversed, double n, double f) {
    return shared::GLINT_ViewDepthCoefficients(reversed, n, f);
}

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 out{};
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c)
            for (std::size_t k = 0; k < 4; ++k) out[4 * r + c] += a[4 * r + k] * b[4 * k + c];
    return out;
}

bool isFinite(const Matrix4& matrix) {
    for (double value : matrix)
        if (!std::isfinite(value)) return false;
    return true;
}

// Gauss-Jordan elimination with partial pivoting, in double.
bool invert(const Matrix4& matrix, Matrix4& inverse) {
    if (!isFinite(matrix)) return false;
    double work[4][8];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 8; ++c)
            work[r][c] = c < 4 ? matrix[static_cast<std::size_t>(4 * r + c)] : (c - 4 == r ? 1.0 : 0.0);
    for (int column = 0; column < 4; ++column) {
        int pivot = column;
        for (int r = column + 1; r < 4; ++r)
            if (std::abs(work[r][column]) > std::abs(work[pivot][column])) pivot = r;
        if (!(std::abs(work[pivot][column]) > 1e-300)) return false;
        if (pivot != column)
            for (int c = 0; c < 8; ++c) std::swap(work[pivot][c], work[column][c]);
        const double scale = 1.0 / work[column][column];
        for (int c = 0; c < 8; ++c) work[column][c] *= scale;
        for (int r = 0; r < 4; ++r) {
            if (r == column) continue;
            const double factor = work[r][column];
            for (int c = 0; c < 8; ++c) work[r][c] -= factor * work[column][c];
        }
    }
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) inverse[static_cast<std::size_t>(4 * r + c)] = work[r][c + 4];
    return isFinite(inverse);
}

void storeRows(const Matrix4& matrix, shared::float4 rows[4]) {
    for (std::size_t row = 0; row < 4; ++row) {
        const double* m = &matrix[4 * row];
        rows[row] = {static_cast<float>(m[0]), static_cast<float>(m[1]), static_cast<float>(m[2]),
                     static_cast<float>(m[3])};
    }
}

} // namespace glint::core
