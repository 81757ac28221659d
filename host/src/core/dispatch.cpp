#include "core/dispatch.h"

namespace glint::core {

DirectDispatch gridFor(std::uint32_t width, std::uint32_t height, std::uint32_t depth,
                       const std::uint32_t groupSize[3]) {
    DirectDispatch grid;
    grid.groupsX = divideRoundUp(width, groupSize[0]);
    grid.groupsY = divideRoundUp(height, groupSize[1]);
    grid.groupsZ = divideRoundUp(depth, groupSize[2]);
    return grid;
}

} // namespace glint::core
