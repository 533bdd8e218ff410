// Scene reader (host): blocks → Scene through the block tables; names resolved in file order; the files a
// scene names (.obj, .csg, images) read relative to the scene's folder.
#include "scene/scene_reader.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "io/text_file.h"
#include "scene/block_lexer.h"
#include "scene/block_table.h"
#include "scene/csg_reader.h"
#include "scene/environment_reader.h"
#include "scene/obj_reader.h"
#include "scene/param_format.h"
#include "scene/source_file.h"
#include "scene/texture_reader.h"
#include "scene/transform_checks.h"

namespace trazo {
namespace {


// Where a texture or material name is first declared: used to tell "declared later" from "never declared".
struct Declaration {
    int line = 0;
    size_t block = 0;
};
using Declarations = std::map<std::string, Declaration>;

class SceneReader {
public:
    SceneReader(const std::string& file, Diagnostics& diags) : file_(file), diags_(diags) { scene_.path = file; }

    Scene read(const std::string& text) {
        const std::vector<Block> blocks = lexBlocks(text, file_, diags_);
        collectDeclarations(blocks);
        for (size_t i = 0; i < blocks.size(); ++i) readBlock(blocks[i], i);
        return std::move(scene_);
    }

private:
    void collectDeclarations(const std::vector<Block>& blocks) {
        for (size_t i = 0; i < blocks.size(); ++i) {
            Declarations* declared = blocks[i].identifier == "Texture"    ? &declaredTextures_
                                     : blocks[i].identifier == "Material" ? &declaredMaterials_
                                                                          : nullptr;
            if (!declared) continue;
            const ParameterLine* name = nullptr;  // the last Name line wins, as it will when the block is read
            for (const ParameterLine& line : blocks[i].parameters) {
                if (line.name == "Name" && line.values.size() == 1) name = &line;
            }
            if (name) declared->emplace(name->values[0].text, Declaration{name->line, i});
        }
    }

    void readBlock(const Block& block, size_t index) {
        const std::string& id = block.identifier;
        if (id.empty()) return;  // a nameless '{', already reported
#define TRAZO_X(Shape, array, Kind, keyword) \
    if (id == keyword) return readObjectBlock(block, index, scene_.array);
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, Kind, keyword, ...) \
    if (id == keyword) return readLightBlock(block, scene_.array);
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
        if (id == "SceneSettings") {
            SceneSettings settings;  // like Camera, the last block wins as a whole
            readParameters(block, sceneSettingsTable(), settings, diags_);
            settings.where = block.where;
            if (!settings.environmentMap.empty()) {
                settings.environmentMap = resolveRelativePath(file_, settings.environmentMap);
                settings.environmentImage = readEnvironmentMap(settings.environmentMap, settings.environmentMapAt, diags_);
            }
            scene_.settings = settings;
        } else if (id == "Camera") {
            readCamera(block);
        } else if (id == "Texture") {
            readTexture(block, index);
        } else if (id == "Material") {
            readMaterial(block, index);
        } else {
            diags_.error(block.where, "unknown block '" + id + "'", didYouMean(id, blockNames(sceneBlocks())));
        }
    }

    template <class Light>
    void readLightBlock(const Block& block, std::vector<Light>& lights) {
        Light light;
        readParameters(block, lightTable<Light>(), light, diags_);
        light.where = block.where;
        lights.push_back(light);
    }

    void readCamera(const Block& block) {
        Camera camera;  // the last Camera block wins (SPEC §3), each starting from the defaults
        readParameters(block, cameraTable(), camera, diags_);
        if (lengthSquared(camera.poi - camera.pov) == 0.0f) {
            diags_.error(block.where, "POV and POI coincide (the view direction has zero length)");
        }
        scene_.camera = camera;
    }

    bool checkUnique(const std::string& what, const std::string& name, const SourceLocation& at,
                     const Declarations& declared, size_t index) {
        const auto it = declared.find(name);
        if (it != declared.end() && it->second.block != index) {
            diags_.error(at, what + " '" + name + "' is already declared at line " + std::to_string(it->second.line));
            return false;
        }
        return true;
    }

    // The index of a declared texture or material; -1 (after reporting, unless already reported) otherwise.
    int32_t resolve(const NameRef& ref, const std::string& what, const std::map<std::string, int32_t>& done,
                    const Declarations& declared, size_t index) {
        if (const auto it = done.find(ref.name); it != done.end()) return it->second;
        const auto it = declared.find(ref.name);
        if (it == declared.end()) {
            std::vector<std::string_view> names;
            for (const auto& [name, unused] : declared) names.push_back(name);
            diags_.error(ref.at, "unknown " + what + " '" + ref.name + "'", didYouMean(ref.name, names));
        } else if (it->second.block > index) {
            diags_.error(ref.at, what + " '" + ref.name + "' is used before it is declared (at line " +
                                     std::to_string(it->second.line) + ")");
        }
        // Otherwise it was declared earlier but its block failed (an unreadable image): already reported.
        return -1;
    }

    void readTexture(const Block& block, size_t index) {
        TextureDraft d;
        readParameters(block, textureTable(), d, diags_);
        Texture& t = d.texture;
        if (t.name.empty() || t.source.empty()) return;  // reported (missing, empty, or on a refused line)
        if (!checkUnique("texture", t.name, d.nameAt, declaredTextures_, index)) return;
        t.source = resolveRelativePath(file_, t.source);
        t.image = readTextureImage(t.source, d.sourceAt, diags_);
        if (!t.image) return;
        t.where = block.where;
        textures_[t.name] = int32_t(scene_.textures.size());
        scene_.textures.push_back(std::move(t));
    }

    // SPEC §6: where the material scatters below its surface, DiffuseColor is the walk's albedo, at most 1 (a
    // larger one grows without bound over the walk's 256 scatterings). Reported at the DiffuseColor line.
    void checkScatteringAlbedo(const Block& block, const Material& m) {
        if (maxComponent(m.scatteringDistance) <= 0.0f || maxComponent(m.diffuseColor) <= 1.0f) return;
        SourceLocation at = block.where;
        for (const ParameterLine& p : block.parameters)
            if (p.name == "DiffuseColor") at.line = p.line, at.column = p.column;
        diags_.error(at, "DiffuseColor components must be at most 1 where ScatteringDistance is not 0 (it is the "
                         "subsurface walk's albedo), got " + formatReal(m.diffuseColor.x) + " " +
                         formatReal(m.diffuseColor.y) + " " + formatReal(m.diffuseColor.z));
    }

    void readMaterial(const Block& block, size_t index) {
        MaterialDraft d;
        readParameters(block, materialTable(), d, diags_);
        Material& m = d.material;
        if (m.name.empty()) return;  // reported as missing
        if (!checkUnique("material", m.name, d.nameAt, declaredMaterials_, index)) return;
        checkScatteringAlbedo(block, m);
        for (size_t s = 0; s < textureSlots().size(); ++s) {
            if (!d.textures[s].name.empty()) {
                m.textures[s] = resolve(d.textures[s], "texture", textures_, declaredTextures_, index);
            }
        }
        m.where = block.where;
        materials_[m.name] = int32_t(scene_.materials.size());
        scene_.materials.push_back(std::move(m));
    }

    template <class T>
    ObjectDraft<T> readObject(const Block& block, size_t index, std::span<const ParamSpec<ObjectDraft<T>>> table) {
        ObjectDraft<T> d;
        readParameters(block, table, d, diags_);
        d.object.where = block.where;
        if (d.material.name.empty()) {
            diags_.warning(block.where, block.identifier + " has no Material; using the default material");
        } else {
            d.object.material = resolve(d.material, "material", materials_, declaredMaterials_, index);
        }
        return d;
    }

    // The transform checks (scene/transform_checks.h) as errors at the block's line.
    bool checkInvertible(const std::vector<TransformStep>& steps, const Block& block) {
        const std::string problem = invertibleProblem(steps);
        if (!problem.empty()) diags_.error(block.where, block.identifier + ": " + problem);
        return problem.empty();
    }

    void checkBoxNormals(const std::vector<TransformStep>& steps, const Block& block) {
        const std::string problem = boxNormalsProblem(steps);
        if (!problem.empty()) diags_.error(block.where, block.identifier + ": " + problem);
    }

    void checkMeshExtent(const Mesh& mesh, const Block& block) {
        const std::string problem = meshExtentProblem(*mesh.data, mesh.transforms);
        if (!problem.empty()) diags_.error(block.where, block.identifier + ": '" + mesh.source + "' " + problem);
    }

    // An object kind's block: its table's parameters, then what the kind checks or loads beyond them.
    template <class T>
    void readObjectBlock(const Block& block, size_t index, std::vector<T>& objects) {
        ObjectDraft<T> d = readObject(block, index, objectTable<T>());
        finishObject(d, block);
        objects.push_back(std::move(d.object));
    }

    template <class T>
    void finishObject(ObjectDraft<T>&, const Block&) {}

    void finishObject(ObjectDraft<Box>& d, const Block& block) {
        if (checkInvertible(d.object.transforms, block)) checkBoxNormals(d.object.transforms, block);
    }

    void finishObject(ObjectDraft<Mesh>& d, const Block& block) {
        Mesh& mesh = d.object;
        const bool invertible = checkInvertible(mesh.transforms, block);
        if (!mesh.source.empty()) {
            mesh.source = resolveRelativePath(file_, mesh.source);
            mesh.data = loadNamedFile(mesh.source, d.sourceAt, meshes_, readObjText, kMaxTextFileBytes);
        }
        if (mesh.data && invertible) checkMeshExtent(mesh, block);
    }

    void finishObject(ObjectDraft<Csg>& d, const Block& block) {
        Csg& csg = d.object;
        checkInvertible(csg.transforms, block);
        if (!csg.source.empty()) {
            csg.source = resolveRelativePath(file_, csg.source);
            csg.tree = loadNamedFile(csg.source, d.sourceAt, csgTrees_, readCsgText, kMaxSceneFileBytes);
        }
    }

    // Reads a file named by a Source line once per scene; an unreadable file (not a regular file, or over
    // `maxBytes`) is reported at that line.
    template <class Data, class Reader>
    std::shared_ptr<const Data> loadNamedFile(const std::string& path, const SourceLocation& namedAt,
                                              std::map<std::string, std::shared_ptr<const Data>>& cache,
                                              Reader reader, size_t maxBytes) {
        if (const auto it = cache.find(path); it != cache.end()) return it->second;
        std::string text, reason;
        if (!readWholeFile(path, text, reason, maxBytes)) {
            diags_.error(namedAt, "cannot read '" + path + "': " + reason);
            return nullptr;
        }
        const size_t before = diags_.items.size();
        std::shared_ptr<const Data> data = reader(text, path, diags_);
        // The file's own errors name its lines; the scene line that named the file follows them.
        bool failed = false;
        for (size_t i = before; i < diags_.items.size(); ++i) failed |= diags_.items[i].severity == Severity::Error;
        if (failed) diags_.error(namedAt, "'" + path + "' (named here) has the errors above");
        if (data) cache[path] = data;
        return data;
    }

    const std::string& file_;
    Diagnostics& diags_;
    Scene scene_;
    Declarations declaredTextures_, declaredMaterials_;
    std::map<std::string, int32_t> textures_, materials_;  // read so far
    std::map<std::string, std::shared_ptr<const MeshData>> meshes_;
    std::map<std::string, std::shared_ptr<const CsgTree>> csgTrees_;
};

}  // namespace

Scene readSceneText(const std::string& text, const std::string& pathForMessages, Diagnostics& diags) {
    return SceneReader(pathForMessages, diags).read(text);
}

Scene readSceneFile(const std::string& path, Diagnostics& diags) {
    const std::optional<std::string> text = readSourceFile(path, "scene", kMaxSceneFileBytes, diags);
    if (text) return readSceneText(*text, path, diags);
    Scene scene;
    scene.path = path;
    return scene;
}

}  // namespace trazo
