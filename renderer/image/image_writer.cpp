// Image output (host): converts a linear float image to a FreeImage bitmap and saves it through
// replaceAtomically.
#include "image/image_writer.h"

#include <FreeImage.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <system_error>

#include "io/atomic_file.h"
#include "io/freeimage_lock.h"

namespace trazo {

namespace fs = std::filesystem;

namespace {

struct FormatInfo {
    FREE_IMAGE_FORMAT fif;
    int flags;
    bool isFloat;   // FIT_RGBF bitmap; otherwise a 24-bit one
    bool flipRows;  // hand FreeImage the rows upside down to undo its plugin's row order
    const char* name;
};

FormatInfo formatInfo(ImageFormat format) {
    switch (format) {
        case ImageFormat::Png: return {FIF_PNG, PNG_DEFAULT, false, false, "PNG"};
        case ImageFormat::Bmp: return {FIF_BMP, BMP_DEFAULT, false, false, "BMP"};
        // The least lossy JPEG FreeImage offers: quality 100 and no chroma subsampling.
        case ImageFormat::Jpeg: return {FIF_JPEG, JPEG_QUALITYSUPERB | JPEG_SUBSAMPLING_444, false, false, "JPEG"};
        case ImageFormat::Tga: return {FIF_TARGA, TARGA_DEFAULT, false, false, "TGA"};
        // Without EXR_FLOAT FreeImage writes half floats (relative error up to 4e-4).
        case ImageFormat::Exr: return {FIF_EXR, EXR_FLOAT | EXR_ZIP, true, false, "EXR"};
        case ImageFormat::Hdr: return {FIF_HDR, HDR_DEFAULT, true, false, "HDR"};
        // The PFM format stores rows bottom to top, but FreeImage 3.18 writes (and reads) the top row
        // first; handing it the rows flipped makes the file follow the format, as other tools expect.
        case ImageFormat::Pfm: return {FIF_PFM, PFM_DEFAULT, true, true, "PFM"};
    }
    return {FIF_UNKNOWN, 0, false, false, "?"};
}

// round(255·clamp(c, 0, 1)); NaN fails both comparisons and lands on 0. Rounded in double so that a
// float just below k + 0.5 (in units of 1/255) is not pushed over by float rounding of the product.
uint8_t toByte(float c) {
    if (!(c > 0.0f)) return 0;
    if (c >= 1.0f) return 255;
    return static_cast<uint8_t>(std::floor(255.0 * static_cast<double>(c) + 0.5));
}

// 2^Exposure × x for a float file. A finite pixel that the exposure takes past float's range is stored as the
// largest float of its sign, not inf (docs/LIMITS.md: no pixel is Inf); with scale 1 this is x itself.
float exposed(float scale, float x) {
    const float y = scale * x;
    return std::isinf(y) && std::isfinite(x) ? std::copysign(std::numeric_limits<float>::max(), y) : y;
}

// FreeImage's scanline 0 is the bottom row; rgbTopDown's row 0 is the top. Float formats get the exposed value,
// 8-bit ones its display encoding (SPEC §7 Image); the identity transform changes no value.
FIBITMAP* makeBitmap(const FormatInfo& info, int width, int height, const std::vector<Vec3>& rgbTopDown,
                     const DisplayTransform& display) {
    FIBITMAP* bitmap = info.isFloat ? FreeImage_AllocateT(FIT_RGBF, width, height)
                                    : FreeImage_Allocate(width, height, 24);
    if (!bitmap) return nullptr;
    for (int y = 0; y < height; ++y) {
        const Vec3* src = rgbTopDown.data() + static_cast<size_t>(y) * width;
        BYTE* line = FreeImage_GetScanLine(bitmap, info.flipRows ? y : height - 1 - y);
        if (info.isFloat) {
            auto* dst = reinterpret_cast<FIRGBF*>(line);
            const float k = display.scale;
            for (int x = 0; x < width; ++x) dst[x] = {exposed(k, src[x].x), exposed(k, src[x].y), exposed(k, src[x].z)};
        } else {
            for (int x = 0; x < width; ++x) {
                BYTE* px = line + 3 * x;  // byte order is platform-defined: BGR on little-endian
                px[FI_RGBA_RED] = toByte(display.encode(src[x].x));
                px[FI_RGBA_GREEN] = toByte(display.encode(src[x].y));
                px[FI_RGBA_BLUE] = toByte(display.encode(src[x].z));
            }
        }
    }
    return bitmap;
}

// Our own FILE*-backed FreeImageIO, so that the errno of a failed write (a full disk) reaches the caller.
struct FileSink {
    FILE* file = nullptr;
    int writeErrno = 0;
};

unsigned DLL_CALLCONV sinkRead(void*, unsigned, unsigned, fi_handle) { return 0; }

unsigned DLL_CALLCONV sinkWrite(void* buffer, unsigned size, unsigned count, fi_handle handle) {
    auto* sink = static_cast<FileSink*>(handle);
    size_t written = std::fwrite(buffer, size, count, sink->file);
    if (written < count && sink->writeErrno == 0) sink->writeErrno = errno ? errno : EIO;
    return static_cast<unsigned>(written);
}

int DLL_CALLCONV sinkSeek(fi_handle handle, long offset, int origin) {
    return std::fseek(static_cast<FileSink*>(handle)->file, offset, origin);
}

long DLL_CALLCONV sinkTell(fi_handle handle) { return std::ftell(static_cast<FileSink*>(handle)->file); }

std::string errnoText(int err) { return std::strerror(err); }

}  // namespace

bool imageFormatFromPath(const std::string& path, ImageFormat& format) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".png") format = ImageFormat::Png;
    else if (ext == ".bmp") format = ImageFormat::Bmp;
    else if (ext == ".jpg" || ext == ".jpeg") format = ImageFormat::Jpeg;
    else if (ext == ".tga") format = ImageFormat::Tga;
    else if (ext == ".exr") format = ImageFormat::Exr;
    else if (ext == ".hdr") format = ImageFormat::Hdr;
    else if (ext == ".pfm") format = ImageFormat::Pfm;
    else return false;
    return true;
}

std::string unknownImageFormatReason(const std::string& path) {
    return "'" + path + "': unknown image extension '" + fs::path(path).extension().string() +
           "' (use .png, .bmp, .jpg, .jpeg, .tga, .exr, .hdr or .pfm)";
}

bool writeImage(const std::string& path, int width, int height, const std::vector<Vec3>& rgbTopDown,
                std::string& error, const DisplayTransform& display) {
    ImageFormat format;
    if (!imageFormatFromPath(path, format)) {
        error = "cannot write " + unknownImageFormatReason(path);
        return false;
    }
    if (width <= 0 || height <= 0 || rgbTopDown.size() != static_cast<size_t>(width) * height) {
        error = "cannot write '" + path + "': " + std::to_string(rgbTopDown.size()) + " pixels for a " +
                std::to_string(width) + "x" + std::to_string(height) + " image";
        return false;
    }
    const fs::path target(path);
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        error = "cannot write '" + path + "': folder '" + dir.string() + "' " +
                (fs::exists(dir, ec) ? "is not a folder" : "does not exist");
        return false;
    }

    const FreeImageLock freeImage;
    const FormatInfo info = formatInfo(format);
    FIBITMAP* bitmap = makeBitmap(info, width, height, rgbTopDown, display);
    if (!bitmap) {
        error = "cannot write '" + path + "': out of memory for a " + std::to_string(width) + "x" +
                std::to_string(height) + " image";
        return false;
    }
    const bool written = replaceAtomically(
        path,
        [&](const std::string& temporary, std::string& why) {
            FileSink sink;
            sink.file = std::fopen(temporary.c_str(), "w+b");
            if (!sink.file) {
                const int openErrno = errno;  // before any allocation below can touch errno
                why = "cannot write '" + path + "': cannot create a file in folder '" + dir.string() +
                      "': " + errnoText(openErrno);
                return false;
            }
            FreeImageIO io{sinkRead, sinkWrite, sinkSeek, sinkTell};
            const bool saved = FreeImage_SaveToHandle(info.fif, bitmap, &io, &sink, info.flags);
            const bool flushed = std::fflush(sink.file) == 0;
            if (!flushed && sink.writeErrno == 0) sink.writeErrno = errno;
            const bool closed = std::fclose(sink.file) == 0;
            if (!closed && sink.writeErrno == 0) sink.writeErrno = errno;
            if (saved && flushed && closed && sink.writeErrno == 0) return true;
            why = "cannot write '" + path + "': FreeImage failed to write the " + info.name + " file";
            if (sink.writeErrno != 0) why += ": " + errnoText(sink.writeErrno);
            return false;
        },
        error);
    FreeImage_Unload(bitmap);
    return written;
}

}  // namespace trazo
