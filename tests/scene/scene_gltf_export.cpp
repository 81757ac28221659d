#include "scene/scene_gltf_export.h"

#include <scene/scene_geometry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace glint::test {
namespace {

std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        auto byte = [&](std::size_t k) { return std::uint32_t{static_cast<unsigned char>(bytes[k])}; };
        std::uint32_t v = byte(i) << 16;
        if (i + 1 < bytes.size()) v |= byte(i + 1) << 8;
        if (i + 2 < bytes.size()) v |= byte(i + 2);
        out += alphabet[(v >> 18) & 63];
        out += alphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[v & 63] : '=';
    }
    return out;
}

// Nine significant digits: every float reads back as itself.
std::string number(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string list(std::initializer_list<double> values) {
    std::string out = "[";
    for (double v : values) out += (out.size() > 1 ? "," : "") + number(v);
    return out + "]";
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

} // namespace

std::string sceneAsGltf(const scene::Scene& scene, std::uint32_t frame) {
    for (const scene::ObjectDesc& object : scene.objects)
        if (object.shape == scene::ShapeKind::Sphere)
            throw std::invalid_argument("object '" + object.name +
                                        "': an analytic sphere has no exact triangles");
    for (const scene::MaterialDesc& material : scene.materials)
        if (material.ramp)
            throw std::invalid_argument("material '" + material.name + "': glTF has no roughness ramp");
    const scene::FrameGeometry geometry = scene::buildGeometry(scene, scene::loadMeshes(scene), frame);

    std::string bin;
    std::string meshes, nodes, accessors, views, sceneNodes;
    auto comma = [](std::string& s) {
        if (!s.empty()) s += ",";
    };
    std::size_t meshCount = 0;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        std::vector<float> floats;
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (const auto& p : geometry.primitives) {
            if (p.object != o) continue;
            for (const auto& v : {p.p0, p.p1, p.p2}) {
                const float xyz[3] = {v.x, v.y, v.z};
                for (int k = 0; k < 3; ++k) {
                    floats.push_back(xyz[k]);
                    lo[k] = std::min(lo[k], xyz[k]);
                    hi[k] = std::max(hi[k], xyz[k]);
                }
            }
        }
        if (floats.empty()) continue;
        const std::size_t offset = bin.size(), bytes = floats.size() * sizeof(float);
        bin.append(reinterpret_cast<const char*>(floats.data()), bytes);
        comma(views);
        views += "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
                 ",\"byteLength\":" + std::to_string(bytes) + "}";
        comma(accessors);
        accessors += "{\"bufferView\":" + std::to_string(meshCount) +
                     ",\"componentType\":5126,\"count\":" + std::to_string(floats.size() / 3) +
                     ",\"type\":\"VEC3\",\"min\":" + list({lo[0], lo[1], lo[2]}) +
                     ",\"max\":" + list({hi[0], hi[1], hi[2]}) + "}";
        comma(meshes);
        meshes += "{\"name\":" + quoted(scene.objects[o].name) +
                  ",\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(meshCount) +
                  "},\"material\":" + std::to_string(scene.objects[o].material) + "}]}";
        comma(sceneNodes);
        sceneNodes += std::to_string(meshCount);
        comma(nodes);
        nodes +=
            "{\"name\":" + quoted(scene.objects[o].name) + ",\"mesh\":" + std::to_string(meshCount) + "}";
        ++meshCount;
    }

    std::string materials;
    bool emissiveStrength = false;
    for (const scene::MaterialDesc& m : scene.materials) {
        const float peak = std::max({m.emissive[0], m.emissive[1], m.emissive[2], 1.0f});
        comma(materials);
        materials += "{\"name\":" + quoted(m.name) + ",\"pbrMetallicRoughness\":{\"baseColorFactor\":" +
                     list({m.baseColor[0], m.baseColor[1], m.baseColor[2], 1.0}) +
                     ",\"metallicFactor\":" + number(m.metallic) +
                     ",\"roughnessFactor\":" + number(m.roughness) + "},\"emissiveFactor\":" +
                     list({m.emissive[0] / peak, m.emissive[1] / peak, m.emissive[2] / peak});
        if (peak > 1.0f) {
            materials +=
                ",\"extensions\":{\"KHR_materials_emissive_strength\":{\"emissiveStrength\":" + number(peak) +
                "}}";
            emissiveStrength = true;
        }
        materials += "}";
    }

    std::string lights;
    const std::vector<scene::LightDesc> frameLights = scene::lightsAt(scene, frame);
    for (std::size_t i = 0; i < frameLights.size(); ++i) {
        const scene::LightDesc& l = frameLights[i];
        const bool directional = l.kind == scene::LightKind::Directional;
        comma(lights);
        lights += std::string("{\"type\":\"") + (directional ? "directional" : "point") +
                  "\",\"color\":" + list({l.color[0], l.color[1], l.color[2]}) +
                  ",\"intensity\":" + number(l.intensity) + "}";
        const std::string name = quoted("light " + std::to_string(i));
        std::string node = "{\"name\":" + name +
                           ",\"extensions\":{\"KHR_lights_punctual\":{\"light\":" + std::to_string(i) + "}}";
        if (directional) {
            // Columns x, y, z of an orthonormal frame with z toward the light: the light
            // travels along the node's -z.
            const double z[3] = {l.direction[0], l.direction[1], l.direction[2]};
            const double up[3] = {std::abs(z[1]) < 0.99 ? 0.0 : 1.0, std::abs(z[1]) < 0.99 ? 1.0 : 0.0, 0.0};
            double x[3] = {up[1] * z[2] - up[2] * z[1], up[2] * z[0] - up[0] * z[2],
                           up[0] * z[1] - up[1] * z[0]};
            const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
            for (double& c : x) c /= n;
            const double y[3] = {z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2],
                                 z[0] * x[1] - z[1] * x[0]};
            node += ",\"matrix\":" +
                    list({x[0], x[1], x[2], 0, y[0], y[1], y[2], 0, z[0], z[1], z[2], 0, 0, 0, 0, 1});
        } else {
            node += ",\"translation\":" + list({l.position[0], l.position[1], l.position[2]});
        }
        node += "}";
        comma(sceneNodes);
        sceneNodes += std::to_string(meshCount + i);
        comma(nodes);
        nodes += node;
    }

    std::string used = "\"KHR_lights_punctual\"";
    if (emissiveStrength) used += ",\"KHR_materials_emissive_strength\"";
    std::string out = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"glint tests (scene_gltf_export)\"},";
    out += "\"extensionsUsed\":[" + used + "],";
    out += "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[" + lights + "]}},";
    out += "\"scene\":0,\"scenes\":[{\"nodes\":[" + sceneNodes + "]}],\n";
    out += "\"nodes\":[" + nodes + "],\n";
    out += "\"meshes\":[" + meshes + "],\n";
    out += "\"materials\":[" + materials + "],\n";
    out += "\"accessors\":[" + accessors + "],\n";
    out += "\"bufferViews\":[" + views + "],\n";
    out += "\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) +
           ",\"uri\":\"data:application/octet-stream;base64," + base64(bin) + "\"}]}\n";
    return out;
}

} // namespace glint::test
