// The recovery file: written while there are unsaved edits (at most once an interval) and read back as the
// scene, removed on a clean save, left behind by an abandoned session, and whole after a kill -9 at any time.
#include "model/recovery_file.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <random>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "model/scene_edit.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

using namespace std::chrono_literals;
using Kind = ObjectId::Kind;

// scene1_area as if it were the file `dir`/edited.scene.
Scene sceneIn(const std::string& dir) {
    Scene scene = test::readSourceScene("scenes/scene1_area.scene");
    scene.path = dir + "/edited.scene";
    return scene;
}

std::string text(const Scene& s) { return formatScene(s, s.path); }

TEST(RecoveryFile, KeepsTheUnsavedSceneNextToItsFile) {
    const std::string dir = test::freshDir("recovery_keep");
    Scene scene = sceneIn(dir);
    RecoveryFile recovery(scene.path);
    EXPECT_EQ(recovery.path(), dir + "/edited.scene.recovery");
    EXPECT_EQ(RecoveryFile::find(scene.path), std::nullopt);
    EXPECT_FALSE(recovery.update(scene, false));  // nothing unsaved: nothing written
    EXPECT_TRUE(test::listDir(dir).empty());

    translateObject(scene, {Kind::Sphere, 0}, Vec3(0.3f, 0, 0));
    addObject(scene, Kind::Box, Vec3(1, 2, 3), 0.7f);
    ASSERT_TRUE(recovery.update(scene, true)) << recovery.error();
    EXPECT_EQ(RecoveryFile::find(scene.path), recovery.path());
    EXPECT_EQ(test::listDir(dir), std::vector<std::string>{"edited.scene.recovery"});
    Diagnostics diags;
    const Scene back = RecoveryFile::read(scene.path, diags);
    EXPECT_FALSE(diags.hasErrors());
    EXPECT_EQ(back.path, scene.path);
    EXPECT_EQ(text(back), text(scene));

    EXPECT_TRUE(recovery.update(scene, false));  // saved: removed
    EXPECT_EQ(RecoveryFile::find(scene.path), std::nullopt);
    EXPECT_TRUE(test::listDir(dir).empty());
}

TEST(RecoveryFile, WritesAtMostOnceAnInterval) {
    const std::string dir = test::freshDir("recovery_rate");
    Scene scene = sceneIn(dir);
    RecoveryFile recovery(scene.path, 1s);
    const auto t0 = RecoveryFile::Clock::now();
    EXPECT_TRUE(recovery.update(scene, true, t0));
    translateObject(scene, {Kind::Sphere, 0}, Vec3(1, 0, 0));
    EXPECT_FALSE(recovery.update(scene, true, t0 + 500ms));  // too soon
    EXPECT_NE(text(RecoveryFile::read(scene.path, *std::make_unique<Diagnostics>())), text(scene));
    EXPECT_TRUE(recovery.update(scene, true, t0 + 1s));
    Diagnostics diags;
    EXPECT_EQ(text(RecoveryFile::read(scene.path, diags)), text(scene));
    EXPECT_FALSE(recovery.update(scene, true, t0 + 3s));  // the same text: not written again
    translateObject(scene, {Kind::Sphere, 0}, Vec3(1, 0, 0));
    EXPECT_TRUE(recovery.flush(scene, true));  // on demand, whatever the time
    EXPECT_EQ(text(RecoveryFile::read(scene.path, diags)), text(scene));
}

TEST(RecoveryFile, AnAbandonedSessionLeavesItForTheNext) {
    const std::string dir = test::freshDir("recovery_abandon");
    Scene scene = sceneIn(dir);
    translateObject(scene, {Kind::Sphere, 1}, Vec3(0, 0.5f, 0));
    {
        RecoveryFile recovery(scene.path);
        ASSERT_TRUE(recovery.update(scene, true));
    }  // gone without remove(), as after a crash
    ASSERT_EQ(RecoveryFile::find(scene.path), RecoveryFile::pathFor(scene.path));
    // The next session's first frames (nothing unsaved yet) leave it while the viewer asks about it.
    RecoveryFile next(scene.path);
    EXPECT_FALSE(next.update(sceneIn(dir), false));
    Diagnostics diags;
    EXPECT_EQ(text(RecoveryFile::read(scene.path, diags)), text(scene));
    next.remove();  // declined
    EXPECT_EQ(RecoveryFile::find(scene.path), std::nullopt);
}

TEST(RecoveryFile, ASceneThatIsNoFileWritesNothing) {
    RecoveryFile recovery("");
    EXPECT_FALSE(recovery.update(Scene{}, true));
    EXPECT_FALSE(recovery.flush(Scene{}, true));
    EXPECT_EQ(RecoveryFile::find(""), std::nullopt);
}

TEST(RecoveryFile, AFailedWriteIsReported) {
    const std::string dir = test::freshDir("recovery_fail");
    RecoveryFile recovery(dir + "/no-such-folder/edited.scene");
    EXPECT_FALSE(recovery.update(sceneIn(dir), true));
    EXPECT_FALSE(recovery.error().empty());
}

// What an update costs the frame that writes: formatScene and the atomic write, for 10^4 objects.
TEST(RecoveryFile, ALargeSceneIsWrittenWhole) {
    const std::string dir = test::freshDir("recovery_large");
    Scene scene = sceneIn(dir);
    for (int i = 0; i < 10000; ++i) addObject(scene, Kind::Sphere, Vec3(float(i), 0, 0), 0.5f);
    RecoveryFile recovery(scene.path);
    const auto start = RecoveryFile::Clock::now();
    ASSERT_TRUE(recovery.flush(scene, true)) << recovery.error();
    const double ms = std::chrono::duration<double, std::milli>(RecoveryFile::Clock::now() - start).count();
    Diagnostics diags;
    const Scene back = RecoveryFile::read(scene.path, diags);
    EXPECT_FALSE(diags.hasErrors());
    EXPECT_EQ(back.spheres.size(), scene.spheres.size());
    std::printf("recovery file of %zu objects: %zu bytes written in %.1f ms\n", listObjects(scene).size(),
                test::readFileText(recovery.path()).size(), ms);
}

// A child writes two scenes in turn as fast as it can and is killed with SIGKILL at a random moment: the file
// is always one of the two, whole.
TEST(RecoveryFile, AKillAtAnyMomentLeavesAWholeFile) {
    const std::string dir = test::freshDir("recovery_kill");
    Scene a = sceneIn(dir), b = sceneIn(dir);
    for (int i = 0; i < 200; ++i) addObject(b, Kind::Sphere, Vec3(float(i), 0, 0), 0.5f);  // a longer write
    const std::string textA = text(a), textB = text(b);
    std::mt19937 random(1234);
    int killedWhileWriting = 0;
    for (int round = 0; round < 20; ++round) {
        int ready[2];
        ASSERT_EQ(pipe(ready), 0);
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            RecoveryFile recovery(a.path);
            recovery.flush(a, true);
            const char byte = 1;
            if (write(ready[1], &byte, 1) != 1) _exit(1);  // the file exists: the parent may start its clock
            for (uint64_t i = 1;; ++i) recovery.flush(i % 2 ? b : a, true);
        }
        char byte = 0;
        ASSERT_EQ(read(ready[0], &byte, 1), 1);
        close(ready[0]);
        close(ready[1]);
        std::this_thread::sleep_for(std::chrono::microseconds(random() % 20000));
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status));
        const std::string kept = test::readFileText(RecoveryFile::pathFor(a.path));
        ASSERT_TRUE(kept == textA || kept == textB) << "round " << round << ": " << kept.size() << " bytes";
        // A temporary the kill cut short may stay (hidden, ".edited.scene.recovery.tmp..."); never the file.
        for (const std::string& name : test::listDir(dir)) {
            if (name == "edited.scene.recovery") continue;
            EXPECT_EQ(name.rfind(".edited.scene.recovery.tmp", 0), 0u) << name;
            ++killedWhileWriting;
            std::filesystem::remove(dir + "/" + name);
        }
    }
    std::printf("%d of 20 kills cut a write short; the recovery file was whole every time\n", killedWhileWriting);
}

}  // namespace
}  // namespace trazo
