// Tests of the texture reader: row order (row 0 = bottom), 8-bit and float paths, and its errors.
#include "scene/texture_reader.h"

#include <FreeImage.h>
#include <gtest/gtest.h>

#include <memory>

#include "test_paths.h"

namespace trazo {
namespace {

// A 2x2 image: bottom-left red, bottom-right green, top-left blue, top-right grey 128.
// FreeImage's y = 0 is the bottom scanline.
FIBITMAP* tinyBitmap() {
    FIBITMAP* bm = FreeImage_Allocate(2, 2, 24);
    RGBQUAD red{0, 0, 255, 0}, green{0, 255, 0, 0}, blue{255, 0, 0, 0}, grey{128, 128, 128, 0};  // B, G, R, A
    FreeImage_SetPixelColor(bm, 0, 0, &red);
    FreeImage_SetPixelColor(bm, 1, 0, &green);
    FreeImage_SetPixelColor(bm, 0, 1, &blue);
    FreeImage_SetPixelColor(bm, 1, 1, &grey);
    return bm;
}

// Saves `bm` (and frees it) as tempPath(name) in `format`, and reads that back as a texture named at t.scene:3.
std::shared_ptr<const TextureImage> savedAndRead(FIBITMAP* bm, FREE_IMAGE_FORMAT format, const std::string& name,
                                                 Diagnostics& diags) {
    const std::string path = test::tempPath(name);
    EXPECT_TRUE(FreeImage_Save(format, bm, path.c_str(), 0)) << name;
    FreeImage_Unload(bm);
    return readTextureImage(path, {"t.scene", 3, 0}, diags);
}

void expectTexel(const TextureImage& image, int x, int y, Vec3 expected) {
    const Vec3 t = image.texels[size_t(y * image.width + x)];
    EXPECT_FLOAT_EQ(t.x, expected.x) << x << "," << y;
    EXPECT_FLOAT_EQ(t.y, expected.y) << x << "," << y;
    EXPECT_FLOAT_EQ(t.z, expected.z) << x << "," << y;
}

TEST(TextureReader, PngRowZeroIsTheBottomRow) {
    Diagnostics diags;
    const auto image = savedAndRead(tinyBitmap(), FIF_PNG, "tiny.png", diags);
    ASSERT_TRUE(image);
    EXPECT_TRUE(diags.items.empty());
    ASSERT_EQ(image->width, 2);
    ASSERT_EQ(image->height, 2);
    ASSERT_EQ(image->texels.size(), 4u);
    expectTexel(*image, 0, 0, {1, 0, 0});  // bottom-left
    expectTexel(*image, 1, 0, {0, 1, 0});
    expectTexel(*image, 0, 1, {0, 0, 1});  // top-left
    const float g = 128.0f / 255.0f;       // no sRGB decoding
    expectTexel(*image, 1, 1, {g, g, g});
}

TEST(TextureReader, FloatImagesKeepTheirValues) {
    FIBITMAP* bm = FreeImage_AllocateT(FIT_RGBF, 2, 1);
    auto* row = reinterpret_cast<FIRGBF*>(FreeImage_GetScanLine(bm, 0));
    row[0] = {0.25f, 2.5f, 0.0f};
    row[1] = {1.0f, 0.5f, 7.0f};
    Diagnostics diags;
    const auto image = savedAndRead(bm, FIF_PFM, "float.pfm", diags);
    ASSERT_TRUE(image);
    expectTexel(*image, 0, 0, {0.25f, 2.5f, 0.0f});
    expectTexel(*image, 1, 0, {1.0f, 0.5f, 7.0f});
}

TEST(TextureReader, GreyscaleBecomesRgb) {
    FIBITMAP* bm = FreeImage_Allocate(1, 1, 8);
    RGBQUAD* palette = FreeImage_GetPalette(bm);
    for (int i = 0; i < 256; ++i) palette[i] = {BYTE(i), BYTE(i), BYTE(i), 0};
    FreeImage_GetScanLine(bm, 0)[0] = 51;
    Diagnostics diags;
    const auto image = savedAndRead(bm, FIF_PNG, "grey.png", diags);
    ASSERT_TRUE(image);
    expectTexel(*image, 0, 0, {0.2f, 0.2f, 0.2f});
}

TEST(TextureReader, MissingFileIsReportedAtTheSourceLine) {
    Diagnostics diags;
    EXPECT_FALSE(readTextureImage("/nonexistent/trazo/t.png", {"t.scene", 7, 0}, diags));
    ASSERT_EQ(diags.items.size(), 1u);
    EXPECT_EQ(formatDiagnostic(diags.items[0]),
              "t.scene:7: error: cannot read texture '/nonexistent/trazo/t.png': No such file or directory");
}

TEST(TextureReader, UndecodableFileIsReported) {
    const std::string path = test::writeTempFile("junk.png", "this is not an image");
    Diagnostics diags;
    EXPECT_FALSE(readTextureImage(path, {"t.scene", 9, 0}, diags));
    ASSERT_EQ(diags.items.size(), 1u);
    const std::string message = formatDiagnostic(diags.items[0]);
    EXPECT_EQ(message.rfind("t.scene:9: error: cannot decode texture '" + path + "': ", 0), 0u) << message;
}

}  // namespace
}  // namespace trazo
