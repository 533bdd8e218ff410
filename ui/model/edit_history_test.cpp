// Undo and redo: sequences, coalesced gestures, redo cleared by a new edit, the depth and memory bounds,
// "unsaved" across save, undo and redo, and move → undo giving back the byte-identical saved scene.
#include "model/edit_history.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "model/scene_edit.h"
#include "scene/scene_writer.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

using Kind = ObjectId::Kind;

Scene seedScene() {
    Scene scene = test::readSourceScene("scenes/scene1_area.scene");
    EXPECT_GE(scene.spheres.size(), 2u);
    return scene;
}

std::string text(const Scene& s) { return formatScene(s, s.path); }

// Moves sphere 0 by `dx` and commits it as one step.
void moveSphere(Scene& scene, EditHistory& history, float dx, uint64_t gesture = 0) {
    const Scene before = scene;
    translateObject(scene, {Kind::Sphere, 0}, Vec3(dx, 0, 0));
    history.commit(before, "Move Sphere 0", kDirtyScene, gesture);
}

TEST(EditHistory, UndoAndRedoWalkTheStates) {
    Scene scene = seedScene();
    EditHistory history;
    EXPECT_FALSE(history.canUndo() || history.canRedo());
    EXPECT_EQ(history.undo(scene), kDirtyNone);
    std::vector<std::string> states = {text(scene)};
    for (float dx : {0.1f, 0.7f, -2.3f}) {
        moveSphere(scene, history, dx);
        states.push_back(text(scene));
    }
    EXPECT_EQ(history.undoSteps(), 3u);
    EXPECT_EQ(history.undoLabel(), "Move Sphere 0");
    EXPECT_EQ(history.redoLabel(), "");
    for (int i = 2; i >= 0; --i) {
        EXPECT_EQ(history.undo(scene), kDirtyScene);
        EXPECT_EQ(text(scene), states[size_t(i)]);
    }
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.redoSteps(), 3u);
    for (int i = 1; i <= 3; ++i) {
        EXPECT_EQ(history.redo(scene), kDirtyScene);
        EXPECT_EQ(text(scene), states[size_t(i)]);
    }
    EXPECT_EQ(history.redo(scene), kDirtyNone);
}

TEST(EditHistory, MoveThenUndoGivesTheByteIdenticalSavedScene) {
    Scene scene = seedScene();
    EditHistory history;
    const std::string path = test::freshDir("edit_history") + "/moved.scene";
    std::string error;
    ASSERT_TRUE(writeSceneFile(scene, path, error)) << error;
    const std::string saved = test::readFileText(path);
    // A drag of many small moves, as the viewer commits it: one gesture.
    for (int frame = 0; frame < 30; ++frame) moveSphere(scene, history, 0.0137f * float(frame + 1), 42);
    ASSERT_NE(text(scene), text(seedScene()));
    EXPECT_EQ(history.undoSteps(), 1u);
    history.undo(scene);
    ASSERT_TRUE(writeSceneFile(scene, path, error)) << error;
    EXPECT_EQ(test::readFileText(path), saved);
}

TEST(EditHistory, AGestureCoalescesUntilSomethingElseHappens) {
    Scene scene = seedScene();
    EditHistory history;
    const std::string start = text(scene);
    for (int i = 0; i < 10; ++i) moveSphere(scene, history, 0.25f, 7);
    EXPECT_EQ(history.undoSteps(), 1u);
    moveSphere(scene, history, 0.25f, 8);  // another gesture
    moveSphere(scene, history, 0.25f);     // a one-shot edit (0) is always its own step
    moveSphere(scene, history, 0.25f);
    EXPECT_EQ(history.undoSteps(), 4u);
    history.undo(scene);
    history.undo(scene);
    history.undo(scene);
    history.undo(scene);
    EXPECT_EQ(text(scene), start);
    // Undo ended gesture 7: the same id again starts a new step.
    history.redo(scene);
    moveSphere(scene, history, 0.25f, 7);
    moveSphere(scene, history, 0.25f, 7);
    EXPECT_EQ(history.undoSteps(), 2u);
    // So does a save.
    history.markSaved();
    moveSphere(scene, history, 0.25f, 7);
    EXPECT_EQ(history.undoSteps(), 3u);
}

TEST(EditHistory, ANewEditClearsRedo) {
    Scene scene = seedScene();
    EditHistory history;
    moveSphere(scene, history, 1);
    moveSphere(scene, history, 2);
    history.undo(scene);
    EXPECT_TRUE(history.canRedo());
    const std::string afterUndo = text(scene);
    moveSphere(scene, history, 3);
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(history.redo(scene), kDirtyNone);
    history.undo(scene);
    EXPECT_EQ(text(scene), afterUndo);
}

TEST(EditHistory, DepthAndMemoryAreBounded) {
    Scene scene = seedScene();
    EditHistory history(5);
    std::vector<std::string> states = {text(scene)};
    for (int i = 0; i < 8; ++i) {
        moveSphere(scene, history, 0.5f);
        states.push_back(text(scene));
    }
    EXPECT_EQ(history.undoSteps(), 5u);
    EXPECT_EQ(history.bytes(), 5 * snapshotBytes(Scene(scene)));  // copies: every vector as long as it holds
    while (history.undo(scene)) {}
    EXPECT_EQ(text(scene), states[3]);  // the 3 oldest steps were dropped

    EditHistory small(200, 3 * snapshotBytes(scene));
    for (int i = 0; i < 8; ++i) moveSphere(scene, small, 0.5f);
    EXPECT_EQ(small.undoSteps(), 3u);
    EditHistory tiny(200, 1);
    for (int i = 0; i < 3; ++i) moveSphere(scene, tiny, 0.5f);
    EXPECT_EQ(tiny.undoSteps(), 1u);  // one step is always kept
}

TEST(EditHistory, UnsavedFollowsTheSavedState) {
    Scene scene = seedScene();
    EditHistory history;
    EXPECT_FALSE(history.unsaved());
    moveSphere(scene, history, 1);
    EXPECT_TRUE(history.unsaved());
    history.undo(scene);
    EXPECT_FALSE(history.unsaved());  // back at the file's state
    history.redo(scene);
    EXPECT_TRUE(history.unsaved());
    history.markSaved();
    EXPECT_FALSE(history.unsaved());
    history.undo(scene);
    EXPECT_TRUE(history.unsaved());
    history.redo(scene);
    EXPECT_FALSE(history.unsaved());
    moveSphere(scene, history, 1, 5);
    moveSphere(scene, history, 1, 5);
    EXPECT_TRUE(history.unsaved());
    history.undo(scene);
    EXPECT_FALSE(history.unsaved());
    // A new edit after an undo makes the saved state one no redo reaches.
    history.undo(scene);
    moveSphere(scene, history, 2);
    EXPECT_TRUE(history.unsaved());
    history.undo(scene);
    EXPECT_TRUE(history.unsaved());
    history.reset();
    EXPECT_FALSE(history.unsaved() || history.canUndo() || history.canRedo());
    history.reset(false);  // a recovered scene: unsaved from the start
    EXPECT_TRUE(history.unsaved());
}

TEST(EditHistory, TheCameraComesBackOnlyWithAStepThatChangedIt) {
    Scene scene = seedScene();
    EditHistory history;
    const Vec3 filePov = scene.camera.pov;
    moveSphere(scene, history, 1);
    scene.camera.pov = Vec3(3, 4, 5);  // an orbit, not recorded
    EXPECT_EQ(history.undo(scene), kDirtyScene);
    EXPECT_EQ(scene.camera.pov.x, 3.0f);  // the view stays
    EXPECT_EQ(history.redo(scene), kDirtyScene);
    EXPECT_EQ(scene.camera.pov.x, 3.0f);

    const Scene before = scene;
    scene.camera.pov = Vec3(7, 7, 7);  // typed in the Camera panel: recorded
    history.commit(before, "Edit Camera", kDirtyCamera);
    EXPECT_EQ(history.undo(scene), kDirtyScene | kDirtyCamera);
    EXPECT_EQ(scene.camera.pov.x, 3.0f);
    EXPECT_EQ(history.redo(scene), kDirtyScene | kDirtyCamera);
    EXPECT_EQ(scene.camera.pov.x, 7.0f);
    EXPECT_NE(filePov.x, 7.0f);
}

TEST(EditHistory, SizeChangesAndThePathAreHandled) {
    Scene scene = seedScene();
    EditHistory history;
    const Scene before = scene;
    scene.settings.renderWidth = 300;
    history.commit(before, "Edit RenderWidth", kDirtySize);
    scene.path = "/elsewhere/saved-as.scene";  // "save as" is no edit
    EXPECT_EQ(history.undo(scene), kDirtyScene | kDirtySize);
    EXPECT_EQ(scene.settings.renderWidth, before.settings.renderWidth);
    EXPECT_EQ(scene.path, "/elsewhere/saved-as.scene");
    // The size is compared too, whatever the step said it changed.
    const Scene before2 = scene;
    scene.settings.renderHeight = 17;
    history.commit(before2, "Edit", kDirtyScene);
    EXPECT_EQ(history.undo(scene), kDirtyScene | kDirtySize);
}

TEST(EditHistory, SnapshotsShareMeshesAndCostTheirParameters) {
    Scene scene;
    scene.path = "/some/folder/of/scenes/quite-a-long-name.scene";
    auto mesh = std::make_shared<MeshData>();
    mesh->positions.assign(300000, Vec3(0, 0, 0));
    mesh->corners.assign(300000, MeshData::Corner{0, -1, -1});
    scene.meshes.push_back(Mesh{kDefaultMaterial, "/some/bunny.obj", {}, mesh, {}});
    EXPECT_LT(snapshotBytes(scene), 4096u);  // not the 7.2 MB of triangles
    const Scene copy = scene;
    EXPECT_EQ(copy.meshes[0].data.get(), mesh.get());

    // 10^4 spheres written in a file (each remembers its file:line): about what a step of such a scene costs.
    for (int i = 0; i < 10000; ++i) scene.spheres.push_back({kDefaultMaterial, Vec3(float(i), 0, 0), 1, {scene.path, i, 1}});
    const size_t bytes = snapshotBytes(scene);
    EXPECT_GE(bytes, 10000 * (sizeof(Sphere) + scene.path.size()));
    EXPECT_LE(bytes, 10000 * (sizeof(Sphere) + 2 * scene.path.size() + 64));
    double fastest = 1e30;
    for (int i = 0; i < 5; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const Scene snapshot = scene;
        fastest = std::min(fastest, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        EXPECT_EQ(snapshot.spheres.size(), 10000u);
    }
    std::printf("snapshot of 10^4 spheres: %zu bytes, copied in %.3f ms (fastest of 5); scene1_area: %zu bytes\n",
                bytes, fastest, snapshotBytes(Scene(seedScene())));
}

}  // namespace
}  // namespace trazo
