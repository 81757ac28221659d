// harness/report: every expected value is computed here from the documented formulas (sRGB
// OETF of Reinhard, the ramp's stops, RFC 4648 vectors, hand-summed errors), never taken from
// the code under test.
#include <report/report_html.h>
#include <report/report_image.h>
#include <report/report_metrics.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <catch2/catch.hpp>
#include <png.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace glint::report;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::filesystem::path freshTestDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "report" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

Image makeImage(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                std::vector<float> pixels) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.pixels = std::move(pixels);
    return image;
}

struct Rgb {
    int r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};
std::ostream& operator<<(std::ostream& os, const Rgb& c) {
    return os << "(" << c.r << "," << c.g << "," << c.b << ")";
}

// Reads a PNG with libpng, checking that the file itself is 8-bit RGB without alpha.
std::vector<Rgb> readPng(const std::filesystem::path& file, std::uint32_t& width, std::uint32_t& height) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&png, file.c_str()) != 0);
    CHECK(png.format == PNG_FORMAT_RGB);
    png.format = PNG_FORMAT_RGB;
    width = png.width;
    height = png.height;
    std::vector<std::uint8_t> bytes(PNG_IMAGE_SIZE(png));
    REQUIRE(png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr) != 0);
    std::vector<Rgb> pixels;
    for (std::size_t i = 0; i + 2 < bytes.size(); i += 3)
        pixels.push_back({bytes[i], bytes[i + 1], bytes[i + 2]});
    return pixels;
}

std::vector<Rgb> writeAndRead(const std::string& name, const Image& image, PngMapping mapping) {
    const auto file = freshTestDir(name) / "preview.png";
    writePng(file.string(), image, mapping);
    std::uint32_t w = 0, h = 0;
    auto pixels = readPng(file, w, h);
    CHECK(w == image.width);
    CHECK(h == image.height);
    return pixels;
}

// IEC 61966-2-1, written out again here rather than shared with the library.
int srgb8(double linear) {
    const double encoded = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(encoded * 255.0));
}

const Rgb kMagenta{255, 0, 255};

std::string messageOf(const std::function<void()>& work) {
    try {
        work();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no exception)";
}

std::uint32_t bits(float v) {
    return std::bit_cast<std::uint32_t>(v);
}

} // namespace

// ---- PNG ----------------------------------------------------------------------------------

TEST_CASE("Tonemap PNG: exposure, Reinhard x/(1+x), then the sRGB OETF, alpha ignored", "[report]") {
    // RGBA pixels; alpha varies to show it has no effect.
    const Image image = makeImage(4, 1, 4,
                                  {0.25f, 1.0f, 3.0f, 0.0f,  //
                                   0.0f, -2.0f, 1e30f, 1.0f, //
                                   0.001f, 0.5f, 0.0f, 0.5f, //
                                   1.0f, 1.0f, 1.0f, 7.0f});
    const auto px = writeAndRead("tonemap", image, Tonemap{1.0f});
    REQUIRE(px.size() == 4);
    // 0.25 -> 0.2, 1 -> 0.5, 3 -> 0.75 before encoding; by hand: 124, 188, 225.
    CHECK(px[0] == Rgb{124, 188, 225});
    CHECK(px[0] == Rgb{srgb8(0.2), srgb8(0.5), srgb8(0.75)});
    // Negative clamps to 0, a huge value saturates at 255.
    CHECK(px[1] == Rgb{0, 0, 255});
    // 0.001 -> 0.000999: on the linear segment of the OETF (12.92 x), 3.29 -> 3.
    CHECK(px[2] == Rgb{3, srgb8(0.5 / 1.5), 0});
    CHECK(px[3] == Rgb{188, 188, 188});

    // Exposure 2 doubles the samples before the curve: 0.5 reads like 1.
    const auto exposed =
        writeAndRead("tonemap_exposure", makeImage(1, 1, 3, {0.5f, 0.125f, 1.5f}), Tonemap{2.0f});
    CHECK(exposed[0] == Rgb{srgb8(0.5), srgb8(0.2), srgb8(0.75)});
}

TEST_CASE("Tonemap PNG: one channel is grey and two channels are R and G with B = 0", "[report]") {
    const auto grey = writeAndRead("tonemap_grey", makeImage(1, 1, 1, {1.0f}), Tonemap{});
    CHECK(grey[0] == Rgb{188, 188, 188});
    const auto rg = writeAndRead("tonemap_rg", makeImage(1, 1, 2, {1.0f, 3.0f}), Tonemap{});
    CHECK(rg[0] == Rgb{188, 225, 0});
}

TEST_CASE("Linear PNG maps [min, max] to 0..255 without the sRGB curve and clamps outside", "[report]") {
    // min -1, max 3: v = 1 is halfway, 127.5 rounds to 128; v = 0 is 63.75 -> 64.
    const auto grey =
        writeAndRead("linear", makeImage(4, 1, 1, {1.0f, 0.0f, -5.0f, 3.0f}), Linear{-1.0f, 3.0f});
    CHECK(grey[0] == Rgb{128, 128, 128});
    CHECK(grey[1] == Rgb{64, 64, 64});
    CHECK(grey[2] == Rgb{0, 0, 0});
    CHECK(grey[3] == Rgb{255, 255, 255});
    // Motion-like data in [-1, 1]: R and G, B = 0.
    const auto motion = writeAndRead("linear_motion", makeImage(1, 1, 2, {-1.0f, 0.5f}), Linear{-1.0f, 1.0f});
    CHECK(motion[0] == Rgb{0, 191, 0}); // 0.75 * 255 = 191.25
}

TEST_CASE("Heat PNG follows the viridis stops: ends, midpoint and linear blend between stops", "[report]") {
    // Stops of viridis at t = 0, 1/2, 1 and 1/8 (the documented ramp).
    const auto px =
        writeAndRead("heat", makeImage(6, 1, 1, {0.0f, 2.0f, 4.0f, 9.0f, -1.0f, 0.75f}), Heat{4.0f});
    CHECK(px[0] == Rgb{68, 1, 84});
    CHECK(px[1] == Rgb{33, 144, 140});
    CHECK(px[2] == Rgb{253, 231, 37});
    CHECK(px[3] == Rgb{253, 231, 37}); // above max clamps
    CHECK(px[4] == Rgb{68, 1, 84});    // below 0 clamps
    // t = 0.1875 lies halfway between the stops at 1/8 (71,45,123) and 2/8 (59,82,139).
    CHECK(px[5] == Rgb{65, 64, 131}); // (71+59)/2 = 65, (45+82)/2 = 63.5 -> 64, (123+139)/2 = 131

    // Two channels: the length of (R, G); (3, 4) has length 5 = max.
    const auto motion = writeAndRead("heat_motion", makeImage(1, 1, 2, {3.0f, 4.0f}), Heat{5.0f});
    CHECK(motion[0] == Rgb{253, 231, 37});
    // Three channels: Rec. 709 luminance; (0, 1, 0) has luminance 0.7152 of max 1.4304 -> 1/2.
    const auto colour = writeAndRead("heat_rgb", makeImage(1, 1, 3, {0.0f, 1.0f, 0.0f}), Heat{1.4304f});
    CHECK(colour[0] == Rgb{33, 144, 140});
}

TEST_CASE("Categories PNG gives each integer class a fixed colour, black for 0, white for negatives",
          "[report]") {
    const auto px =
        writeAndRead("categories", makeImage(6, 1, 1, {0.0f, 1.0f, 2.4f, 1.6f, -1.0f, 10.0f}), Categories{});
    CHECK(px[0] == Rgb{0, 0, 0});
    CHECK(px[1] == Rgb{31, 119, 180});
    CHECK(px[2] == Rgb{255, 127, 14}); // 2.4 rounds to 2
    CHECK(px[3] == Rgb{255, 127, 14}); // 1.6 rounds to 2
    CHECK(px[4] == Rgb{255, 255, 255});
    CHECK(px[5] == Rgb{0, 0, 0}); // the palette of 10 repeats
    // Every class colour differs from every other and from the non-finite magenta.
    for (std::uint64_t a = 0; a < 10; ++a) {
        CHECK(!(categoryColor(a) == kNonFiniteColor));
        for (std::uint64_t b = a + 1; b < 10; ++b) CHECK(!(categoryColor(a) == categoryColor(b)));
    }
}

TEST_CASE("every PNG mapping writes non-finite samples as magenta (255,0,255)", "[report]") {
    const Image grey = makeImage(3, 1, 1, {kNaN, kInf, -kInf});
    const Image rgb = makeImage(3, 1, 3, {kNaN, 0.0f, 0.0f, 0.0f, kInf, 0.0f, 0.0f, 0.0f, -kInf});
    const std::vector<PngMapping> mappings{Tonemap{}, Linear{0.0f, 1.0f}, Heat{1.0f}, Categories{}};
    for (std::size_t m = 0; m < mappings.size(); ++m) {
        INFO("mapping " << m);
        for (Rgb c : writeAndRead("non_finite_grey_" + std::to_string(m), grey, mappings[m]))
            CHECK(c == kMagenta);
    }
    for (std::size_t m = 0; m < 3; ++m) { // Categories reads channel 0 only
        INFO("mapping " << m);
        for (Rgb c : writeAndRead("non_finite_rgb_" + std::to_string(m), rgb, mappings[m]))
            CHECK(c == kMagenta);
    }
    // An alpha NaN is ignored, as alpha is.
    const auto alpha =
        writeAndRead("non_finite_alpha", makeImage(1, 1, 4, {1.0f, 1.0f, 1.0f, kNaN}), Tonemap{});
    CHECK(alpha[0] == Rgb{188, 188, 188});
}

TEST_CASE("writePng errors are one line naming the path", "[report]") {
    const auto dir = freshTestDir("png_errors");
    const std::string missingDir = (dir / "no_such_dir" / "x.png").string();
    const Image image = makeImage(1, 1, 1, {0.0f});
    const std::string open = messageOf([&] { writePng(missingDir, image, Tonemap{}); });
    CHECK(open.find(missingDir) == 0);
    CHECK(open.find('\n') == std::string::npos);
    const std::string path = (dir / "x.png").string();
    CHECK(messageOf([&] { writePng(path, makeImage(2, 1, 1, {0.0f}), Tonemap{}); }).find(path) == 0);
    CHECK(messageOf([&] {
              writePng(path, makeImage(1, 1, 5, {0, 0, 0, 0, 0}), Tonemap{});
          }).find("1 to 4") != std::string::npos);
    CHECK(messageOf([&] {
              writePng(path, image, Linear{1.0f, 1.0f});
          }).find("min < max") != std::string::npos);
    CHECK(messageOf([&] { writePng(path, image, Heat{0.0f}); }).find("max > 0") != std::string::npos);
    CHECK(!std::filesystem::exists(path));
    CHECK(!std::filesystem::exists(path + ".partial"));
}

// ---- OpenEXR --------------------------------------------------------------------------------

TEST_CASE("EXR round trip is bit-exact and channels come back as R, G, B, A, then by name", "[report]") {
    const auto file = (freshTestDir("exr_round_trip") / "out.exr").string();
    // Written in the order Y, B, R, A, G, depth: read back as R, G, B, A, Y, depth.
    const std::vector<std::string> written{"Y", "B", "R", "A", "G", "depth"};
    Image image = makeImage(3, 2, 6, {});
    for (std::size_t i = 0; i < 3 * 2 * 6; ++i)
        image.pixels.push_back(std::sin(0.731f * static_cast<float>(i)) * 1e3f);
    image.pixels[7] = kNaN;
    image.pixels[8] = -kInf;
    image.pixels[9] = -0.0f;
    writeExr(file, image, written);
    CHECK(!std::filesystem::exists(file + ".partial"));

    std::vector<std::string> names;
    const Image read = readExr(file, &names);
    REQUIRE(names == std::vector<std::string>{"R", "G", "B", "A", "Y", "depth"});
    REQUIRE(read.width == 3);
    REQUIRE(read.height == 2);
    REQUIRE(read.channels == 6);
    REQUIRE(read.pixels.size() == image.pixels.size());
    const std::array<std::size_t, 6> source{2, 4, 1, 3, 0, 5}; // index in `written` of each read channel
    std::size_t mismatches = 0;
    for (std::size_t p = 0; p < 6; ++p)
        for (std::size_t c = 0; c < 6; ++c) {
            const float w = image.pixels[p * 6 + source[c]], r = read.pixels[p * 6 + c];
            const bool same = std::isnan(w) ? std::isnan(r) : bits(w) == bits(r);
            if (!same) ++mismatches;
        }
    CHECK(mismatches == 0);
}

TEST_CASE("readExr converts HALF channels written by another tool to float", "[report]") {
    const auto file = (freshTestDir("exr_half") / "half.exr").string();
    {
        Imf::Header header(2, 1);
        header.channels().insert("Y", Imf::Channel(Imf::HALF));
        std::array<Imath::half, 2> samples{Imath::half(0.5f), Imath::half(-3.25f)};
        Imf::FrameBuffer fb;
        fb.insert("Y", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(samples.data()), sizeof(Imath::half),
                                  2 * sizeof(Imath::half)));
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(1);
    }
    std::vector<std::string> names;
    const Image read = readExr(file, &names);
    CHECK(names == std::vector<std::string>{"Y"});
    REQUIRE(read.pixels.size() == 2);
    CHECK(read.pixels[0] == 0.5f); // both exactly representable in half
    CHECK(read.pixels[1] == -3.25f);
}

TEST_CASE("EXR errors are one line naming the path", "[report]") {
    const auto dir = freshTestDir("exr_errors");
    const std::string missing = (dir / "missing.exr").string();
    const std::string missingMessage = messageOf([&] { (void)readExr(missing); });
    CHECK(missingMessage.find(missing) == 0);
    CHECK(missingMessage.find('\n') == std::string::npos);

    const std::string text = (dir / "text.exr").string();
    std::ofstream(text) << "this is not an OpenEXR file\n";
    CHECK(messageOf([&] { (void)readExr(text); }).find(text + ": not an OpenEXR file") == 0);

    const std::string truncated = (dir / "truncated.exr").string();
    writeExr(truncated, makeImage(16, 16, 1, std::vector<float>(256, 1.0f)), {"Y"});
    std::filesystem::resize_file(truncated, std::filesystem::file_size(truncated) - 20);
    const std::string truncatedMessage = messageOf([&] { (void)readExr(truncated); });
    CHECK(truncatedMessage.find(truncated) == 0);
    CHECK(truncatedMessage.find('\n') == std::string::npos);
    // Incompressible pixels cut to a third: refused by the check of the file's length against the pixel data
    // its header declares, before the image is allocated (issue 24: memory bounded by the file).
    const std::string headerOnly = (dir / "header_only.exr").string();
    std::vector<float> noise(64 * 64 * 4);
    std::uint32_t state = 1;
    for (float& value : noise) value = static_cast<float>((state = state * 1664525u + 1013904223u) >> 8);
    writeExr(headerOnly, makeImage(64, 64, 4, noise), {"R", "G", "B", "A"});
    std::filesystem::resize_file(headerOnly, std::filesystem::file_size(headerOnly) / 3);
    const std::string headerOnlyMessage = messageOf([&] { (void)readExr(headerOnly); });
    INFO(headerOnlyMessage);
    CHECK(headerOnlyMessage.find(headerOnly + ": file is truncated or incomplete") == 0);

    const std::string out = (dir / "out.exr").string();
    const Image rg = makeImage(1, 1, 2, {0.0f, 0.0f});
    CHECK(messageOf([&] { writeExr(out, rg, {"R"}); }).find("1 channel names for an image of 2") !=
          std::string::npos);
    CHECK(messageOf([&] { writeExr(out, rg, {"R", "R"}); }).find("appears twice") != std::string::npos);
    const std::string badDir = (dir / "no_such_dir" / "x.exr").string();
    CHECK(messageOf([&] { writeExr(badDir, rg, {"R", "G"}); }).find(badDir) == 0);
}

// ---- metrics --------------------------------------------------------------------------------

TEST_CASE("rmse over RGB equals the hand-computed value, with mask and non-finite pixels skipped",
          "[report]") {
    // Differences (1,0,0) and (0,0,3): squares sum to 10 over 6 samples.
    const Image a = makeImage(2, 1, 3, {0, 0, 0, 1, 1, 1});
    const Image b = makeImage(2, 1, 3, {1, 0, 0, 1, 1, 4});
    CHECK(rmse(a, b) == Approx(std::sqrt(10.0 / 6.0)).epsilon(1e-12));
    const Image mask = makeImage(2, 1, 1, {1.0f, 0.0f});
    CHECK(rmse(a, b, &mask) == Approx(std::sqrt(1.0 / 3.0)).epsilon(1e-12));
    // A NaN in a's first pixel removes that pixel: 9 over 3 samples.
    Image withNaN = a;
    withNaN.pixels[1] = kNaN;
    CHECK(rmse(withNaN, b) == Approx(std::sqrt(3.0)).epsilon(1e-12));
    // Alpha does not count.
    const Image a4 = makeImage(1, 1, 4, {0, 0, 0, 0});
    const Image b4 = makeImage(1, 1, 4, {0, 0, 3, 100});
    CHECK(rmse(a4, b4) == Approx(std::sqrt(3.0)).epsilon(1e-12));
    // Nothing comparable: 0, not NaN.
    const Image allNaN = makeImage(1, 1, 1, {kNaN});
    CHECK(rmse(allNaN, allNaN) == 0.0);
    CHECK(messageOf([&] { (void)rmse(a, a4); }) == "images differ in size: 2x1x3 vs 1x1x4");
}

TEST_CASE("relativeErrorMap divides the luminance of |a - ref| by the reference luminance", "[report]") {
    const Image ref = makeImage(4, 1, 3, {1, 1, 1, 0, 0, 0, 2, 2, 2, 1, 1, 1});
    const Image a = makeImage(4, 1, 3, {2, 1, 1, 0, 0.001f, 0, 2, 2, 2, kNaN, 1, 1});
    const Image map = relativeErrorMap(a, ref, 0.01f);
    REQUIRE(map.channels == 1);
    REQUIRE(map.pixels.size() == 4);
    CHECK(map.pixels[0] == Approx(0.2126).epsilon(1e-6));                // (1,0,0) over luminance 1
    CHECK(map.pixels[1] == Approx(0.7152 * 0.001 / 0.01).epsilon(1e-5)); // black reference: eps
    CHECK(map.pixels[2] == 0.0f);
    CHECK(map.pixels[3] == kInf); // non-finite input

    // A huge difference over a black reference (3e38 / 0.01) is clamped to the largest float:
    // finite input never reads as non-finite.
    const Image huge = relativeErrorMap(makeImage(1, 1, 1, {3e38f}), makeImage(1, 1, 1, {0.0f}), 0.01f);
    CHECK(huge.pixels[0] == std::numeric_limits<float>::max());
}

TEST_CASE("nonFiniteFraction and meanLuminance count pixels and skip non-finite ones", "[report]") {
    const Image image = makeImage(4, 1, 3, {1, 1, 1, 0, 1, 0, kNaN, 0, 0, 0, 0, kInf});
    CHECK(nonFiniteFraction(image) == 0.5);
    CHECK(meanLuminance(image) == Approx((1.0 + 0.7152) / 2.0).epsilon(1e-12));
    CHECK(meanLuminance(makeImage(1, 1, 1, {kNaN})) == 0.0);
    CHECK(nonFiniteFraction(Image{}) == 0.0);
}

TEST_CASE("diffImages applies absolute plus relative tolerance and matches non-finite samples", "[report]") {
    const Image expected = makeImage(6, 1, 1, {1.0f, 100.0f, 0.0f, kNaN, kInf, 5.0f});
    const Image actual = makeImage(6, 1, 1, {1.05f, 100.5f, 0.2f, kNaN, kInf, kNaN});
    // Tolerance abs 0.1 + rel 0.01 * |e|: 0.05 <= 0.11 ok; 0.5 <= 1.1 ok; 0.2 > 0.1 differs;
    // NaN matches NaN; +Inf matches +Inf; NaN against 5 differs.
    const ImageDiff diff = diffImages(actual, expected, 0.1, 0.01);
    CHECK(diff.differing == 2);
    CHECK(diff.nonFinite == 3);
    CHECK(diff.maxAbs == Approx(0.5).epsilon(1e-6));
    const double d0 = double{1.05f} - 1.0, d1 = double{100.5f} - 100.0, d2 = double{0.2f};
    CHECK(diff.rmse == Approx(std::sqrt((d0 * d0 + d1 * d1 + d2 * d2) / 3.0)).epsilon(1e-12));
    const ImageDiff same = diffImages(expected, expected, 0.0, 0.0);
    CHECK(same.differing == 0);
    CHECK(same.maxAbs == 0.0);
}

// ---- HTML -----------------------------------------------------------------------------------

TEST_CASE("base64 matches the RFC 4648 test vectors", "[report]") {
    CHECK(base64Encode("") == "");
    CHECK(base64Encode("f") == "Zg==");
    CHECK(base64Encode("fo") == "Zm8=");
    CHECK(base64Encode("foo") == "Zm9v");
    CHECK(base64Encode("foob") == "Zm9vYg==");
    CHECK(base64Encode("fooba") == "Zm9vYmE=");
    CHECK(base64Encode("foobar") == "Zm9vYmFy");
    CHECK(base64Encode(std::string("\xff\xfe\x00", 3)) == "//4A"); // high bytes and NUL
}

TEST_CASE("the HTML report escapes text, embeds figures as data URIs and links nothing", "[report]") {
    const auto dir = freshTestDir("html");
    const std::string png = (dir / "tiny.png").string();
    writePng(png, makeImage(16, 8, 1, std::vector<float>(128, 0.5f)), Linear{});
    std::ifstream in(png, std::ios::binary);
    const std::string pngBytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

    Report report;
    report.title = "glint <report> & \"friends\"";
    report.facts = {{"device", "llvmpipe <LLVM 15>"}, {"date", "2024-01-01"}};
    Section section;
    section.heading = "SSSR & denoiser";
    section.text = "first <b>paragraph</b>\n\nsecond 'one'";
    section.figures = {{"a < b", png}, {"same again", png}};
    section.tables = {{{"pass", "ms"}, {{"classify", "0.12"}, {"<script>", "1 & 2"}}}};
    report.sections.push_back(section);
    const std::string path = (dir / "report.html").string();
    writeHtml(path, report);

    std::ifstream page(path);
    const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
    CHECK(html.find("glint &lt;report&gt; &amp; &quot;friends&quot;") != std::string::npos);
    CHECK(html.find("llvmpipe &lt;LLVM 15&gt;") != std::string::npos);
    CHECK(html.find("<p>first &lt;b&gt;paragraph&lt;/b&gt;</p>") != std::string::npos);
    CHECK(html.find("<p>second &#39;one&#39;</p>") != std::string::npos);
    CHECK(html.find("<td>&lt;script&gt;</td><td>1 &amp; 2</td>") != std::string::npos);
    CHECK(html.find("<script>") == std::string::npos);
    CHECK(html.find("<b>") == std::string::npos);
    const std::string uri = "data:image/png;base64," + base64Encode(pngBytes);
    CHECK(html.find(uri) != std::string::npos);
    CHECK(html.find(uri, html.find(uri) + 1) != std::string::npos); // both figures
    CHECK(html.find("http") == std::string::npos);
    // 16 px wide is scaled by 16 to 256 px, pixelated.
    CHECK(html.find("class=\"pixelated\" width=\"256\"") != std::string::npos);
    CHECK(html.find("image-rendering: pixelated") != std::string::npos);
    CHECK(html.find("flex-wrap: wrap") != std::string::npos);
}

TEST_CASE("the HTML report refuses a missing or non-PNG figure with one line naming it", "[report]") {
    const auto dir = freshTestDir("html_errors");
    const std::string missing = (dir / "missing.png").string();
    Report report;
    report.sections.push_back({"s", "", {{"c", missing}}, {}});
    CHECK(messageOf([&] { writeHtml((dir / "r.html").string(), report); }).find(missing) == 0);
    const std::string text = (dir / "text.png").string();
    std::ofstream(text) << "not a png, but long enough to have a header";
    report.sections[0].figures[0].pngPath = text;
    CHECK(messageOf([&] { writeHtml((dir / "r.html").string(), report); }) == text + ": not a PNG file");
    CHECK(!std::filesystem::exists(dir / "r.html"));
}

TEST_CASE("A crop repeats each pixel scale times and encodes to a PNG that reads back the same", "[report]") {
    RgbImage image{3, 2, {}};
    for (std::uint8_t i = 0; i < 18; ++i) image.rgb.push_back(static_cast<std::uint8_t>(10 * i));
    const RgbImage crop = cropScaled(image, 1, 0, 2, 2, 3);
    REQUIRE(crop.width == 6);
    REQUIRE(crop.height == 6);
    // Crop pixel (cx, cy) is source pixel (1 + cx / 3, cy / 3), whose red byte is 10 * 3 * index.
    for (std::uint32_t cy = 0; cy < 6; ++cy)
        for (std::uint32_t cx = 0; cx < 6; ++cx) {
            const std::uint32_t source = (cy / 3) * 3 + 1 + cx / 3;
            INFO("crop pixel " << cx << ", " << cy);
            CHECK(crop.rgb[(cy * 6 + cx) * 3] == 30 * source);
        }
    CHECK_THROWS_AS(cropScaled(image, 2, 0, 2, 1, 1), std::invalid_argument);
    CHECK_THROWS_AS(cropScaled(image, 0, 0, 1, 1, 0), std::invalid_argument);

    const auto dir = freshTestDir("crop");
    const std::string path = (dir / "crop.png").string();
    std::ofstream(path, std::ios::binary) << encodeRgbPng(path, crop);
    const RgbImage back = readRgbPng(path);
    CHECK(back.width == crop.width);
    CHECK(back.height == crop.height);
    CHECK(back.rgb == crop.rgb);
}
