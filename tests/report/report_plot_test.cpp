// harness/report/report_plot.h: the places of the drawn values follow from the geometry the
// header documents (computed here from kPlot*), the axis top from the 1-2-5 rule worked by hand.
#include <report/report_html.h>
#include <report/report_plot.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace glint::report;

namespace {

// "x,y" with one decimal, as an SVG attribute would carry it.
std::string point(double x, double y) {
    char text[64];
    std::snprintf(text, sizeof text, "%.1f,%.1f", x, y);
    return text;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

} // namespace

TEST_CASE("the plot axis ends at the smallest 1, 2 or 5 x 10^k at or above the largest value", "[report]") {
    CHECK(plotAxisMax(0.07) == Approx(0.1));
    CHECK(plotAxisMax(0.1) == Approx(0.1));
    CHECK(plotAxisMax(0.11) == Approx(0.2));
    CHECK(plotAxisMax(2.59) == Approx(5.0));
    CHECK(plotAxisMax(6.0) == Approx(10.0));
    CHECK(plotAxisMax(0.0) == 1.0);
    CHECK(plotAxisMax(-3.0) == 1.0);
    CHECK(plotAxisMax(std::numeric_limits<double>::quiet_NaN()) == 1.0);
}

TEST_CASE("a plotted series puts frame i and value v where the documented geometry says", "[report]") {
    Plot plot{"t", "frame", "error", {{"noisy", {0.4, 0.2, 0.1}, "#f00"}}};
    const std::string svg = renderSvgPlot(plot);
    // Largest 0.4 -> axis top 0.5; three frames span the area's width in two steps.
    const double areaWidth = kPlotWidth - kPlotLeft - kPlotRight;
    const double areaHeight = kPlotHeight - kPlotTop - kPlotBottom;
    const double bottom = kPlotHeight - kPlotBottom;
    const std::string expected = point(kPlotLeft, bottom - 0.4 / 0.5 * areaHeight) + " " +
                                 point(kPlotLeft + areaWidth / 2, bottom - 0.2 / 0.5 * areaHeight) + " " +
                                 point(kPlotLeft + areaWidth, bottom - 0.1 / 0.5 * areaHeight);
    CHECK(svg.find("points=\"" + expected + "\"") != std::string::npos);
    CHECK(svg.rfind("<svg", 0) == 0);
    // Inline in HTML, the parser gives <svg> its namespace: no xmlns, nothing that links out.
    CHECK(count(svg, "http") == 0);
}

TEST_CASE("a missing value breaks the line, markers show isolated values, text is escaped", "[report]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Plot plot{"a <b> & c",
              "frame",
              "error",
              {{"output", {1.0, 1.0, nan, 1.0, 1.0}, "#00f"},
               {"anchor", {nan, nan, nan, nan, 1.0}, "#0a0", false, true},
               {"empty", {}, "#000", true}}};
    const std::string svg = renderSvgPlot(plot);
    CHECK(count(svg, "<polyline") == 2); // frames 0-1 and 3-4; the single anchor value is no line
    CHECK(count(svg, "<circle") == 1);
    const double bottom = kPlotHeight - kPlotBottom;
    const double areaHeight = kPlotHeight - kPlotTop - kPlotBottom;
    const std::string anchor = point(kPlotWidth - kPlotRight, bottom - areaHeight); // 1.0 on an axis of 1
    CHECK(svg.find("cx=\"" + anchor.substr(0, anchor.find(',')) + "\" cy=\"" +
                   anchor.substr(anchor.find(',') + 1)) != std::string::npos);
    CHECK(svg.find("a &lt;b&gt; &amp; c") != std::string::npos);
    CHECK(svg.find("empty (none)") != std::string::npos);
    CHECK(svg.find("stroke-dasharray") != std::string::npos);
}

TEST_CASE("a section's plots are inlined in the HTML page before its figures", "[report]") {
    Report report;
    report.title = "plots";
    Section section;
    section.heading = "scene";
    section.plots.push_back({"error of scene", "frame", "error", {{"output", {0.5, 0.25}, "#00f"}}});
    report.sections.push_back(section);
    const std::string html = renderHtml(report);
    CHECK(html.find("<svg") != std::string::npos);
    CHECK(html.find("error of scene") != std::string::npos);
    CHECK(html.find("<img") == std::string::npos);
}
