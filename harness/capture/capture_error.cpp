#include "capture/capture_error.h"

namespace glint::capture {

std::string oneLine(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        const bool control = static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        const char ch = control ? ' ' : c;
        if (ch == ' ' && (out.empty() || out.back() == ' ')) continue;
        out.push_back(ch);
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

CaptureError::CaptureError(const std::filesystem::path& file, std::string_view problem)
    : std::runtime_error(oneLine(file.string()) + ": " + oneLine(problem)) {}

void fail(const std::filesystem::path& file, std::string_view problem) {
    throw CaptureError(file, problem);
}

} // namespace glint::capture
