// Tests of the environment map reader: its errors at the EnvironmentMap line, texels that are not radiance made
// so with one warning, the size bound, PFM's row order (the format's, not FreeImage's), and the generated sky of
// scenes/assets.
#include "scene/environment_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "image/image_writer.h"
#include "test_paths.h"

namespace trazo {
namespace {

const SourceLocation kAt{"sky.scene", 7, 0};

// A little-endian PFM (scale −1) of width × height RGB texels, `rgb` bottom row first as PFM stores them.
std::string pfm(int width, int height, const std::vector<float>& rgb) {
    std::string out = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
    const size_t header = out.size();
    out.resize(header + rgb.size() * 4);
    std::memcpy(out.data() + header, rgb.data(), rgb.size() * 4);  // x86 and ARM hosts are little-endian
    return out;
}

void expectErrorAtTheLine(const Diagnostics& diags, const std::string& path, const std::string& reason) {
    ASSERT_EQ(diags.items.size(), 1u);
    const Diagnostic& d = diags.items[0];
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_EQ(formatDiagnostic(d).rfind("sky.scene:7:", 0), 0u) << formatDiagnostic(d);
    EXPECT_NE(d.message.find("environment map '" + path + "'"), std::string::npos) << d.message;
    EXPECT_NE(d.message.find(reason), std::string::npos) << d.message;
}

TEST(EnvironmentReader, MissingFileIsAnErrorWithTheOsReason) {
    Diagnostics diags;
    const std::string path = test::tempPath("no_such_sky.pfm");
    EXPECT_EQ(readEnvironmentMap(path, kAt, diags), nullptr);
    expectErrorAtTheLine(diags, path, "No such file or directory");
    EXPECT_TRUE(diags.hasErrors()) << "the app's status 2, as for a texture";
}

TEST(EnvironmentReader, MalformedFilesAreErrors) {
    struct Bad {
        const char* name;
        std::string bytes;
        const char* reason;
    };
    const Bad bad[] = {
        {"text.pfm", "not an image at all\n", "not a PNG, JPEG, BMP, EXR or PFM file"},
        {"radiance.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n", "Radiance HDR"},
        {"short.pfm", pfm(4, 2, std::vector<float>(24, 1.0f)).substr(0, 40), "cannot decode"},
        {"folder.pfm", "", "Is a directory"},  // empty bytes: a folder of that name
    };
    for (const Bad& b : bad) {
        SCOPED_TRACE(b.name);
        const std::string path = b.bytes.empty() ? test::freshDir(b.name) : test::writeTempFile(b.name, b.bytes);
        Diagnostics diags;
        EXPECT_EQ(readEnvironmentMap(path, kAt, diags), nullptr);
        expectErrorAtTheLine(diags, path, b.reason);
    }
}

// Larger than kMaxTextureTexels (8192 × 4096): refused from the header, before anything is decoded or allocated.
TEST(EnvironmentReader, HugeMapIsRefusedFromItsHeader) {
    Diagnostics diags;
    const std::string path = test::writeTempFile("huge.pfm", "PF\n16384 8192\n-1.0\n");
    EXPECT_EQ(readEnvironmentMap(path, kAt, diags), nullptr);
    expectErrorAtTheLine(diags, path, "claims 16384 × 8192 texels");
}

// The PFM's first row is the bottom one (texels[0..2]), as the format defines it.
TEST(EnvironmentReader, BadTexelsBecomeRadianceWithOneWarning) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const std::vector<float> rgb = {
        nan,     0.5f,  1.0f,   // bottom row: NaN
        -2.0f,   0.25f, 0.0f,   // a negative component
        inf,     1.0f,  -inf,   // infinities
        5000.0f, 0.0f,  0.75f,  // top row: a bright texel, kept (float maps are not clamped to 1)
        2e13f,   1.0f,  1.0f,   // above the bound
        0.1f,    0.2f,  0.3f,
    };
    Diagnostics diags;
    const auto image = readEnvironmentMap(test::writeTempFile("bad_texels.pfm", pfm(3, 2, rgb)), kAt, diags);
    ASSERT_NE(image, nullptr);
    ASSERT_EQ(diags.items.size(), 1u);
    EXPECT_EQ(diags.items[0].severity, Severity::Warning);
    EXPECT_EQ(diags.items[0].where.line, 7);
    EXPECT_NE(diags.items[0].message.find("4 of 6 texels"), std::string::npos) << diags.items[0].message;
    ASSERT_EQ(image->texels.size(), 6u);
    const Vec3 want[] = {{0.0f, 0.5f, 1.0f},
                         {0.0f, 0.25f, 0.0f},
                         {kMaxEnvironmentTexel, 1.0f, 0.0f},
                         {5000.0f, 0.0f, 0.75f},
                         {kMaxEnvironmentTexel, 1.0f, 1.0f},
                         {0.1f, 0.2f, 0.3f}};
    for (size_t k = 0; k < 6; ++k) {
        EXPECT_EQ(image->texels[k].x, want[k].x) << k;
        EXPECT_EQ(image->texels[k].y, want[k].y) << k;
        EXPECT_EQ(image->texels[k].z, want[k].z) << k;
    }
    Diagnostics clean;
    EXPECT_NE(readEnvironmentMap(test::writeTempFile("good.pfm", pfm(1, 1, {1.0f, 2.0f, 3.0f})), kAt, clean), nullptr);
    EXPECT_TRUE(clean.items.empty());
}

// Trazo's own renders read back as maps the right way up: writeImage's PFM and EXR rows follow their formats.
TEST(EnvironmentReader, RendersWrittenByTrazoReadTheRightWayUp) {
    std::vector<Vec3> topDown(2 * 3, Vec3(0.0f));
    topDown[0] = Vec3(7.0f, 0.0f, 0.0f);  // top-left
    for (const char* name : {"render.pfm", "render.exr"}) {
        SCOPED_TRACE(name);
        const std::string path = test::tempPath(name);
        std::string error;
        ASSERT_TRUE(writeImage(path, 2, 3, topDown, error)) << error;
        Diagnostics diags;
        const auto map = readEnvironmentMap(path, kAt, diags);
        ASSERT_NE(map, nullptr);
        EXPECT_EQ(map->texels[size_t(2) * 2].x, 7.0f) << "row 2 of 3 from the bottom: the top";
        EXPECT_EQ(map->texels[0].x, 0.0f);
    }
}

// scenes/assets/sky.pfm, written by generate_sky in every build: FreeImage reads it, 512 × 256, and its brightest
// texel is the sun's, at u = 0.35 and elevation 35° (v = 55/180 from the top row).
TEST(EnvironmentReader, ReadsTheGeneratedSky) {
    Diagnostics diags;
    const auto sky = readEnvironmentMap(test::sourcePath("scenes/assets/sky.pfm"), kAt, diags);
    ASSERT_NE(sky, nullptr) << (diags.items.empty() ? "" : diags.items[0].message);
    EXPECT_TRUE(diags.items.empty());
    ASSERT_EQ(sky->width, 512);
    ASSERT_EQ(sky->height, 256);
    size_t brightest = 0;
    for (size_t k = 0; k < sky->texels.size(); ++k)
        if (sky->texels[k].x > sky->texels[brightest].x) brightest = k;
    const int column = int(brightest % 512), rowFromTop = 255 - int(brightest / 512);
    EXPECT_NEAR((column + 0.5) / 512.0, 0.35, 2.0 / 512);
    EXPECT_NEAR((rowFromTop + 0.5) / 256.0, 55.0 / 180.0, 2.0 / 256);
    EXPECT_GT(sky->texels[brightest].x, 1000.0f);
    EXPECT_LT(sky->texels[size_t(10) * 512].x, 0.2f) << "a bottom row: the ground";
}

}  // namespace
}  // namespace trazo
