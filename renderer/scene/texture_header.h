// What a texture file says it is before anything is decoded: its format, from the file's own signature,
// and the size its header claims. Only formats whose FreeImage readers survived fuzzing are accepted (PNG,
// JPEG, BMP, OpenEXR, PFM: TGA and Radiance HDR crashed it within seconds); a file is decoded only once its
// claimed size is known to be within kMaxTextureTexels and, for EXR, every read is known to stay in the file.
#pragma once

#include <cstdint>
#include <string>

namespace trazo {

enum class TextureFormat { Png, Jpeg, Bmp, Exr, Pfm };

// 2^25 texels (e.g. 8192 × 4096): 384 MiB as float RGB, the most one texture may take.
constexpr uint64_t kMaxTextureTexels = uint64_t(1) << 25;
constexpr uint32_t kMaxTextureSide = 32768;
// The most bytes read from a texture file (a 2^25-texel EXR of 32-bit floats with alpha is 512 MiB raw).
constexpr size_t kMaxTextureFileBytes = size_t(640) << 20;

struct TextureHeader {
    TextureFormat format;
    uint32_t width, height;
};

// Reads the signature and the header's size from the file's bytes. `path` only names a refused TGA (which has
// no signature) by its extension. False with a plain reason ("not a PNG, JPEG, BMP, EXR or PFM file", "the PNG
// header claims 2147483647 × 1 texels; ...") when the file must not be decoded.
bool readTextureHeader(const std::string& bytes, const std::string& path, TextureHeader& header, std::string& why);

const char* textureFormatName(TextureFormat format);

}  // namespace trazo
