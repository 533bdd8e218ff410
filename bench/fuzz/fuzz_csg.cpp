// libFuzzer harness: .csg text → readCsgText; a tree that reads is placed in a small scene (fuzz::stageScene)
// and flattened and rendered for one 8 × 8 pass, so the CSG kernels' fixed-size stacks see it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "scene/csg_reader.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace trazo;
    if (size > fuzz::kMaxInputBytes) return 0;
    const std::string text(reinterpret_cast<const char*>(data), size);
    Diagnostics diags;
    std::shared_ptr<const CsgTree> tree = readCsgText(text, fuzz::sceneRoot() + "/fuzz.csg", diags);
    if (!fuzz::keptReadContract(tree != nullptr, diags, "readCsgText", "a tree")) return 0;
    if (tree->nodes.empty() || tree->nodes.size() > size_t(kMaxCsgNodes) || tree->root < 0 ||
        size_t(tree->root) >= tree->nodes.size())
        fuzz::fail("readCsgText returned a tree without a valid root or over kMaxCsgNodes nodes");

    Csg csg;
    csg.source = fuzz::sceneRoot() + "/fuzz.csg";
    csg.tree = tree;
    fuzz::renderTinyWith(fuzz::stageScene(), &Scene::csgs, csg);
    return 0;
}
