// glint_compare_png: the viewer tests' comparison of two PNG images, channel by channel.
//   glint_compare_png same A B MAX      exit 0 when A and B have one size and no channel
//                                       differs by more than MAX (8-bit codes)
//   glint_compare_png differ A B MAX N  exit 0 when at least N pixels have a channel that
//                                       differs by more than MAX
// Prints the size, the largest difference and the count of pixels beyond MAX; exit 1 when
// the condition fails, 2 on unreadable input.
#include "report/report_image.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (!((mode == "same" && argc == 5) || (mode == "differ" && argc == 6))) {
            std::fprintf(stderr, "usage: glint_compare_png same A B MAX | differ A B MAX N\n");
            return 2;
        }
        const glint::report::RgbImage a = glint::report::readRgbPng(argv[2]);
        const glint::report::RgbImage b = glint::report::readRgbPng(argv[3]);
        const int allowed = std::atoi(argv[4]);
        if (a.width != b.width || a.height != b.height) {
            std::printf("%s is %ux%u, %s is %ux%u\n", argv[2], a.width, a.height, argv[3], b.width, b.height);
            return 1;
        }
        int largest = 0;
        std::size_t beyond = 0;
        for (std::size_t pixel = 0; pixel < std::size_t{a.width} * a.height; ++pixel) {
            bool differs = false;
            for (std::size_t c = 0; c < 3; ++c) {
                const int difference = std::abs(int{a.rgb[pixel * 3 + c]} - int{b.rgb[pixel * 3 + c]});
                largest = std::max(largest, difference);
                differs = differs || difference > allowed;
            }
            beyond += differs ? 1 : 0;
        }
        std::printf("%ux%u: largest difference %d, %zu pixels beyond %d\n", a.width, a.height, largest,
                    beyond, allowed);
        if (mode == "same") return beyond == 0 ? 0 : 1;
        return beyond >= static_cast<std::size_t>(std::atoll(argv[5])) ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "glint_compare_png: %s\n", error.what());
        return 2;
    }
}
