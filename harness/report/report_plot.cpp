#include "report/report_plot.h"

#include "report/report_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace glint::report {
namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

// Tick labels: up to 4 significant digits, no trailing zeros.
std::string tickLabel(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

bool hasValue(const PlotSeries& series) {
    return std::any_of(series.values.begin(), series.values.end(), [](double v) { return std::isfinite(v); });
}

} // namespace

double plotAxisMax(double largest) {
    if (!std::isfinite(largest) || largest <= 0.0) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(largest)));
    for (double step : {1.0, 2.0, 5.0, 10.0})
        if (step * decade >= largest * (1.0 - 1e-12)) return step * decade;
    return 10.0 * decade;
}

std::string renderSvgPlot(const Plot& plot) {
    std::size_t frames = 0;
    double largest = 0.0;
    for (const PlotSeries& series : plot.series) {
        frames = std::max(frames, series.values.size());
        for (double v : series.values)
            if (std::isfinite(v)) largest = std::max(largest, v);
    }
    const double yMax = plotAxisMax(largest);
    const double areaWidth = kPlotWidth - kPlotLeft - kPlotRight;
    const double areaHeight = kPlotHeight - kPlotTop - kPlotBottom;
    const double bottom = kPlotHeight - kPlotBottom;
    const auto x = [&](std::size_t i) {
        return kPlotLeft +
               static_cast<double>(i) * areaWidth / static_cast<double>(std::max<std::size_t>(frames, 2) - 1);
    };
    const auto y = [&](double v) { return bottom - std::max(v, 0.0) / yMax * areaHeight; };

    std::string out = "<svg class=\"plot\" width=\"" + number(kPlotWidth) + "\" height=\"" +
                      number(kPlotHeight) + "\" viewBox=\"0 0 " + number(kPlotWidth) + " " +
                      number(kPlotHeight) + "\" role=\"img\" aria-label=\"" + htmlEscape(plot.title) +
                      "\">\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
    out += "<text x=\"" + number(kPlotLeft) + "\" y=\"16\" font-size=\"13\" font-weight=\"600\">" +
           htmlEscape(plot.title) + "</text>\n";
    // Axes, y ticks at quarters of yMax, x ticks at every frame up to 16 of them, else 8.
    out += "<path d=\"M" + number(kPlotLeft) + " " + number(kPlotTop) + "V" + number(bottom) + "H" +
           number(kPlotWidth - kPlotRight) + "\" fill=\"none\" stroke=\"#333\"/>\n";
    for (int t = 0; t <= 4; ++t) {
        const double v = yMax * t / 4.0;
        out += "<text x=\"" + number(kPlotLeft - 6) + "\" y=\"" + number(y(v) + 4) +
               "\" font-size=\"11\" text-anchor=\"end\">" + tickLabel(v) + "</text>\n";
        if (t > 0)
            out += "<path d=\"M" + number(kPlotLeft) + " " + number(y(v)) + "H" +
                   number(kPlotWidth - kPlotRight) + "\" stroke=\"#ddd\"/>\n";
    }
    const std::size_t every = frames <= 16 ? 1 : (frames + 7) / 8;
    for (std::size_t i = 0; i < frames; i += every)
        out += "<text x=\"" + number(x(i)) + "\" y=\"" + number(bottom + 15) +
               "\" font-size=\"11\" text-anchor=\"middle\">" + std::to_string(i) + "</text>\n";
    out += "<text x=\"" + number(kPlotLeft + areaWidth / 2) + "\" y=\"" + number(kPlotHeight - 6) +
           "\" font-size=\"12\" text-anchor=\"middle\">" + htmlEscape(plot.xLabel) + "</text>\n";
    out += "<text transform=\"translate(14 " + number(kPlotTop + areaHeight / 2) +
           ") rotate(-90)\" font-size=\"12\" text-anchor=\"middle\">" + htmlEscape(plot.yLabel) + "</text>\n";

    for (const PlotSeries& series : plot.series) {
        const std::string colour = htmlEscape(series.colour.empty() ? "#000" : series.colour);
        // One polyline per run of consecutive finite values.
        std::string points;
        const auto flush = [&] {
            if (points.find(' ') != std::string::npos)
                out += "<polyline class=\"series\" fill=\"none\" stroke=\"" + colour +
                       "\" stroke-width=\"2\"" + (series.dashed ? " stroke-dasharray=\"6 4\"" : "") +
                       " points=\"" + points + "\"/>\n";
            points.clear();
        };
        for (std::size_t i = 0; i < series.values.size(); ++i) {
            const double v = series.values[i];
            if (!std::isfinite(v)) {
                flush();
                continue;
            }
            points += (points.empty() ? "" : " ") + number(x(i)) + "," + number(y(v));
            if (series.markers)
                out += "<circle cx=\"" + number(x(i)) + "\" cy=\"" + number(y(v)) + "\" r=\"4\" fill=\"" +
                       colour + "\"/>\n";
        }
        flush();
    }
    // Legend, top right, one line per series.
    double legendY = kPlotTop + 12;
    for (const PlotSeries& series : plot.series) {
        const std::string colour = htmlEscape(series.colour.empty() ? "#000" : series.colour);
        const double legendX = kPlotWidth - kPlotRight - 190;
        out += "<path d=\"M" + number(legendX) + " " + number(legendY - 4) + "h18\" stroke=\"" + colour +
               "\" stroke-width=\"2\"" + (series.dashed ? " stroke-dasharray=\"6 4\"" : "") + "/>\n";
        out += "<text x=\"" + number(legendX + 24) + "\" y=\"" + number(legendY) + "\" font-size=\"11\">" +
               htmlEscape(series.label) + (hasValue(series) ? "" : " (none)") + "</text>\n";
        legendY += 15;
    }
    out += "</svg>";
    return out;
}

} // namespace glint::report
