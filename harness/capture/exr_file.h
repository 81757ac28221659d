// OpenEXR plumbing shared by the frame and environment readers/writers: a header read that
// checks sizes before OpenEXR allocates anything, a check that the file can hold the pixel
// data its header declares, window rules, and exception translation.
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

// Where readExrHeader found the header to end (the chunk offset table follows it).
struct ExrLayout {
    std::uint64_t fileBytes = 0;
    std::uint64_t headerEnd = 0; // offset of the first byte after the header
    bool tiled = false;
};

// Reads only the header, via our own stream, and checks it: the file exists and is a regular
// file, starts with the OpenEXR magic number, is single-part and flat (not deep), every
// attribute's size fits in the bytes left in the file (walked before OpenEXR reads a value,
// since OpenEXR allocates whatever a size field says), the header passes OpenEXR's own
// sanity check, its data window equals its display window with origin (0,0), and its size
// is within the limits of frame_validation.h. Imf::InputFile sizes its scanline offset table
// from the data window as it opens, so a corrupt or hostile size must be refused before
// InputFile sees the file.
Imf::Header readExrHeader(const std::filesystem::path& file, ExrSize& size, ExrLayout* layout = nullptr);

// The largest ratio of uncompressed to stored bytes a chunk of each compression can reach
// (1 for NO_COMPRESSION, where stored chunks must match exactly); see exr_file.cpp.
std::uint64_t maxCompressionRatio(Imf::Compression compression);

// Checks, before any pixel buffer is allocated, that the file can hold the pixel data its
// header declares: the chunk offset table fits in the file and every entry points inside it,
// each level-0 chunk starts with its own scanline (or tile) and its stored size fits in the
// bytes left, an uncompressed chunk stores exactly the bytes of its scanlines, and a
// compressed one at least 1/maxCompressionRatio of them; tiles are no larger than the image
// needs. What the readers (and OpenEXR) then allocate is bounded by the ratio times the size
// of the file, not by what its header claims. Call with the layout readExrHeader returned.
void checkPixelData(const std::filesystem::path& file, const Imf::Header& header, const ExrLayout& layout);

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
