// SSSR's tables as the texels of plan-owned images (ImageDesc::initialTexels), made once per
// process and shared by every plan that owns them (the reflections and hybrid effects).
#pragma once

#include <memory>
#include <vector>

namespace glint::core {

std::shared_ptr<const std::vector<float>> sssrBlueNoiseTexels(); // kSssrBlueNoiseSize^2 RG
std::shared_ptr<const std::vector<float>> sssrBrdfLutTexels();   // kSssrBrdfLutSize^2 RG

} // namespace glint::core
