// OpenEXR plumbing shared by the frame and environment readers/writers: a header read that
// checks sizes before OpenEXR allocates anything, window rules, and exception translation.
// Internal to the capture library; users include frame_io.h / environment_io.h.
#pragma once

#include "capture/capture_error.h"

#include <OpenEXR/ImfHeader.h>

#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

namespace glint::capture {

struct ExrSize {
    std::uint32_t width = 0, height = 0;
};

// Reads only the header, via our own stream, and checks it: the file exists and is a regular
// file, starts with the OpenEXR magic number, is single-part and flat (not deep), its data
// window equals its display window with origin (0,0), and its size is within the limits of
// frame_validation.h. Imf::InputFile sizes its scanline offset table from the data window
// as it opens, so a corrupt or hostile size must be refused before InputFile sees the file.
Imf::Header readExrHeader(const std::filesystem::path& file, ExrSize& size);

// Runs `work`, turning any exception other than CaptureError into a CaptureError naming
// `file` and prefixing `context` (e.g. "cannot read pixel data").
template <typename Work>
decltype(auto) translateErrors(const std::filesystem::path& file, std::string_view context, Work&& work) {
    try {
        return std::forward<Work>(work)();
    } catch (const CaptureError&) {
        throw;
    } catch (const std::exception& e) {
        fail(file, std::string(context) + ": " + e.what());
    } catch (...) {
        fail(file, std::string(context) + ": unknown error");
    }
}

// Writes through a sibling temporary file renamed into place at the end, so that an
// interrupted write never leaves a truncated capture under the final name.
template <typename Write> void writeAtomically(const std::filesystem::path& file, Write&& write) {
    std::filesystem::path partial = file;
    partial += ".partial";
    try {
        std::forward<Write>(write)(partial);
        std::filesystem::rename(partial, file);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        throw;
    }
}

} // namespace glint::capture
