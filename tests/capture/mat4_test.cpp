#include <capture/mat4.h>

#include <catch2/catch.hpp>

using namespace glint::capture;

TEST_CASE("the inverse of a perspective view-projection composes to the identity in double", "[capture]") {
    // Zero diagonal entries (m[15]) need pivoting; reversed-depth-like values stress precision.
    const Mat4 p{{1.2, 0.0, 0.1, 0.0, 0.0, 1.6, -0.05, 0.0, 0.0, 0.0, 0.0001, 0.1, 0.0, 0.0, -1.0, 0.0}};
    const Mat4 v{{0.8, 0.0, -0.6, 3.0, 0.0, 1.0, 0.0, -2.0, 0.6, 0.0, 0.8, 10.0, 0.0, 0.0, 0.0, 1.0}};
    const Mat4 vp = multiply(p, v);
    const auto inv = inverse(vp);
    REQUIRE(inv.has_value());
    const Mat4 id = multiply(*inv, vp);
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c)
            CHECK(id.m[r * 4 + c] == Approx(r == c ? 1.0 : 0.0).margin(1e-12));
}

TEST_CASE("a singular matrix has no inverse", "[capture]") {
    Mat4 m = identity();
    m.m[10] = 0.0;
    CHECK_FALSE(inverse(m).has_value());
    CHECK_FALSE(inverse(Mat4{}).has_value());
}

TEST_CASE("matrices act on column vectors with row-major storage", "[capture]") {
    Mat4 t = identity();
    t.m[3] = 5.0; // translation x lives in row 0, column 3
    const Vec4 p = transform(t, {1.0, 2.0, 3.0, 1.0});
    CHECK(p.x == 6.0);
    CHECK(p.y == 2.0);
    CHECK(transpose(t).m[12] == 5.0);
    CHECK(multiply(t, t).m[3] == 10.0);
}
