// Tests for image output: every format read back through FreeImage, orientation, and failure hygiene.
#include "image/image_writer.h"

#include <FreeImage.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "test_paths.h"

namespace trazo {
namespace {

namespace fs = std::filesystem;

using Rgb8 = std::array<int, 3>;

// A fresh, empty folder per test, so "nothing else was left behind" is a directory listing.
fs::path freshDir(const std::string& name) { return test::freshDir("image_writer_" + name); }

std::vector<std::string> listDir(const fs::path& dir) { return test::listDir(dir.string()); }

// writeImage's error where it fails, "" where it writes `image` to `path`.
std::string writeError(const fs::path& path, int width, int height, const std::vector<Vec3>& image) {
    std::string error;
    return writeImage(path.string(), width, height, image, error) ? "" : "failed: " + error;
}

FIBITMAP* loadImage(const fs::path& path) {
    FREE_IMAGE_FORMAT fif = FreeImage_GetFileType(path.c_str());
    if (fif == FIF_UNKNOWN) fif = FreeImage_GetFIFFromFilename(path.c_str());  // TGA has no signature
    return fif == FIF_UNKNOWN ? nullptr : FreeImage_Load(fif, path.c_str());
}

// The image at `path` where it loads as `type` (and `bpp` bits a pixel, where not 0) of width × height; null
// otherwise, each difference a failure of the test.
FIBITMAP* loadExpected(const fs::path& path, FREE_IMAGE_TYPE type, unsigned bpp, int width, int height) {
    FIBITMAP* bitmap = loadImage(path);
    EXPECT_NE(bitmap, nullptr) << path;
    if (!bitmap) return nullptr;
    EXPECT_EQ(FreeImage_GetImageType(bitmap), type);
    const bool bppAsAsked = !bpp || FreeImage_GetBPP(bitmap) == bpp;
    EXPECT_TRUE(bppAsAsked) << FreeImage_GetBPP(bitmap) << " bits a pixel, not " << bpp;
    const int w = static_cast<int>(FreeImage_GetWidth(bitmap)), h = static_cast<int>(FreeImage_GetHeight(bitmap));
    EXPECT_EQ(w, width);
    EXPECT_EQ(h, height);
    if (FreeImage_GetImageType(bitmap) == type && bppAsAsked && w == width && h == height) return bitmap;
    FreeImage_Unload(bitmap);
    return nullptr;
}

// Top-down pixels of the image at `path` as loadExpected takes it, pixel(scanline, x) each; none where it is not.
template <class Pixel, class PixelOf>
std::vector<Pixel> readPixels(const fs::path& path, FREE_IMAGE_TYPE type, unsigned bpp, int width, int height,
                              PixelOf pixel) {
    std::vector<Pixel> pixels;
    FIBITMAP* bitmap = loadExpected(path, type, bpp, width, height);
    if (!bitmap) return pixels;
    for (int y = 0; y < height; ++y) {
        const BYTE* line = FreeImage_GetScanLine(bitmap, height - 1 - y);  // scanline 0 = bottom row
        for (int x = 0; x < width; ++x) pixels.push_back(pixel(line, x));
    }
    FreeImage_Unload(bitmap);
    return pixels;
}

// Top-down 8-bit pixels of a 24-bit file, in R, G, B order.
std::vector<Rgb8> readBytes(const fs::path& path, int width, int height) {
    return readPixels<Rgb8>(path, FIT_BITMAP, 24, width, height, [](const BYTE* line, int x) {
        const BYTE* px = line + 3 * x;
        return Rgb8{px[FI_RGBA_RED], px[FI_RGBA_GREEN], px[FI_RGBA_BLUE]};
    });
}

// Top-down pixels of an RGBF file.
std::vector<Vec3> readFloats(const fs::path& path, int width, int height) {
    return readPixels<Vec3>(path, FIT_RGBF, 0, width, height, [](const BYTE* line, int x) {
        const FIRGBF& px = reinterpret_cast<const FIRGBF*>(line)[x];
        return Vec3(px.red, px.green, px.blue);
    });
}

// Top-down pixels of a little-endian RGB PFM, read by the format's definition (rows bottom to top),
// not by FreeImage, whose PFM plugin takes the first row for the top.
std::vector<Vec3> readPfm(const fs::path& path, int width, int height) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int w = 0, h = 0;
    float scale = 0.0f;
    in >> magic >> w >> h >> scale;
    in.get();  // the single whitespace byte that ends the header
    EXPECT_EQ(magic, "PF");
    EXPECT_EQ(w, width);
    EXPECT_EQ(h, height);
    EXPECT_LT(scale, 0.0f);  // little-endian
    if (magic != "PF" || w != width || h != height || !(scale < 0.0f)) return {};
    std::vector<float> data(3 * static_cast<size_t>(width) * height);
    in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(float)));
    EXPECT_TRUE(in.good());
    EXPECT_EQ(in.peek(), std::char_traits<char>::eof());
    std::vector<Vec3> pixels(static_cast<size_t>(width) * height);
    for (int row = 0; row < height; ++row) {
        const float* src = data.data() + 3 * static_cast<size_t>(row) * width;
        for (int x = 0; x < width; ++x)
            pixels[(height - 1 - row) * width + x] = {src[3 * x], src[3 * x + 1], src[3 * x + 2]};
    }
    return pixels;
}

std::vector<Vec3> readFloatFile(const fs::path& path, int width, int height) {
    return path.extension() == ".pfm" ? readPfm(path, width, height) : readFloats(path, width, height);
}

// A channel value and the byte SPEC §5 requires for it, worked out by hand (not by the code under test).
struct ByteCase {
    float value;
    int expected;
};

std::vector<ByteCase> byteCases() {
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<ByteCase> cases = {
        {0.0f, 0},           {1.0f, 255},          {0.5f, 128},  // 127.5 rounds up
        {-1.0f, 0},          {2.0f, 255},          {1e30f, 255},          {-0.0f, 0},
        {1e-8f, 0},          {0.49f / 255, 0},     {0.51f / 255, 1},      {1.49f / 255, 1},
        {1.51f / 255, 2},    {127.49f / 255, 127}, {127.51f / 255, 128},  {254.49f / 255, 254},
        {254.51f / 255, 255}, {0.998f, 254},       {0.999f, 255},
        {std::numeric_limits<float>::quiet_NaN(), 0}, {inf, 255},   {-inf, 0},
    };
    for (int k = 0; k <= 255; ++k) cases.push_back({static_cast<float>(k) / 255.0f, k});
    return cases;
}

// Pixel i carries cases i, i+1, i+2 in R, G, B, so a swapped channel or a flipped row shows.
void makeByteImage(int width, int height, std::vector<Vec3>& image, std::vector<Rgb8>& expected) {
    const std::vector<ByteCase> cases = byteCases();
    const size_t n = cases.size();
    for (int i = 0; i < width * height; ++i) {
        const ByteCase& r = cases[i % n];
        const ByteCase& g = cases[(i + 1) % n];
        const ByteCase& b = cases[(i + 2) % n];
        image.push_back({r.value, g.value, b.value});
        expected.push_back({r.expected, g.expected, b.expected});
    }
}

class ImageWriterLossless8Bit : public ::testing::TestWithParam<std::string> {};

TEST_P(ImageWriterLossless8Bit, StoresRoundedClampedBytesExactly) {
    // 23 wide: rows of 69 bytes need scanline padding; 24·23 pixels cover every case at least twice.
    const int width = 23, height = 24;
    std::vector<Vec3> image;
    std::vector<Rgb8> expected;
    makeByteImage(width, height, image, expected);
    const fs::path path = freshDir("lossless_" + GetParam()) / ("out." + GetParam());
    ASSERT_EQ(writeError(path, width, height, image), "");
    const std::vector<Rgb8> got = readBytes(path, width, height);
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(got[i][c], expected[i][c]) << "pixel " << i << " channel " << c << " value "
                                                 << image[i][c];
        }
    }
    EXPECT_EQ(listDir(path.parent_path()), std::vector<std::string>{path.filename().string()});
}

INSTANTIATE_TEST_SUITE_P(ImageWriter, ImageWriterLossless8Bit, ::testing::Values("png", "bmp", "tga", "PNG"),
                         [](const auto& info) { return info.param; });

TEST(ImageWriterJpeg, StoresBytesWithinJpegLoss) {
    // JPEG is lossy at any quality; flat 8x8 blocks (one per JPEG block) keep the loss to rounding.
    const int width = 32, height = 24;
    std::vector<Vec3> image(width * height);
    std::vector<Rgb8> expected(width * height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int block = (y / 8) * (width / 8) + x / 8;
            const Rgb8 rgb = {(block * 53) % 256, (block * 97 + 40) % 256, (block * 31 + 200) % 256};
            image[y * width + x] = {rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f};
            expected[y * width + x] = rgb;
        }
    }
    for (const char* ext : {"jpg", "jpeg", "JPG"}) {
        const fs::path path = freshDir(std::string("jpeg_") + ext) / (std::string("out.") + ext);
        ASSERT_EQ(writeError(path, width, height, image), "");
        const std::vector<Rgb8> got = readBytes(path, width, height);
        ASSERT_EQ(got.size(), expected.size());
        int worst = 0;
        for (size_t i = 0; i < got.size(); ++i)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[i][c] - expected[i][c]));
        EXPECT_LE(worst, 3) << ext;
    }
}

// Values a float format must keep bit for bit: tiny, huge, negative, non-dyadic.
std::vector<Vec3> floatImage(int width, int height, bool positiveOnly) {
    std::vector<Vec3> image;
    for (int i = 0; i < width * height; ++i) {
        const float a = 0.1f + 0.37f * static_cast<float>(i);
        const float b = std::pow(10.0f, static_cast<float>(i % 13) - 6.0f);  // 1e-6 .. 1e6
        const float c = positiveOnly ? 1.0f / (1.0f + static_cast<float>(i)) : 0.5f - static_cast<float>(i % 7);
        image.push_back({a, b, c});
    }
    return image;
}

class ImageWriterExactFloat : public ::testing::TestWithParam<std::string> {};

TEST_P(ImageWriterExactFloat, StoresFloatsExactly) {
    const int width = 13, height = 7;
    const std::vector<Vec3> image = floatImage(width, height, false);
    const fs::path path = freshDir("float_" + GetParam()) / ("out." + GetParam());
    ASSERT_EQ(writeError(path, width, height, image), "");
    const std::vector<Vec3> got = readFloatFile(path, width, height);
    ASSERT_EQ(got.size(), image.size());
    for (size_t i = 0; i < got.size(); ++i) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(got[i][c], image[i][c]) << "pixel " << i << " channel " << c;
    }
    EXPECT_EQ(listDir(path.parent_path()), std::vector<std::string>{path.filename().string()});
}

INSTANTIATE_TEST_SUITE_P(ImageWriter, ImageWriterExactFloat, ::testing::Values("exr", "pfm"),
                         [](const auto& info) { return info.param; });

TEST(ImageWriterHdr, StoresRgbeWithinOnePercentOfLargestChannel) {
    const int width = 13, height = 7;
    const std::vector<Vec3> image = floatImage(width, height, true);
    const fs::path path = freshDir("hdr") / "out.hdr";
    ASSERT_EQ(writeError(path, width, height, image), "");
    const std::vector<Vec3> got = readFloats(path, width, height);
    ASSERT_EQ(got.size(), image.size());
    for (size_t i = 0; i < got.size(); ++i) {
        // RGBE shares one exponent per pixel: the error scales with the pixel's largest channel.
        const float largest = std::max({image[i].x, image[i].y, image[i].z});
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(got[i][c], image[i][c], 0.01f * largest) << "pixel " << i << " channel " << c;
    }
}

class ImageWriterOrientation : public ::testing::TestWithParam<std::string> {};

TEST_P(ImageWriterOrientation, TopLeftPixelStaysTopLeft) {
    // 16x16 so that JPEG's 8x8 blocks keep the red corner apart from the blue bottom-right quadrant.
    const int width = 16, height = 16;
    std::vector<Vec3> image(width * height, Vec3(0.0f));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) image[y * width + x] = {1.0f, 0.0f, 0.0f};
    for (int y = 8; y < 16; ++y)
        for (int x = 8; x < 16; ++x) image[y * width + x] = {0.0f, 0.0f, 1.0f};
    const std::string ext = GetParam();
    const fs::path path = freshDir("orientation_" + ext) / ("out." + ext);
    ASSERT_EQ(writeError(path, width, height, image), "");

    const bool isFloat = ext == "exr" || ext == "hdr" || ext == "pfm";
    auto pixel = [&](const std::vector<Vec3>& floats, const std::vector<Rgb8>& bytes, int x, int y) {
        if (isFloat) return floats[y * width + x];
        const Rgb8& b = bytes[y * width + x];
        return Vec3(b[0] / 255.0f, b[1] / 255.0f, b[2] / 255.0f);
    };
    const std::vector<Vec3> floats = isFloat ? readFloatFile(path, width, height) : std::vector<Vec3>{};
    const std::vector<Rgb8> bytes = isFloat ? std::vector<Rgb8>{} : readBytes(path, width, height);
    ASSERT_EQ(isFloat ? floats.size() : bytes.size(), image.size());
    const Vec3 topLeft = pixel(floats, bytes, 0, 0);
    const Vec3 bottomRight = pixel(floats, bytes, width - 1, height - 1);
    const Vec3 topRight = pixel(floats, bytes, width - 1, 0);
    EXPECT_GT(topLeft.x, 0.9f);
    EXPECT_LT(topLeft.z, 0.1f);
    EXPECT_GT(bottomRight.z, 0.9f);
    EXPECT_LT(bottomRight.x, 0.1f);
    EXPECT_LT(topRight.x + topRight.y + topRight.z, 0.1f);
}

INSTANTIATE_TEST_SUITE_P(ImageWriter, ImageWriterOrientation,
                         ::testing::Values("png", "bmp", "jpg", "tga", "exr", "hdr", "pfm"),
                         [](const auto& info) { return info.param; });

TEST(ImageWriterPfm, FileStoresTopRowLastAndFreeImageReadsItFlipped) {
    const int width = 2, height = 3;
    std::vector<Vec3> image(width * height, Vec3(0.0f));
    image[0] = {1.0f, 0.0f, 0.0f};  // top-left
    const fs::path path = freshDir("pfm_rows") / "out.pfm";
    ASSERT_EQ(writeError(path, width, height, image), "");

    std::ifstream in(path, std::ios::binary);
    const std::string expectedHeader = "PF\n2 3\n-1.000000\n";  // RGB, 2x3, little-endian
    std::string header(expectedHeader.size(), '\0');
    in.read(header.data(), static_cast<std::streamsize>(header.size()));
    EXPECT_EQ(header, expectedHeader);
    std::vector<float> data(3 * width * height);
    in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(float)));
    ASSERT_TRUE(in.good()) << header;
    const size_t lastRowStart = 3 * static_cast<size_t>(width) * (height - 1);
    EXPECT_EQ(data[lastRowStart], 1.0f);
    EXPECT_EQ(std::count(data.begin(), data.end(), 1.0f), 1);

    // FreeImage 3.18's PFM loader takes the first row for the top: if this starts failing, FreeImage
    // has been fixed and the row flip in image_writer.cpp must go.
    const std::vector<Vec3> viaFreeImage = readFloats(path, width, height);
    ASSERT_EQ(viaFreeImage.size(), image.size());
    EXPECT_EQ(viaFreeImage[(height - 1) * width].x, 1.0f);
}

TEST(ImageWriterFormat, RecognisesExtensionsCaseInsensitively) {
    const std::vector<std::pair<std::string, ImageFormat>> known = {
        {"a.png", ImageFormat::Png},        {"dir.x/a.PNG", ImageFormat::Png},  {"a.bmp", ImageFormat::Bmp},
        {"a.jpg", ImageFormat::Jpeg},       {"a.JpEg", ImageFormat::Jpeg},      {"a.tga", ImageFormat::Tga},
        {"/tmp/out.exr", ImageFormat::Exr}, {"a.b.hdr", ImageFormat::Hdr},      {"a.PFM", ImageFormat::Pfm},
    };
    for (const auto& [path, want] : known) {
        ImageFormat got = ImageFormat::Png;
        EXPECT_TRUE(imageFormatFromPath(path, got)) << path;
        EXPECT_EQ(got, want) << path;
    }
    for (const char* path : {"a.gif", "a", "png", "a.png.txt", "dir.png/", ".png", "a.tiff", ""}) {
        ImageFormat got;
        EXPECT_FALSE(imageFormatFromPath(path, got)) << path;
    }
}

// SPEC §7 Image: 2^Exposure scales every output, sRGB's transfer function encodes only the 8-bit ones.
std::string writeDisplayed(const fs::path& path, int width, int height, const std::vector<Vec3>& image,
                           const DisplayTransform& display) {
    std::string error;
    return writeImage(path.string(), width, height, image, error, display) ? "" : "failed: " + error;
}

TEST(ImageWriterDisplay, SrgbStoresKnownBytes) {
    // Worked by hand: E(0.5) = 1.055·0.5^(1/2.4) − 0.055 = 0.73536, ·255 = 187.52 → 188; E(0.002) = 12.92·0.002
    // (the linear toe), ·255 = 6.59 → 7; E(0.2) = 0.48450, ·255 = 123.55 → 124; clamped and NaN as in §5.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<Vec3> image = {{0.5f, 0.002f, 0.2f}, {1.0f, 2.0f, 0.0f}, {nan, -1.0f, 0.5f}};
    const std::vector<Rgb8> expected = {{188, 7, 124}, {255, 255, 0}, {0, 0, 188}};
    const fs::path path = freshDir("srgb") / "out.png";
    ASSERT_EQ(writeDisplayed(path, 3, 1, image, DisplayTransform{1.0f, true}), "");
    EXPECT_EQ(readBytes(path, 3, 1), expected);
    // Float files store the value linear: the transfer function is for 8-bit outputs only.
    const fs::path exr = path.parent_path() / "out.exr";
    ASSERT_EQ(writeDisplayed(exr, 3, 1, image, DisplayTransform{1.0f, true}), "");
    const std::vector<Vec3> floats = readFloats(exr, 3, 1);
    ASSERT_EQ(floats.size(), 3u);
    EXPECT_EQ(floats[0].x, 0.5f);
    EXPECT_EQ(floats[0].z, 0.2f);
}

TEST(ImageWriterDisplay, OneStopOfExposureDoublesEveryOutput) {
    const DisplayTransform plusOne = displayTransform(1.0f, ViewTransform::Linear, IntegratorKind::Path);
    ASSERT_EQ(plusOne.scale, 2.0f);
    // 8-bit: 0.25 → 0.5 → 127.5 → 128; 0.1 → 0.2 → 51; 0.6 → 1.2, clamped to 255. Linear: no gamma.
    const std::vector<Vec3> image = {{0.25f, 0.1f, 0.6f}, {0.3f, 1e-3f, 0.0f}};
    const fs::path dir = freshDir("exposure");
    ASSERT_EQ(writeDisplayed(dir / "out.png", 2, 1, image, plusOne), "");
    EXPECT_EQ(readBytes(dir / "out.png", 2, 1), (std::vector<Rgb8>{{128, 51, 255}, {153, 1, 0}}));
    // Float files: exactly twice the pixel (a power of two scales floats exactly).
    for (const char* name : {"out.exr", "out.pfm"}) {
        ASSERT_EQ(writeDisplayed(dir / name, 2, 1, image, plusOne), "");
        const std::vector<Vec3> got = readFloatFile(dir / name, 2, 1);
        ASSERT_EQ(got.size(), image.size()) << name;
        for (size_t i = 0; i < got.size(); ++i)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(got[i][c], 2.0f * image[i][c]) << name << " pixel " << i;
    }
    // Exposure −1 halves: 0.25 → 0.125 → 31.875 → 32.
    ASSERT_EQ(writeDisplayed(dir / "half.png", 2, 1, image,
                             displayTransform(-1.0f, ViewTransform::Linear, IntegratorKind::Thesis)), "");
    EXPECT_EQ(readBytes(dir / "half.png", 2, 1)[0][0], 32);
}

TEST(ImageWriterDisplay, AnExposureThatOverflowsStoresTheLargestFloatNotInf) {
    const float big = 1e30f, max = std::numeric_limits<float>::max();
    const std::vector<Vec3> image = {{big, -big, 1.0f}};
    const DisplayTransform brightest = displayTransform(64.0f, ViewTransform::Linear, IntegratorKind::Path);
    const fs::path dir = freshDir("overflow");
    for (const char* name : {"out.exr", "out.pfm"}) {
        ASSERT_EQ(writeDisplayed(dir / name, 1, 1, image, brightest), "");
        const std::vector<Vec3> got = readFloatFile(dir / name, 1, 1);
        ASSERT_EQ(got.size(), 1u) << name;
        EXPECT_EQ(got[0].x, max) << name;
        EXPECT_EQ(got[0].y, -max) << name;
        EXPECT_EQ(got[0].z, 18446744073709551616.0f) << name;  // 2^64
    }
}

TEST(ImageWriterDisplay, LinearAtZeroStopsIsByteIdenticalToTheDefault) {
    // The byte cases (NaN, ±inf, halves, every k/255) in every format: a scene that names neither Exposure
    // nor ViewTransform under thesis, or `linear` and 0 under path, writes the very file it wrote before.
    const int width = 23, height = 24;
    std::vector<Vec3> image;
    std::vector<Rgb8> expected;
    makeByteImage(width, height, image, expected);
    const fs::path dir = freshDir("identity");
    for (const char* ext : {"png", "bmp", "jpg", "tga", "exr", "hdr", "pfm"}) {
        const fs::path before = dir / (std::string("default.") + ext);
        ASSERT_EQ(writeError(before, width, height, image), "");
        for (const DisplayTransform& same : {displayTransform(0.0f, ViewTransform::Auto, IntegratorKind::Thesis),
                                             displayTransform(0.0f, ViewTransform::Linear, IntegratorKind::Path)}) {
            ASSERT_TRUE(same.identity());
            const fs::path after = dir / (std::string("explicit.") + ext);
            ASSERT_EQ(writeDisplayed(after, width, height, image, same), "");
            EXPECT_EQ(test::readFileText(after.string()), test::readFileText(before.string())) << ext;
        }
    }
}

TEST(ImageWriterFailure, UnknownExtensionCreatesNothing) {
    const fs::path dir = freshDir("unknown_ext");
    std::string error;
    EXPECT_FALSE(writeImage((dir / "out.gif").string(), 2, 2, std::vector<Vec3>(4), error));
    EXPECT_NE(error.find("extension"), std::string::npos) << error;
    EXPECT_TRUE(listDir(dir).empty());
}

TEST(ImageWriterFailure, WrongPixelCountCreatesNothing) {
    const fs::path dir = freshDir("wrong_size");
    std::string error;
    EXPECT_FALSE(writeImage((dir / "out.png").string(), 3, 2, std::vector<Vec3>(5), error));
    EXPECT_FALSE(error.empty());
    EXPECT_FALSE(writeImage((dir / "out.png").string(), 0, 0, std::vector<Vec3>{}, error));
    EXPECT_TRUE(listDir(dir).empty());
}

TEST(ImageWriterFailure, MissingFolderFailsAndCreatesNothing) {
    const fs::path dir = freshDir("missing_folder");
    const fs::path path = dir / "no_such_folder" / "out.png";
    std::string error;
    EXPECT_FALSE(writeImage(path.string(), 2, 2, std::vector<Vec3>(4), error));
    EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
    EXPECT_TRUE(listDir(dir).empty());
}

TEST(ImageWriterFailure, UnwritableFolderFailsAndLeavesNoTemporary) {
    const fs::path dir = freshDir("read_only");
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                             fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    // Root (and CAP_DAC_OVERRIDE) ignores permission bits: probe instead of guessing from the uid.
    const fs::path probe = dir / "probe";
    if (FILE* f = std::fopen(probe.c_str(), "wb")) {
        std::fclose(f);
        fs::remove(probe);
        fs::permissions(dir, fs::perms::owner_all);
        GTEST_SKIP() << "folder permissions are not enforced for this user (root?)";
    }
    std::string error;
    const bool ok = writeImage((dir / "out.png").string(), 2, 2, std::vector<Vec3>(4), error);
    const std::vector<std::string> left = listDir(dir);
    fs::permissions(dir, fs::perms::owner_all);
    EXPECT_FALSE(ok);
    EXPECT_FALSE(error.empty());
    EXPECT_TRUE(left.empty());
}

TEST(ImageWriterFailure, ExistingFileIsReplacedOnlyOnSuccess) {
    const fs::path dir = freshDir("replace");
    const fs::path path = dir / "out.png";
    { std::ofstream(path) << "old contents"; }
    auto contents = [&] { return test::readFileText(path.string()); };

    std::string error;
    EXPECT_FALSE(writeImage(path.string(), 2, 2, std::vector<Vec3>(3), error));
    EXPECT_EQ(contents(), "old contents");

    std::vector<Vec3> image(4, Vec3(0.0f, 1.0f, 0.0f));
    ASSERT_TRUE(writeImage(path.string(), 2, 2, image, error)) << error;
    const std::vector<Rgb8> got = readBytes(path, 2, 2);
    ASSERT_EQ(got.size(), 4u);
    EXPECT_EQ(got[3], (Rgb8{0, 255, 0}));
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(ImageWriterFailure, FailedRenameLeavesNoTemporary) {
    // The destination is a non-empty folder: FreeImage writes the temporary fine, the rename fails.
    const fs::path dir = freshDir("rename_fails");
    const fs::path path = dir / "out.png";
    fs::create_directories(path / "inside");
    std::string error;
    EXPECT_FALSE(writeImage(path.string(), 2, 2, std::vector<Vec3>(4), error));
    EXPECT_FALSE(error.empty());
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
    EXPECT_TRUE(fs::is_directory(path / "inside"));
}

TEST(ImageWriterFailure, WritesIntoTheCurrentFolderForABareName) {
    const fs::path dir = freshDir("bare_name");
    const fs::path previous = fs::current_path();
    fs::current_path(dir);
    std::string error;
    const bool ok = writeImage("bare.bmp", 1, 1, std::vector<Vec3>(1, Vec3(1.0f)), error);
    fs::current_path(previous);
    EXPECT_TRUE(ok) << error;
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"bare.bmp"});
}

}  // namespace
}  // namespace trazo
