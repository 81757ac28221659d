// Helpers shared by the capture tests: per-test output folders, a frame with every layer
// kind, raw OpenEXR writing for files the library itself refuses to produce, and a probe
// that runs a reader and returns its CaptureError message.
#pragma once

#include <capture/capture_frame.h>

#include <OpenEXR/ImfHeader.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace glint::capture::test {

// GLINT_TEST_OUTPUT_DIR/capture/<name>, emptied and created.
std::filesystem::path freshTestDir(std::string_view name);

// A valid frame declaring reflections, shadows and depth_pyramid, with every layer kind
// (color RGBA, depth, normal, material, roughness, motion, shadow, reference.reflection,
// reference.shadow), HALF and FLOAT storage, sample values that HALF must round, and
// camera matrices whose doubles do not survive a trip through float.
Frame makeFullFrame(std::uint32_t width, std::uint32_t height);

// A frame with only depth and the depth_pyramid effect: the smallest valid capture.
Frame makeDepthOnlyFrame(std::uint32_t width, std::uint32_t height);

// The OpenEXR header of an existing file, to be edited into a malformed one.
Imf::Header exrHeaderOf(const std::filesystem::path& file);

// Writes a complete single-part file with `header` and all-zero samples in every channel.
void writeZeroExr(const std::filesystem::path& file, const Imf::Header& header);

// Writes the OpenEXR preamble and `header` and nothing else: a file whose header may claim
// any size without the test having to write (or OpenEXR to allocate) its offset table.
void writeHeaderOnlyExr(const std::filesystem::path& file, const Imf::Header& header);

// Copies `header` with the channel list rebuilt: `drop` removed, everything else kept.
Imf::Header withoutChannel(const Imf::Header& header, const std::string& drop);

// Copies `header` without attribute `drop`. (Imf::Header::erase in OpenEXR 3.1 leaks the
// erased attribute, which the sanitized build reports, so the header is rebuilt instead.)
Imf::Header withoutAttribute(const Imf::Header& header, const std::string& drop);

// Runs `read`; returns the CaptureError message, or a text starting "NO ERROR" / "OTHER
// EXCEPTION" so that a failed REQUIRE shows what happened instead.
std::string captureErrorOf(const std::function<void()>& read);

bool isOneLine(const std::string& text);

// The header of a valid full frame of the given size written into dir, for tests that break
// it one way each.
Imf::Header validFrameHeader(const std::filesystem::path& dir, std::uint32_t width, std::uint32_t height);

// Writes a frame file with `header` and returns readFrame's error, after checking that it is
// one line naming the file.
std::string rejectionOf(const std::filesystem::path& file, const Imf::Header& header);

void writeBytes(const std::filesystem::path& file, const std::string& bytes);
std::string readBytes(const std::filesystem::path& file);

} // namespace glint::capture::test
