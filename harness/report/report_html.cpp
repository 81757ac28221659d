#include "report/report_html.h"

#include "capture/capture_error.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace glint::report {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw std::runtime_error(capture::oneLine(path) + ": " + capture::oneLine(problem));
}

constexpr std::uint32_t kMinFigureWidth = 256;

struct Png {
    std::string bytes;
    std::uint32_t width = 0;
};

// The figure's PNG (its bytes, or the whole file) with the signature and the IHDR chunk that must follow it
// checked, from which the width is taken (big-endian at byte 16).
Png readPng(const Figure& figure) {
    const std::string& path = figure.pngPath;
    Png png;
    if (!figure.pngBytes.empty()) {
        png.bytes = figure.pngBytes;
    } else {
        std::ifstream in(path, std::ios::binary);
        if (!in) fail(path, "cannot open figure for reading");
        png.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (in.bad()) fail(path, "cannot read figure");
    }
    static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
    if (png.bytes.size() < 24 || std::string_view(png.bytes).substr(0, 8) != kSignature ||
        std::string_view(png.bytes).substr(12, 4) != "IHDR")
        fail(path, "not a PNG file");
    for (std::size_t i = 16; i < 20; ++i)
        png.width = (png.width << 8) | std::uint32_t{static_cast<unsigned char>(png.bytes[i])};
    if (png.width == 0) fail(path, "PNG header gives a width of 0");
    return png;
}

// Paragraphs at blank lines, each escaped; CSS white-space: pre-line keeps single newlines.
void appendParagraphs(std::string& out, std::string_view text) {
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find("\n\n", start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view paragraph = text.substr(start, end - start);
        while (!paragraph.empty() && paragraph.front() == '\n') paragraph.remove_prefix(1);
        if (!paragraph.empty()) out += "<p>" + htmlEscape(paragraph) + "</p>\n";
        start = end + 2;
    }
}

void appendFigure(std::string& out, const Figure& figure) {
    const Png png = readPng(figure);
    std::string style;
    std::uint32_t shownWidth = png.width;
    const std::uint32_t minWidth = figure.minWidth > 0 ? figure.minWidth : kMinFigureWidth;
    if (png.width < minWidth) {
        const std::uint32_t scale = (minWidth + png.width - 1) / png.width;
        shownWidth = png.width * scale;
        style = " class=\"pixelated\"";
    }
    out += "<figure><img" + style + " width=\"" + std::to_string(shownWidth) + "\" alt=\"" +
           htmlEscape(figure.caption) + "\" src=\"data:image/png;base64," + base64Encode(png.bytes) + "\">";
    if (!figure.caption.empty()) out += "<figcaption>" + htmlEscape(figure.caption) + "</figcaption>";
    out += "</figure>\n";
}

void appendTable(std::string& out, const Table& table) {
    out += table.compact ? "<table class=\"compact\">\n" : "<table>\n";
    if (!table.header.empty()) {
        out += "<thead><tr>";
        for (const std::string& cell : table.header) out += "<th>" + htmlEscape(cell) + "</th>";
        out += "</tr></thead>\n";
    }
    out += "<tbody>\n";
    for (const auto& row : table.rows) {
        out += "<tr>";
        for (const std::string& cell : row) out += "<td>" + htmlEscape(cell) + "</td>";
        out += "</tr>\n";
    }
    out += "</tbody></table>\n";
}

constexpr std::string_view kStyle = R"(
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 80em; padding: 0 1em;
       color: #1a1a1a; background: #fafafa; line-height: 1.45; }
h1 { font-size: 1.6em; margin-bottom: 0.3em; }
h2 { font-size: 1.25em; margin-top: 2em; border-bottom: 1px solid #ccc; padding-bottom: 0.2em; }
p { white-space: pre-line; }
dl.facts { display: grid; grid-template-columns: max-content auto; gap: 0.2em 1.2em; }
dl.facts dt { font-weight: 600; }
dl.facts dd { margin: 0; font-family: ui-monospace, monospace; }
.figures { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; }
figure { margin: 0; display: table; }
figure img { display: block; height: auto; max-width: 100%; background: #000; }
img.pixelated { image-rendering: pixelated; }
svg.plot { max-width: 100%; height: auto; font-family: system-ui, sans-serif; }
figcaption { font-size: 0.9em; margin-top: 0.3em; display: table-caption; caption-side: bottom; }
table { border-collapse: collapse; margin: 1em 0; font-variant-numeric: tabular-nums; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; }
th { background: #eee; }
table.compact { font-size: 0.85em; }
table.compact th, table.compact td { padding: 0.15em 0.45em; }
table.compact td { white-space: nowrap; }
)";

} // namespace

std::string base64Encode(std::string_view bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const std::uint32_t v = std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16 |
                                std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8 |
                                std::uint32_t{static_cast<unsigned char>(bytes[i + 2])};
        for (int shift = 18; shift >= 0; shift -= 6) out += kAlphabet[(v >> shift) & 63u];
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        std::uint32_t v = std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16;
        if (rest == 2) v |= std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8;
        out += kAlphabet[(v >> 18) & 63u];
        out += kAlphabet[(v >> 12) & 63u];
        out += rest == 2 ? kAlphabet[(v >> 6) & 63u] : '=';
        out += '=';
    }
    return out;
}

std::string htmlEscape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&#39;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string renderHtml(const Report& report) {
    std::string out;
    out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    out += "<title>" + htmlEscape(report.title) + "</title>\n<style>";
    out += kStyle;
    out += "</style>\n</head>\n<body>\n";
    out += "<h1>" + htmlEscape(report.title) + "</h1>\n";
    if (!report.facts.empty()) {
        out += "<dl class=\"facts\">\n";
        for (const auto& [key, value] : report.facts)
            out += "<dt>" + htmlEscape(key) + "</dt><dd>" + htmlEscape(value) + "</dd>\n";
        out += "</dl>\n";
    }
    for (const Section& section : report.sections) {
        out += "<section>\n<h2>" + htmlEscape(section.heading) + "</h2>\n";
        appendParagraphs(out, section.lead);
        if (!section.figures.empty()) {
            out += "<div class=\"figures\">\n";
            for (const Figure& figure : section.figures) appendFigure(out, figure);
            out += "</div>\n";
        }
        if (!section.plots.empty()) {
            out += "<div class=\"figures\">\n";
            for (const Plot& plot : section.plots) out += renderSvgPlot(plot) + "\n";
            out += "</div>\n";
        }
        appendParagraphs(out, section.text);
        for (const Table& table : section.tables) appendTable(out, table);
        out += "</section>\n";
    }
    out += "</body>\n</html>\n";
    return out;
}

void writeHtml(const std::string& path, const Report& report) {
    const std::string html = renderHtml(report); // figure errors before any file is touched
    const std::string partial = path + ".partial";
    {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        if (!out) fail(path, "cannot open for writing");
        out.write(html.data(), static_cast<std::streamsize>(html.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(partial, ignored);
            fail(path, "cannot write the report");
        }
    }
    std::error_code ec;
    std::filesystem::rename(partial, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        fail(path, "cannot rename " + partial + " into place: " + ec.message());
    }
}

} // namespace glint::report
