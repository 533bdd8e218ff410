// The trazo command line as a user meets it: exit codes, FILE:LINE errors, no image on failure, stats.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "backends/backend.h"
#include "fetched_assets.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

namespace fs = std::filesystem;

const char* kSmallScene =
    "SceneSettings\n{\n    RenderWidth 16\n    RenderHeight 12\n}\n"
    "Camera\n{\n    POV 0 0 5\n}\n"
    "Material\n{\n    Name white\n}\n"
    "Sphere\n{\n    Material white\n}\n"
    "PointLight\n{\n    Position 2 2 2\n}\n";

TEST(Cli, RendersAFileAndWritesStats) {
    const std::string scene = writeTempFile("small.scene", kSmallScene);
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
    const std::string scene = writeTempFile("bad.scene",
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
    const std::string scene = writeTempFile("blocks.scene", kSmallScene);
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
    const std::string scene = writeTempFile("bad2.scene", "Sphere\n{\n    Radius -1\n}\n");
    const std::string out = writeTempFile("keep.png", "previous contents");
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
    const std::string scene = writeTempFile("usage.scene", kSmallScene);
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
    const std::string scene = writeTempFile("cuda.scene", kSmallScene);
    const std::string out = tempPath("cuda.png");
    fs::remove(out);
    const CommandResult r = runTrazo("--render " + scene + " --backend cuda -o " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.errors.find("CUDA"), std::string::npos) << r.errors;
    EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, TimeBudgetStopsTheRender) {
    const std::string scene = writeTempFile("timed.scene", kSmallScene);
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
    std::string absent;  // the scenes not rendered, and why
    for (const auto& entry : fs::directory_iterator(sourcePath("scenes"))) {
        if (entry.path().extension() != ".scene") continue;
        ++count;
        if (const std::string why = absentFetchedAsset(entry.path().string()); !why.empty()) {
            absent += "\n" + why;
            continue;
        }
        const std::string out = tempPath(entry.path().stem().string() + ".png");
        const CommandResult r =
            runTrazo("--render " + entry.path().string() + " -o " + out + " --width 24 --height 24 --spp 1 --quiet");
        EXPECT_EQ(r.status, 0) << entry.path() << "\n" << r.errors;
        EXPECT_TRUE(fs::exists(out)) << entry.path();
        EXPECT_EQ(r.errors.find("warning"), std::string::npos) << entry.path() << "\n" << r.errors;
    }
    EXPECT_GE(count, 19);  // the seed's 19 scene files (the 20th seed file is the .csg)
    if (!absent.empty()) GTEST_SKIP() << "not rendered:" << absent;
}

}  // namespace
}  // namespace trazo::test

// Hostile input (issue 18): the scene-text path. Each case is a reproducer written here into the per-process
// temp folder: status 2, FILE:LINE and a plain reason, no image, and never a hang (every run under `timeout`).
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>

#include "scene/block_lexer.h"

namespace trazo::test {
namespace {

namespace fs = std::filesystem;

using HostileResult = CommandResult;

// trazo --render on `scene`, killed after `seconds` (status 124 then: a hang); the image must not appear.
HostileResult renderHostile(const std::string& scene, const std::string& name, int seconds = 20) {
    const std::string out = tempPath(name + ".png");
    fs::remove(out);
    const HostileResult r = runCommand("timeout -k 5 " + std::to_string(seconds) + " " + trazoBinary() + " --render '" +
                                       scene + "' -o '" + out + "' --width 8 --height 8 --spp 1 --quiet");
    EXPECT_FALSE(fs::exists(out)) << name << ": an image was written";
    return r;
}

size_t lineCount(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

const char* kHostileHead =
    "Camera\n{\n    POV 0 0 5\n}\nMaterial\n{\n    Name white\n}\nPointLight\n{\n    Position 2 2 2\n}\n";  // 12 lines

TEST(CliHostile, HundredThousandNestedBraces) {
    std::string lines = "Sphere\n";
    for (int i = 0; i < 100000; ++i) lines += "{\n";
    const HostileResult r = renderHostile(writeTempFile("nest.scene", lines), "nest");
    EXPECT_EQ(r.status, 2) << r.errors;
    EXPECT_NE(r.errors.find("nest.scene:1: error: unterminated block 'Sphere'"), std::string::npos) << r.errors;
    EXPECT_NE(r.errors.find("too many syntax errors"), std::string::npos) << r.errors;
    EXPECT_LE(lineCount(r.errors), size_t(kMaxLexerErrors) + 10);
    std::string braces = "Sphere";  // and as many as fit on one line (this recursed once a brace)
    while (braces.size() + 2 <= kMaxLineBytes) braces += " {";
    const HostileResult one = renderHostile(writeTempFile("nest1.scene", braces + "\n"), "nest1");
    EXPECT_EQ(one.status, 2) << one.errors;
    EXPECT_NE(one.errors.find("nest1.scene:1:"), std::string::npos) << one.errors;
}

TEST(CliHostile, LongLinesAndHugeFilesAreRefused) {
    const std::string line = "Sphere\n{\n    Radius 1 #" + std::string(kMaxLineBytes, '#') + "\n}\n";
    const HostileResult r = renderHostile(writeTempFile("long.scene", kHostileHead + line), "long");
    EXPECT_EQ(r.status, 2) << r.errors;
    EXPECT_NE(r.errors.find("long.scene:15: error: line too long ("), std::string::npos) << r.errors;
    // A file that claims 2^31 + 1 bytes (sparse: nothing is written) is refused before it is read.
    const std::string huge = writeTempFile("huge.scene", kSmallScene);
    ASSERT_EQ(::truncate(huge.c_str(), (off_t(1) << 31) + 1), 0);
    const HostileResult h = renderHostile(huge, "huge", 10);
    EXPECT_EQ(h.status, 2) << h.errors;
    EXPECT_NE(h.errors.find("huge.scene: error: cannot read scene file: file too large (2147483649 bytes"),
              std::string::npos)
        << h.errors;
    fs::remove(huge);
    // A CSG file over the scene-file limit, named by a Source line: that line, and the reason.
    const std::string csg = writeTempFile("huge.csg", "");
    ASSERT_EQ(::truncate(csg.c_str(), off_t(kMaxSceneFileBytes) + 1), 0);
    const HostileResult c = renderHostile(
        writeTempFile("hugecsg.scene", std::string(kHostileHead) + "CSG\n{\n    Material white\n    Source \"huge.csg\"\n}\n"),
        "hugecsg");
    EXPECT_EQ(c.status, 2) << c.errors;
    EXPECT_NE(c.errors.find("hugecsg.scene:16:"), std::string::npos) << c.errors;
    EXPECT_NE(c.errors.find("file too large"), std::string::npos) << c.errors;
    fs::remove(csg);
}

// A FIFO blocks an ordinary open until a writer comes, which never happens: as a Source of every kind and as
// the scene itself it is refused before it is opened.
TEST(CliHostile, FifoIsRefusedNotWaitedFor) {
    const std::string fifo = tempPath("pipe.fifo");
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const struct {
        const char* name;
        std::string block;
    } cases[] = {
        {"fifomesh", "Mesh\n{\n    Material white\n    Source \"pipe.fifo\"\n}\n"},
        {"fifocsg", "CSG\n{\n    Material white\n    Source \"pipe.fifo\"\n}\n"},
        {"fifotex", "Texture\n{\n    Name t\n    Source \"pipe.fifo\"\n}\n"},
    };
    for (const auto& c : cases) {
        const HostileResult r =
            renderHostile(writeTempFile(std::string(c.name) + ".scene", kHostileHead + c.block), c.name);
        EXPECT_EQ(r.status, 2) << c.name << ": " << r.errors;
        EXPECT_NE(r.errors.find(std::string(c.name) + ".scene:16:"), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find("not a regular file (a FIFO)"), std::string::npos) << r.errors;
    }
    const HostileResult s = renderHostile(fifo, "fifoscene");
    EXPECT_EQ(s.status, 2) << s.errors;
    EXPECT_NE(s.errors.find("pipe.fifo: error: cannot read scene file: not a regular file (a FIFO)"),
              std::string::npos)
        << s.errors;
    fs::remove(fifo);
}

// A NUL inside a Source path would open the file named by the bytes before it and cut every message short.
TEST(CliHostile, NulInASourcePathIsAnError) {
    writeTempFile("nul.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string mesh = std::string("Mesh\n{\n    Material white\n    Source \"nul.obj") + '\0' + "x.obj\"\n}\n";
    const HostileResult r = renderHostile(writeTempFile("nul.scene", kHostileHead + mesh), "nul");
    EXPECT_EQ(r.status, 2) << r.errors;
    EXPECT_NE(r.errors.find("nul.scene:16:20: error: NUL byte in the text (not allowed)"), std::string::npos)
        << r.errors;
    EXPECT_EQ(lineCount(r.errors), 1u) << r.errors;  // no "missing required parameter" after it
}

// `Source ""` used to drop the texture, mesh or CSG without a word and render the rest.
TEST(CliHostile, EmptySourceIsAnError) {
    for (const char* block : {"Texture\n{\n    Name t\n    Source \"\"\n}\n",
                              "Mesh\n{\n    Material white\n    Source \"\"\n}\n",
                              "CSG\n{\n    Material white\n    Source \"\"\n}\n"}) {
        const HostileResult r = renderHostile(writeTempFile("empty.scene", kHostileHead + std::string(block)), "empty");
        EXPECT_EQ(r.status, 2) << block << r.errors;
        EXPECT_NE(r.errors.find("empty.scene:16:12: error: Source: empty path"), std::string::npos) << r.errors;
    }
}

}  // namespace
}  // namespace trazo::test
