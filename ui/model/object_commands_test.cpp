// The Objects panel's commands: the selection follows each edit and stays valid, labels name the object, and
// an add → delete → duplicate session committed to the history undoes back to the scene as read.
#include "model/object_commands.h"

#include <gtest/gtest.h>

#include "model/edit_history.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

using Kind = ObjectId::Kind;

Scene seedScene() { return test::readSourceScene("scenes/scene1_area.scene"); }

TEST(ObjectCommands, TheSelectionFollowsEachEdit) {
    Scene scene = seedScene();
    const size_t spheres = scene.spheres.size();
    Selection selection;
    ObjectEdit edit = addAndSelect(scene, selection, Kind::Sphere, Vec3(1, 2, 3));
    EXPECT_EQ(edit.dirty, kDirtyScene);
    EXPECT_EQ(edit.label, "Add Sphere " + std::to_string(spheres));
    ASSERT_EQ(selection, (ObjectId{Kind::Sphere, uint32_t(spheres)}));
    EXPECT_EQ(scene.spheres.back().radius, 0.5f * newObjectSize(scene.camera));

    edit = duplicateSelected(scene, selection);
    EXPECT_EQ(edit.label, "Duplicate Sphere " + std::to_string(spheres));
    EXPECT_EQ(selection, (ObjectId{Kind::Sphere, uint32_t(spheres + 1)}));

    edit = moveSelected(scene, selection, Vec3(0, 1, 0));
    EXPECT_EQ(edit.label, "Move Sphere " + std::to_string(spheres + 1));
    EXPECT_EQ(scene.spheres.back().center.y, 3.0f);
    EXPECT_EQ(moveSelected(scene, selection, Vec3(0, 0, 0)).dirty, kDirtyNone);

    edit = deleteSelected(scene, selection);  // the last sphere: the previous one is selected
    EXPECT_EQ(edit.label, "Delete Sphere " + std::to_string(spheres + 1));
    EXPECT_EQ(selection, (ObjectId{Kind::Sphere, uint32_t(spheres)}));
    EXPECT_EQ(scene.spheres.size(), spheres + 1);

    // Meshes and CSG solids come from files only; nothing selected, nothing to duplicate or delete.
    EXPECT_EQ(addAndSelect(scene, selection, Kind::Mesh, Vec3(0, 0, 0)).dirty, kDirtyNone);
    selection.reset();
    EXPECT_EQ(duplicateSelected(scene, selection).dirty, kDirtyNone);
    EXPECT_EQ(deleteSelected(scene, selection).dirty, kDirtyNone);
    EXPECT_EQ(moveSelected(scene, selection, Vec3(1, 0, 0)).dirty, kDirtyNone);

    Diagnostics diags;
    EXPECT_EQ(addFileAndSelect(scene, selection, Kind::Mesh, "no-such.obj", Vec3(0, 0, 0), diags).dirty, kDirtyNone);
    EXPECT_TRUE(diags.hasErrors());
    EXPECT_EQ(selection, std::nullopt);
    const ObjectEdit csg = addFileAndSelect(scene, selection, Kind::Csg, test::sourcePath("scenes/csg_example.csg"),
                                            Vec3(0, 0, 0), diags);
    EXPECT_EQ(csg.label, "Add CSG 0");
    EXPECT_EQ(selection, (ObjectId{Kind::Csg, 0}));
}

TEST(ObjectCommands, ASelectionAnUndoRemovedIsDropped) {
    Scene scene = seedScene();
    EditHistory history;
    Selection selection;
    const Scene before = scene;
    const ObjectEdit edit = addAndSelect(scene, selection, Kind::PointLight, Vec3(0, 1, 0));
    history.commit(before, edit.label, edit.dirty);
    EXPECT_EQ(validSelection(scene, selection), selection);
    history.undo(scene);
    EXPECT_EQ(validSelection(scene, selection), std::nullopt);
    history.redo(scene);
    EXPECT_EQ(validSelection(scene, selection), selection);
}

TEST(ObjectCommands, AnEditingSessionUndoesToTheSceneAsRead) {
    Scene scene = seedScene();
    const std::string original = formatScene(scene, scene.path);
    EditHistory history;
    Selection selection;
    auto commit = [&](const Scene& before, const ObjectEdit& e) {
        ASSERT_NE(e.dirty, kDirtyNone);
        history.commit(before, e.label, e.dirty);
    };
    for (Kind kind : {Kind::Sphere, Kind::Box, Kind::Cylinder, Kind::AreaLight}) {
        const Scene before = scene;
        commit(before, addAndSelect(scene, selection, kind, Vec3(0.5f, 0.25f, 0)));
    }
    {
        const Scene before = scene;
        selection = ObjectId{Kind::Sphere, 0};
        commit(before, deleteSelected(scene, selection));
    }
    {
        const Scene before = scene;
        commit(before, duplicateSelected(scene, selection));
    }
    // The edited scene saves and reloads as itself.
    const std::string edited = formatScene(scene, scene.path);
    Diagnostics diags;
    const Scene back = readSceneText(edited, scene.path, diags);
    EXPECT_FALSE(diags.hasErrors());
    EXPECT_EQ(formatScene(back, scene.path), edited);
    EXPECT_EQ(history.undoLabel(), "Duplicate Sphere 0");
    while (history.undo(scene)) {}
    EXPECT_EQ(formatScene(scene, scene.path), original);
    EXPECT_FALSE(history.unsaved());
}

}  // namespace
}  // namespace trazo
