// Model files through assimp (Debian's libassimp-dev): glTF 2.0 and whatever else it reads.
// Only positions are used: the object's scene material shades the whole model, and shading
// uses the geometric normal (docs/scenes.md).
#include "scene/scene_file.h"
#include "scene/scene_geometry.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace glint::scene {

std::vector<Mesh> loadMeshes(const Scene& scene) {
    std::vector<Mesh> meshes;
    for (const ObjectDesc& object : scene.objects) {
        if (object.shape != ShapeKind::Mesh) continue;
        Assimp::Importer importer;
        // PreTransformVertices bakes every node's transform into world-of-the-model space, so
        // the node hierarchy of the file is honoured without us walking it.
        const aiScene* model =
            importer.ReadFile(object.file.string(),
                              aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType);
        if (!model || (model->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || model->mNumMeshes == 0) {
            std::string problem = importer.GetErrorString();
            if (problem.empty()) problem = "no meshes in the file";
            for (char& c : problem)
                if (c == '\n' || c == '\r') c = ' ';
            throw SceneError(object.file.string() + ": object '" + object.name +
                             "': cannot load model: " + problem);
        }
        Mesh mesh;
        for (unsigned m = 0; m < model->mNumMeshes; ++m) {
            const aiMesh* part = model->mMeshes[m];
            if (!(part->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
                continue; // points and lines have no area
            for (unsigned f = 0; f < part->mNumFaces; ++f) {
                const aiFace& face = part->mFaces[f];
                if (face.mNumIndices != 3) continue;
                for (unsigned k = 0; k < 3; ++k) {
                    const aiVector3D& v = part->mVertices[face.mIndices[k]];
                    mesh.positions.push_back({v.x, v.y, v.z});
                }
            }
        }
        if (mesh.positions.empty())
            throw SceneError(object.file.string() + ": object '" + object.name +
                             "': the model has no triangles");
        meshes.push_back(std::move(mesh));
    }
    return meshes;
}

} // namespace glint::scene
