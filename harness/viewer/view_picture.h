// What glint view puts in its window: an image of the replay mapped to 8-bit colour exactly as
// glint run maps its PNG previews (cli_images.h), with an exposure factor on tone-mapped
// colour, and optionally a second image right of a divider.
#pragma once

#include "report/report_image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::cli::view {

// `image` (named as the replay names it) mapped to 8-bit RGB; `exposure` scales colour that
// is tone mapped (HDR radiance) and leaves data views (depth, classes, heat maps) alone.
report::RgbImage mapView(const std::string& name, const report::Image& image, float exposure);

// RGBA, row-major from the top left, alpha 255.
struct Picture {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

// A width x height picture of `left` (scaled to that size, nearest texel, when its size
// differs: a pyramid mip), or with `right` as well: left of column floor(divider * width)
// from `left`, from that column on from `right`, and the column itself white so the two
// sides can be told apart. `divider` is clamped to [0, 1].
Picture composePicture(std::uint32_t width, std::uint32_t height, const report::RgbImage& left,
                       const report::RgbImage* right, float divider);

} // namespace glint::cli::view
