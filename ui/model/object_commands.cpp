// Object commands: scene_edit's operations with the selection kept valid and the undo labels named.
#include "model/object_commands.h"

namespace trazo {
namespace {

// "Verb Kind index": named after the block (the label outlives the object's material).
std::string labelFor(const char* verb, ObjectId id) {
    return std::string(verb) + " " + kindKeyword(id.kind) + " " + std::to_string(id.index);
}

}  // namespace

Selection validSelection(const Scene& scene, Selection selection) {
    return selection && isValidObject(scene, *selection) ? selection : std::nullopt;
}

ObjectEdit addAndSelect(Scene& scene, Selection& selection, ObjectId::Kind kind, Vec3 at) {
    if (kind == ObjectId::Kind::Mesh || kind == ObjectId::Kind::Csg) return {};
    selection = addObject(scene, kind, at, newObjectSize(scene.camera));
    return {kDirtyScene, labelFor("Add", *selection)};
}

ObjectEdit addFileAndSelect(Scene& scene, Selection& selection, ObjectId::Kind kind, const std::string& path,
                            Vec3 at, Diagnostics& diags) {
    const std::optional<ObjectId> id = addObjectFromFile(scene, kind, path, at, diags);
    if (!id) return {};
    selection = id;
    return {kDirtyScene, labelFor("Add", *id)};
}

ObjectEdit duplicateSelected(Scene& scene, Selection& selection) {
    if (!validSelection(scene, selection)) return {};
    const ObjectId original = *selection;
    selection = duplicateObject(scene, original);
    return {kDirtyScene, labelFor("Duplicate", original)};
}

ObjectEdit deleteSelected(Scene& scene, Selection& selection) {
    if (!validSelection(scene, selection)) return {};
    const ObjectId deleted = *selection;
    selection = deleteObject(scene, deleted);
    return {kDirtyScene, labelFor("Delete", deleted)};
}

ObjectEdit moveSelected(Scene& scene, Selection selection, Vec3 delta) {
    if (!validSelection(scene, selection) || (delta.x == 0 && delta.y == 0 && delta.z == 0)) return {};
    translateObject(scene, *selection, delta);
    return {kDirtyScene, labelFor("Move", *selection)};
}

}  // namespace trazo
