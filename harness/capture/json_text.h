// JSON side files (manifests, camera files, run summaries) parsed with messages for people:
// nlohmann::json's "[json.exception.<kind>.<id>]" codes are left out, and a number too large
// for a double (1e999, which the library reports as "number overflow") is named with its line.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>

namespace glint::capture {

// The problem a JSON exception describes, in words, e.g. "line 3: the number 1e999 is too large
// for a double (beyond 1.8e308)" or "line 1, column 5: syntax error while parsing value ...".
// `text` is the parsed text, used to find the line of an out-of-range number.
std::string jsonProblem(const nlohmann::json::exception& error, std::string_view text);

// Parses `text`; on failure throws CaptureError "<file>: <what>: <problem>".
nlohmann::json parseJson(std::string_view text, const std::filesystem::path& file, std::string_view what);

} // namespace glint::capture
