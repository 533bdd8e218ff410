// Partial renders and `trazo merge` as a user (or a Slurm job array) runs them: a seed scene in 4 processes
// merges to one process's render of the same passes; usage errors; a time limit or SIGTERM hands back what was
// rendered; a merge that cannot be made writes nothing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "render/merge.h"
#include "render/partial_file.h"
#include "seed_accumulation.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

namespace fs = std::filesystem;

const std::string kSeed =
    "--render " + sourcePath("scenes/scene1_area.scene") + " --width 64 --height 48 --backend cpu --quiet";

// A PFM's floats (RGB, as stored) after its three header lines.
std::vector<float> readPfm(const std::string& path) {
    const std::string bytes = readFileText(path);
    size_t at = 0;
    for (int line = 0; line < 3; ++line) at = bytes.find('\n', at) + 1;
    std::vector<float> floats((bytes.size() - at) / 4);
    std::memcpy(floats.data(), bytes.data() + at, floats.size() * 4);
    return floats;
}

std::vector<AccumPixel> readAccum(const std::string& path, PartialHeader& header) {
    std::vector<AccumPixel> accum;
    std::string error;
    EXPECT_TRUE(readPartialFile(path, header, accum, error)) << error;
    return accum;
}

TEST(PartialCli, FourProcessesMergeToOneProcessOfTheSamePasses) {
    const std::string dir = freshDir("four_parts");
    // --passes 0:N -o is --spp N's image, bit for bit.
    CommandResult r = runTrazo(kSeed + " --passes 0:16 -o " + dir + "/single.pfm");
    ASSERT_EQ(r.status, 0) << r.errors;
    r = runTrazo(kSeed + " --spp 16 -o " + dir + "/spp.pfm");
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(readFileText(dir + "/single.pfm"), readFileText(dir + "/spp.pfm"));
    r = runTrazo(kSeed + " --passes 0:16 --partial " + dir + "/whole.part");
    ASSERT_EQ(r.status, 0) << r.errors;

    const std::vector<std::string> ranges{"0:3", "3:8", "8:9", "9:16"};
    std::string parts;
    for (auto it = ranges.rbegin(); it != ranges.rend(); ++it) {  // listed to merge in reverse
        const std::string part = dir + "/p" + it->substr(0, it->find(':')) + ".part";
        r = runTrazo(kSeed + " --passes " + *it + " --partial " + part);
        ASSERT_EQ(r.status, 0) << r.errors;
        parts += " " + part;
    }
    EXPECT_EQ(listDir(dir).size(), 7u) << "a partial render writes no image";
    r = runTrazo("merge" + parts + " -o " + dir + "/merged.pfm --partial " + dir + "/merged.part --stats " + dir +
              "/merged.json");
    ASSERT_EQ(r.status, 0) << r.errors;
    EXPECT_NE(r.errors.find("trazo: merge: estimated relative error "), std::string::npos) << r.errors;

    PartialHeader wholeHeader, mergedHeader;
    const std::vector<AccumPixel> whole = readAccum(dir + "/whole.part", wholeHeader);
    const std::vector<AccumPixel> merged = readAccum(dir + "/merged.part", mergedHeader);
    EXPECT_EQ(fingerprintDifference(wholeHeader.fingerprint, mergedHeader.fingerprint), "");
    EXPECT_EQ(formatRanges(mergedHeader.passes), "0:16");
    EXPECT_EQ(mergedHeader.parts, 4u);
    const MergeComparison c = expectWithinMergeBound(merged, whole, 16);
    std::printf("[ cli ] %zu of %zu pixels identical in every double, %zu in every float\n", c.identicalPixels,
                c.pixels, c.identicalFloats);

    // The images: every float within one ulp of the single render's.
    const std::vector<float> a = readPfm(dir + "/single.pfm"), b = readPfm(dir + "/merged.pfm");
    ASSERT_EQ(a.size(), 64u * 48u * 3u);
    ASSERT_EQ(b.size(), a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        uint32_t ia, ib;
        std::memcpy(&ia, &a[i], 4);
        std::memcpy(&ib, &b[i], 4);
        ASSERT_LE(ia > ib ? ia - ib : ib - ia, 1u) << "float " << i << ": " << a[i] << " vs " << b[i];
    }
    const std::string json = readFileText(dir + "/merged.json");
    for (const char* key : {"\"parts\": 4", "\"spp\": 16", "\"passes\": \"0:16\"", "\"rays\"", "\"render_s\"",
                            "\"estimated_rel_error\"", "\"width\": 64"})
        EXPECT_NE(json.find(key), std::string::npos) << key << " missing in " << json;
}

TEST(PartialCli, UsageErrors) {
    const std::string part = tempPath("usage.part");
    for (const std::string& args : {kSeed + " --passes 0:4 --partial " + part + " -o x.png",
                                    kSeed + " --passes 4:4 --partial " + part, kSeed + " --passes 0:4 --spp 4",
                                    kSeed + " --partial " + part + " --target-error 0.1",
                                    kSeed + " --devices 0", kSeed + " --backend cuda --devices 0,0",
                                    std::string("merge ") + part})
        EXPECT_EQ(runTrazo(args).status, 2) << args;
    EXPECT_FALSE(fs::exists(part));
}

TEST(PartialCli, TimeLimitWritesThePassesRendered) {
    const std::string part = tempPath("timed.part");
    fs::remove(part);
    const CommandResult r = runTrazo(kSeed + " --passes 8:100000 --time 1 --partial " + part);
    ASSERT_EQ(r.status, 0) << r.errors;
    PartialHeader h;
    const std::vector<AccumPixel> accum = readAccum(part, h);
    ASSERT_EQ(h.passes.size(), 1u);
    EXPECT_EQ(h.passes[0].first, 8u);
    EXPECT_GT(h.passes[0].end, 8u);
    EXPECT_LT(h.passes[0].end, 100000u);
    EXPECT_EQ(h.requested, (PassRange{8, 100000}));
    EXPECT_EQ(accum[0].count, (double)h.passes[0].count());
    EXPECT_NE(r.errors.find("trazo: stopped by --time after passes " + formatRange(h.passes[0]) + " of 8:100000"),
              std::string::npos) << r.errors;
    // The merge names what the time limit left out.
    const CommandResult m = runTrazo("merge --allow-gaps " + part + " -o " + tempPath("timed.pfm"));
    EXPECT_EQ(m.status, 0) << m.errors;
    EXPECT_NE(m.errors.find("passes 0:8 are missing"), std::string::npos) << m.errors;
    EXPECT_NE(m.errors.find("passes " + std::to_string(h.passes[0].end) + ":100000 are missing"), std::string::npos)
        << m.errors;
}

TEST(PartialCli, SigtermFinishesTheBatchAndWritesThePassesRendered) {
    const std::string part = tempPath("signalled.part"), status = tempPath("signalled.status");
    fs::remove(part);
    const std::string errors = tempPath("signalled.err");
    const std::string command = trazoBinary() + " " + kSeed + " --passes 0:1000000 --partial " + part + " 2>" +
                                errors + " & pid=$!; sleep 2; kill -TERM $pid; wait $pid; echo $? >" + status;
    ASSERT_EQ(std::system(("bash -c '" + command + "'").c_str()), 0);
    EXPECT_EQ(readFileText(status), "3\n") << readFileText(errors);
    PartialHeader h;
    readAccum(part, h);
    ASSERT_EQ(h.passes.size(), 1u);
    EXPECT_GT(h.passes[0].end, 0u);
    EXPECT_NE(readFileText(errors).find("stopped by signal 15 after passes " + formatRange(h.passes[0])),
              std::string::npos)
        << readFileText(errors);
}

TEST(PartialCli, MergeRefusalsWriteNothing) {
    const std::string dir = freshDir("merge_refusals");
    ASSERT_EQ(runTrazo(kSeed + " --passes 0:2 --partial " + dir + "/a.part").status, 0);
    ASSERT_EQ(runTrazo(kSeed + " --passes 4:6 --partial " + dir + "/b.part").status, 0);
    ASSERT_EQ(runTrazo(kSeed + " --passes 2:4 --seed 9 --partial " + dir + "/c.part").status, 0);
    const std::string out = " -o " + dir + "/out.png --stats " + dir + "/out.json --partial " + dir + "/out.part";

    CommandResult r = runTrazo("merge " + dir + "/a.part " + dir + "/b.part" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find("trazo: merge: passes 2:4 are missing"), std::string::npos) << r.errors;

    r = runTrazo("merge " + dir + "/a.part " + dir + "/b.part " + dir + "/c.part" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find(dir + "/c.part: cannot be merged with " + dir + "/a.part: they differ in seed (0 vs 9)"),
              std::string::npos) << r.errors;

    std::string bytes = readFileText(dir + "/b.part");
    std::ofstream(dir + "/b.part", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    r = runTrazo("merge --allow-gaps " + dir + "/a.part " + dir + "/b.part" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.errors.find(dir + "/b.part: truncated: " + std::to_string(bytes.size() / 2) + " bytes of " +
                            std::to_string(bytes.size())),
              std::string::npos) << r.errors;
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"a.part", "b.part", "c.part"}));

    r = runTrazo("merge " + dir + "/a.part" + out);  // a merge that can be made writes all three
    EXPECT_EQ(r.status, 0) << r.errors;
    EXPECT_EQ(listDir(dir).size(), 6u);
}

}  // namespace
}  // namespace trazo::test
