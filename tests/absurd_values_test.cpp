// Absurd but well-formed settings and geometry through the trazo binary, each under a memory limit (RLIMIT_AS
// in the child) and a time limit: every case either renders quickly, with every pixel finite and the image
// it must give, or is refused with its reason (status 2 and file:line for the scene's values, status 1 and
// the bytes needed for an image that cannot be held), never a crash, an abort or a marathon, and never an
// image on refusal. Issue 18's table of absurd values.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "flatten/flatten.h"
#include "fetched_assets.h"
#include "render/render_plan.h"
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
        const std::string scene = writeTempFile(std::string("absurd_") + c.name + ".scene", c.scene);
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
        const std::string scene = writeTempFile(std::string("inside_") + c.name + ".scene", c.scene);
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
    const std::string scene = writeTempFile("absurd_size.scene", sceneText(""));
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
        const std::string scene = writeTempFile(
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
    const std::string scene = writeTempFile("absurd_long.scene", sceneText("    IndirectQuality 724\n"));
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

// --- Geometry from 1e-30 to 1e30: radii, scales, distances, object counts ---

// A float image read back from a PFM file (rows bottom to top, as PFM stores them; only their set matters).
struct FloatImage {
    int width = 0, height = 0;
    std::vector<float> rgb;
};

FloatImage readPfm(const std::string& path) {
    FloatImage image;
    const std::string data = readFileText(path);
    std::istringstream header(data);
    std::string magic;
    double scale = 0;
    header >> magic >> image.width >> image.height >> scale;
    if (magic != "PF" || image.width <= 0 || image.height <= 0 || scale >= 0) return {};  // little-endian only
    const size_t start = size_t(header.tellg()) + 1;  // one whitespace byte after the scale
    const size_t floats = size_t(image.width) * size_t(image.height) * 3;
    if (data.size() < start + 4 * floats) return {};
    image.rgb.resize(floats);
    std::memcpy(image.rgb.data(), data.data() + start, 4 * floats);
    return image;
}

constexpr float kBackground[3] = {0.25f, 0.5f, 0.75f};  // no lit white surface gives it

// A 16² view from POV `pov` towards the origin, background kBackground, material "white", `lights` then
// `objects`.
std::string geometryScene(const std::string& objects, const std::string& pov = "0 0 5",
                          const std::string& lights = "PointLight\n{\n    Position 2 2 2\n}\n") {
    return "SceneSettings\n{\n    RenderWidth 16\n    RenderHeight 16\n    BackgroundColor 0.25 0.5 0.75\n}\n"
           "Camera\n{\n    POV " + pov + "\n}\n"
           "Material\n{\n    Name white\n    SpecularColor 0 0 0\n}\n" + lights + objects;
}

std::string block(const std::string& name, const std::string& lines) {
    return name + "\n{\n    Material white\n" + lines + "}\n";
}

// A 2×2 square in the plane z = 0, facing +z, as an OBJ file (no normals: they are computed).
std::string squareObj() {
    const std::string path = tempPath("square.obj");
    std::ofstream(path) << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";
    return "    Source \"" + path + "\"\n";
}

enum class Expect { Background, Lit, Drawn, Anything };  // Lit: no pixel background, none black; Drawn: not all background

struct GeometryCase {
    std::string name;
    std::string scene;
    Expect expect;
};

// Renders `c` to a PFM under the limits: status 0 within 20 s, every pixel finite, and what it expects.
void expectRenders(const GeometryCase& c, double maxSeconds = 20) {
    const std::string scene = writeTempFile("geometry_" + c.name + ".scene", c.scene);
    const std::string out = tempPath("geometry.pfm");
    fs::remove(out);
    const Limited r = runLimited(renderArgs(scene, out, {}), maxSeconds);
    EXPECT_FALSE(r.timedOut) << c.name << " still running after " << r.seconds << " s";
    EXPECT_EQ(r.signal, 0) << c.name << ": killed by signal " << r.signal << "\n" << r.errors;
    ASSERT_EQ(r.status, 0) << c.name << "\n" << r.errors;
    const FloatImage image = readPfm(out);
    ASSERT_EQ(image.width * image.height, 256) << c.name << ": no 16×16 PFM";
    int nonFinite = 0, background = 0, black = 0;
    for (size_t i = 0; i < image.rgb.size(); i += 3) {
        for (int k = 0; k < 3; ++k) nonFinite += !std::isfinite(image.rgb[i + size_t(k)]);
        background += image.rgb[i] == kBackground[0] && image.rgb[i + 1] == kBackground[1] &&
                      image.rgb[i + 2] == kBackground[2];
        black += !(image.rgb[i] > 0.0f || image.rgb[i + 1] > 0.0f || image.rgb[i + 2] > 0.0f);
    }
    EXPECT_EQ(nonFinite, 0) << c.name;
    if (c.expect == Expect::Background) {
        EXPECT_EQ(background, 256) << c.name << ": something drawn";
    }
    if (c.expect == Expect::Lit) {
        EXPECT_EQ(background + black, 0) << c.name << ": background or black pixels";
    }
    if (c.expect == Expect::Drawn) {
        EXPECT_LT(background, 256) << c.name << ": nothing drawn";
    }
}

// Objects far below a pixel are not seen; the camera inside a huge sphere, cylinder or box sees its lit inside
// up to the bounds of docs/LIMITS.md (the light is inside too; a box of 1e13 needs the inverse taken in
// double). 1e-50 rounds to 0 in float: a radius of zero draws nothing.
TEST(AbsurdGeometry, RadiiAndScalesFrom1eMinus30To1e19Render) {
    std::vector<GeometryCase> cases;
    for (const char* tiny : {"1e-30", "1e-10"}) {
        const std::string s(tiny);
        cases.push_back({"SphereRadius" + s, geometryScene(block("Sphere", "    Radius " + s + "\n")), Expect::Background});
        cases.push_back({"CylinderRadius" + s,
                         geometryScene(block("Cylinder", "    Radius " + s + "\n    Base 0 -1 0\n    Height 2\n")),
                         Expect::Background});
        cases.push_back({"CylinderAll" + s,
                         geometryScene(block("Cylinder", "    Radius " + s + "\n    Height " + s + "\n")),
                         Expect::Background});
        cases.push_back({"BoxScale" + s, geometryScene(block("Box", "    Scale " + s + " " + s + " " + s + "\n")),
                         Expect::Background});
        cases.push_back({"MeshScale" + s, geometryScene(block("Mesh", squareObj() + "    Scale " + s + " " + s + " 1\n")),
                         Expect::Background});
    }
    cases.push_back({"SphereRadius1e-50", geometryScene(block("Sphere", "    Radius 1e-50\n")), Expect::Background});
    for (const char* huge : {"1e10", "1e19"}) {
        const std::string s(huge);
        cases.push_back({"SphereRadius" + s, geometryScene(block("Sphere", "    Radius " + s + "\n")), Expect::Lit});
    }
    for (const char* huge : {"1e10", "1e13", "6e18"}) {
        const std::string s(huge);
        cases.push_back({"BoxScale" + s, geometryScene(block("Box", "    Scale " + s + " " + s + " " + s + "\n")),
                         Expect::Lit});
    }
    for (const char* huge : {"1e10", "1e19"}) {
        const std::string s(huge);
        cases.push_back({"CylinderRadius" + s,
                         geometryScene(block("Cylinder", "    Radius " + s + "\n    Base 0 -" + s + " 0\n    Height 2" +
                                                             s.substr(1) + "\n")),
                         Expect::Lit});
    }
    cases.push_back({"MeshScale1e5", geometryScene(block("Mesh", squareObj() + "    Scale 1e5 1e5 1\n")), Expect::Lit});
    cases.push_back({"MeshScale4e8", geometryScene(block("Mesh", squareObj() + "    Scale 4e8 4e8 4e8\n")), Expect::Lit});
    for (const GeometryCase& c : cases) expectRenders(c);
}

// Values beyond what float squares, inside the bounds, that once rendered silently wrong: a box pane thinner than
// 5e-20 lost its normals (black), a FocalDistance of 2e19 sent every lens ray nowhere (background), and a
// RefractionIndex of 1.9e19 with Fresnel made F NaN (black). Now the pane is lit, the far focus sees the pane,
// and the huge index reflects everything: a clear Fresnel pane shows the background it mirrors, exactly.
TEST(AbsurdGeometry, ThinPanesFarFociAndHugeIndicesRenderRight) {
    const std::string pane = "    Scale 100 100 ";
    for (const char* thin : {"1e-19", "1e-25", "1e-30"})
        expectRenders({std::string("PaneThin") + thin, geometryScene(block("Box", pane + thin + "\n")), Expect::Lit});
    for (const char* focus : {"2e19", "1e30"}) {
        const std::string camera = "0 0 5\n    Aperture 0.01\n    FocalDistance " + std::string(focus);
        expectRenders({std::string("FocalDistance") + focus, geometryScene(block("Box", pane + "1\n"), camera),
                       Expect::Lit});
    }
    for (const char* index : {"1.9e19", "1e30"}) {
        const std::string glass = "Material\n{\n    Name glass\n    Opacity 0\n    Fresnel 1\n    RefractionIndex " +
                                  std::string(index) + "\n}\nBox\n{\n    Material glass\n" + pane + "1\n}\n";
        expectRenders({std::string("RefractionIndex") + index, geometryScene(glass), Expect::Background});
    }
}

// A unit sphere seen from 1e20 and 1e30 away is far below a pixel; so is a scene of everything far away.
TEST(AbsurdGeometry, ACameraFarAwaySeesTheBackground) {
    const std::string sphere = block("Sphere", "");
    for (const char* pov : {"0 0 1e20", "0 0 1e30", "1e30 -1e30 1e30", "0 0 -1e30"})
        expectRenders({std::string("Camera") + pov, geometryScene(sphere, pov), Expect::Background});
    // A unit sphere 1e30 from the origin seen from 1.5 away, where float's spacing is ~1e23: the camera and
    // the centre differ only in z, exactly, so the sphere is drawn.
    expectRenders({"CameraNextToAFarSphere", geometryScene(block("Sphere", "    Center 1e30 0 0\n    Radius 1\n"),
                                                           "1e30 0 1.5\n    POI 1e30 0 0"),
                   Expect::Drawn});
}

// An area light of zero size (1e-50 rounds to 0) or below any scale lights like a point; one 1e30 wide
// between the camera and the scene is all the camera sees.
TEST(AbsurdGeometry, AreaLightsOfAbsurdSizesRender) {
    const std::string sphere = block("Sphere", "");
    for (const char* size : {"1e-30", "1e-50"}) {
        const std::string light = std::string("AreaLight\n{\n    Position 0 0 3\n    Direction 0 0 -1\n    Width ") +
                                  size + "\n    Height " + size + "\n}\n";
        expectRenders({std::string("AreaLight") + size, geometryScene(sphere, "0 0 5", light), Expect::Anything});
    }
    expectRenders({"AreaLight1e30",
                   geometryScene(sphere, "0 0 5",
                                 "AreaLight\n{\n    Position 0 0 3\n    Direction 0 0 -1\n    Width 1e30\n    Height 1e30\n}\n"),
                   Expect::Lit});
}

// 10⁴ spheres, and 10⁴ boxes, on a 100×100 grid filling the view: read, built and rendered in seconds.
TEST(AbsurdGeometry, TenThousandObjectsRenderQuickly) {
    for (const char* kind : {"Sphere", "Box"}) {
        std::string objects;
        for (int i = 0; i < 100; ++i)
            for (int j = 0; j < 100; ++j) {
                const std::string x = std::to_string(-1.0 + 0.02 * i), y = std::to_string(-1.0 + 0.02 * j);
                objects += std::string(kind) == "Sphere"
                               ? block("Sphere", "    Center " + x + " " + y + " 0\n    Radius 0.012\n")
                               : block("Box", "    Scale 0.012 0.012 0.012\n    Translation " + x + " " + y + " 0\n");
            }
        const auto t0 = std::chrono::steady_clock::now();
        expectRenders({std::string("TenThousand") + kind, geometryScene(objects, "0 0 2.5"), Expect::Drawn});
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0) << kind;
    }
}

// Renders `c`, which must be refused: status 2 within 20 s, `where` (the file's name and line) and `reason` in
// the message, no image.
void expectRefused(const GeometryCase& c, const std::string& where, const std::string& reason) {
    const std::string scene = writeTempFile("refused_" + c.name + ".scene", c.scene);
    const std::string out = tempPath("refused.pfm");
    fs::remove(out);
    const Limited r = runLimited(renderArgs(scene, out, {}), 20);
    EXPECT_EQ(r.signal, 0) << c.name << "\n" << r.errors;
    EXPECT_EQ(r.status, 2) << c.name << "\n" << r.errors;
    EXPECT_NE(r.errors.find("refused_" + c.name + ".scene:" + where), std::string::npos) << r.errors;
    EXPECT_NE(r.errors.find(reason), std::string::npos) << r.errors;
    EXPECT_FALSE(fs::exists(out)) << c.name;
}

// Scales that are each non-zero as written but compose to a map float cannot hold or invert (1e-50 rounds to
// 0; two 1e-30 scales make 1e-60; two 1e30 scales overflow) are refused at the block's line.
TEST(AbsurdGeometry, TransformsThatFloatCannotInvertAreRefusedWithTheirLine) {
    const GeometryCase cases[] = {
        {"BoxScaleRoundsToZero", geometryScene(block("Box", "    Scale 1e-50 1 1\n")), Expect::Anything},
        {"BoxScalesMultiplyToZero",
         geometryScene(block("Box", "    Scale 1e-30 1e-30 1e-30\n    Scale 1e-30 1e-30 1e-30\n")), Expect::Anything},
        {"MeshScalesOverflow", geometryScene(block("Mesh", squareObj() + "    Scale 1e30 1 1\n    Scale 1e30 1 1\n")),
         Expect::Anything},
    };
    for (const GeometryCase& c : cases)
        expectRefused(c, "20:", "transforms compose to a map single precision cannot hold or invert");
}

// Sizes whose squares leave float are refused where they are written (docs/LIMITS.md, Geometry): a radius
// above 1e19 (r² in the sphere's and cylinder's quadratics), a box scaled beyond ~6e18 (its face normal,
// of squared length 1/scale²), a mesh spanning more than 1e9 (its triangles' cross products, squared).
// Rendering them would cost every ordinary ray a rescaling test in the intersection kernels.
TEST(AbsurdGeometry, SizesWhoseSquaresLeaveFloatAreRefusedWithTheirLine) {
    for (const char* huge : {"1e20", "1e30"}) {
        const std::string s(huge);
        expectRefused({"SphereRadius" + s, geometryScene(block("Sphere", "    Radius " + s + "\n")), Expect::Anything},
                      "23:12:", "Radius must be at most 1e19");
        expectRefused({"CylinderRadius" + s,
                       geometryScene(block("Cylinder", "    Radius " + s + "\n    Base 0 -" + s + " 0\n    Height " + s + "\n")),
                       Expect::Anything},
                      "23:12:", "Radius must be at most 1e19");
        expectRefused({"BoxScale" + s, geometryScene(block("Box", "    Scale " + s + " " + s + " " + s + "\n")),
                       Expect::Anything},
                      "20:", "transforms scale an axis by more than about 6e18");
    }
    for (const char* huge : {"1e10", "1e30"})
        expectRefused({std::string("MeshScale") + huge,
                       geometryScene(block("Mesh", squareObj() + "    Scale " + huge + " " + huge + " 1\n")),
                       Expect::Anything},
                      "20:", "a mesh may span at most 1e9");
}

// Lights have no distance falloff (SPEC §5): a light 1e18 away, the bound, lights the front of the unit sphere
// seen from +z with N·L ≈ 1 at its centre, as one 1e6 away does. One 1e30 away is refused: its squared distance
// overflows float, and lighting it would cost every shadow ray a rescaling test.
TEST(AbsurdGeometry, FarLightsLightUpToTheirBoundAndAreRefusedBeyond) {
    const std::string sphere = block("Sphere", "");
    for (const char* kind : {"PointLight", "AreaLight"}) {
        const std::string k(kind);
        auto light = [&](const std::string& z) {
            return k + "\n{\n    Position 0 0 " + z + "\n" + (k == "AreaLight" ? "    Direction 0 0 -1\n" : "") + "}\n";
        };
        std::vector<float> centre;  // the centre pixel's red, for the light at 1e6 and at 1e18
        for (const char* z : {"1e6", "1e18"}) {
            const std::string scene = writeTempFile("far_light.scene", geometryScene(sphere, "0 0 5", light(z)));
            const std::string out = tempPath("far_light.pfm");
            fs::remove(out);
            const Limited r = runLimited(renderArgs(scene, out, {}), 20);
            ASSERT_EQ(r.status, 0) << r.errors;
            const FloatImage image = readPfm(out);
            ASSERT_EQ(image.rgb.size(), 768u);
            for (const float x : image.rgb) ASSERT_TRUE(std::isfinite(x)) << k << " at " << z;
            centre.push_back(image.rgb[3 * (8 * 16 + 8)]);
        }
        EXPECT_GT(centre[1], 0.5f) << k;
        EXPECT_NEAR(centre[1], centre[0], 1e-3f * centre[0]) << k << ": N·L ≈ 1 from 1e6 and from 1e18 away";
        expectRefused({k + "1e30", geometryScene(sphere, "0 0 5", light("1e30")), Expect::Anything}, "18:18:",
                      "Position must be within 1e18 of the origin");
    }
}

// Colours near float's maximum would sum to inf in a sample (16 antialiasing positions of 3e38): refused at
// the line, as is any component beyond ±1e12, where a light's colour times a material's through the
// Cook–Torrance peak and 2^24 summed samples stays inside float.
TEST(AbsurdGeometry, ColoursBeyondTheirBoundAreRefusedWithTheirLine) {
    const std::string settings = "SceneSettings\n{\n    RenderWidth 16\n    RenderHeight 16\n    Antialiasing 16\n";
    expectRefused({"BackgroundColour3e38", settings + "    BackgroundColor 3e38 3e38 3e38\n}\nSphere\n{\n}\nPointLight\n{\n}\n",
                   Expect::Anything},
                  "6:21:", "BackgroundColor components must be within ±1e12");
    expectRefused({"LightColour1e13", geometryScene(block("Sphere", ""), "0 0 5", "PointLight\n{\n    Color 1e13 1 1\n}\n"),
                   Expect::Anything},
                  "18:11:", "Color components must be within ±1e12");
    // At the bound, a white sphere under a light of 1e12 renders finite, and lit.
    expectRenders({"LightColour1e12",
                   geometryScene(block("Sphere", "    Radius 10\n"), "0 0 5", "PointLight\n{\n    Color 1e12 1e12 1e12\n}\n"),
                   Expect::Lit});
}

}  // namespace
}  // namespace trazo::test
