// Checks on an effect plan and the barriers its declared accesses imply. Vulkan-free: the
// backend maps AccessFlags onto stages and access masks, tests check the plan directly.
#pragma once

#include "glint/glint_pass.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::core {

// What a barrier waits for (src) or protects (dst).
enum AccessFlags : std::uint32_t {
    kAccessNone = 0,
    kAccessShaderRead = 1u << 0,
    kAccessShaderWrite = 1u << 1,
    kAccessIndirectRead = 1u << 2,
    kAccessExternalWrite = 1u << 3, // anything before the plan: uploads, the engine's own passes
    kAccessTransferWrite = 1u << 4, // a pass's zeroBuffers fill
};

// Where in a pass a barrier goes: before its buffer fills, or between them and the dispatch.
enum class BarrierPoint : std::uint8_t { BeforeFills, BeforeDispatch };

struct PlannedBarrier {
    std::size_t beforePass = 0;
    BarrierPoint point = BarrierPoint::BeforeDispatch;
    std::string resource;
    std::uint32_t src = kAccessNone;
    std::uint32_t dst = kAccessNone;
};

// Empty when the plan is well formed; otherwise one line naming the pass and the problem
// (duplicate pass names, a resource both written and read as indirect arguments by one pass,
// a zero group size, a group count beyond kMaxGroupsPerDimension, an empty pipeline name...).
std::string validatePlan(const EffectPlan& plan);

// The barriers that make every pass see what earlier passes wrote (read after write), keep
// writes after reads ordered (write after read), and order writes (write after write). Every
// resource starts with a pending external write, so its first use waits for the upload or
// the engine pass that produced it. Reads after reads need nothing.
std::vector<PlannedBarrier> planBarriers(const EffectPlan& plan);

// Renames resource `from` to `to` in every pass's uses and indirect dispatches: how effects
// compose by resource name (a history that another effect writes, a shared buffer's name).
void renameResource(std::vector<Pass>& passes, const std::string& from, const std::string& to);

// The union of a pass's accesses to one resource (a pass may bind it more than once).
std::uint32_t accessFlags(Access access);

} // namespace glint::core
