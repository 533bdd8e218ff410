// Scene writer (host): every block through its table's rows (scene/block_table.h), in the order the reader
// needs (textures, then materials, then the objects that name them).
#include "scene/scene_writer.h"

#include <algorithm>

#include "io/text_file.h"
#include "scene/block_table.h"

namespace trazo {
namespace {

// One block: each row's lines in table order; the steps of the accumulating (transform) rows together, in
// their written order, where the first of those rows stands.
template <class Target>
void writeBlock(std::string& out, std::string_view block, std::span<const ParamSpec<Target>> table,
                const Target& target, const std::string& scenePath) {
    out += "\n";
    out += block;
    out += "\n{\n";
    auto line = [&](const ParamInfo& info, const ParamValue& v) {
        out += "    ";
        out += info.name;
        out += ' ';
        out += formatValues(info, v, scenePath);
        out += '\n';
    };
    bool stepsWritten = false;
    for (const ParamSpec<Target>& row : table) {
        std::vector<ParamValue> values;
        if (!row.info.accumulates) {
            row.extract(target, values);
            for (const ParamValue& v : values) line(row.info, v);
            continue;
        }
        if (stepsWritten) continue;
        std::vector<std::pair<const ParamInfo*, ParamValue>> steps;
        for (const ParamSpec<Target>& other : table) {
            if (!other.info.accumulates) continue;
            values.clear();
            other.extract(target, values);
            for (const ParamValue& v : values) steps.emplace_back(&other.info, v);
        }
        std::sort(steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.second.step < b.second.step; });
        for (const auto& [info, v] : steps) line(*info, v);
        stepsWritten = true;
    }
    out += "}\n";
}

template <class T>
void writeObjects(std::string& out, std::string_view block, std::span<const ParamSpec<ObjectDraft<T>>> table,
                  const std::vector<T>& objects, const Scene& scene, const std::string& scenePath) {
    for (const T& object : objects) writeBlock(out, block, table, objectDraft(object, scene.materials), scenePath);
}

}  // namespace

std::string formatScene(const Scene& scene, const std::string& scenePath) {
    std::string out = "# Written by trazo's scene writer (SPEC.md); angles in Rotation are radians.\n";
    writeBlock(out, "SceneSettings", sceneSettingsTable(), scene.settings, scenePath);
    writeBlock(out, "Camera", cameraTable(), scene.camera, scenePath);
    for (const Texture& t : scene.textures) writeBlock(out, "Texture", textureTable(), TextureDraft{t, {}, {}}, scenePath);
    for (const Material& m : scene.materials)
        writeBlock(out, "Material", materialTable(), materialDraft(m, scene.textures), scenePath);
#define TRAZO_X(Shape, array, Kind, keyword) \
    writeObjects(out, keyword, objectTable<Kind>(), scene.array, scene, scenePath);
    TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, Kind, keyword, ...) \
    for (const Kind& l : scene.array) writeBlock(out, keyword, lightTable<Kind>(), l, scenePath);
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    return out;
}

bool writeSceneFile(const Scene& scene, const std::string& path, std::string& error) {
    return writeTextFileAtomically(path, formatScene(scene, path), error);
}

}  // namespace trazo
