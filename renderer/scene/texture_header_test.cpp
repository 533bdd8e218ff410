// Tests of the texture header check: every accepted format, written by FreeImage at a known size, reads back
// with that size; other formats, damaged headers and headers that claim absurd sizes are refused before any
// decoding, and the texture reader reports them at the Source line.
#include "scene/texture_header.h"

#include <FreeImage.h>
#include <gtest/gtest.h>

#include "scene/texture_reader.h"
#include "test_paths.h"

namespace trazo {
namespace {

// A 5 × 3 image in `format`, saved by FreeImage (float RGB for the HDR formats).
std::string writeImage(const std::string& name, FREE_IMAGE_FORMAT format) {
    const bool isFloat = format == FIF_EXR || format == FIF_HDR || format == FIF_PFM;
    FIBITMAP* bm = isFloat ? FreeImage_AllocateT(FIT_RGBF, 5, 3) : FreeImage_Allocate(5, 3, 24);
    const std::string path = test::tempPath(name);
    EXPECT_TRUE(FreeImage_Save(format, bm, path.c_str(), 0)) << name;
    FreeImage_Unload(bm);
    return path;
}

TEST(TextureHeader, EveryAcceptedFormatReadsItsSize) {
    const struct {
        const char* name;
        FREE_IMAGE_FORMAT fif;
        TextureFormat format;
    } cases[] = {{"h.png", FIF_PNG, TextureFormat::Png}, {"h.jpg", FIF_JPEG, TextureFormat::Jpeg},
                 {"h.bmp", FIF_BMP, TextureFormat::Bmp}, {"h.exr", FIF_EXR, TextureFormat::Exr},
                 {"h.pfm", FIF_PFM, TextureFormat::Pfm}};
    for (const auto& c : cases) {
        const std::string path = writeImage(c.name, c.fif);
        TextureHeader header{};
        std::string why;
        ASSERT_TRUE(readTextureHeader(test::readFileText(path), path, header, why)) << c.name << ": " << why;
        EXPECT_EQ(header.format, c.format) << c.name;
        EXPECT_EQ(header.width, 5u) << c.name;
        EXPECT_EQ(header.height, 3u) << c.name;
        Diagnostics diags;
        const auto image = readTextureImage(path, {"t.scene", 4, 0}, diags);
        ASSERT_TRUE(image) << c.name << (diags.items.empty() ? "" : ": " + diags.items[0].message);
        EXPECT_EQ(image->width, 5);
        EXPECT_EQ(image->height, 3);
    }
}

// The refusal of `bytes` (saved as `name`): at the Source line, naming the file, with `reason` in it.
void expectRefused(const std::string& name, const std::string& bytes, const std::string& reason) {
    const std::string path = test::writeTempFile(name, bytes);
    TextureHeader header{};
    std::string why;
    EXPECT_FALSE(readTextureHeader(bytes, path, header, why)) << name;
    EXPECT_NE(why.find(reason), std::string::npos) << name << ": " << why;
    Diagnostics diags;
    EXPECT_FALSE(readTextureImage(path, {"t.scene", 7, 0}, diags)) << name;
    ASSERT_EQ(diags.items.size(), 1u) << name;
    EXPECT_EQ(diags.items[0].where.line, 7);
    EXPECT_NE(diags.items[0].message.find(path), std::string::npos);
}

std::string be32(uint32_t v) {
    return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

TEST(TextureHeader, OtherFormatsAreRefusedBeforeDecoding) {
    // A Sun RAS header with negative sizes (crashed FreeImage), a WBMP and an IFF claiming huge sizes (ran for
    // minutes), a GIF, and text.
    expectRefused("s.ras", std::string("\x59\xa6\x6a\x95", 4) + be32(0x80000000u) + be32(0xffffffffu) + be32(8) +
                               std::string(16, '\0'), "not a PNG, JPEG");
    expectRefused("w.wbmp", std::string("\x00\x00\x8f\xff\xff\x7f\x8f\xff\xff\x7f", 10), "not a PNG, JPEG");
    expectRefused("i.iff", "FORM" + be32(100) + "ILBMBMHD" + be32(20) + std::string(20, '\xff'), "not a PNG, JPEG");
    expectRefused("g.gif", "GIF89a" + std::string(20, '\0'), "not a PNG, JPEG");
    expectRefused("t.png", "just text", "not a PNG, JPEG");
    // TGA and Radiance HDR, even well formed: FreeImage's decoders crashed on fuzzed ones within seconds
    // (bench/fuzz/regressions/texture/).
    expectRefused("ok.tga", test::readFileText(writeImage("w.tga", FIF_TARGA)), "a TGA file");
    expectRefused("ok.hdr", test::readFileText(writeImage("w.hdr", FIF_HDR)), "a Radiance HDR file");
}

TEST(TextureHeader, AbsurdOrDamagedHeadersAreRefused) {
    const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + "IHDR";
    expectRefused("wide.png", png + be32(2147483647u) + be32(1) + std::string(5, '\0'), "claims 2147483647 × 1");
    expectRefused("zero.png", png + be32(0) + be32(4) + std::string(5, '\0'), "claims 0 × 4");
    expectRefused("square.png", png + be32(8192) + be32(8192) + std::string(5, '\0'), "claims 8192 × 8192");
    expectRefused("cut.png", std::string("\x89PNG\r\n\x1a\n", 8), "damaged PNG header");
    // A JPEG frame header (SOF0) claiming 65535 × 65535, after an APP0 segment.
    const std::string jpeg = std::string("\xFF\xD8\xFF\xE0\x00\x04\x00\x00\xFF\xC0\x00\x11\x08\xFF\xFF\xFF\xFF\x03", 18);
    expectRefused("big.jpg", jpeg, "claims 65535 × 65535");
    expectRefused("cut.jpg", std::string("\xFF\xD8\xFF\xE0\x00\x40", 6), "damaged JPEG header");
    // A BMP whose width is negative.
    std::string bmp = "BM" + std::string(24, '\0');
    bmp[18] = bmp[19] = bmp[20] = bmp[21] = '\xff';
    bmp[22] = 2;
    expectRefused("neg.bmp", bmp, "claims 0 × 2");
    // A PFM that claims too much, and EXR headers OpenEXR would read past: cut short, and a float of size 0.
    expectRefused("big.pfm", "PF\n100000 100000\n-1\n", "claims 100000 × 100000");
    const std::string exr = test::readFileText(writeImage("w.exr", FIF_EXR));
    expectRefused("cut.exr", exr.substr(0, exr.size() / 3), "damaged EXR header");
    expectRefused("tableless.exr", exr.substr(0, exr.find("\0\0", 8) + 1), "damaged EXR header");
    // A channel list OpenEXR would read out of step with the file: a subsampled first channel, and the list
    // ended one channel early (the next "attribute" then claims megabytes past the end: OpenEXR hung).
    const size_t channels = exr.find(std::string("channels\0chlist\0", 16)) + 16 + 4;
    const size_t firstFields = exr.find('\0', channels) + 1;
    std::string subsampled = exr;
    subsampled[firstFields + 8] = 2;
    expectRefused("subsampled.exr", subsampled, "damaged EXR header");
    std::string endedEarly = exr;
    endedEarly[firstFields + 16] = '\0';
    expectRefused("ended-early.exr", endedEarly, "damaged EXR header");
}

// A valid header over pixels that do not match it is still FreeImage's to refuse, which it must do cleanly.
TEST(TextureHeader, TruncatedPixelsAreReportedNotCrashedOn) {
    const std::string path = writeImage("whole.png", FIF_PNG);
    const std::string bytes = test::readFileText(path);
    for (size_t keep : {size_t(33), bytes.size() / 2, bytes.size() - 12}) {
        Diagnostics diags;
        const std::string cut = test::writeTempFile("cut" + std::to_string(keep) + ".png", bytes.substr(0, keep));
        EXPECT_FALSE(readTextureImage(cut, {"t.scene", 2, 0}, diags)) << keep;
        EXPECT_EQ(diags.items.size(), 1u) << keep;
    }
}

}  // namespace
}  // namespace trazo
