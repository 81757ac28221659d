#include "capture/json_text.h"

#include "capture/capture_error.h"

#include <algorithm>

namespace glint::capture {

namespace {
// nlohmann::json's out_of_range id for a number literal beyond the range of a double.
constexpr int kNumberOverflow = 406;

// "[json.exception.parse_error.101] parse error at line 1, column 5: ..." -> "line 1, column 5: ...".
std::string withoutCode(std::string message) {
    if (!message.empty() && message.front() == '[') {
        const std::size_t end = message.find("] ");
        if (end != std::string::npos) message.erase(0, end + 2);
    }
    const std::string_view parseError = "parse error at ";
    if (message.starts_with(parseError)) message.erase(0, parseError.size());
    return message;
}
} // namespace

std::string jsonProblem(const nlohmann::json::exception& error, std::string_view text) {
    std::string message = withoutCode(error.what());
    if (error.id != kNumberOverflow) return message;
    // "number overflow parsing '1e999'": the literal between the quotes.
    const std::size_t open = message.find('\'');
    const std::size_t close = message.rfind('\'');
    if (open == std::string::npos || close <= open) return message;
    const std::string literal = message.substr(open + 1, close - open - 1);
    std::string out = "the number " + literal + " is too large for a double (beyond 1.8e308)";
    const std::size_t at = text.find(literal);
    if (at == std::string_view::npos) return out;
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    return "line " + std::to_string(line) + ": " + out;
}

nlohmann::json parseJson(std::string_view text, const std::filesystem::path& file, std::string_view what) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        fail(file, std::string(what) + ": " + jsonProblem(error, text));
    }
}

} // namespace glint::capture
