#include "core/sssr_table_images.h"

#include "glint/glint_sssr_tables.h"

namespace glint::core {

std::shared_ptr<const std::vector<float>> sssrBlueNoiseTexels() {
    static const auto texels = std::make_shared<const std::vector<float>>(sssrBlueNoise());
    return texels;
}

std::shared_ptr<const std::vector<float>> sssrBrdfLutTexels() {
    static const auto texels = std::make_shared<const std::vector<float>>(sssrBrdfLut(kSssrBrdfLutSize));
    return texels;
}

} // namespace glint::core
