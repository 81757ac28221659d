// Model files through assimp (Debian's libassimp-dev): glTF 2.0 and whatever else it reads.
// Only positions are used, with flat (geometric) normals (docs/scenes.md). A scene file's mesh
// object shades the whole model with its own material; a geometry file (loadGeometryScene,
// glint run --geometry) becomes one object per material of the file, with the file's materials
// and punctual lights.
#include "scene/scene_file.h"
#include "scene/scene_geometry.h"

#include "capture/json_text.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>

namespace glint::scene {
namespace {

std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

std::uint32_t le32(const unsigned char* p) {
    return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
           std::uint32_t{p[3]} << 24;
}

// A binary glTF's container, checked before assimp reads it: assimp 5.2.5 trusts the header's
// lengths (it allocates a chunk's length before comparing it with the file, and reads past a
// short header; tests/fuzz/third_party_crashes/). Empty when the file is not binary glTF or
// its container is sound, else what is wrong.
std::string glbProblem(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    unsigned char header[12] = {};
    in.read(reinterpret_cast<char*>(header), 4);
    if (in.gcount() < 4 || std::memcmp(header, "glTF", 4) != 0) return {};
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec || size < 12) return "binary glTF shorter than its 12-byte header";
    in.read(reinterpret_cast<char*>(header + 4), 8);
    const std::uint32_t version = le32(header + 4), length = le32(header + 8);
    if (version != 1 && version != 2)
        return "binary glTF version " + std::to_string(version) + " (expected 2)";
    if (length != size)
        return "binary glTF header gives a length of " + std::to_string(length) + " bytes, the file has " +
               std::to_string(size);
    // Version 1 (KHR_binary_glTF): content length and format follow; version 2: chunks.
    std::uint64_t at = 12;
    for (int chunk = 0; at < size; ++chunk) {
        unsigned char head[8] = {};
        in.seekg(static_cast<std::streamoff>(at));
        in.read(reinterpret_cast<char*>(head), 8);
        if (in.gcount() < 8 || size - at < 8)
            return "binary glTF chunk " + std::to_string(chunk) + " is cut off";
        const std::uint64_t chunkLength = le32(head);
        if (chunkLength > size - at - 8)
            return "binary glTF chunk " + std::to_string(chunk) + " claims " + std::to_string(chunkLength) +
                   " bytes, " + std::to_string(size - at - 8) + " are left";
        if (version == 1) break;
        if (chunk == 0 && std::memcmp(head + 4, "JSON", 4) != 0)
            return "binary glTF's first chunk is not JSON";
        at += 8 + chunkLength;
    }
    return {};
}

// The JSON of a glTF 2.0 file (a .gltf, or a .glb's JSON chunk, whose container glbProblem
// has checked), or null for other formats. JSON that does not parse throws the problem with
// its line and column (assimp would only say that no reader takes the file).
nlohmann::json gltfJson(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string text;
    unsigned char header[20] = {};
    in.read(reinterpret_cast<char*>(header), 20);
    std::string what = "malformed glTF JSON";
    if (in.gcount() == 20 && std::memcmp(header, "glTF", 4) == 0 && le32(header + 4) == 2 &&
        std::memcmp(header + 16, "JSON", 4) == 0) {
        text.resize(le32(header + 12));
        in.read(text.data(), static_cast<std::streamsize>(text.size()));
        what = "malformed JSON chunk";
    } else {
        std::string extension = file.extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (extension != ".gltf") return nullptr;
        in.clear();
        in.seekg(0);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        throw SceneError(what + ": " + capture::jsonProblem(error, text));
    }
}

// KHR_materials_emissive_strength, which assimp 5.2.5 does not import: per material of the
// glTF that has it, its name, emissive factor and strength.
struct EmissiveStrength {
    std::string name;
    Vec3 factor{0.0f, 0.0f, 0.0f};
    float strength = 1.0f;
};

std::vector<EmissiveStrength> emissiveStrengths(const nlohmann::json& json) {
    std::vector<EmissiveStrength> out;
    if (!json.is_object() || !json.contains("materials") || !json["materials"].is_array()) return out;
    for (const nlohmann::json& material : json["materials"]) {
        if (!material.is_object()) continue;
        const nlohmann::json* strength = nullptr;
        if (auto e = material.find("extensions"); e != material.end() && e->is_object())
            if (auto k = e->find("KHR_materials_emissive_strength"); k != e->end() && k->is_object())
                if (auto v = k->find("emissiveStrength"); v != k->end() && v->is_number()) strength = &*v;
        if (!strength) continue;
        EmissiveStrength entry;
        entry.strength = strength->get<float>();
        if (auto n = material.find("name"); n != material.end() && n->is_string())
            entry.name = n->get<std::string>();
        if (auto f = material.find("emissiveFactor"); f != material.end() && f->is_array() && f->size() == 3)
            for (std::size_t c = 0; c < 3; ++c)
                if ((*f)[c].is_number()) entry.factor[c] = (*f)[c].get<float>();
        out.push_back(entry);
    }
    return out;
}

// A model imported as loadMeshes always has: triangulated, every node's transform baked into
// the vertices (the file's world space), sorted by primitive type. The lights are taken out of
// the scene while the transforms are baked (assimp's step dereferences the node of every light
// and camera, and a light no node uses has none) and their world matrices returned instead.
struct Imported {
    const aiScene* model = nullptr;
    std::vector<aiMatrix4x4> lightWorld; // per light; the light is used by no node when absent
    std::vector<bool> lightPlaced;
};

aiMatrix4x4 worldOf(const aiNode* node) {
    aiMatrix4x4 m;
    for (; node; node = node->mParent) m = node->mTransformation * m;
    return m;
}

// Throws the problem (one line, without the file's name) when the file cannot be read.
Imported importModel(Assimp::Importer& importer, const std::filesystem::path& file) {
    if (const std::string problem = glbProblem(file); !problem.empty()) throw SceneError(problem);
    Imported out;
    const aiScene* model = importer.ReadFile(file.string(), 0);
    if (!model || (model->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || model->mNumMeshes == 0 ||
        !model->mRootNode) {
        std::string problem = oneLine(importer.GetErrorString());
        if (problem.empty()) problem = "no meshes in the file";
        throw SceneError(problem);
    }
    auto* scene = const_cast<aiScene*>(model);
    for (unsigned i = 0; i < scene->mNumLights; ++i) {
        const aiNode* node = scene->mRootNode->FindNode(scene->mLights[i]->mName);
        out.lightPlaced.push_back(node != nullptr);
        out.lightWorld.push_back(node ? worldOf(node) : aiMatrix4x4());
    }
    aiLight** lights = scene->mLights;
    aiCamera** cameras = scene->mCameras;
    const unsigned lightCount = scene->mNumLights, cameraCount = scene->mNumCameras;
    scene->mLights = nullptr;
    scene->mCameras = nullptr;
    scene->mNumLights = scene->mNumCameras = 0;
    model = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                         aiProcess_SortByPType);
    if (!model) { // assimp deleted the scene, which no longer held these
        for (unsigned i = 0; i < lightCount; ++i) delete lights[i];
        for (unsigned i = 0; i < cameraCount; ++i) delete cameras[i];
        delete[] lights;
        delete[] cameras;
        std::string problem = oneLine(importer.GetErrorString());
        throw SceneError(problem.empty() ? "no meshes in the file" : problem);
    }
    scene = const_cast<aiScene*>(model);
    scene->mLights = lights;
    scene->mCameras = cameras;
    scene->mNumLights = lightCount;
    scene->mNumCameras = cameraCount;
    out.model = model;
    return out;
}

// The triangles of one imported part (an aiMesh: one material after the pre-transform).
void appendTriangles(const aiMesh* part, std::vector<Vec3>& positions) {
    if (!(part->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return; // points and lines have no area
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
        const aiFace& face = part->mFaces[f];
        if (face.mNumIndices != 3) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const aiVector3D& v = part->mVertices[face.mIndices[k]];
            positions.push_back({v.x, v.y, v.z});
        }
    }
}

// A file's triangles by the material the file gives them.
struct ModelTriangles {
    std::map<std::uint32_t, std::vector<Vec3>> byMaterial;
};

ModelTriangles trianglesOf(const aiScene* model) {
    ModelTriangles out;
    for (unsigned m = 0; m < model->mNumMeshes; ++m) {
        const aiMesh* part = model->mMeshes[m];
        std::vector<Vec3> positions;
        appendTriangles(part, positions);
        if (positions.empty()) continue;
        std::vector<Vec3>& into = out.byMaterial[part->mMaterialIndex];
        into.insert(into.end(), positions.begin(), positions.end());
    }
    return out;
}

Vec3 vec3(const aiColor3D& c) {
    return {c.r, c.g, c.b};
}

bool finite(const Vec3& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

MaterialDesc materialOf(const aiMaterial& material, std::uint32_t index,
                        const std::vector<EmissiveStrength>& strengths, std::vector<std::string>* warnings) {
    MaterialDesc m;
    aiString name;
    const bool named = material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0;
    m.name = named ? name.C_Str() : "material " + std::to_string(index);
    aiColor4D base;
    aiColor3D colour;
    if (material.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS)
        m.baseColor = {base.r, base.g, base.b};
    else if (material.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
        m.baseColor = vec3(colour);
    float value = 0.0f;
    if (material.Get(AI_MATKEY_METALLIC_FACTOR, value) == AI_SUCCESS) m.metallic = value;
    if (material.Get(AI_MATKEY_ROUGHNESS_FACTOR, value) == AI_SUCCESS) m.roughness = value;
    if (material.Get(AI_MATKEY_COLOR_EMISSIVE, colour) == AI_SUCCESS) m.emissive = vec3(colour);
    if (material.Get(AI_MATKEY_EMISSIVE_INTENSITY, value) == AI_SUCCESS) {
        for (float& c : m.emissive) c *= value;
    } else if (!strengths.empty()) {
        // assimp keeps neither the glTF material's index nor the extension: the file's
        // material with this name and emissive factor gives the strength.
        std::optional<float> strength;
        bool ambiguous = false;
        for (const EmissiveStrength& s : strengths) {
            if (s.name != (named ? m.name : std::string()) || s.factor != m.emissive) continue;
            ambiguous = ambiguous || (strength && *strength != s.strength);
            strength = s.strength;
        }
        if (ambiguous && warnings)
            warnings->push_back("material '" + m.name +
                                "': several of the file's materials of that name and emissive factor have "
                                "different emissive strengths; none applied");
        else if (strength)
            for (float& c : m.emissive) c *= *strength;
    }
    // What the shading can use: colours non-negative and finite, factors in 0..1.
    for (Vec3* v : {&m.baseColor, &m.emissive}) {
        if (!finite(*v)) *v = {0.0f, 0.0f, 0.0f};
        for (float& c : *v) c = std::max(c, 0.0f);
    }
    m.metallic = std::isfinite(m.metallic) ? std::clamp(m.metallic, 0.0f, 1.0f) : 0.0f;
    m.roughness = std::isfinite(m.roughness) ? std::clamp(m.roughness, 0.0f, 1.0f) : 1.0f;
    return m;
}

// A unit vector as it is (so that a direction written from a scene file reads back bit for
// bit), anything else divided by its length.
Vec3 normalised(const aiVector3D& v) {
    const double x = static_cast<double>(v.x), y = static_cast<double>(v.y), z = static_cast<double>(v.z);
    const double length = std::sqrt(x * x + y * y + z * z);
    if (std::abs(length - 1.0) <= 4.0 * static_cast<double>(std::numeric_limits<float>::epsilon()))
        return {v.x, v.y, v.z};
    return {static_cast<float>(x / length), static_cast<float>(y / length), static_cast<float>(z / length)};
}

} // namespace

std::vector<Mesh> loadMeshes(const Scene& scene) {
    std::vector<Mesh> meshes;
    std::map<std::filesystem::path, ModelTriangles> files; // each file read once
    for (const ObjectDesc& object : scene.objects) {
        if (object.shape != ShapeKind::Mesh) continue;
        auto found = files.find(object.file);
        if (found == files.end()) {
            Assimp::Importer importer;
            try {
                found =
                    files.emplace(object.file, trianglesOf(importModel(importer, object.file).model)).first;
            } catch (const SceneError& error) {
                throw SceneError(object.file.string() + ": object '" + object.name +
                                 "': cannot load model: " + error.what());
            }
        }
        Mesh mesh;
        for (const auto& [material, positions] : found->second.byMaterial)
            if (object.fileMaterial < 0 || material == static_cast<std::uint32_t>(object.fileMaterial))
                mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
        if (mesh.positions.empty())
            throw SceneError(object.file.string() + ": object '" + object.name +
                             (object.fileMaterial < 0 ? "': the model has no triangles"
                                                      : "': the model has no triangles of material " +
                                                            std::to_string(object.fileMaterial)));
        meshes.push_back(std::move(mesh));
    }
    return meshes;
}

Scene loadGeometryScene(const std::filesystem::path& file, std::vector<std::string>* warnings) {
    const std::string where = file.string() + ": ";
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw SceneError(where + "no such file");
    if (std::filesystem::is_directory(file, ec)) throw SceneError(where + "is a folder, not a model file");
    if (!std::ifstream(file, std::ios::binary)) throw SceneError(where + "cannot be opened for reading");
    Assimp::Importer importer;
    Imported imported;
    std::vector<EmissiveStrength> strengths;
    try {
        if (const std::string problem = glbProblem(file); !problem.empty()) throw SceneError(problem);
        strengths = emissiveStrengths(gltfJson(file));
        imported = importModel(importer, file);
    } catch (const SceneError& error) {
        throw SceneError(where + "cannot read as a model: " + error.what());
    }
    const aiScene* model = imported.model;
    const ModelTriangles triangles = trianglesOf(model);
    if (triangles.byMaterial.empty())
        throw SceneError(where + "no triangles (the file's meshes are points or lines only)");

    Scene scene;
    scene.file = file;
    scene.frameCount = 1;
    scene.effects = {Effect::Hybrid};
    for (const auto& [index, positions] : triangles.byMaterial) {
        ObjectDesc object;
        object.shape = ShapeKind::Mesh;
        object.file = file;
        object.fileMaterial = static_cast<std::int32_t>(index);
        object.material = static_cast<std::uint32_t>(scene.materials.size());
        scene.materials.push_back(index < model->mNumMaterials && model->mMaterials[index]
                                      ? materialOf(*model->mMaterials[index], index, strengths, warnings)
                                      : MaterialDesc{"material " + std::to_string(index)});
        object.name = scene.materials.back().name;
        scene.objects.push_back(object);
    }

    for (unsigned i = 0; i < model->mNumLights; ++i) {
        const aiLight& light = *model->mLights[i];
        const std::string name = light.mName.length > 0 ? light.mName.C_Str() : "light " + std::to_string(i);
        auto warn = [&](const std::string& text) {
            if (warnings) warnings->push_back("light '" + name + "' " + text);
        };
        if (!imported.lightPlaced[i]) {
            warn("is used by no node; left out");
            continue;
        }
        const aiMatrix4x4& world = imported.lightWorld[i];
        LightDesc l;
        l.color = vec3(light.mColorDiffuse);
        l.intensity = 1.0f;
        if (!finite(l.color) || std::min({l.color[0], l.color[1], l.color[2]}) < 0.0f) {
            warn("has a negative or non-finite colour; left out");
            continue;
        }
        if (light.mType == aiLightSource_DIRECTIONAL) {
            const aiVector3D travel = aiMatrix3x3(world) * light.mDirection;
            if (!(travel.Length() > 1e-12f) || !std::isfinite(travel.Length())) {
                warn("has no direction; left out");
                continue;
            }
            l.kind = LightKind::Directional;
            l.direction = normalised(-travel); // toward the light
            l.angularRadiusDegrees = 0.0f;
        } else if (light.mType == aiLightSource_POINT || light.mType == aiLightSource_SPOT) {
            const aiVector3D p = world * light.mPosition;
            l.kind = LightKind::Sphere;
            l.position = {p.x, p.y, p.z};
            if (!finite(l.position)) {
                warn("has a non-finite position; left out");
                continue;
            }
            l.radius = 0.0f;
            if (light.mType == aiLightSource_SPOT)
                warn("is a spot light: shaded as a point light, without its cone");
        } else {
            warn(light.mType == aiLightSource_AMBIENT ? "is an ambient light; left out"
                 : light.mType == aiLightSource_AREA  ? "is an area light; left out"
                                                      : "has no type; left out");
            continue;
        }
        scene.lights.push_back(l);
    }
    // Every light is a point or a direction, so one visibility ray per light is exact.
    scene.shadowSamples = 1;
    scene.shadowLight = 0;
    return scene;
}

} // namespace glint::scene
