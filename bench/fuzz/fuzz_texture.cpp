// libFuzzer harness: bytes → a private temp file → readTextureImage (signature, bounded header, FreeImage).
// The file is named *.tga, so every format is reachable: the signed ones by their signature, TGA by name.
// A texture that decodes must be as large as it says, and is then the diffuse and normal texture of a
// textured quad rendered for one 8 × 8 pass (texel lookups at every size, 1 × N included).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "fuzz_support.h"
#include "scene/scene.h"
#include "scene/texture_header.h"
#include "scene/texture_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace trazo;
    if (size > fuzz::kMaxInputBytes) return 0;
    static const std::string path = fuzz::privateTempPath(".tga");
    fuzz::writeFileOrDie(path, data, size);
    Diagnostics diags;
    const SourceLocation where{"fuzz.scene", 1, 0};
    std::shared_ptr<const TextureImage> image = readTextureImage(path, where, diags);
    if (!fuzz::keptReadContract(image != nullptr, diags, "readTextureImage", "an image")) return 0;
    if (image->width <= 0 || image->height <= 0 ||
        uint64_t(image->width) * uint64_t(image->height) > kMaxTextureTexels ||
        image->texels.size() != size_t(image->width) * size_t(image->height))
        fuzz::fail("readTextureImage returned an image whose size and texels disagree");

    Scene scene = fuzz::stageScene();
    Texture texture;
    texture.name = "fuzzed";
    texture.source = path;
    texture.image = image;
    scene.textures.push_back(texture);
    scene.materials[0].textures[kDiffuseTexture] = 0;
    scene.materials[0].textures[kNormalTexture] = 0;
    auto quad = std::make_shared<MeshData>();
    quad->positions = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
    quad->normals = {Vec3(0, 0, 1)};
    quad->uvs = {0, 0, 1, 0, 1, 1, 0, 1};
    quad->corners = {{0, 0, 0}, {1, 0, 1}, {2, 0, 2}, {0, 0, 0}, {2, 0, 2}, {3, 0, 3}};
    quad->hasNormals = quad->hasUvs = true;
    Mesh mesh;
    mesh.source = fuzz::sceneRoot() + "/quad.obj";
    mesh.data = quad;
    fuzz::renderTinyWith(std::move(scene), &Scene::meshes, mesh);
    return 0;
}
