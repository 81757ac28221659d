// Line plots drawn as inline SVG (no script, no external resource), for the HTML report: a
// value against frame per series, on one linear y axis from 0.
//
// Geometry (fixed, so that a reader or a test can map a value to its place): the SVG is
// kPlotWidth x kPlotHeight; the plot area spans x in [kPlotLeft, kPlotWidth - kPlotRight] and
// y in [kPlotTop, kPlotHeight - kPlotBottom]. Sample i of n sits at
// x = kPlotLeft + i * areaWidth / max(n - 1, 1), where n is the longest series' length; a value
// v at y = (kPlotHeight - kPlotBottom) - v / yMax * areaHeight, yMax = plotAxisMax(the largest
// finite value of every series). Values below 0 are drawn at 0.
#pragma once

#include <string>
#include <vector>

namespace glint::report {

inline constexpr double kPlotWidth = 520, kPlotHeight = 300;
inline constexpr double kPlotLeft = 64, kPlotRight = 16, kPlotTop = 28, kPlotBottom = 44;

struct PlotSeries {
    std::string label;
    std::vector<double> values; // one per frame; NaN (or infinite): no value, the line breaks
    std::string colour;         // any CSS colour, e.g. "#1f77b4"
    bool dashed = false;
    bool markers = false; // a circle at every value (an isolated value shows only as one)
};

struct Plot {
    std::string title;  // above the area
    std::string xLabel; // "frame"
    std::string yLabel;
    std::vector<PlotSeries> series;
};

// The top of the y axis for a largest value `largest`: the smallest 1, 2 or 5 x 10^k that is
// >= largest; 1 when largest is not finite or not above 0.
double plotAxisMax(double largest);

// The plot as one <svg> element for inline HTML (no xmlns: the HTML parser supplies the SVG
// namespace, and the page links nothing). Text is escaped; a series that is empty or has no finite
// value is left out of the lines but kept in the legend, marked "(none)".
std::string renderSvgPlot(const Plot& plot);

} // namespace glint::report
