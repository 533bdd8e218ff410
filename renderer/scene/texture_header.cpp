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

// OpenEXR: the required dataWindow attribute (box2i: xMin, yMin, xMax, yMax) among the header's attributes.
bool exrSize(const std::string& b, uint32_t& w, uint32_t& h) {
    size_t i = 8;  // magic, version
    while (i < b.size() && b[i] != '\0') {
        const size_t nameEnd = b.find('\0', i);
        if (nameEnd == std::string::npos) return false;
        const size_t typeEnd = b.find('\0', nameEnd + 1);
        if (typeEnd == std::string::npos || typeEnd + 5 > b.size()) return false;
        const std::string name = b.substr(i, nameEnd - i), type = b.substr(nameEnd + 1, typeEnd - nameEnd - 1);
        const uint32_t size = le32(b, typeEnd + 1);
        const size_t value = typeEnd + 5;
        if (size > b.size() - value) return false;
        if (name == "dataWindow" && type == "box2i" && size == 16) {
            const int64_t xMin = int32_t(le32(b, value)), yMin = int32_t(le32(b, value + 4));
            const int64_t xMax = int32_t(le32(b, value + 8)), yMax = int32_t(le32(b, value + 12));
            if (xMax < xMin || yMax < yMin) return false;
            const int64_t width = xMax - xMin + 1, height = yMax - yMin + 1;
            w = width > 0xffffffffLL ? 0xffffffffu : uint32_t(width);
            h = height > 0xffffffffLL ? 0xffffffffu : uint32_t(height);
            return true;
        }
        i = value + size;
    }
    return false;
}

// Radiance HDR: header lines up to an empty one, then "-Y H +X W" (or another orientation).
bool hdrSize(const std::string& b, uint32_t& w, uint32_t& h) {
    const size_t end = b.find("\n\n");
    if (end == std::string::npos) return false;
    const size_t lineEnd = b.find('\n', end + 2);
    const std::string line = b.substr(end + 2, (lineEnd == std::string::npos ? b.size() : lineEnd) - end - 2);
    char a1[3] = {}, a2[3] = {};
    unsigned long n1 = 0, n2 = 0;
    char s1, s2;
    if (std::sscanf(line.c_str(), " %c%c %lu %c%c %lu", &s1, &a1[0], &n1, &s2, &a2[0], &n2) != 6) return false;
    if ((s1 != '+' && s1 != '-') || (s2 != '+' && s2 != '-')) return false;
    const bool yFirst = a1[0] == 'Y';
    if ((a1[0] != 'X' && a1[0] != 'Y') || a2[0] != (yFirst ? 'X' : 'Y')) return false;
    const unsigned long rows = yFirst ? n1 : n2, columns = yFirst ? n2 : n1;
    w = columns > 0xffffffffUL ? 0xffffffffu : uint32_t(columns);
    h = rows > 0xffffffffUL ? 0xffffffffu : uint32_t(rows);
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
        case TextureFormat::Tga: return "TGA";
        case TextureFormat::Exr: return "EXR";
        case TextureFormat::Hdr: return "HDR";
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
        header.format = TextureFormat::Hdr;
        sized = hdrSize(b, w, h);
    } else if ((startsWith(b, "PF", 2) || startsWith(b, "Pf", 2)) && b.size() > 2 && std::isspace(uint8_t(b[2]))) {
        header.format = TextureFormat::Pfm;
        sized = pfmSize(b, w, h);
    } else if (endsWithTga(path) && b.size() >= 18) {
        // Uncompressed or RLE colour-mapped, true-colour or grey images, 8–32 bits a pixel.
        const uint8_t type = uint8_t(b[2]), bits = uint8_t(b[16]);
        const bool knownType = type == 1 || type == 2 || type == 3 || type == 9 || type == 10 || type == 11;
        if (!knownType || (bits != 8 && bits != 15 && bits != 16 && bits != 24 && bits != 32)) {
            why = "not a TGA image (its header names no image type Trazo reads)";
            return false;
        }
        header.format = TextureFormat::Tga;
        w = le16(b, 12), h = le16(b, 14), sized = true;
    } else {
        why = "not a PNG, JPEG, BMP, TGA, EXR, HDR or PFM file (the format is read from the file's first bytes)";
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
