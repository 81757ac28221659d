#include "view_picture.h"

#include "cli_images.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

namespace glint::cli::view {

report::RgbImage mapView(const std::string& name, const report::Image& image, float exposure) {
    report::PngMapping mapping = previewMapping(name, image);
    if (auto* tonemap = std::get_if<report::Tonemap>(&mapping)) tonemap->exposure = exposure;
    return {image.width, image.height, report::mapToRgb8(name, image, mapping)};
}

Picture composePicture(std::uint32_t width, std::uint32_t height, const report::RgbImage& left,
                       const report::RgbImage* right, float divider) {
    if (width == 0 || height == 0) throw std::invalid_argument("view: an empty picture");
    for (const report::RgbImage* side : {&left, right})
        if (side && (side->width == 0 || side->height == 0 ||
                     side->rgb.size() != std::size_t{side->width} * side->height * 3))
            throw std::invalid_argument("view: an image without pixels");
    Picture picture{width, height, std::vector<std::uint8_t>(std::size_t{width} * height * 4, 255)};
    const float fraction = std::isfinite(divider) ? std::clamp(divider, 0.0f, 1.0f) : 0.5f;
    const auto column =
        right ? static_cast<std::uint32_t>(std::floor(fraction * static_cast<float>(width))) : width;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            std::uint8_t* out = &picture.rgba[(std::size_t{y} * width + x) * 4];
            if (right && x == column) {
                out[0] = out[1] = out[2] = 255;
                continue;
            }
            const report::RgbImage& side = x < column ? left : *right;
            // Nearest texel: the centre of pixel x lands in texel floor((x + 0.5) * w / width).
            const std::uint32_t sx =
                side.width == width
                    ? x
                    : static_cast<std::uint32_t>((std::uint64_t{x} * 2 + 1) * side.width / (2ull * width));
            const std::uint32_t sy =
                side.height == height
                    ? y
                    : static_cast<std::uint32_t>((std::uint64_t{y} * 2 + 1) * side.height / (2ull * height));
            const std::uint8_t* in = &side.rgb[(std::size_t{sy} * side.width + sx) * 3];
            out[0] = in[0];
            out[1] = in[1];
            out[2] = in[2];
        }
    return picture;
}

} // namespace glint::cli::view
