// Block tables (host): one table of parameter rows per scene and CSG block, as SPEC.md §3–§4 lists them. They
// drive the readers, the scene writer, the viewer's edit widgets, the "did you mean" hints, and a test that
// compares them with SPEC.md. Adding a parameter is one struct field (scene.h) and one row (scene_tables.cpp);
// a Material parameter is one row of shading/material_fields.h's list.
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/did_you_mean.h"
#include "objects/object_kind_list.h"
#include "scene/param_spec.h"
#include "scene/scene.h"

namespace trazo {

// A name given in a block (material, texture, CSG child type), resolved after the block is read.
struct NameRef {
    std::string name;  // empty when not given
    SourceLocation at;
};

struct TextureDraft {
    Texture texture;  // source as written until resolved
    SourceLocation nameAt, sourceAt;
};

// The texture parameters of a Material (shading/material_fields.h TRAZO_TEXTURE_SLOTS), by TextureSlot.
struct TextureSlotInfo {
    std::string_view name, doc;
};
const std::array<TextureSlotInfo, kTextureSlotCount>& textureSlots();

struct MaterialDraft {
    Material material;
    SourceLocation nameAt;
    std::array<NameRef, kTextureSlotCount> textures;  // by TextureSlot
};

template <class T>
struct ObjectDraft {
    T object;
    NameRef material;
    SourceLocation sourceAt;  // Mesh and CSG: the Source line
};

struct CsgNodeDraft {
    CsgNode node;
    NameRef leftType, rightType;
    int leftIndex = -1, rightIndex = -1;
    SourceLocation leftIndexAt, rightIndexAt;
};

// The drafts a read scene's entities come from (the inverse of the reader's name resolution), for writing.
MaterialDraft materialDraft(const Material& material, const std::vector<Texture>& textures);
template <class T>
ObjectDraft<T> objectDraft(const T& object, const std::vector<Material>& materials) {
    ObjectDraft<T> d{object, {}, {}};
    if (object.material >= 0 && size_t(object.material) < materials.size())
        d.material.name = materials[size_t(object.material)].name;
    return d;
}

// Scene blocks (SPEC §3).
std::span<const ParamSpec<SceneSettings>> sceneSettingsTable();
std::span<const ParamSpec<Camera>> cameraTable();
std::span<const ParamSpec<TextureDraft>> textureTable();
std::span<const ParamSpec<MaterialDraft>> materialTable();
// The table of each object kind's block (objects/object_kind_list.h): objectTable<Sphere>(), objectTable<Mesh>(), ...
template <class T>
std::span<const ParamSpec<ObjectDraft<T>>> objectTable();
#define TRAZO_X(Shape, array, Kind, keyword) \
    template <>                              \
    std::span<const ParamSpec<ObjectDraft<Kind>>> objectTable<Kind>();
TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
// The table of each light kind's block (lights/light_kind_list.h): lightTable<PointLight>(), ...
template <class T>
std::span<const ParamSpec<T>> lightTable();
#define TRAZO_X(Data, array, Kind, ...) \
    template <>                         \
    std::span<const ParamSpec<Kind>> lightTable<Kind>();
TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X

// CSG-file blocks (SPEC §4); Union, Difference and Intersection share the operation table.
std::span<const ParamSpec<CsgNodeDraft>> csgSphereTable();
std::span<const ParamSpec<CsgNodeDraft>> csgBoxTable();
std::span<const ParamSpec<CsgNodeDraft>> csgCylinderTable();
std::span<const ParamSpec<CsgNodeDraft>> csgOperationTable();

struct BlockInfo {
    std::string_view name;
    std::vector<ParamInfo> params;
};

const std::vector<BlockInfo>& sceneBlocks();  // in SPEC §3 order
const std::vector<BlockInfo>& csgBlocks();    // Sphere, Box, Cylinder, Union, Difference, Intersection

std::vector<std::string_view> blockNames(const std::vector<BlockInfo>& blocks);

}  // namespace trazo
