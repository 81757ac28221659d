// glint public API: an effect as data.
//
// Every effect is described as an ordered list of passes. A pass names its compute pipeline
// (an embedded SPIR-V module), the resources it reads and writes under the names its shader
// binds them by, its constants, and how it is dispatched (a direct grid, or indirect from a
// buffer that an earlier pass wrote). The Vulkan backend executes such a list, deriving
// barriers from the declared accesses; an engine can execute the same list with its own
// renderer (the NRD model). Nothing here touches a graphics API.
#pragma once

#include "glint/glint_types.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace glint {

enum class Access : std::uint8_t {
    Read = 1,         // sampled or storage read by the shader
    Write = 2,        // storage write (contents before the pass are not needed)
    ReadWrite = 3,    // storage read-modify-write or atomics
    IndirectArgs = 4, // read by the dispatch itself as VkDispatchIndirectCommand
};

struct ResourceUse {
    std::string binding;  // the shader's variable name, e.g. "g_glint_material"
    std::string resource; // the effect-level resource name, e.g. "material"
    Access access = Access::Read;
};

struct DirectDispatch {
    std::uint32_t groupsX = 1, groupsY = 1, groupsZ = 1;
};

struct IndirectDispatch {
    std::string resource;     // the buffer holding the arguments
    std::uint64_t offset = 0; // byte offset of the 3 x uint32 arguments, 4-byte aligned
};

// Formats of the resources an effect owns. Every storage image declares exactly one of these
// in its entry file (GLINT_IMAGE_FORMAT), and the backend checks the bound image against it.
enum class Format : std::uint8_t {
    R32Float,
    RG32Float,
    RGBA32Float,
    R16Float,
    RG16Float,
    RGBA16Float,
    R8Unorm,
    RGBA8Unorm,
    R32Uint,
};

// An image the effect needs the application (or harness) to create: the plan is the single
// source of truth for its size, format and level count, and the backend refuses a bound
// image that disagrees.
struct ImageDesc {
    std::string name;
    std::uint32_t width = 0, height = 0;
    std::uint32_t mipLevels = 1;
    Format format = Format::R32Float;
    // Level 0's texels (4-byte floats, channel count of the format) uploaded once when the
    // image is created; without them the image starts zeroed.
    std::shared_ptr<const std::vector<float>> initialTexels;
};

struct BufferDesc {
    std::string name;
    std::uint64_t size = 0;    // bytes
    bool indirectArgs = false; // also used as VkDispatchIndirectCommand source
};

struct Pass {
    std::string name;                       // unique within the effect, used for timings and dumps
    std::string pipeline;                   // embedded shader module name, e.g. "gbuffer_extract_roughness"
    std::uint32_t groupSize[3] = {8, 8, 1}; // must equal the shader's [numthreads]
    std::vector<ResourceUse> uses;
    std::string constantsBinding;     // empty when the pass has no constants
    std::vector<std::byte> constants; // packed exactly as the shader's cbuffer
    std::variant<DirectDispatch, IndirectDispatch> dispatch;
    // Buffers set to zero right before the dispatch (e.g. atomic counters), ordered after every
    // earlier access and before the dispatch's own.
    std::vector<std::string> zeroBuffers;
};

// How a tool turns a resource into a picture. Wire formats are the ones of
// glint/common/glint_wire_formats.h.
enum class OutputDecoder : std::uint8_t {
    Channels,        // an image's channels [firstChannel, firstChannel + channels) at `level`
    MipChain,        // every level from `level` on, channel firstChannel: outputs "<name><level>"
    RayList,         // a ray-list buffer: 1 at each listed pixel; the entry count is counter `count`
    TileList,        // a tile-list buffer: 1 over each listed 8x8 tile; the count is counter `count`
    ShadowMask,      // the shadow denoiser's packed visibility (one word per 8x4 pixels)
    ShadowTileClass, // the shadow tile metadata: its CLEAR and LIGHT bits over each 8x8 tile
};

// A named output of the effect: "denoised" is resource "sssr_radiance" as pass "resolve" left
// it. When a later pass overwrites the resource, a tool copies it right after `pass`.
struct OutputDesc {
    std::string name;
    std::string resource;
    std::string pass;
    OutputDecoder decoder = OutputDecoder::Channels;
    std::uint32_t firstChannel = 0, channels = 1, level = 0;
    std::string count;         // RayList, TileList: the counter holding the entry count
    bool intermediate = false; // only when a tool asks for intermediates (glint dump)
};

// A word of a buffer worth reporting every frame, e.g. the number of traced pixels.
struct CounterDesc {
    std::string name;
    std::string buffer;
    std::uint32_t word = 0;
    std::string fractionName; // non-empty: also reported under this name divided by the pixel count
};

struct EffectPlan {
    std::string effect;
    Extent2D size; // the frame size the plan was made for (outputs are decoded at it)
    std::vector<Pass> passes;
    std::vector<ImageDesc> images;     // images the effect defines (not the application's inputs)
    std::vector<BufferDesc> buffers;   // buffers the effect defines
    std::vector<OutputDesc> outputs;   // filled by the effect descriptors (glint_effect.h)
    std::vector<CounterDesc> counters; // likewise
};

} // namespace glint
