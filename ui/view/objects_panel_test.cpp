// The Objects panel drawn headless (an ImGui context without a window or renderer), with mouse input set
// frame by frame: drawing alone edits nothing and leaves ImGui's ID and window stacks balanced for every kind;
// a click on "Sphere" adds one; a held drag on a parameter makes every frame's edit with one gesture id, and
// the next drag another, so EditHistory makes each drag one undo step.
#include "view/objects_panel.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>

#include "model/edit_history.h"
#include "scene/scene_writer.h"
#include "view/panels.h"
#include "view/param_editor.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

using Kind = ObjectId::Kind;

class HeadlessImGui {
public:
    HeadlessImGui() {
        context_ = ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(700, 1400);
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas, as a renderer backend would
    }
    ~HeadlessImGui() { ImGui::DestroyContext(context_); }

    // One frame with the mouse at `mouse` (left button `down`), `draw` inside a fixed window.
    void frame(ImVec2 mouse, bool down, const std::function<void()>& draw) {
        ImGuiIO& io = ImGui::GetIO();
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = mouse;
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(io.DisplaySize);
        ImGui::Begin("Objects");
        draw();
        ImGui::End();
        ImGui::Render();
    }

private:
    ImGuiContext* context_;
};

Scene editScene() {
    Scene scene = test::readSourceScene("scenes/scene3_csg_area.scene");
    Selection none;
    addAndSelect(scene, none, Kind::Sphere, Vec3(0, 1, 0));
    addAndSelect(scene, none, Kind::Cylinder, Vec3(0, 1, 0));
#define TRAZO_X(Data, array, HostKind, ...) addAndSelect(scene, none, Kind::HostKind, Vec3(0, 3, 0));
    TRAZO_LIGHT_KINDS(TRAZO_X)  // every light kind, so a new one is drawn too
#undef TRAZO_X
    const std::string obj = test::writeTempFile("panel_tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
    Diagnostics diags;
    EXPECT_TRUE(addObjectFromFile(scene, Kind::Mesh, obj, Vec3(0, 1, 0), diags));
    return scene;
}

TEST(ObjectsPanel, DrawingEditsNothingAndBalancesImGuisStacks) {
    HeadlessImGui imgui;
    Scene scene = editScene();
    const std::string before = formatScene(scene, scene.path);
    ObjectsPanelState state;
    std::vector<ObjectId> every = listObjects(scene);
    for (int k = 0; k < kObjectIdKindCount; ++k) EXPECT_GT(objectCount(scene, Kind(k)), 0u) << k;
    for (const ObjectId id : every) {
        state.selection = id;
        state.scrollToSelection = true;
        for (int f = 0; f < 2; ++f) {
            imgui.frame(ImVec2(-1, -1), false, [&] {
                const ImGuiID probe = ImGui::GetID("probe");
                const ImVec2 size = ImGui::GetWindowSize();
                ObjectsPanelActions actions;
                EXPECT_EQ(drawObjectsPanel(scene, state, actions, Vec3(0, 0, 0)), kDirtyNone);
                EXPECT_EQ(ImGui::GetID("probe"), probe) << describeObject(scene, id);
                EXPECT_EQ(ImGui::GetWindowSize().y, size.y) << "a child window left open";
                EXPECT_TRUE(actions.label.empty());
            });
        }
        EXPECT_EQ(state.selection, id);
    }
    EXPECT_EQ(formatScene(scene, scene.path), before);
    state.selection = ObjectId{Kind::Sphere, 999};  // gone (an undo removed it): dropped, not drawn
    imgui.frame(ImVec2(-1, -1), false, [&] {
        ObjectsPanelActions actions;
        drawObjectsPanel(scene, state, actions, Vec3(0, 0, 0));
    });
    EXPECT_EQ(state.selection, std::nullopt);
}

// The Scene settings and Camera panels share the Objects panel's table-driven editors: their word lists (an
// unwritten ViewTransform too), turn slider, EnvironmentMap field and Focus button draw without editing.
TEST(ObjectsPanel, TheSettingsAndCameraPanelsDrawWithoutEditing) {
    HeadlessImGui imgui;
    for (const ViewTransform view : {ViewTransform::Auto, ViewTransform::Srgb}) {
        Scene scene = editScene();
        scene.settings.integrator = IntegratorKind::Path;
        scene.settings.viewTransform = view;
        scene.settings.environmentRotation = 270.0f;  // beyond the slider's turn: shown, kept
        const std::string before = formatScene(scene, scene.path);
        PanelState state;
        Gestures gestures;
        for (int f = 0; f < 2; ++f) {
            imgui.frame(ImVec2(-1, -1), false, [&] {
                const ImGuiID probe = ImGui::GetID("probe");
                PanelActions actions;
                startGestures(gestures);
                EXPECT_EQ(drawSceneSettingsPanel(scene, state, gestures), kDirtyNone);
                EXPECT_EQ(drawCameraPanel(scene.camera, state, gestures, actions), kDirtyNone);
                EXPECT_EQ(ImGui::GetID("probe"), probe);
                EXPECT_TRUE(actions.commands.empty());
            });
        }
        EXPECT_EQ(formatScene(scene, scene.path), before);
        EXPECT_TRUE(state.environmentStatus.empty());
    }
}

TEST(ObjectsPanel, AClickOnSphereAddsOneAtTheViewCentre) {
    HeadlessImGui imgui;
    Scene scene = editScene();
    const size_t spheres = scene.spheres.size();
    ObjectsPanelState state;
    ImVec2 button;
    DirtyFlags dirty = kDirtyNone;
    ObjectsPanelActions actions;
    auto draw = [&] {
        drawObjectList(scene, state, actions);
        const ImVec2 at = ImGui::GetCursorScreenPos();  // "Add at the view centre:", then the buttons
        button = ImVec2(at.x + 8, at.y + ImGui::GetTextLineHeightWithSpacing() + 0.5f * ImGui::GetTextLineHeight());
        dirty |= drawAddButtons(scene, state, actions, Vec3(4, 5, 6));
    };
    imgui.frame(ImVec2(-1, -1), false, draw);
    imgui.frame(button, false, draw);
    imgui.frame(button, true, draw);
    imgui.frame(button, false, draw);  // buttons act on release
    EXPECT_EQ(dirty, kDirtyScene);
    ASSERT_EQ(scene.spheres.size(), spheres + 1);
    EXPECT_EQ(scene.spheres.back().center.z, 6.0f);
    EXPECT_EQ(actions.label, "Add Sphere " + std::to_string(spheres));
    EXPECT_EQ(actions.gesture, 0u);
    EXPECT_EQ(state.selection, (ObjectId{Kind::Sphere, uint32_t(spheres)}));

    // A click on the list's first row selects the first object.
    ImVec2 firstRow;
    auto list = [&] {
        const ImVec2 at = ImGui::GetCursorScreenPos();
        firstRow = ImVec2(at.x + 30, at.y + ImGui::GetStyle().WindowPadding.y + 0.5f * ImGui::GetTextLineHeight());
        drawObjectList(scene, state, actions);
    };
    actions = {};
    imgui.frame(ImVec2(-1, -1), false, list);
    imgui.frame(firstRow, false, list);
    imgui.frame(firstRow, true, list);
    imgui.frame(firstRow, false, list);
    EXPECT_TRUE(actions.selectionChanged);
    EXPECT_EQ(state.selection, listObjects(scene).front());
}

// A drag on a transform step's values, through drawTransformSteps, committed as the viewer would.
TEST(ObjectsPanel, EachHeldDragIsOneGesture) {
    HeadlessImGui imgui;
    Scene scene = editScene();
    const std::string original = formatScene(scene, scene.path);
    EditHistory history;
    ObjectsPanelState state;
    const ObjectId box{Kind::Box, 0};
    std::vector<uint64_t> gestures;
    ImVec2 values;
    auto draw = [&] {
        startGestures(state.gestures);
        const ImVec2 at = ImGui::GetCursorScreenPos();  // the first step's row: kind combo, then its values
        values = ImVec2(at.x + 100 + ImGui::GetStyle().ItemSpacing.x + 20, at.y + 0.5f * ImGui::GetFrameHeight());
        const Scene before = scene;
        const DirtyFlags dirty = drawTransformSteps(*objectTransforms(scene, box), box.kind, state.gestures, state.status);
        if (dirty) {
            history.commit(before, "Edit Box 0", dirty, state.gestures.edited);
            gestures.push_back(state.gestures.edited);
            EXPECT_EQ(heldGesture(state.gestures), state.gestures.edited);  // the panel-wide view agrees
        } else if (!ImGui::IsMouseDown(0)) {
            EXPECT_EQ(heldGesture(state.gestures), 0u);
        }
    };
    imgui.frame(ImVec2(-1, -1), false, draw);
    for (int drag = 0; drag < 2; ++drag) {
        // Half a second apart: two presses closer in time are a double-click (a drag field's text entry).
        for (int idle = 0; idle < 30; ++idle) imgui.frame(values, false, draw);
        for (int f = 0; f <= 5; ++f) imgui.frame(ImVec2(values.x + 10.0f * float(f), values.y), true, draw);
        imgui.frame(ImVec2(values.x + 50, values.y), false, draw);
    }
    std::string seen;
    for (uint64_t g : gestures) seen += std::to_string(g) + " ";
    ASSERT_GE(gestures.size(), 6u) << state.status << " gestures: " << seen;
    const uint64_t first = gestures.front(), last = gestures.back();
    EXPECT_NE(first, 0u);
    EXPECT_NE(last, 0u);
    EXPECT_NE(first, last);
    for (uint64_t g : gestures) EXPECT_TRUE(g == first || g == last);
    EXPECT_EQ(history.undoSteps(), 2u);  // two drags, two steps
    EXPECT_NE(formatScene(scene, scene.path), original);
    history.undo(scene);
    history.undo(scene);
    EXPECT_EQ(formatScene(scene, scene.path), original);
}

}  // namespace
}  // namespace trazo
