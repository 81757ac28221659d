#include "core/pass_model.h"

#include "core/dispatch.h"

#include <algorithm>
#include <map>
#include <set>

namespace glint::core {

std::uint32_t accessFlags(Access access) {
    switch (access) {
    case Access::Read:
        return kAccessShaderRead;
    case Access::Write:
        return kAccessShaderWrite;
    case Access::ReadWrite:
        return kAccessShaderRead | kAccessShaderWrite;
    case Access::IndirectArgs:
        return kAccessIndirectRead;
    }
    return kAccessNone;
}

namespace {

// Each resource a pass touches, with the union of its accesses (the indirect argument buffer
// included).
std::map<std::string, std::uint32_t> passAccesses(const Pass& pass) {
    std::map<std::string, std::uint32_t> accesses;
    for (const ResourceUse& use : pass.uses) accesses[use.resource] |= accessFlags(use.access);
    if (const auto* indirect = std::get_if<IndirectDispatch>(&pass.dispatch))
        accesses[indirect->resource] |= kAccessIndirectRead;
    return accesses;
}

std::string checkDispatch(const Pass& pass) {
    for (std::uint32_t size : pass.groupSize)
        if (size == 0) return "pass '" + pass.name + "': zero group size";
    if (const auto* direct = std::get_if<DirectDispatch>(&pass.dispatch)) {
        for (std::uint32_t groups : {direct->groupsX, direct->groupsY, direct->groupsZ})
            if (groups > kMaxGroupsPerDimension)
                return "pass '" + pass.name + "': " + std::to_string(groups) +
                       " groups in one dimension exceed the guaranteed limit of 65535";
    } else {
        const auto& indirect = std::get<IndirectDispatch>(pass.dispatch);
        if (indirect.resource.empty()) return "pass '" + pass.name + "': indirect dispatch names no buffer";
        if (indirect.offset % 4 != 0)
            return "pass '" + pass.name + "': indirect offset is not 4-byte aligned";
    }
    return {};
}

} // namespace

std::string validatePlan(const EffectPlan& plan) {
    std::set<std::string> resourceNames;
    for (const ImageDesc& image : plan.images) {
        if (!resourceNames.insert(image.name).second)
            return "effect '" + plan.effect + "': duplicate resource '" + image.name + "'";
        if (image.width == 0 || image.height == 0 || image.mipLevels == 0)
            return "effect '" + plan.effect + "': image '" + image.name + "' has a zero size or level count";
    }
    for (const BufferDesc& buffer : plan.buffers) {
        if (!resourceNames.insert(buffer.name).second)
            return "effect '" + plan.effect + "': duplicate resource '" + buffer.name + "'";
        if (buffer.size == 0 || buffer.size % 4 != 0)
            return "effect '" + plan.effect + "': buffer '" + buffer.name +
                   "' size must be a non-zero multiple of 4";
    }
    std::set<std::string> names;
    for (const Pass& pass : plan.passes) {
        if (pass.name.empty()) return "effect '" + plan.effect + "': a pass has no name";
        if (!names.insert(pass.name).second)
            return "effect '" + plan.effect + "': duplicate pass '" + pass.name + "'";
        if (pass.pipeline.empty()) return "pass '" + pass.name + "': no pipeline";
        if (pass.constants.empty() != pass.constantsBinding.empty())
            return "pass '" + pass.name + "': constants and their binding name must come together";
        if (pass.constants.size() % 16 != 0)
            return "pass '" + pass.name + "': constants are not a multiple of 16 bytes";
        for (const ResourceUse& use : pass.uses)
            if (use.binding.empty() || use.resource.empty())
                return "pass '" + pass.name + "': a resource use lacks its binding or resource name";
        for (const auto& [resource, flags] : passAccesses(pass))
            if ((flags & kAccessIndirectRead) && (flags & kAccessShaderWrite))
                return "pass '" + pass.name + "': '" + resource +
                       "' is written and read as indirect arguments";
        if (std::string error = checkDispatch(pass); !error.empty()) return error;
        for (const std::string& buffer : pass.zeroBuffers)
            if (std::none_of(plan.buffers.begin(), plan.buffers.end(),
                             [&](const BufferDesc& desc) { return desc.name == buffer; }))
                return "pass '" + pass.name + "': zeroes '" + buffer +
                       "', which is not among the plan's buffers";
    }
    return {};
}

std::vector<PlannedBarrier> planBarriers(const EffectPlan& plan) {
    struct State {
        std::uint32_t pendingWrite = kAccessExternalWrite; // writes not yet made visible
        std::uint32_t readsSinceWrite = kAccessNone;       // reads a later write must wait for
    };
    std::map<std::string, State> states;
    std::vector<PlannedBarrier> barriers;
    auto access = [&](std::size_t index, BarrierPoint point, const std::string& resource,
                      std::uint32_t flags) {
        State& state = states[resource];
        const bool writes = (flags & (kAccessShaderWrite | kAccessTransferWrite)) != 0;
        const bool hazard =
            state.pendingWrite != kAccessNone || (writes && state.readsSinceWrite != kAccessNone);
        if (hazard) {
            barriers.push_back({index, point, resource, state.pendingWrite | state.readsSinceWrite, flags});
            state.pendingWrite = kAccessNone;
            state.readsSinceWrite = kAccessNone;
        }
        if (writes) {
            state.pendingWrite = flags & (kAccessShaderWrite | kAccessTransferWrite);
            state.readsSinceWrite = kAccessNone;
        } else {
            state.readsSinceWrite |= flags;
        }
    };
    for (std::size_t index = 0; index < plan.passes.size(); ++index) {
        const Pass& pass = plan.passes[index];
        for (const std::string& buffer : pass.zeroBuffers)
            access(index, BarrierPoint::BeforeFills, buffer, kAccessTransferWrite);
        for (const auto& [resource, flags] : passAccesses(pass))
            access(index, BarrierPoint::BeforeDispatch, resource, flags);
    }
    return barriers;
}

void renameResource(std::vector<Pass>& passes, const std::string& from, const std::string& to) {
    for (Pass& pass : passes) {
        for (ResourceUse& use : pass.uses)
            if (use.resource == from) use.resource = to;
        if (auto* indirect = std::get_if<IndirectDispatch>(&pass.dispatch);
            indirect && indirect->resource == from)
            indirect->resource = to;
    }
}

} // namespace glint::core
