// A self-contained HTML report: one file with inline CSS, every figure embedded as a base64
// PNG data URI and every plot as inline SVG, so it can be moved or mailed alone and opens
// without a network.
#pragma once

#include "report/report_plot.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace glint::report {

struct Figure {
    std::string caption;
    std::string pngPath;  // read when the report is written and embedded
    std::string pngBytes; // a PNG made in memory, embedded instead of pngPath's (which then names it)
    // Shown at least this wide, scaled up by the smallest integer factor reaching it with each
    // pixel a sharp square; 0: 256 px.
    std::uint32_t minWidth = 0;
};

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    bool compact = false; // smaller type, cells kept on one line (a summary to read at a glance)
};

// Shown in this order: heading, lead, figures, plots, text, tables.
struct Section {
    std::string heading;
    std::string text; // blank lines separate paragraphs; single newlines are kept as line breaks
    std::vector<Figure> figures;
    std::vector<Table> tables;
    std::vector<Plot> plots; // inline SVG
    std::string lead;        // as text, right under the heading
};

struct Report {
    std::string title;
    std::vector<std::pair<std::string, std::string>> facts; // e.g. device, driver, date
    std::vector<Section> sections;
};

// RFC 4648 base64 (standard alphabet, '=' padding, no line breaks).
std::string base64Encode(std::string_view bytes);

// Escapes & < > " ' so that any text is safe in element content and in quoted attributes.
std::string htmlEscape(std::string_view text);

// The page as a string. Figures of a section sit side by side and wrap; an image narrower
// than its figure's minWidth is scaled up by the smallest integer factor reaching it, with
// image-rendering: pixelated so each pixel stays a sharp square. Throws std::runtime_error
// "<pngPath>: <problem>" when a figure's file cannot be read or is not a PNG.
std::string renderHtml(const Report& report);

// renderHtml written to `path` (through "<path>.partial", renamed into place when complete);
// errors are std::runtime_error "<path>: <problem>".
void writeHtml(const std::string& path, const Report& report);

} // namespace glint::report
