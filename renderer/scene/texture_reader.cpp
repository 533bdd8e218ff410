// Texture reader (host): FreeImage load, conversion to float RGB, scanline 0 (FreeImage's bottom row) first.
#include "scene/texture_reader.h"

#include <FreeImage.h>

#include <memory>
#include <string>

#include "io/freeimage_lock.h"
#include "io/text_file.h"
#include "scene/texture_header.h"

namespace trazo {
namespace {

struct BitmapDeleter {
    void operator()(FIBITMAP* b) const {
        if (b) FreeImage_Unload(b);
    }
};
using Bitmap = std::unique_ptr<FIBITMAP, BitmapDeleter>;

void copyTexels(FIBITMAP* converted, bool isFloat, TextureImage& image) {
    image.texels.resize(size_t(image.width) * size_t(image.height));
    for (int y = 0; y < image.height; ++y) {
        const BYTE* row = FreeImage_GetScanLine(converted, y);
        Vec3* out = &image.texels[size_t(y) * size_t(image.width)];
        for (int x = 0; x < image.width; ++x) {
            if (isFloat) {
                const FIRGBF& p = reinterpret_cast<const FIRGBF*>(row)[x];
                out[x] = {p.red, p.green, p.blue};
            } else {
                const BYTE* p = row + 3 * x;
                out[x] = Vec3(p[FI_RGBA_RED], p[FI_RGBA_GREEN], p[FI_RGBA_BLUE]) / 255.0f;
            }
        }
    }
}

FREE_IMAGE_FORMAT freeImageFormat(TextureFormat format) {
    switch (format) {
        case TextureFormat::Png: return FIF_PNG;
        case TextureFormat::Jpeg: return FIF_JPEG;
        case TextureFormat::Bmp: return FIF_BMP;
        case TextureFormat::Exr: return FIF_EXR;
        case TextureFormat::Pfm: return FIF_PFM;
    }
    return FIF_UNKNOWN;
}

struct MemoryDeleter {
    void operator()(FIMEMORY* m) const {
        if (m) FreeImage_CloseMemory(m);
    }
};

}  // namespace

std::shared_ptr<const TextureImage> readTextureImage(const std::string& path, const SourceLocation& where,
                                                     Diagnostics& diags) {
    // FreeImage is not safe on hostile files (a corrupt Sun RAS header crashes it, WBMP and IFF headers that
    // claim huge sizes run for minutes), so it decodes only bytes read here, from a regular file, in an accepted
    // format named by their signature, whose header's size is bounded.
    std::string bytes, reason;
    if (!readWholeFile(path, bytes, reason, kMaxTextureFileBytes)) {
        diags.error(where, "cannot read texture '" + path + "': " + reason);
        return nullptr;
    }
    TextureHeader header{};
    if (!readTextureHeader(bytes, path, header, reason)) {
        diags.error(where, "cannot decode texture '" + path + "': " + reason);
        return nullptr;
    }

    const FreeImageLock freeImage;  // FreeImage's decoding problems come back as its message
    const std::unique_ptr<FIMEMORY, MemoryDeleter> memory(
        FreeImage_OpenMemory(reinterpret_cast<BYTE*>(bytes.data()), DWORD(bytes.size())));
    Bitmap loaded(memory ? FreeImage_LoadFromMemory(freeImageFormat(header.format), memory.get(), 0) : nullptr);
    if (!loaded) {
        const std::string why =
            freeImage.message().empty() ? "the image is damaged or unsupported" : freeImage.message();
        diags.error(where, "cannot decode texture '" + path + "': " + why);
        return nullptr;
    }
    if (FreeImage_GetWidth(loaded.get()) != header.width || FreeImage_GetHeight(loaded.get()) != header.height) {
        diags.error(where, "cannot decode texture '" + path + "': the image is not the size its header claims");
        return nullptr;
    }
    // 8-bit images of any layout (palette, grey, RGBA) go through 24-bit RGB; wider ones through float RGB.
    const bool isFloat = FreeImage_GetImageType(loaded.get()) != FIT_BITMAP;
    Bitmap converted(isFloat ? FreeImage_ConvertToRGBF(loaded.get()) : FreeImage_ConvertTo24Bits(loaded.get()));
    if (!converted) {
        diags.error(where, "cannot decode texture '" + path + "': pixel type not convertible to RGB");
        return nullptr;
    }
    auto image = std::make_shared<TextureImage>();
    image->width = int(FreeImage_GetWidth(converted.get()));
    image->height = int(FreeImage_GetHeight(converted.get()));
    if (image->width <= 0 || image->height <= 0) {
        diags.error(where, "cannot decode texture '" + path + "': the image is empty");
        return nullptr;
    }
    copyTexels(converted.get(), isFloat, *image);
    image->eightBit = !isFloat;
    return image;
}

}  // namespace trazo
