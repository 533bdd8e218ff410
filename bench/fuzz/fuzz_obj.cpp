// libFuzzer harness: OBJ text → readObjText; a mesh that reads must keep the OBJ mesh contract
// (objMeshContractViolation, obj_reader.h), and is then placed in a small scene, flattened (prepareMesh,
// the BVH) and rendered for one 8 × 8 pass.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "scene/obj_reader.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace trazo;
    if (size > fuzz::kMaxInputBytes) return 0;
    const std::string text(reinterpret_cast<const char*>(data), size);
    Diagnostics diags;
    std::shared_ptr<const MeshData> mesh = readObjText(text, fuzz::sceneRoot() + "/fuzz.obj", diags);
    if (!fuzz::keptReadContract(mesh != nullptr, diags, "readObjText", "a mesh")) return 0;
    const std::string broken = objMeshContractViolation(*mesh);
    if (!broken.empty()) fuzz::fail("readObjText returned a mesh that breaks the OBJ mesh contract: " + broken);

    Mesh object;
    object.source = fuzz::sceneRoot() + "/fuzz.obj";
    object.data = mesh;
    fuzz::renderTinyWith(fuzz::stageScene(), &Scene::meshes, object);
    return 0;
}
