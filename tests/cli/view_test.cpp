// glint view's pieces that need no window: its script reader and the picture it shows (the
// mapping glint run's previews use, exposure, split screen and scaling).
#include "view_picture.h"
#include "view_script.h"

#include "report/report_image.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

using glint::cli::view::ScriptCommand;

namespace {

ScriptCommand parsed(const std::string& line) {
    ScriptCommand command;
    REQUIRE(glint::cli::view::parseScriptLine(line, "s.txt:3", command));
    return command;
}

std::string refusal(const std::string& line) {
    ScriptCommand command;
    try {
        glint::cli::view::parseScriptLine(line, "s.txt:3", command);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "(accepted)";
}

glint::report::RgbImage solid(std::uint32_t width, std::uint32_t height, std::uint8_t value) {
    return {width, height, std::vector<std::uint8_t>(std::size_t{width} * height * 3, value)};
}

std::uint8_t red(const glint::cli::view::Picture& picture, std::uint32_t x, std::uint32_t y) {
    return picture.rgba[(std::size_t{y} * picture.width + x) * 4];
}

} // namespace

TEST_CASE("view scripts: every command reads with its argument", "[view]") {
    using Kind = ScriptCommand::Kind;
    CHECK(parsed("set thickness=0.5").kind == Kind::Set);
    CHECK(parsed("set thickness=0.5").text == "thickness=0.5");
    CHECK(parsed("  view reflections/noisy  ").text == "reflections/noisy");
    CHECK(parsed("split off").text.empty());
    CHECK(parsed("split reflections/denoised").text == "reflections/denoised");
    CHECK(parsed("divider 0.25").number == 0.25);
    CHECK(parsed("exposure 4").number == 4.0);
    CHECK(parsed("step").number == 1.0);
    CHECK(parsed("step 12").number == 12.0);
    CHECK(parsed("loop off").number == 0.0);
    CHECK(parsed("ui on").number == 1.0);
    CHECK(parsed("screenshot out/a.png").text == "out/a.png");
    CHECK(parsed("quit").kind == Kind::Quit);
    CHECK(parsed("toggle shadows").text == "shadows");
    CHECK(parsed("reset").where == "s.txt:3");
    ScriptCommand ignored;
    CHECK_FALSE(glint::cli::view::parseScriptLine("# a comment", "s.txt:1", ignored));
    CHECK_FALSE(glint::cli::view::parseScriptLine("   ", "s.txt:2", ignored));
}

TEST_CASE("view scripts: a line it cannot run is refused naming the file and line", "[view]") {
    CHECK(refusal("frobnicate") ==
          "s.txt:3: unknown command 'frobnicate' (set, toggle, view, split, divider, "
          "exposure, step, play, pause, loop, reset, ui, screenshot, quit)");
    CHECK(refusal("set thickness") == "s.txt:3: set needs NAME=VALUE, got 'thickness'");
    CHECK(refusal("divider 1.5") == "s.txt:3: divider needs a fraction in [0, 1], got 1.5");
    CHECK(refusal("exposure 0") == "s.txt:3: exposure needs a factor above 0, got 0");
    CHECK(refusal("exposure nan") == "s.txt:3: exposure needs a finite number, got 'nan'");
    CHECK(refusal("step 0") == "s.txt:3: step needs a whole number of frames from 1 to 1000000, got 0");
    CHECK(refusal("step 2.5") == "s.txt:3: step needs a whole number of frames from 1 to 1000000, got 2.5");
    CHECK(refusal("step 3x") == "s.txt:3: step needs a finite number, got '3x'");
    CHECK(refusal("loop maybe") == "s.txt:3: loop takes 'on' or 'off', got 'maybe'");
    CHECK(refusal("view") == "s.txt:3: view takes 1 argument(s), got 0");
    CHECK(refusal("step 1 2") == "s.txt:3: step takes 0 or 1 argument(s), got 2");
    CHECK(refusal("quit now") == "s.txt:3: quit takes 0 argument(s), got 1");
}

TEST_CASE("view scripts: a file is read in order and its errors name the line", "[view]") {
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "view_script";
    std::filesystem::create_directories(dir);
    const std::string good = (dir / "good.txt").string();
    std::ofstream(good) << "# drive the viewer\nstep 2\n\nscreenshot a.png\nquit\n";
    const std::vector<ScriptCommand> commands = glint::cli::view::readScript(good);
    REQUIRE(commands.size() == 3);
    CHECK(commands[0].number == 2.0);
    CHECK(commands[1].where == good + ":4");
    CHECK(commands[2].kind == ScriptCommand::Kind::Quit);
    const std::string bad = (dir / "bad.txt").string();
    std::ofstream(bad) << "step 1\nsplit\n";
    CHECK_THROWS_WITH(glint::cli::view::readScript(bad), bad + ":2: split takes 1 argument(s), got 0");
    CHECK_THROWS_WITH(glint::cli::view::readScript((dir / "missing.txt").string()),
                      (dir / "missing.txt").string() + ": cannot open the script");
}

TEST_CASE("view pictures: one image fills the picture, a smaller one is scaled by nearest texel", "[view]") {
    glint::report::RgbImage twoTexels{2, 1, {10, 0, 0, 200, 0, 0}};
    const glint::cli::view::Picture picture =
        glint::cli::view::composePicture(4, 2, twoTexels, nullptr, 0.5f);
    REQUIRE(picture.rgba.size() == 4 * 2 * 4);
    // Pixel centres 0.5 and 1.5 of 4 fall in texel 0 of 2, 2.5 and 3.5 in texel 1.
    for (std::uint32_t y = 0; y < 2; ++y) {
        CHECK(red(picture, 0, y) == 10);
        CHECK(red(picture, 1, y) == 10);
        CHECK(red(picture, 2, y) == 200);
        CHECK(red(picture, 3, y) == 200);
    }
    CHECK(picture.rgba[3] == 255); // opaque
}

TEST_CASE("view pictures: a split shows the left image, a white divider column, then the right", "[view]") {
    const glint::report::RgbImage left = solid(10, 3, 40), right = solid(10, 3, 90);
    const glint::cli::view::Picture picture = glint::cli::view::composePicture(10, 3, left, &right, 0.5f);
    for (std::uint32_t y = 0; y < 3; ++y)
        for (std::uint32_t x = 0; x < 10; ++x) CHECK(red(picture, x, y) == (x < 5 ? 40 : x == 5 ? 255 : 90));
    // At the ends the divider leaves one whole side.
    const glint::cli::view::Picture allRight = glint::cli::view::composePicture(10, 3, left, &right, 0.0f);
    CHECK(red(allRight, 0, 0) == 255);
    CHECK(red(allRight, 1, 0) == 90);
    const glint::cli::view::Picture allLeft = glint::cli::view::composePicture(10, 3, left, &right, 2.0f);
    CHECK(red(allLeft, 9, 0) == 40);
}

TEST_CASE("view pictures: the mapping is glint run's preview mapping, exposure scales only colour",
          "[view]") {
    glint::report::Image radiance{3,
                                  2,
                                  3,
                                  {0.0f, 0.1f, 0.2f, 0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f, 0.05f, 0.3f, 0.7f,
                                   1.5f, 3.0f, 6.0f, 0.0f, 0.0f, 100.0f}};
    // The same pixels as glint run writes them (writePng with the preview mapping of the name).
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "view_picture";
    std::filesystem::create_directories(dir);
    const std::string png = (dir / "denoised.png").string();
    glint::report::writePng(png, radiance, glint::report::Tonemap{1.0f});
    CHECK(glint::cli::view::mapView("reflections/denoised", radiance, 1.0f).rgb ==
          glint::report::readRgbPng(png).rgb);
    // Exposure is a linear factor before the curve: twice the exposure maps like twice the radiance.
    glint::report::Image doubled = radiance;
    for (float& value : doubled.pixels) value *= 2.0f;
    CHECK(glint::cli::view::mapView("reflections/denoised", radiance, 2.0f).rgb ==
          glint::cli::view::mapView("reflections/denoised", doubled, 1.0f).rgb);
    CHECK(glint::cli::view::mapView("reflections/denoised", radiance, 2.0f).rgb !=
          glint::cli::view::mapView("reflections/denoised", radiance, 1.0f).rgb);
    // Data views (classes here) keep their colours whatever the exposure.
    glint::report::Image classes{2, 1, 1, {1.0f, 3.0f}};
    CHECK(glint::cli::view::mapView("reflections/ray_class", classes, 8.0f).rgb ==
          glint::cli::view::mapView("reflections/ray_class", classes, 1.0f).rgb);
}
