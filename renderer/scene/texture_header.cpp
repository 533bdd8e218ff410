// Signatures and header sizes of the accepted texture formats, read from the bytes without a decoder.
#include "scene/texture_header.h"

#include <cctype>
#include <cstdlib>
#include <cstring>

namespace trazo {
namespace {

uint32_t be16(const std::string& b, size_t i) { return uint32_t(uint8_t(b[i])) << 8 | uint8_t(b[i + 1]); }
uint32_t be32(const std::string& b, size_t i) { return be16(b, i) << 16 | be16(b, i + 2); }
uint32_t le16(const std::string& b, size_t i) { return uint32_t(uint8_t(b[i])) | uint32_t(uint8_t(b[i + 1])) << 8; }
uint32_t le32(const std::string& b, size_t i) { return le16(b, i) | le16(b, i + 2) << 16; }

bool startsWith(const std::string& b, const char* prefix, size_t length) {
    return b.size() >= length && std::memcmp(b.data(), prefix, length) == 0;
}

bool endsWithTga(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = char(std::tolower(uint8_t(c)));
    return ext == ".tga";
}

// JPEG: the frame header (SOF0–SOF15 but DHT, JPG and DAC) after the segments before it.
bool jpegSize(const std::string& b, uint32_t& w, uint32_t& h) {
    size_t i = 2;
    while (i + 4 <= b.size()) {
        if (uint8_t(b[i]) != 0xFF) return false;
        const uint8_t marker = uint8_t(b[i + 1]);
        if (marker == 0xFF) {  // fill byte
            ++i;
            continue;
        }
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD9)) {  // no length
            i += 2;
            continue;
        }
        const uint32_t length = be16(b, i + 2);
        if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) {
            if (i + 9 > b.size() || length < 7) return false;
            h = be16(b, i + 5);
            w = be16(b, i + 7);
            return true;
        }
        if (length < 2) return false;
        i += 2 + length;
    }
    return false;
}

// The size an OpenEXR attribute of `type` must have, or 0 for types of any size (strings, channel lists).
uint32_t exrAttributeSize(const std::string& type) {
    if (type == "box2i" || type == "box2f") return 16;
    if (type == "v2i" || type == "v2f" || type == "double" || type == "rational") return 8;
    if (type == "v3i" || type == "v3f") return 12;
    if (type == "int" || type == "float") return 4;
    if (type == "timecode") return 8;
    if (type == "keycode") return 28;
    if (type == "compression" || type == "lineOrder" || type == "envmap" || type == "deepImageState") return 1;
    if (type == "chromaticities") return 32;
    if (type == "m33f") return 36;
    if (type == "m44f") return 64;
    if (type == "tiledesc") return 9;
    return 0;
}

// Whether an attribute of variable size parses to exactly its `size` bytes at `value`, as OpenEXR will read it:
// OpenEXR parses a channel list or a preview by its content, not by its declared size, so a list that ends
// early leaves the reader out of step with the file (reading a bogus attribute of megabytes past the end).
bool exrVariableAttributeFits(const std::string& b, const std::string& type, size_t value, uint32_t size) {
    const size_t end = value + size;
    if (type == "chlist") {
        // Channels: a name, then pixel type (uint, half, float), pLinear, 3 reserved bytes, x and y sampling;
        // a texture's channels are never subsampled. An empty name ends the list, on the attribute's last byte.
        size_t i = value;
        int channels = 0;
        while (i < end && b[i] != '\0') {
            const size_t nameEnd = b.find('\0', i);
            if (nameEnd == std::string::npos || nameEnd >= end || nameEnd - i > 255) return false;
            if (end - (nameEnd + 1) < 16) return false;
            const size_t fields = nameEnd + 1;
            if (le32(b, fields) > 2 || le32(b, fields + 8) != 1 || le32(b, fields + 12) != 1) return false;
            if (++channels > 64) return false;
            i = fields + 16;
        }
        return channels > 0 && i + 1 == end;
    }
    if (type == "preview") return size >= 8 && uint64_t(le32(b, value)) * le32(b, value + 4) * 4 + 8 == size;
    if (type == "stringvector") {
        for (size_t i = value; i < end;) {
            if (end - i < 4 || le32(b, i) > end - i - 4) return false;
            i += 4 + le32(b, i);
        }
        return true;
    }
    if (type == "floatvector") return size % 4 == 0;
    return true;  // strings and types OpenEXR does not know: read as exactly `size` bytes
}

// OpenEXR: the header's attributes, every one whole and of its type's size, up to the byte that ends them;
// then the required dataWindow (box2i: xMin, yMin, xMax, yMax). OpenEXR's reader does not stop at the end of
// the bytes it is given: a header cut short, or a float attribute of size 0, makes it read for ever.
bool exrSize(const std::string& b, uint32_t& w, uint32_t& h) {
    // Version 2, one part of scan lines: no tiles, deep data or parts (flag bits 9, 11 and 12).
    if (b.size() < 8 || uint8_t(b[4]) != 2 || (le32(b, 4) & 0x1a00u) != 0) return false;
    size_t i = 8;
    bool found = false;
    int compression = -1;
    while (i < b.size() && b[i] != '\0') {
        const size_t nameEnd = b.find('\0', i);
        if (nameEnd == std::string::npos) return false;
        const size_t typeEnd = b.find('\0', nameEnd + 1);
        if (typeEnd == std::string::npos || typeEnd + 5 > b.size()) return false;
        const std::string name = b.substr(i, nameEnd - i), type = b.substr(nameEnd + 1, typeEnd - nameEnd - 1);
        if (name.empty() || type.empty() || name.size() > 255 || type.size() > 255) return false;
        const uint32_t size = le32(b, typeEnd + 1);
        const size_t value = typeEnd + 5;
        if (size > b.size() - value) return false;
        const uint32_t expected = exrAttributeSize(type);
        if (expected != 0 && size != expected) return false;
        if (expected == 0 && (size == 0 || !exrVariableAttributeFits(b, type, value, size))) return false;
        if (name == "dataWindow") {
            if (type != "box2i") return false;
            const int64_t xMin = int32_t(le32(b, value)), yMin = int32_t(le32(b, value + 4));
            const int64_t xMax = int32_t(le32(b, value + 8)), yMax = int32_t(le32(b, value + 12));
            if (xMax < xMin || yMax < yMin) return false;
            const int64_t width = xMax - xMin + 1, height = yMax - yMin + 1;
            w = width > 0xffffffffLL ? 0xffffffffu : uint32_t(width);
            h = height > 0xffffffffLL ? 0xffffffffu : uint32_t(height);
            found = true;
        }
        if (name == "compression") compression = uint8_t(b[value]);
        i = value + size;
    }
    if (i >= b.size() || !found || compression < 0) return false;
    // OpenEXR reads past the bytes it is given without stopping (FreeImage's memory stream), so every read it
    // will make must lie inside them: the offset table (a block of lines per entry, as many lines as the
    // compression groups) and each block's header (y, data size) and data.
    static const int kLinesPerBlock[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};  // by compression, 0–9
    if (compression > 9) return false;
    const uint64_t blocks = (uint64_t(h) + kLinesPerBlock[compression] - 1) / kLinesPerBlock[compression];
    const size_t table = i + 1;
    if (h > kMaxTextureSide || blocks * 8 > b.size() - table) return false;
    for (uint64_t k = 0; k < blocks; ++k) {
        const uint64_t offset = uint64_t(le32(b, table + 8 * k)) | uint64_t(le32(b, table + 8 * k + 4)) << 32;
        if (offset < table + blocks * 8 || offset > b.size() || b.size() - offset < 8) return false;
        const uint32_t dataSize = le32(b, size_t(offset) + 4);
        if (dataSize > b.size() - offset - 8) return false;
    }
    return true;
}

// PFM: "PF" or "Pf", whitespace, then the width and height as decimal numbers.
bool pfmSize(const std::string& b, uint32_t& w, uint32_t& h) {
    const std::string head = b.substr(0, 256);
    char kind[3] = {};
    unsigned long width = 0, height = 0;
    if (std::sscanf(head.c_str(), "%2s %lu %lu", kind, &width, &height) != 3) return false;
    w = width > 0xffffffffUL ? 0xffffffffu : uint32_t(width);
    h = height > 0xffffffffUL ? 0xffffffffu : uint32_t(height);
    return true;
}

}  // namespace

const char* textureFormatName(TextureFormat format) {
    switch (format) {
        case TextureFormat::Png: return "PNG";
        case TextureFormat::Jpeg: return "JPEG";
        case TextureFormat::Bmp: return "BMP";
        case TextureFormat::Exr: return "EXR";
        case TextureFormat::Pfm: return "PFM";
    }
    return "?";
}

bool readTextureHeader(const std::string& b, const std::string& path, TextureHeader& header, std::string& why) {
    bool sized = false;
    uint32_t w = 0, h = 0;
    if (startsWith(b, "\x89PNG\r\n\x1a\n", 8)) {
        header.format = TextureFormat::Png;
        if (b.size() >= 24 && b.compare(12, 4, "IHDR") == 0) w = be32(b, 16), h = be32(b, 20), sized = true;
    } else if (startsWith(b, "\xFF\xD8\xFF", 3)) {
        header.format = TextureFormat::Jpeg;
        sized = jpegSize(b, w, h);
    } else if (startsWith(b, "BM", 2)) {
        header.format = TextureFormat::Bmp;
        if (b.size() >= 26) {
            const int64_t width = int32_t(le32(b, 18)), height = int32_t(le32(b, 22));  // height < 0: top down
            w = width < 0 ? 0u : uint32_t(width);
            h = uint32_t(height < 0 ? -height : height);
            sized = true;
        }
    } else if (startsWith(b, "\x76\x2f\x31\x01", 4)) {
        header.format = TextureFormat::Exr;
        sized = exrSize(b, w, h);
    } else if (startsWith(b, "#?", 2)) {
        why = "a Radiance HDR file, which Trazo does not read (FreeImage's HDR decoder overflows its buffers on "
              "damaged headers); convert it to EXR or PFM";
        return false;
    } else if ((startsWith(b, "PF", 2) || startsWith(b, "Pf", 2)) && b.size() > 2 && std::isspace(uint8_t(b[2]))) {
        header.format = TextureFormat::Pfm;
        sized = pfmSize(b, w, h);
    } else if (endsWithTga(path)) {
        why = "a TGA file, which Trazo does not read (FreeImage's TGA decoder writes through a null pointer on "
              "damaged headers); convert it to PNG";
        return false;
    } else {
        why = "not a PNG, JPEG, BMP, EXR or PFM file (the format is read from the file's first bytes)";
        return false;
    }
    if (!sized) {
        why = std::string("a damaged ") + textureFormatName(header.format) + " header (no image size in it)";
        return false;
    }
    if (w == 0 || h == 0 || w > kMaxTextureSide || h > kMaxTextureSide || uint64_t(w) * h > kMaxTextureTexels) {
        why = std::string("the ") + textureFormatName(header.format) + " header claims " + std::to_string(w) + " × " +
              std::to_string(h) + " texels; a texture may have 1 to " + std::to_string(kMaxTextureSide) +
              " on a side and " + std::to_string(kMaxTextureTexels) + " in all";
        return false;
    }
    header.width = w;
    header.height = h;
    return true;
}

}  // namespace trazo
