// Partial files: what is written reads back bit for bit; a short, damaged or foreign file is an error naming
// it; fingerprints name the field that differs.
#include "render/partial_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "render/xxhash64.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo {
namespace {

namespace fs = std::filesystem;
using test::tempPath;

PartialHeader sampleHeader(uint32_t width, uint32_t height) {
    PartialHeader h;
    h.fingerprint.scenePath = "scenes/a b\nc.scene";  // a space and a newline survive the text header
    h.fingerprint.sceneHash = 0x0123456789abcdefull;
    h.fingerprint.assets = {{"scenes/assets/head.obj", 42}, {"tex.png", 0xffffffffffffffffull}};
    h.fingerprint.width = width;
    h.fingerprint.height = height;
    h.fingerprint.seed = 7;
    h.fingerprint.blocks = "1,100,1,5";
    h.fingerprint.fullCycle = 100;
    h.fingerprint.version = "trazo 0.1.0";
    h.passes = {{16, 24}};
    h.requested = {16, 32};
    h.parts = 3;
    h.rays = 123456789012ull;
    h.seconds = 0.1 + 0.2;  // not a short decimal: must round-trip exactly
    h.backend = "cpu (2 CPU threads)";
    return h;
}

std::vector<AccumPixel> sampleAccum(size_t pixels, bool uniformCounts) {
    std::vector<AccumPixel> accum(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        const double x = 1.0 / (double)(i + 3);
        accum[i] = AccumPixel{{x, 2 * x, x / 3}, uniformCounts ? 8.0 : 8.0 + (double)(i % 3), {x / 7, x, 0.0}, 4.0};
    }
    return accum;
}

void expectSameHeader(const PartialHeader& a, const PartialHeader& b) {
    EXPECT_EQ(fingerprintDifference(a.fingerprint, b.fingerprint), "");
    EXPECT_EQ(a.fingerprint.scenePath, b.fingerprint.scenePath);
    ASSERT_EQ(a.fingerprint.assets.size(), b.fingerprint.assets.size());
    EXPECT_EQ(a.fingerprint.assets[0].path, b.fingerprint.assets[0].path);
    EXPECT_EQ(a.passes, b.passes);
    EXPECT_EQ(a.requested, b.requested);
    EXPECT_EQ(a.parts, b.parts);
    EXPECT_EQ(a.rays, b.rays);
    EXPECT_EQ(a.seconds, b.seconds);
    EXPECT_EQ(a.backend, b.backend);
}

TEST(PartialFile, ReadsBackBitForBitWithUniformAndPerPixelCounts) {
    for (const bool uniform : {true, false}) {
        const std::string path = tempPath(uniform ? "uniform.part" : "perpixel.part");
        const PartialHeader header = sampleHeader(5, 3);
        const std::vector<AccumPixel> accum = sampleAccum(15, uniform);
        std::string error;
        ASSERT_TRUE(writePartialFile(path, header, accum, error)) << error;
        // Uniform counts are stored once: 6 doubles a pixel instead of 8.
        const std::string text = test::readFileText(path);
        const size_t headerBytes = text.find("\n\n") + 2;
        EXPECT_EQ(text.size() - headerBytes, (uniform ? 16 + 15 * 48 : 15 * 64) + 8u);
        EXPECT_NE(text.find(uniform ? "counts: uniform\n" : "counts: per-pixel\n"), std::string::npos);

        PartialHeader readHeader, fullHeader;
        std::vector<AccumPixel> readAccum;
        ASSERT_TRUE(readPartialHeader(path, readHeader, error)) << error;
        ASSERT_TRUE(readPartialFile(path, fullHeader, readAccum, error)) << error;
        expectSameHeader(header, readHeader);
        expectSameHeader(header, fullHeader);
        ASSERT_EQ(readAccum.size(), accum.size());
        EXPECT_EQ(std::memcmp(readAccum.data(), accum.data(), accum.size() * sizeof(AccumPixel)), 0);
    }
}

// SPEC §7's image transform rides in a `display:` line only where it is not the identity; a bad one is refused.
TEST(PartialFile, TheDisplayLineReadsBackAndIsLeftOutWhenItIsTheIdentity) {
    const std::string path = tempPath("display.part");
    PartialHeader header = sampleHeader(2, 1);
    std::string error;
    ASSERT_TRUE(writePartialFile(path, header, sampleAccum(2, true), error)) << error;
    EXPECT_EQ(test::readFileText(path).find("display:"), std::string::npos);
    header.fingerprint.exposure = -2.3f;  // not a short decimal in binary: written with a float's 9 digits
    header.fingerprint.srgb = true;
    ASSERT_TRUE(writePartialFile(path, header, sampleAccum(2, true), error)) << error;
    const std::string text = test::readFileText(path);
    EXPECT_NE(text.find("\nsettings: full-cycle=100\ndisplay: exposure=-2.29999995 view=srgb\n"), std::string::npos)
        << text.substr(0, 400);
    PartialHeader back;
    ASSERT_TRUE(readPartialHeader(path, back, error)) << error;
    EXPECT_EQ(back.fingerprint.exposure, -2.3f);
    EXPECT_TRUE(back.fingerprint.srgb);
    expectSameHeader(header, back);
    // A header that names a view it does not know, or an exposure past ±64 stops, is not a trazo partial file's.
    for (const char* bad : {"exposure=-2.29999995 view=gamma", "exposure=65 view=srgb", "exposure=nan view=srgb",
                            "exposure= view=srgb", "view=srgb"}) {
        std::string damaged = text;
        const size_t at = damaged.find("exposure=-2.29999995 view=srgb");
        damaged.replace(at, std::strlen("exposure=-2.29999995 view=srgb"), bad);
        const std::string badPath = tempPath("display_bad.part");
        std::ofstream(badPath, std::ios::binary) << damaged;
        EXPECT_FALSE(readPartialHeader(badPath, back, error)) << bad;
        EXPECT_NE(error.find("bad value"), std::string::npos) << bad << ": " << error;
    }
}

// Writes a good file and returns its bytes.
std::string goodFile(const std::string& path) {
    std::string error;
    EXPECT_TRUE(writePartialFile(path, sampleHeader(5, 3), sampleAccum(15, true), error)) << error;
    return test::readFileText(path);
}

void writeBytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

TEST(PartialFile, TruncatedFileSaysHowManyBytesOfHowMany) {
    const std::string path = tempPath("truncated.part");
    const std::string bytes = goodFile(path);
    const size_t headerEnd = bytes.find("\n\n") + 2;
    for (size_t keep : {bytes.size() - 1, headerEnd + 100, headerEnd}) {
        writeBytes(path, bytes.substr(0, keep));
        PartialHeader h;
        std::vector<AccumPixel> accum;
        std::string error;
        EXPECT_FALSE(readPartialHeader(path, h, error));
        EXPECT_EQ(error, path + ": truncated: " + std::to_string(keep) + " bytes of " + std::to_string(bytes.size()));
        EXPECT_FALSE(readPartialFile(path, h, accum, error));
        EXPECT_EQ(error, path + ": truncated: " + std::to_string(keep) + " bytes of " + std::to_string(bytes.size()));
    }
    writeBytes(path, bytes.substr(0, 40));  // inside the header
    PartialHeader h;
    std::string error;
    EXPECT_FALSE(readPartialHeader(path, h, error));
    EXPECT_EQ(error, path + ": truncated: 40 bytes, and its header does not end");
    writeBytes(path, bytes + "x");
    EXPECT_FALSE(readPartialHeader(path, h, error));
    EXPECT_NE(error.find("1 bytes after the end of the data"), std::string::npos) << error;
}

TEST(PartialFile, ADamagedByteAnywhereIsCaughtByTheChecksum) {
    const std::string path = tempPath("corrupt.part");
    const std::string bytes = goodFile(path);
    const size_t seedAt = bytes.find("seed: 7") + 6;
    for (size_t at : {bytes.size() / 2, bytes.size() - 9, bytes.size() - 1, seedAt}) {
        std::string damaged = bytes;
        damaged[at] = damaged[at] == '8' ? '9' : '8';
        writeBytes(path, damaged);
        PartialHeader h;
        std::vector<AccumPixel> accum;
        std::string error;
        EXPECT_FALSE(readPartialFile(path, h, accum, error)) << "byte " << at;
        EXPECT_EQ(error.rfind(path + ": corrupt: its checksum is xxh64 ", 0), 0u) << error;
    }
}

TEST(PartialFile, ForeignOrFutureFilesAreRefusedByName) {
    const std::string path = tempPath("foreign.part");
    PartialHeader h;
    std::string error;
    writeBytes(path, "P6\n5 3\n255\n...............");
    EXPECT_FALSE(readPartialHeader(path, h, error));
    EXPECT_EQ(error, path + ": not a trazo partial file (it does not start with \"TRAZO PARTIAL\")");
    std::string bytes = goodFile(path);
    bytes.replace(bytes.find("TRAZO PARTIAL 1"), 15, "TRAZO PARTIAL 9");
    writeBytes(path, bytes);
    EXPECT_FALSE(readPartialHeader(path, h, error));
    EXPECT_NE(error.find("format version 9; this trazo reads version 1"), std::string::npos) << error;
    EXPECT_FALSE(readPartialHeader(tempPath("absent.part"), h, error));
    EXPECT_EQ(error, tempPath("absent.part") + ": No such file or directory");
}

TEST(PartialFile, FingerprintNamesTheFieldThatDiffers) {
    const Fingerprint base = sampleHeader(5, 3).fingerprint;
    EXPECT_EQ(fingerprintDifference(base, base), "");
    Fingerprint other = base;
    other.scenePath = "/elsewhere/a.scene";  // another mount of the same bytes: still the same render
    EXPECT_EQ(fingerprintDifference(base, other), "");
    const std::vector<std::pair<std::string, std::function<void(Fingerprint&)>>> edits{
        {"scene", [](Fingerprint& f) { f.sceneHash ^= 1; }},
        {"assets", [](Fingerprint& f) { f.assets[1].hash ^= 1; }},
        {"assets", [](Fingerprint& f) { f.assets.pop_back(); }},
        {"settings", [](Fingerprint& f) { f.fullCycle = 50; }},
        {"size", [](Fingerprint& f) { f.width = 6; }},
        {"size", [](Fingerprint& f) { f.height = 4; }},
        {"seed", [](Fingerprint& f) { f.seed = 8; }},
        {"blocks", [](Fingerprint& f) { f.blocks = "whole"; }},
        {"version", [](Fingerprint& f) { f.version = "trazo 0.2.0"; }},
        {"display", [](Fingerprint& f) { f.exposure = 1.0f; }},
        {"display", [](Fingerprint& f) { f.srgb = true; }},
    };
    for (const auto& [field, edit] : edits) {
        Fingerprint changed = base;
        edit(changed);
        EXPECT_EQ(fingerprintDifference(base, changed).rfind(field + " (", 0), 0u)
            << field << ": " << fingerprintDifference(base, changed);
    }
    Fingerprint seed = base;
    seed.seed = 8;
    EXPECT_EQ(fingerprintDifference(base, seed), "seed (7 vs 8)");
}

TEST(PartialFile, FingerprintHashesTheSceneAndEveryAssetItReads) {
    Diagnostics diags;
    const Scene scene = readSceneFile(test::sourcePath("scenes/scene3_csg.scene"), diags);
    ASSERT_FALSE(diags.hasErrors());
    Fingerprint f;
    std::string error;
    ASSERT_TRUE(hashSceneFiles(scene, f, error)) << error;
    const std::string sceneBytes = test::readFileText(scene.path);
    EXPECT_EQ(f.sceneHash, xxhash64(sceneBytes.data(), sceneBytes.size()));
    ASSERT_EQ(f.assets.size(), scene.csgs.size());
    ASSERT_FALSE(f.assets.empty());
    const std::string csgBytes = test::readFileText(scene.csgs[0].source);
    EXPECT_EQ(f.assets[0].path, scene.csgs[0].source);
    EXPECT_EQ(f.assets[0].hash, xxhash64(csgBytes.data(), csgBytes.size()));
}

}  // namespace
}  // namespace trazo
