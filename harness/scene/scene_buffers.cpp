#include "scene/scene_buffers.h"

#include <gpu/gpu_transfer.h>

#include <algorithm>
#include <numbers>

namespace glint::scene {
namespace {

template <typename T> vk::Buffer upload(const gpu::Context& context, const std::vector<T>& values) {
    vk::Buffer buffer = vk::createBuffer(context.device, sizeof(T) * values.size(),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::DeviceLocal);
    gpu::uploadBuffer(context, buffer, std::span<const T>(values));
    return buffer;
}

} // namespace

std::vector<shaders::SceneMaterial> packMaterials(const Scene& scene) {
    std::vector<shaders::SceneMaterial> out;
    for (const MaterialDesc& m : scene.materials) {
        shaders::SceneMaterial g{};
        g.baseColor = {m.baseColor[0], m.baseColor[1], m.baseColor[2]};
        g.metallic = m.metallic;
        g.emissive = {m.emissive[0], m.emissive[1], m.emissive[2]};
        g.roughness = m.roughness;
        g.roughnessEnd = m.ramp ? m.rampRoughnessEnd : m.roughness;
        if (m.ramp) {
            // t = dot(p - start, axis) / |axis|^2 = dot(p, axis / |axis|^2) - dot(start, axis) / |axis|^2
            const float a[3] = {m.rampEnd[0] - m.rampStart[0], m.rampEnd[1] - m.rampStart[1],
                                m.rampEnd[2] - m.rampStart[2]};
            const float len2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
            g.rampPlane = {a[0] / len2, a[1] / len2, a[2] / len2,
                           -(m.rampStart[0] * a[0] + m.rampStart[1] * a[1] + m.rampStart[2] * a[2]) / len2};
        }
        out.push_back(g);
    }
    if (out.empty()) out.push_back({});
    return out;
}

std::vector<shaders::SceneLight> packLights(const std::vector<LightDesc>& lights) {
    std::vector<shaders::SceneLight> out;
    for (const LightDesc& l : lights) {
        shaders::SceneLight g{};
        const bool directional = l.kind == LightKind::Directional;
        g.kind = directional ? GLINT_SCENE_LIGHT_DIRECTIONAL : GLINT_SCENE_LIGHT_SPHERE;
        const Vec3& v = directional ? l.direction : l.position;
        g.where = {v[0], v[1], v[2]};
        g.radiance = {l.color[0] * l.intensity, l.color[1] * l.intensity, l.color[2] * l.intensity};
        g.size =
            directional
                ? static_cast<float>(static_cast<double>(l.angularRadiusDegrees) * std::numbers::pi / 180.0)
                : l.radius;
        out.push_back(g);
    }
    if (out.empty()) out.push_back({});
    return out;
}

SceneBuffers::SceneBuffers(const gpu::Context& context, Scene scene, bool accelerationStructure)
    : context_(context), scene_(std::move(scene)), meshes_(loadMeshes(scene_)) {
    if (accelerationStructure) acceleration_ = std::make_unique<SceneAccelerationStructure>(context_);
    materials_ = upload(context_, packMaterials(scene_));
    try {
        setFrame(0);
    } catch (...) {
        release();
        vk::destroyBuffer(context_.device, materials_);
        throw;
    }
}

SceneBuffers::~SceneBuffers() {
    release();
    vk::destroyBuffer(context_.device, materials_);
}

void SceneBuffers::release() {
    for (Stored* stored : {&constants_, &nodes_, &primitives_, &lights_})
        if (stored->buffer.buffer != VK_NULL_HANDLE) vk::destroyBuffer(context_.device, stored->buffer);
}

void SceneBuffers::setFrame(std::uint32_t frame) {
    frame = std::min(frame, scene_.frameCount == 0 ? 0u : scene_.frameCount - 1);
    Bvh bvh = buildBvh(buildGeometry(scene_, meshes_, frame).primitives);
    if (acceleration_) acceleration_->build(bvh.primitives);  // the BVH's order: the same primitive indices
    if (bvh.primitives.empty()) bvh.primitives.push_back({}); // never read: the root is an empty leaf
    shaders::GLINT_SceneConstants c{};
    c.size = {scene_.width, scene_.height};
    c.frameIndex = frame;
    c.seed = scene_.seed;
    c.lightCount = static_cast<std::uint32_t>(scene_.lights.size());
    c.samples = 1;
    c.shadowSamples = scene_.shadowSamples;
    c.environmentIntensity = 1.0f;
    refresh(constants_, std::as_bytes(std::span(&c, 1)));
    refresh(nodes_, std::as_bytes(std::span(bvh.nodes)));
    refresh(primitives_, std::as_bytes(std::span(bvh.primitives)));
    const std::vector<shaders::SceneLight> lights = packLights(lightsAt(scene_, frame));
    refresh(lights_, std::as_bytes(std::span(lights)));
}

void SceneBuffers::refresh(Stored& stored, std::span<const std::byte> bytes) {
    // A static scene's BVH and lights are the same on every frame: uploaded once.
    if (stored.buffer.buffer != VK_NULL_HANDLE && stored.bytes.size() == bytes.size() &&
        std::equal(bytes.begin(), bytes.end(), stored.bytes.begin()))
        return;
    if (stored.buffer.buffer != VK_NULL_HANDLE && stored.buffer.size != bytes.size())
        vk::destroyBuffer(context_.device, stored.buffer);
    if (stored.buffer.buffer == VK_NULL_HANDLE)
        stored.buffer = vk::createBuffer(context_.device, bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                         vk::MemoryUse::DeviceLocal);
    gpu::uploadBuffer(context_, stored.buffer, bytes);
    stored.bytes.assign(bytes.begin(), bytes.end());
}

void SceneBuffers::addTo(vk::ResourceTable& table) const {
    table.buffers["scene_constants"] = &constants_.buffer;
    table.buffers["scene_nodes"] = &nodes_.buffer;
    table.buffers["scene_primitives"] = &primitives_.buffer;
    table.buffers["scene_materials"] = &materials_;
    table.buffers["scene_lights"] = &lights_.buffer;
    if (acceleration_) table.accelerationStructures[kSceneAccelerationStructure] = acceleration_->topLevel();
}

} // namespace glint::scene
