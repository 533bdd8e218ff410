// Writes tiny images of every texture format Trazo accepts (PNG 8-bit RGB/RGBA/grey/palette and 16-bit,
// JPEG, BMP, TGA, EXR, HDR, PFM) into the folder given, as seeds for trazo_fuzz_texture and as the small
// textures of the scene harness's root. Built with FreeImage; each file is a few hundred bytes.
#include <FreeImage.h>

#include <cstdio>
#include <string>

namespace {

FIBITMAP* rgb8(int w, int h, int bpp) {
    FIBITMAP* b = FreeImage_Allocate(w, h, bpp);
    for (int y = 0; y < h; ++y) {
        BYTE* row = FreeImage_GetScanLine(b, y);
        for (int x = 0; x < w; ++x) {
            BYTE* p = row + x * (bpp / 8);
            p[FI_RGBA_RED] = BYTE(40 * x + 10);
            p[FI_RGBA_GREEN] = BYTE(60 * y + 20);
            p[FI_RGBA_BLUE] = BYTE(200 - 30 * x);
            if (bpp == 32) p[FI_RGBA_ALPHA] = BYTE(255 - 50 * y);
        }
    }
    return b;
}

FIBITMAP* rgbf(int w, int h) {
    FIBITMAP* b = FreeImage_AllocateT(FIT_RGBF, w, h);
    for (int y = 0; y < h; ++y) {
        FIRGBF* row = reinterpret_cast<FIRGBF*>(FreeImage_GetScanLine(b, y));
        for (int x = 0; x < w; ++x) row[x] = {0.25f * float(x), 0.5f * float(y), 2.0f};
    }
    return b;
}

int failures = 0;

void save(FREE_IMAGE_FORMAT format, FIBITMAP* bitmap, const std::string& path, int flags = 0) {
    if (!bitmap || !FreeImage_Save(format, bitmap, path.c_str(), flags)) {
        std::fprintf(stderr, "make_texture_seeds: cannot write %s\n", path.c_str());
        ++failures;
    }
    if (bitmap) FreeImage_Unload(bitmap);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <folder>\n", argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    FreeImage_Initialise();
    save(FIF_PNG, rgb8(4, 3, 24), dir + "/rgb.png");
    save(FIF_PNG, rgb8(3, 2, 32), dir + "/rgba.png");
    save(FIF_PNG, FreeImage_ConvertToGreyscale(rgb8(5, 1, 24)), dir + "/grey_5x1.png");
    save(FIF_PNG, FreeImage_ColorQuantize(rgb8(2, 4, 24), FIQ_WUQUANT), dir + "/palette.png");
    save(FIF_PNG, FreeImage_ConvertToType(FreeImage_ConvertToGreyscale(rgb8(2, 2, 24)), FIT_UINT16),
         dir + "/grey16.png");
    save(FIF_JPEG, rgb8(8, 8, 24), dir + "/rgb.jpg", JPEG_QUALITYBAD);
    save(FIF_BMP, rgb8(3, 3, 24), dir + "/rgb.bmp");
    save(FIF_BMP, rgb8(2, 2, 24), dir + "/rle.bmp", BMP_SAVE_RLE);
    save(FIF_TARGA, rgb8(3, 2, 24), dir + "/rgb.tga");
    save(FIF_TARGA, rgb8(4, 2, 32), dir + "/rle.tga", TARGA_SAVE_RLE);
    save(FIF_EXR, rgbf(3, 2), dir + "/rgbf.exr", EXR_NONE);
    save(FIF_EXR, rgbf(2, 3), dir + "/zip.exr", EXR_ZIP);
    save(FIF_HDR, rgbf(3, 2), dir + "/rgbf.hdr");
    save(FIF_PFM, rgbf(2, 2), dir + "/rgbf.pfm");
    FreeImage_DeInitialise();
    return failures ? 1 : 0;
}
