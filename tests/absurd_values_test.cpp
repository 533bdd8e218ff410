// Absurd but well-formed settings through the trazo binary, each under a memory limit (RLIMIT_AS in the child)
// and a time limit: every case either renders quickly or is refused with its reason (status 2 and file:line
// for the scene's values, status 1 and the bytes needed for an image that cannot be held), never a crash, an
// abort or a marathon, and never an image on refusal. Issue 18's table of absurd values.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "device/flatten.h"
#include "fetched_assets.h"
#include "render/strata_plan.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

namespace fs = std::filesystem;

constexpr rlim_t kMemoryLimit = rlim_t(4) << 30;  // 4 GiB of address space for the whole process

struct Limited {
    int status = -1;       // exit status; -1 when killed or signalled
    int signal = 0;        // the signal that ended it (SIGKILL: the time limit)
    bool timedOut = false;
    double seconds = 0;
    std::string errors;    // stderr
};

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif

// Runs trazo with `args` under memoryLimit bytes of address space; kills it after `limitSeconds`, or as soon as stderr contains
// `stopAt` (when given: a note that must come before any long work).
Limited runLimited(const std::vector<std::string>& args, double limitSeconds, const std::string& stopAt = {},
                   rlim_t memoryLimit = kMemoryLimit) {
    const std::string errFile = tempPath("absurd_stderr.txt");
    fs::remove(errFile);
    const std::string binary = trazoBinary();
    std::vector<std::string> all{binary};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        // AddressSanitizer reserves terabytes of address space at start: under it only the time is limited.
        const rlimit limit{memoryLimit, memoryLimit};
        if (!kAddressSanitizer) setrlimit(RLIMIT_AS, &limit);
        const int err = open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        dup2(err, 2);
        dup2(null, 1);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
    Limited r;
    int raw = 0;
    for (;;) {
        const pid_t done = waitpid(pid, &raw, WNOHANG);
        if (done == pid) break;
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const bool stop = !stopAt.empty() && readFileText(errFile).find(stopAt) != std::string::npos;
        if (r.seconds > limitSeconds || stop) {
            r.timedOut = !stop;
            kill(pid, SIGKILL);
            waitpid(pid, &raw, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
    if (WIFSIGNALED(raw)) r.signal = WTERMSIG(raw);
    r.errors = readFileText(errFile);
    return r;
}

// A small lit scene: `settings` go in SceneSettings, `extra` after the lights.
std::string sceneText(const std::string& settings, const std::string& extra = {}) {
    return "SceneSettings\n{\n    RenderWidth 16\n    RenderHeight 16\n" + settings +
           "}\nCamera\n{\n    POV 0 0 5\n}\nMaterial\n{\n    Name white\n    SpecularColor 0 0 0\n}\n"
           "Material\n{\n    Name glossy\n    ReflectionAmount 0.5\n    ReflectionAngle 10\n}\n"
           "Sphere\n{\n    Material white\n}\nSphere\n{\n    Material glossy\n    Center 2 0 0\n}\n"
           "PointLight\n{\n    Position 2 2 2\n}\n" + extra;
}

// The camera inside a closed box whose walls are perfect mirrors: every ray reflects ReflectionSteps times.
std::string mirrorBox(int steps) {
    return "SceneSettings\n{\n    RenderWidth 16\n    RenderHeight 16\n    ReflectionSteps " + std::to_string(steps) +
           "\n}\nCamera\n{\n    POV 0 0 0\n    POI 0 0 -1\n}\n"
           "Material\n{\n    Name mirror\n    DiffuseColor 0 0 0\n    SpecularColor 1 1 1\n    ReflectionAmount 1\n}\n"
           "Box\n{\n    Material mirror\n    Scale 4 4 4\n}\nPointLight\n{\n    Position 0 1 0\n}\n";
}

std::string writeScene(const std::string& name, const std::string& text) {
    const std::string path = tempPath(name);
    std::ofstream(path) << text;
    return path;
}

struct Case {
    const char* name;
    std::string scene;
    std::vector<std::string> extraArgs;
};

std::vector<std::string> renderArgs(const std::string& scene, const std::string& out,
                                    const std::vector<std::string>& extra) {
    std::vector<std::string> args{"--render", scene, "-o", out, "--backend", "cpu", "--threads", "2", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

// Values whose strata would wrap 32 bits (and divided by zero: SIGFPE) or whose mirror chain is unbounded in
// practice are refused before any work, with the scene's file:line and the parameter's name.
TEST(AbsurdValues, StrataThatWouldOverflowAreRefusedWithTheirLine) {
    const Case cases[] = {
        {"Subdivision", sceneText("", "AreaLight\n{\n    Position 0 3 0\n    Subdivision 65536 65536\n}\n"), {}},
        {"IndirectQuality", sceneText("    IndirectQuality 65536\n"), {}},
        {"ReflectionQuality", sceneText("    ReflectionQuality 65536\n"), {}},
        {"ReflectionSteps", mirrorBox(1000000), {}},
        {"Subdivision", sceneText("", "AreaLight\n{\n    Subdivision 2147483647 2\n}\n"), {"--spp", "1"}},
    };
    for (const Case& c : cases) {
        const std::string scene = writeScene(std::string("absurd_") + c.name + ".scene", c.scene);
        const std::string out = tempPath("absurd.png");
        fs::remove(out);
        const Limited r = runLimited(renderArgs(scene, out, c.extraArgs), 30);
        EXPECT_FALSE(r.timedOut) << c.name;
        EXPECT_EQ(r.signal, 0) << c.name << ": killed by signal " << r.signal << "\n" << r.errors;
        EXPECT_EQ(r.status, 2) << c.name << "\n" << r.errors;
        EXPECT_NE(r.errors.find(std::string("absurd_") + c.name + ".scene:"), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find(std::string("error: ") + c.name), std::string::npos) << r.errors;
        EXPECT_FALSE(fs::exists(out)) << c.name;
    }
}

// Antialiasing values other than 1, 4 and 16 fall back to 1 with a warning and render at once; large values
// inside the bounds render in time proportional to what they ask.
TEST(AbsurdValues, ValuesInsideTheBoundsRenderQuickly) {
    const Case cases[] = {
        {"Antialiasing3", sceneText("    Antialiasing 3\n"), {}},
        {"AntialiasingHuge", sceneText("    Antialiasing 2147483647\n"), {}},
        {"AntialiasingNegative", sceneText("    Antialiasing -16\n"), {}},
        {"Antialiasing16", sceneText("    Antialiasing 16\n"), {}},
        {"MirrorBox1000", mirrorBox(1000), {}},
        {"Subdivision1024", sceneText("", "AreaLight\n{\n    Position 0 3 0\n    Subdivision 1024 1024\n}\n"),
         {"--spp", "2", "--blocks", "1", "--width", "4", "--height", "4"}},
        {"BlocksNearAPrimeGrid", sceneText("", "AreaLight\n{\n    Position 0 3 0\n    Subdivision 1048573 1\n}\n"),
         {"--spp", "1", "--blocks", "1,1048572,1,1", "--width", "4", "--height", "4"}},
    };
    for (const Case& c : cases) {
        const std::string scene = writeScene(std::string("inside_") + c.name + ".scene", c.scene);
        const std::string out = tempPath("inside.png");
        fs::remove(out);
        const Limited r = runLimited(renderArgs(scene, out, c.extraArgs), 60);
        EXPECT_FALSE(r.timedOut) << c.name << " still running after " << r.seconds << " s";
        EXPECT_EQ(r.status, 0) << c.name << "\n" << r.errors;
        EXPECT_TRUE(fs::exists(out)) << c.name;
        if (std::string(c.name).rfind("Antialiasing", 0) == 0 && std::string(c.name) != "Antialiasing16") {
            EXPECT_NE(r.errors.find("must be 1, 4 or 16"), std::string::npos) << r.errors;
        }
    }
}

// A 16384² image (its accumulation alone is 16 GiB) is refused up front, naming the bytes it needs, under a
// memory limit it cannot fit: at once, status 1, no image (it used to fail after the render, or abort).
TEST(AbsurdValues, AnImageTooLargeForMemoryIsRefusedBeforeRendering) {
    const std::string scene = writeScene("absurd_size.scene", sceneText(""));
    const std::string out = tempPath("absurd_size.png");
    fs::remove(out);
    const Limited r = runLimited(renderArgs(scene, out, {"--width", "16384", "--height", "16384"}), 30);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.signal, 0) << r.errors;
    EXPECT_EQ(r.status, 1) << r.errors;
    EXPECT_NE(r.errors.find("a 16384×16384 render needs 37580963840 bytes"), std::string::npos) << r.errors;
    EXPECT_LT(r.seconds, 20.0);
    EXPECT_FALSE(fs::exists(out));
}

// Memory exhausted while reading is a message and status 1, not an abort (status 134): a mesh file of 1000 MiB
// (sparse: no disk used; inside the OBJ reader's size bound) read under a 768 MiB address-space limit, and a
// mesh whose Source is /dev/zero (which a reader that opens only regular files refuses first: status 2).
TEST(AbsurdValues, OutOfMemoryWhileReadingIsAnErrorNotAnAbort) {
    if (kAddressSanitizer) GTEST_SKIP() << "needs a memory limit, which an AddressSanitizer build cannot start under";
    const std::string big = tempPath("absurd_big.obj");
    { std::ofstream(big) << "v 0 0 0\n"; }
    fs::resize_file(big, uintmax_t(1000) << 20);
    for (const std::string& source : {big, std::string("/dev/zero")}) {
        const std::string scene = writeScene(
            "absurd_read.scene", sceneText("", "Mesh\n{\n    Material white\n    Source \"" + source + "\"\n}\n"));
        const std::string out = tempPath("absurd_read.png");
        fs::remove(out);
        const Limited r = runLimited(renderArgs(scene, out, {}), 60, {}, rlim_t(768) << 20);
        EXPECT_FALSE(r.timedOut) << source << "\n" << r.errors;
        EXPECT_EQ(r.signal, 0) << source << "\n" << r.errors;
        if (source == big) {
            EXPECT_EQ(r.status, 1) << r.errors;
            EXPECT_NE(r.errors.find("out of memory"), std::string::npos) << r.errors;
        } else {
            EXPECT_TRUE(r.status == 1 || r.status == 2) << r.status << "\n" << r.errors;
        }
        EXPECT_FALSE(fs::exists(out));
    }
    fs::remove(big);
}

// A default render that would run long (here 18 glossy passes of 2·724² indirect directions a camera hit) says what
// it will cost before it starts; the test stops it once it has.
TEST(AbsurdValues, ALongDefaultRenderIsAnnouncedFirst) {
    const std::string scene = writeScene("absurd_long.scene", sceneText("    IndirectQuality 724\n"));
    const std::string out = tempPath("absurd_long.png");
    fs::remove(out);
    const Limited r = runLimited(renderArgs(scene, out, {"--width", "512", "--height", "512"}), 30,
                                 "note: this render will trace");
    EXPECT_FALSE(r.timedOut) << r.errors;
    EXPECT_NE(r.errors.find("18 passes (the default: one full cycle of the scene's strata)"), std::string::npos)
        << r.errors;
    EXPECT_NE(r.errors.find("--spp or --time renders less"), std::string::npos) << r.errors;
    EXPECT_FALSE(fs::exists(out));
}

// The note is for long renders only: no shipped scene's default render is announced, and every one is inside
// the bounds.
TEST(AbsurdValues, NoShippedSceneIsAnnouncedOrRefused) {
    std::string absent;  // the scenes not checked, and why
    for (const auto& entry : fs::directory_iterator(sourcePath("scenes"))) {
        if (entry.path().extension() != ".scene") continue;
        if (const std::string why = absentFetchedAsset(entry.path().string()); !why.empty()) {
            absent += "\n" + why;
            continue;
        }
        Diagnostics diags;
        const Scene scene = readSceneFile(entry.path().string(), diags);
        ASSERT_FALSE(diags.hasErrors()) << entry.path();
        EXPECT_TRUE(checkRenderBounds(scene, diags)) << entry.path();
        const FlattenResult flat = flatten(scene);
        const StrataBlocks blocks = headlessBlocks(flat.arrays);
        const std::string note = longRenderNote(flat.arrays, blocks, cameraPathPasses(flat.arrays, blocks), true,
                                                uint32_t(scene.settings.renderWidth),
                                                uint32_t(scene.settings.renderHeight));
        EXPECT_TRUE(note.empty()) << entry.path() << ": " << note;
    }
    if (!absent.empty()) GTEST_SKIP() << "not checked:" << absent;
}

}  // namespace
}  // namespace trazo::test
