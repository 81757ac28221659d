// The SSSR CPU references (classification and brute-force ray march) against hand-worked
// examples. Every expected value below was computed by hand from docs/sssr.md and the
// rules in reference/sssr_reference.h, not by running the code.
#include "reference/sssr_reference.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace glint;
using namespace glint::reference;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// One character per pixel, rows top to bottom:
//   g glossy (alpha 0.1)   m mirror (alpha 0)   r rough (alpha 0.5)   a NaN alpha
//   B background depth (1 standard, 0 reversed) with alpha 0.1   N NaN depth, alpha 0.1
//   n zero normal, alpha 0.1   F depth 1.0 (the near plane when reversed), alpha 0.1
// Every other pixel has depth 0.5 and normal (0, 0, 1).
SssrClassifyInputs image(const std::vector<std::string>& rows, bool reversed = false) {
    SssrClassifyInputs in;
    in.width = static_cast<std::uint32_t>(rows[0].size());
    in.height = static_cast<std::uint32_t>(rows.size());
    in.reversedDepth = reversed;
    for (const std::string& row : rows) {
        REQUIRE(row.size() == in.width);
        for (const char c : row) {
            float depth = 0.5f, alpha = 0.1f, nz = 1.0f;
            switch (c) {
            case 'g':
                break;
            case 'm':
                alpha = 0.0f;
                break;
            case 'r':
                alpha = 0.5f;
                break;
            case 'a':
                alpha = kNaN;
                break;
            case 'B':
                depth = reversed ? 0.0f : 1.0f;
                break;
            case 'N':
                depth = kNaN;
                break;
            case 'n':
                nz = 0.0f;
                break;
            case 'F':
                depth = 1.0f;
                break;
            default:
                FAIL("unknown pixel code " << c);
            }
            in.depth.push_back(depth);
            in.alpha.push_back(alpha);
            in.normals.insert(in.normals.end(), {0.0f, 0.0f, nz});
        }
    }
    return in;
}

std::uint8_t classOf(const SssrClassification& c, const SssrClassifyInputs& in, std::uint32_t x,
                     std::uint32_t y) {
    return c.classes[std::size_t{y} * in.width + x];
}

// The 4x4 image of the hand-worked classification examples. Quads: top-left all glossy;
// top-right base pixel background with a mirror in it; bottom-left base pixel background,
// the other candidates unusable (NaN depth, zero normal) so (1,2) is promoted; bottom-right a
// mirror at (3,2) and a NaN alpha (rough) at (2,3).
const std::vector<std::string> kImage4x4 = {
    "ggBg",
    "gggm",
    "Bggm",
    "nNag",
};

SssrDepthField field(std::uint32_t width, std::uint32_t height, float fill, bool reversed = false) {
    return {width, height, std::vector<float>(std::size_t{width} * height, fill), reversed};
}

void set(SssrDepthField& f, std::uint32_t i, std::uint32_t j, float value) {
    f.depth[std::size_t{j} * f.width + i] = value;
}

SssrTraceRay ray(double ox, double oy, double oz, double dx, double dy, double dz, double tEnd) {
    return {{ox, oy, oz}, {dx, dy, dz}, tEnd};
}

// The walk's texel boundaries sit 0.005 px past the integer lines; t values built from them
// carry double rounding only (a few ulps of numbers below 100).
constexpr double kTMargin = 1e-12;

} // namespace

// ---------------------------------------------------------------------------------------------
// Shared rules

TEST_CASE("sssr background: non-finite, out of range and within 1e-6 of the far plane", "[reference]") {
    CHECK(sssrIsBackground(1.0f, false));
    CHECK(sssrIsBackground(0.99999994f, false)); // 1 - 2^-24, within 1e-6
    CHECK_FALSE(sssrIsBackground(0.999f, false));
    CHECK_FALSE(sssrIsBackground(0.0f, false)); // the near plane is a surface
    CHECK_FALSE(sssrIsBackground(-0.0f, false));
    CHECK(sssrIsBackground(-1e-7f, false));
    CHECK(sssrIsBackground(1.5f, false));
    CHECK(sssrIsBackground(kNaN, false));
    CHECK(sssrIsBackground(kInf, false));
    CHECK(sssrIsBackground(-kInf, false));

    CHECK(sssrIsBackground(0.0f, true));
    CHECK(sssrIsBackground(1e-6f, true));
    CHECK_FALSE(sssrIsBackground(2e-6f, true));
    CHECK_FALSE(sssrIsBackground(1.0f, true));
    CHECK(sssrIsBackground(1.0000001f, true));
    CHECK(sssrIsBackground(-0.5f, true));
    CHECK(sssrIsBackground(kNaN, true));
    CHECK(sssrIsBackground(kInf, true));
}

TEST_CASE("sssr normals: valid when finite and longer than 1e-6", "[reference]") {
    CHECK(sssrNormalValid(0.0f, 0.0f, 1.0f));
    CHECK(sssrNormalValid(2e-6f, 0.0f, 0.0f));
    CHECK(sssrNormalValid(3e38f, 3e38f, 3e38f)); // the length overflows float, not double
    CHECK_FALSE(sssrNormalValid(0.0f, 0.0f, 0.0f));
    CHECK_FALSE(sssrNormalValid(1e-7f, 0.0f, 0.0f));
    CHECK_FALSE(sssrNormalValid(kNaN, 0.0f, 1.0f));
    CHECK_FALSE(sssrNormalValid(0.0f, kInf, 1.0f));
}

TEST_CASE("sssr list entries pack as in conventions §8", "[reference]") {
    CHECK(packSssrRay(0, 0, false, false, false) == 0u);
    CHECK(packSssrRay(32767, 16383, false, false, false) == 0x1FFFFFFFu);
    CHECK(packSssrRay(5, 3, true, false, false) == 0x20018005u);
    CHECK(packSssrRay(5, 3, false, true, false) == 0x40018005u);
    CHECK(packSssrRay(5, 3, false, false, true) == 0x80018005u);
    CHECK(packSssrTile(0, 0) == 0u);
    CHECK(packSssrTile(2, 1) == 0x00080010u);
}

// ---------------------------------------------------------------------------------------------
// A. Classification

TEST_CASE("sssr classify 4x4, one sample per quad: donors, a mirror donor and a promotion", "[reference]") {
    SssrClassifyInputs in = image(kImage4x4);
    in.samplesPerQuad = 1;
    const SssrClassification c = sssrClassify(in);
    // (0,0) base, copied by (1,0) H, (0,1) V, (1,1) D.
    // (3,1) mirror; (3,0) finds (2,0) background then (3,1): V; (2,1) finds (3,1) first: H.
    // (1,2): (0,2) background, (1,3) NaN depth, (0,3) zero normal: promoted.
    // (2,2) base, no flags: (3,2) is a mirror, (2,3) rough, (3,3) picks (3,2) via V first.
    const std::vector<std::uint32_t> expected = {
        0x00010001u, // (1,2) promoted
        0x00010002u, // (2,2)
        0x40010003u, // (3,2) mirror, V
        0x60008003u, // (3,1) mirror, H + V
        0xE0000000u, // (0,0) H + V + D
    };
    CHECK(c.rays == expected);
    CHECK(c.rayCount == 5);
    CHECK(c.tiles == std::vector<std::uint32_t>{0u});
    CHECK(c.tileCount == 1);
    CHECK(c.glossyCount == 11);
    CHECK(c.mirrorCount == 2);
    CHECK(c.copyCount == 6); // (1,0) (0,1) (1,1) (3,0) (2,1) (3,3)
    CHECK(c.promotedCount == 1);

    const std::uint8_t glossy = kSssrReflective | kSssrGlossy;
    CHECK(classOf(c, in, 0, 0) == (glossy | kSssrTraces));
    CHECK(classOf(c, in, 1, 1) == (glossy | kSssrRequiresCopy));
    CHECK(classOf(c, in, 2, 0) == 0);
    CHECK(classOf(c, in, 3, 1) == (glossy | kSssrMirror | kSssrTraces));
    CHECK(classOf(c, in, 1, 2) == (glossy | kSssrTraces | kSssrPromoted));
    CHECK(classOf(c, in, 0, 3) == 0);               // zero normal
    CHECK(classOf(c, in, 1, 3) == 0);               // NaN depth
    CHECK(classOf(c, in, 2, 3) == kSssrReflective); // NaN alpha counts as 1
    CHECK(classOf(c, in, 3, 3) == (glossy | kSssrRequiresCopy));
}

TEST_CASE("sssr classify 4x4, two samples per quad: the diagonal pair traces", "[reference]") {
    SssrClassifyInputs in = image(kImage4x4);
    in.samplesPerQuad = 2;
    const SssrClassification c = sssrClassify(in);
    // Base pixels: (0,0) (1,1) | (2,0)bg (3,1)m | (0,2)bg (1,3)NaN | (2,2) (3,3).
    // (1,0) -> (0,0) H; (0,1) -> (1,1) H; (3,0) -> (3,1) V; (2,1) -> (3,1) H; (1,2) promoted.
    const std::vector<std::uint32_t> expected = {
        0x00010001u, // (1,2) promoted
        0x00010002u, // (2,2)
        0x00010003u, // (3,2) mirror, no flags: (3,3) traces itself
        0x00018003u, // (3,3)
        0x20000000u, // (0,0) H
        0x20008001u, // (1,1) H
        0x60008003u, // (3,1) H + V
    };
    CHECK(c.rays == expected);
    CHECK(c.promotedCount == 1);
    CHECK(c.copyCount == 4);
}

TEST_CASE("sssr classify 4x4, four samples per quad: every glossy pixel traces, no flags", "[reference]") {
    SssrClassifyInputs in = image(kImage4x4);
    in.samplesPerQuad = 4;
    const SssrClassification c = sssrClassify(in);
    const std::vector<std::uint32_t> expected = {
        0x00000000u, 0x00000001u, 0x00000003u,              // row 0 without (2,0)
        0x00008000u, 0x00008001u, 0x00008002u, 0x00008003u, // row 1
        0x00010001u, 0x00010002u, 0x00010003u,              // row 2 without (0,2)
        0x00018003u,                                        // row 3: (3,3)
    };
    CHECK(c.rays == expected);
    CHECK(c.copyCount == 0);
    CHECK(c.promotedCount == 0);
}

TEST_CASE("sssr classify 5x3 reversed: cut quads at the right and bottom edges", "[reference]") {
    // (0,2) background (depth 0, reversed); (4,2) at depth 1, the near plane, is a surface.
    SssrClassifyInputs in = image({"ggggg", "ggggg", "BgggF"}, true);

    SECTION("one sample per quad") {
        in.samplesPerQuad = 1;
        const SssrClassification c = sssrClassify(in);
        // (4,1): (5,1) is outside, (4,0) traces: V. (1,2): (0,2) background, (1,3) and (0,3)
        // outside: promoted. (3,2) -> (2,2) H.
        const std::vector<std::uint32_t> expected = {
            0x00010001u, // (1,2) promoted
            0x00010004u, // (4,2)
            0x20010002u, // (2,2) H
            0x40000004u, // (4,0) V
            0xE0000000u, // (0,0) H + V + D
            0xE0000002u, // (2,0) H + V + D
        };
        CHECK(c.rays == expected);
        CHECK(c.promotedCount == 1);
        CHECK(c.tiles == std::vector<std::uint32_t>{0u});
    }
    SECTION("two samples per quad") {
        in.samplesPerQuad = 2;
        const SssrClassification c = sssrClassify(in);
        // Base (x&1)==(y&1). (4,1) has no x^1 neighbour inside, so it copies (4,0) via V.
        const std::vector<std::uint32_t> expected = {
            0x00010001u, // (1,2) promoted
            0x00010004u, // (4,2)
            0x20000000u, // (0,0) H
            0x20000002u, // (2,0) H
            0x20008001u, // (1,1) H
            0x20008003u, // (3,1) H
            0x20010002u, // (2,2) H
            0x40000004u, // (4,0) V
        };
        CHECK(c.rays == expected);
    }
    SECTION("four samples per quad") {
        in.samplesPerQuad = 4;
        const SssrClassification c = sssrClassify(in);
        const std::vector<std::uint32_t> expected = {
            0x00000000u, 0x00000001u, 0x00000002u, 0x00000003u, 0x00000004u, 0x00008000u, 0x00008001u,
            0x00008002u, 0x00008003u, 0x00008004u, 0x00010001u, 0x00010002u, 0x00010003u, 0x00010004u,
        };
        CHECK(c.rays == expected);
    }
}

TEST_CASE("sssr classify: variance guidance adds rays where the variance is high or NaN", "[reference]") {
    SssrClassifyInputs in = image({"gggg", "gggg", "gggg", "gggr"});
    in.samplesPerQuad = 1;
    in.varianceThreshold = 0.5f;
    in.variance.assign(16, 0.1f);
    in.variance[1] = 0.9f;  // (1,0): above
    in.variance[4] = kNaN;  // (0,1): NaN counts as high
    in.variance[5] = 0.5f;  // (1,1): equal is not above
    in.variance[15] = 0.9f; // (3,3): rough, never traces

    SECTION("guided") {
        in.varianceGuided = true;
        const SssrClassification c = sssrClassify(in);
        // (1,1) -> candidates (0,1) traces first: H on (0,1).
        const std::vector<std::uint32_t> expected = {
            0x00000000u, // (0,0), no flags: its quad neighbours trace or chose (0,1)
            0x00000001u, // (1,0)
            0x20008000u, // (0,1) H
            0x60010002u, // (2,2) H + V, (3,3) is rough
            0xE0000002u, // (2,0)
            0xE0010000u, // (0,2)
        };
        CHECK(c.rays == expected);
    }
    SECTION("not guided: the variance is ignored") {
        in.varianceGuided = false;
        const SssrClassification c = sssrClassify(in);
        const std::vector<std::uint32_t> expected = {0x60010002u, 0xE0000000u, 0xE0000002u, 0xE0010000u};
        CHECK(c.rays == expected);
    }
}

TEST_CASE("sssr classify 17x9: a tile is listed when it has a glossy pixel", "[reference]") {
    std::vector<std::string> rows(9, std::string(17, 'r'));
    rows[0][16] = 'g'; // tile (2,0)
    rows[8][3] = 'g';  // tile (0,1)
    rows[8][9] = 'm';  // tile (1,1)
    rows[8][16] = 'g'; // tile (2,1)
    rows[3][10] = 'B'; // tile (1,0): background, not glossy
    SssrClassifyInputs in = image(rows);
    in.alpha[7 * 17 + 7] = 0.2f; // tile (0,0): alpha at the threshold is not glossy
    in.samplesPerQuad = 1;
    const SssrClassification c = sssrClassify(in);
    const std::vector<std::uint32_t> tiles = {0x00000010u, 0x00080000u, 0x00080008u, 0x00080010u};
    CHECK(c.tiles == tiles);
    CHECK(c.tileCount == 4);
    // (16,0) and (16,8) are base pixels; (9,8) is a mirror; (3,8) has no donor inside the
    // image ((2,8) is rough) and is promoted.
    const std::vector<std::uint32_t> rays = {0x00000010u, 0x00040003u, 0x00040009u, 0x00040010u};
    CHECK(c.rays == rays);
    CHECK(c.promotedCount == 1);
}

TEST_CASE("sssr classify: no glossy pixel gives empty lists", "[reference]") {
    const SssrClassification c = sssrClassify(image({"rrr", "BBa"}));
    CHECK(c.rays.empty());
    CHECK(c.tiles.empty());
    CHECK(c.rayCount == 0);
    CHECK(c.tileCount == 0);
}

// ---------------------------------------------------------------------------------------------
// B. Ray march

TEST_CASE("sssr march: a ray going away hits a flat plane where its depth reaches the plane", "[reference]") {
    SECTION("standard, along x") {
        // z(t) = 0.25 + t/16 reaches 0.5 at t = 4: x = 6.5 -> texel (6, 4).
        const auto r = sssrMarch(field(16, 8, 0.5f), ray(2.5, 4.5, 0.25, 1.0, 0.0, 0.0625, 12.0));
        CHECK(r.hit);
        CHECK(r.miss == SssrMiss::None);
        CHECK(r.x == 6);
        CHECK(r.y == 4);
        CHECK(r.t == Approx(4.0).margin(kTMargin));
        CHECK(r.texelsWalked == 4); // 3, 4, 5, 6: the origin texel is skipped
    }
    SECTION("standard, diagonal") {
        // t = 4 at (6.5, 4.5); texels (3,2) ... (5,4) are entered while z < 0.5.
        const auto r = sssrMarch(field(16, 8, 0.5f), ray(2.5, 2.5, 0.25, 1.0, 0.5, 0.0625, 10.0));
        CHECK(r.hit);
        CHECK(r.x == 6);
        CHECK(r.y == 4);
        CHECK(r.t == Approx(4.0).margin(kTMargin));
    }
    SECTION("reversed") {
        const auto r = sssrMarch(field(16, 8, 0.5f, true), ray(2.5, 4.5, 0.75, 1.0, 0.0, -0.0625, 12.0));
        CHECK(r.hit);
        CHECK(r.x == 6);
        CHECK(r.y == 4);
        CHECK(r.t == Approx(4.0).margin(kTMargin));
    }
}

TEST_CASE("sssr march: a ray that stays closer than a wall passes over it", "[reference]") {
    // Background 0.9, wall at texel (5,4). z(t) = 0.25 + t/128 <= 0.34375 up to tEnd = 12.
    SssrDepthField f = field(16, 8, 0.9f);
    const SssrTraceRay r = ray(2.5, 4.5, 0.25, 1.0, 0.0, 1.0 / 128.0, 12.0);
    SECTION("wall at 0.5: no hit, escapes at tEnd") {
        set(f, 5, 4, 0.5f);
        const auto m = sssrMarch(f, r);
        CHECK_FALSE(m.hit);
        CHECK(m.miss == SssrMiss::Escaped);
        CHECK(m.x == -1);
        CHECK(m.texelsWalked == 12); // texels 3 to 14; 14 is entered at t = 11.505 <= 12
    }
    SECTION("wall at 0.26: behind at entry (z(2.505) = 0.2696)") {
        set(f, 5, 4, 0.26f);
        const auto m = sssrMarch(f, r);
        CHECK(m.hit);
        CHECK(m.x == 5);
        CHECK(m.y == 4);
        CHECK(m.t == Approx(2.505).margin(kTMargin));
    }
}

TEST_CASE("sssr march: a ray toward the camera hits a closer texel at entry", "[reference]") {
    SECTION("standard") {
        // z from 0.8 down by 0.01 per pixel stays < 0.9 over the background; the wall at 0.5
        // is closer than z(3.505) = 0.76495: behind at entry.
        SssrDepthField f = field(16, 8, 0.9f);
        set(f, 6, 4, 0.5f);
        const auto m = sssrMarch(f, ray(2.5, 4.5, 0.8, 1.0, 0.0, -0.01, 12.0));
        CHECK(m.hit);
        CHECK(m.x == 6);
        CHECK(m.y == 4);
        CHECK(m.t == Approx(3.505).margin(kTMargin));
    }
    SECTION("reversed") {
        SssrDepthField f = field(16, 8, 0.1f, true);
        set(f, 6, 4, 0.5f);
        const auto m = sssrMarch(f, ray(2.5, 4.5, 0.2, 1.0, 0.0, 0.01, 12.0));
        CHECK(m.hit);
        CHECK(m.x == 6);
        CHECK(m.t == Approx(3.505).margin(kTMargin));
    }
}

TEST_CASE("sssr march: walls beside a slanted ray are not touched; crossed texels are", "[reference]") {
    // From (0.5, 0.5) with slope 1/2 the ray crosses (1,0) (1,1) (2,1) (3,1) (3,2) (4,2) ...
    // Row 1 spans x in [1.5, 3.5]; it enters (3,2) through y = 2.005 at t = 3.01.
    SssrDepthField f = field(16, 8, 0.9f);
    set(f, 2, 0, 0.1f);
    set(f, 2, 2, 0.1f);
    set(f, 3, 2, 0.1f);
    set(f, 5, 2, 0.1f);
    const auto m = sssrMarch(f, ray(0.5, 0.5, 0.5, 1.0, 0.5, 0.0, 14.0));
    CHECK(m.hit);
    CHECK(m.x == 3);
    CHECK(m.y == 2);
    CHECK(m.t == Approx(3.01).margin(kTMargin));
    CHECK(m.texelsWalked == 5);
}

TEST_CASE("sssr march: the origin texel is skipped, and bad depths are far", "[reference]") {
    SECTION("origin texel closer than the ray") {
        SssrDepthField f = field(16, 8, 0.5f);
        set(f, 2, 4, 0.1f);
        const auto m = sssrMarch(f, ray(2.5, 4.5, 0.3, 1.0, 0.0, 0.0, 10.0));
        CHECK_FALSE(m.hit);
        CHECK(m.miss == SssrMiss::Escaped);
    }
    SECTION("non-finite and out-of-range texels") {
        // Ray at 0.999 over 0.9999: a texel read as anything closer than 0.999 would hit.
        SssrDepthField f = field(8, 2, 0.9999f);
        set(f, 1, 0, kNaN);
        set(f, 2, 0, kInf);
        set(f, 3, 0, -kInf);
        set(f, 4, 0, -0.5f);
        set(f, 5, 0, 1.5f);
        CHECK(sssrSurfaceDepth(f, 1, 0) == 1.0);
        CHECK(sssrSurfaceDepth(f, 3, 0) == 1.0);
        CHECK(sssrSurfaceDepth(f, 4, 0) == 1.0);
        CHECK(sssrSurfaceDepth(f, 5, 0) == 1.0);
        CHECK(sssrSurfaceDepth(f, 6, 0) == static_cast<double>(0.9999f)); // 1e-4 from far: kept
        const auto m = sssrMarch(f, ray(0.5, 0.5, 0.999, 1.0, 0.0, 0.0, 100.0));
        CHECK_FALSE(m.hit);
        CHECK(m.miss == SssrMiss::Escaped);
        CHECK(m.texelsWalked == 7); // 1 to 7, then x = 8.005 leaves the image
    }
    SECTION("reversed: background texels hold 0") {
        SssrDepthField f = field(4, 1, kNaN, true);
        set(f, 1, 0, 1.5f);
        set(f, 2, 0, 0.25f);
        CHECK(sssrSurfaceDepth(f, 0, 0) == 0.0);
        CHECK(sssrSurfaceDepth(f, 1, 0) == 0.0);
        CHECK(sssrSurfaceDepth(f, 2, 0) == 0.25);
    }
}

TEST_CASE("sssr march: leaving the image is an escape", "[reference]") {
    const auto m = sssrMarch(field(16, 8, 0.9f), ray(13.5, 4.5, 0.5, 1.0, 0.0, 0.0, 100.0));
    CHECK_FALSE(m.hit);
    CHECK(m.miss == SssrMiss::Escaped);
    CHECK(m.texelsWalked == 2); // 14, 15
    CHECK(m.t == Approx(2.505).margin(kTMargin));
}

TEST_CASE("sssr march: a ray without screen progress is degenerate", "[reference]") {
    // |(0.005, 0.005)| = 0.00707 < 0.01 px per unit t.
    auto m = sssrMarch(field(16, 8, 0.5f), ray(2.5, 4.5, 0.25, 0.005, 0.005, 0.1, 100.0));
    CHECK_FALSE(m.hit);
    CHECK(m.miss == SssrMiss::Degenerate);
    CHECK(m.texelsWalked == 0);
    // Exactly 0.01 px per unit t marches: t0 = 0.505 / 0.01 = 50.5, the next exit 150.5.
    m = sssrMarch(field(16, 8, 0.9f), ray(2.5, 4.5, 0.25, 0.01, 0.0, 0.0, 100.0));
    CHECK(m.miss == SssrMiss::Escaped);
    CHECK(m.texelsWalked == 1);
    // A non-finite direction is degenerate too.
    m = sssrMarch(field(16, 8, 0.5f), ray(2.5, 4.5, 0.25, std::nan(""), 1.0, 0.0, 10.0));
    CHECK(m.miss == SssrMiss::Degenerate);
}

TEST_CASE("sssr march, thickness: a ray 10 units behind a thin wall passes unless the wall is thick",
          "[reference]") {
    // Reversed infinite far with near 1: viewDepth(d) = 1 / d. Wall column x = 6 at d = 0.1
    // (view depth 10), background 0 elsewhere. The ray holds d = 0.05: view depth 20.
    SssrDepthField f = field(16, 8, 0.0f, true);
    for (std::uint32_t j = 0; j < 8; ++j) set(f, 6, j, 0.1f);
    const SssrTraceRay behindWall = ray(2.5, 4.5, 0.05, 1.0, 0.0, 0.0, 10.0);
    SssrThickness thickness;
    thickness.viewDepth = {1.0, 0.0, 1.0};

    SECTION("no thickness test: behind is a hit") {
        const auto m = sssrMarch(f, behindWall);
        CHECK(m.hit);
        CHECK(m.x == 6);
    }
    SECTION("thickness 1: 20 > 10 + 1, passes and escapes") {
        thickness.enabled = true;
        thickness.thickness = 1.0;
        const auto m = sssrMarch(f, behindWall, thickness);
        CHECK_FALSE(m.hit);
        CHECK(m.miss == SssrMiss::Escaped);
    }
    SECTION("thickness 100: 20 <= 110, hits at entry") {
        thickness.enabled = true;
        thickness.thickness = 100.0;
        const auto m = sssrMarch(f, behindWall, thickness);
        CHECK(m.hit);
        CHECK(m.x == 6);
        CHECK(m.y == 4);
        CHECK(m.t == Approx(3.505).margin(kTMargin));
    }
    SECTION("thickness 1: after passing, a wall within reach is hit") {
        // d = 0.0505: view depth 19.80; 20 <= 20.80.
        for (std::uint32_t j = 0; j < 8; ++j) set(f, 9, j, 0.0505f);
        thickness.enabled = true;
        thickness.thickness = 1.0;
        const auto m = sssrMarch(f, behindWall, thickness);
        CHECK(m.hit);
        CHECK(m.x == 9);
        CHECK(m.t == Approx(6.505).margin(kTMargin));
    }
    SECTION("thickness 1: a ray crossing the wall's plane inside the texel hits at the crossing") {
        // d(t) = 0.14 - 0.01 t: 0.10495 at entry (t = 3.505, in front), 0.09495 at exit
        // (behind); the behind part starts on the surface itself. Crossing at
        // t = (0.1f - 0.14) / -0.01 = 4 - 1.5e-7 (0.1f = 0.1 + 1.5e-9).
        thickness.enabled = true;
        thickness.thickness = 1.0;
        const auto m = sssrMarch(f, ray(2.5, 4.5, 0.14, 1.0, 0.0, -0.01, 10.0), thickness);
        CHECK(m.hit);
        CHECK(m.x == 6);
        CHECK(m.t == Approx(4.0).margin(1e-6));
    }
}
