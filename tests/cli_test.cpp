// The trazo command line as a user meets it: exit codes, FILE:LINE errors, no image on failure, stats.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>

#include "backends/backend.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

namespace fs = std::filesystem;

struct CommandResult {
    int status = -1;
    std::string errors;  // stderr
};

CommandResult runTrazo(const std::string& arguments) {
    const std::string errFile = tempPath("stderr.txt");
    const std::string command = trazoBinary() + " " + arguments + " 2>" + errFile + " >/dev/null";
    const int raw = std::system(command.c_str());
    CommandResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.errors = readFileText(errFile);
    return r;
}

std::string writeFile(const std::string& name, const std::string& text) {
    const std::string path = tempPath(name);
    std::ofstream(path) << text;
    return path;
}

const char* kSmallScene =
    "SceneSettings\n{\n    RenderWidth 16\n    RenderHeight 12\n}\n"
    "Camera\n{\n    POV 0 0 5\n}\n"
    "Material\n{\n    Name white\n}\n"
    "Sphere\n{\n    Material white\n}\n"
    "PointLight\n{\n    Position 2 2 2\n}\n";

TEST(Cli, RendersAFileAndWritesStats) {
    const std::string scene = writeFile("small.scene", kSmallScene);
    const std::string out = tempPath("small.png"), stats = tempPath("small.json");
    fs::remove(out);
    const CommandResult r = runTrazo("--render " + scene + " -o " + out + " --stats " + stats + " --quiet");
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_TRUE(fs::exists(out));
    const std::string json = readFileText(stats);
    for (const char* key : {"\"parse_s\"", "\"read_s\"", "\"build_s\"", "\"upload_s\"", "\"render_s\"",
                            "\"peak_rss_mb\"", "\"spp\"", "\"rays\"", "\"mrays_per_s\"", "\"backend\"", "\"device\"",
                            "\"blocks\"", "\"width\": 16", "\"height\": 12"})
        EXPECT_NE(json.find(key), std::string::npos) << key << " missing in " << json;
    // --backend auto takes CUDA on a machine with a device: it must say which it used, and the stats agree.
    const bool onCuda = r.errors.find("rendering on cuda") != std::string::npos;
    EXPECT_TRUE(onCuda || r.errors.find("rendering on cpu") != std::string::npos) << r.errors;
    EXPECT_NE(json.find(onCuda ? "\"backend\": \"cuda\"" : "\"backend\": \"cpu\""), std::string::npos) << json;
}

TEST(Cli, BadSceneGivesFileLineExitTwoAndNoImage) {
    const std::string scene = writeFile("bad.scene",
                                        "Camera\n{\n    POV 0 0 5\n}\nSphere\n{\n    Radius 1\n    Radus 2\n}\n");
    const std::string out = tempPath("bad.png");
    fs::remove(out);
    const CommandResult r = runTrazo("--render " + scene + " -o " + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("bad.scene:8:"), std::string::npos) << r.errors;
    EXPECT_NE(r.errors.find("Radius"), std::string::npos) << "expected a did-you-mean hint: " << r.errors;
    EXPECT_FALSE(fs::exists(out));
}

// A malformed --blocks is a usage error (exit 2, the option and the accepted forms named, no image); a good one
// is what the stats report.
TEST(Cli, BlocksAreParsedOrRefused) {
    const std::string scene = writeFile("blocks.scene", kSmallScene);
    const std::string out = tempPath("blocks.png"), stats = tempPath("blocks.json");
    fs::remove(out);
    for (const char* bad : {"0", "1,2", "x"}) {
        const CommandResult r = runTrazo("--render " + scene + " -o " + out + " --blocks " + bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.errors.find(std::string("--blocks ") + bad + ":"), std::string::npos) << r.errors;
        EXPECT_FALSE(fs::exists(out));
    }
    const CommandResult r =
        runTrazo("--render " + scene + " -o " + out + " --blocks 1,whole,3,1 --quiet --stats " + stats);
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_NE(readFileText(stats).find("\"blocks\": \"1,whole,3,1\""), std::string::npos);
}

TEST(Cli, FailedRenderLeavesAnExistingImageAlone) {
    const std::string scene = writeFile("bad2.scene", "Sphere\n{\n    Radius -1\n}\n");
    const std::string out = writeFile("keep.png", "previous contents");
    EXPECT_EQ(runTrazo("--render " + scene + " -o " + out).status, 2);
    std::ifstream in(out);
    std::string contents;
    std::getline(in, contents);
    EXPECT_EQ(contents, "previous contents");
}

TEST(Cli, MissingSceneFileIsABadSceneError) {
    const CommandResult r = runTrazo("--render " + tempPath("does_not_exist.scene") + " -o " + tempPath("x.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("does_not_exist.scene"), std::string::npos) << r.errors;
}

TEST(Cli, BadUsageExitsTwo) {
    const std::string scene = writeFile("usage.scene", kSmallScene);
    EXPECT_EQ(runTrazo("--render " + scene + " -o " + tempPath("out.xyz")).status, 2);
    EXPECT_EQ(runTrazo("--render " + scene + " --spp 0").status, 2);
    EXPECT_EQ(runTrazo("--render " + scene + " --backend metal").status, 2);
    EXPECT_EQ(runTrazo("--render " + scene + " --width 20000").status, 2);
    EXPECT_EQ(runTrazo("").status, 2);
    EXPECT_EQ(runTrazo("--help").status, 0);
    EXPECT_EQ(runTrazo("--version").status, 0);
}

TEST(Cli, CudaRequestedWithoutADeviceIsARuntimeFailure) {
    std::string device;
    if (cudaDeviceAvailable(device)) GTEST_SKIP() << "a CUDA device is present: " << device;
    const std::string scene = writeFile("cuda.scene", kSmallScene);
    const std::string out = tempPath("cuda.png");
    fs::remove(out);
    const CommandResult r = runTrazo("--render " + scene + " --backend cuda -o " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.errors.find("CUDA"), std::string::npos) << r.errors;
    EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, TimeBudgetStopsTheRender) {
    const std::string scene = writeFile("timed.scene", kSmallScene);
    const std::string stats = tempPath("timed.json");
    const CommandResult r =
        runTrazo("--render " + scene + " -o " + tempPath("timed.bmp") + " --time 0.3 --quiet --stats " + stats);
    ASSERT_EQ(r.status, 0) << r.errors;
    const std::string json = readFileText(stats);
    const auto pos = json.find("\"render_s\": ");
    ASSERT_NE(pos, std::string::npos);
    EXPECT_LT(std::stod(json.substr(pos + 12)), 1.0);
}

// Every scene shipped in scenes/ renders (tiny, one pass) with nothing of it left out (no warning).
TEST(Cli, EveryShippedSceneRenders) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(sourcePath("scenes"))) {
        if (entry.path().extension() != ".scene") continue;
        ++count;
        const std::string out = tempPath(entry.path().stem().string() + ".png");
        const CommandResult r =
            runTrazo("--render " + entry.path().string() + " -o " + out + " --width 24 --height 24 --spp 1 --quiet");
        EXPECT_EQ(r.status, 0) << entry.path() << "\n" << r.errors;
        EXPECT_TRUE(fs::exists(out)) << entry.path();
        EXPECT_EQ(r.errors.find("warning"), std::string::npos) << entry.path() << "\n" << r.errors;
    }
    EXPECT_GE(count, 19);  // the seed's 19 scene files (the 20th seed file is the .csg)
}

}  // namespace
}  // namespace trazo::test
