// The partial file: text header, little-endian doubles, XXH64 trailer (docs/PARTIAL_FORMAT.md).
#include "render/partial_file.h"

#include <bit>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include <sys/stat.h>
#include <unistd.h>

#include "io/atomic_file.h"
#include "io/text_file.h"
#include "render/xxhash64.h"
#include "scene/param_check.h"

namespace trazo {

static_assert(std::endian::native == std::endian::little, "the partial format is little-endian; so is this code");
static_assert(sizeof(AccumPixel) == 8 * sizeof(double), "the per-pixel layout is AccumPixel's eight doubles");

namespace {

constexpr char kMagic[] = "TRAZO PARTIAL";
constexpr size_t kMaxHeaderBytes = size_t(1) << 20;
constexpr size_t kChunkPixels = 1 << 15;  // pixels per write or read (1.5 to 2 MB)

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

bool hashFile(const std::string& path, uint64_t& hash, std::string& error) {
    std::string reason;
    const int fd = openRegularFile(path, reason);
    if (fd < 0) {
        error = "cannot read '" + path + "': " + reason;
        return false;
    }
    Xxhash64 h;
    std::vector<char> buffer(1 << 20);
    for (;;) {
        const ssize_t n = ::read(fd, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = "cannot read '" + path + "': " + std::strerror(errno);
            ::close(fd);
            return false;
        }
        if (n == 0) break;
        h.update(buffer.data(), (size_t)n);
    }
    ::close(fd);
    hash = h.digest();
    return true;
}

// Header values are one line each: a newline or backslash in a path is escaped.
std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '\\') out += "\\\\";
        else if (c == '\n') out += "\\n";
        else out += c;
    }
    return out;
}
std::string unescape(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\\' && i + 1 < s.size()) {
            ++i;
            out += s[i] == 'n' ? '\n' : s[i];
        } else {
            out += s[i];
        }
    }
    return out;
}

bool uniformCounts(const std::vector<AccumPixel>& accum) {
    for (const AccumPixel& p : accum)
        if (std::memcmp(&p.count, &accum[0].count, sizeof p.count) != 0 ||
            std::memcmp(&p.countB, &accum[0].countB, sizeof p.countB) != 0)
            return false;
    return !accum.empty();
}

uint64_t dataBytes(uint64_t pixels, bool uniform) {
    return uniform ? 2 * sizeof(double) + pixels * 6 * sizeof(double) : pixels * sizeof(AccumPixel);
}

// "exposure=E view=linear|srgb", E with the digits a float needs to read back exactly.
std::string formatDisplay(const Fingerprint& f) {
    char exposure[32];
    std::snprintf(exposure, sizeof exposure, "%.9g", double(f.exposure));
    return std::string("exposure=") + exposure + (f.srgb ? " view=srgb" : " view=linear");
}

std::string formatHeader(const PartialHeader& h, bool uniform, uint64_t data) {
    const Fingerprint& f = h.fingerprint;
    char seconds[40];
    std::snprintf(seconds, sizeof seconds, "%.17g", h.seconds);
    std::string text = std::string(kMagic) + " " + std::to_string(kPartialFormatVersion) + "\n";
    text += "version: " + escape(f.version) + "\n";
    text += "scene: " + escape(f.scenePath) + "\n";
    text += "scene-xxh64: " + hexHash(f.sceneHash) + "\n";
    for (const AssetHash& a : f.assets) text += "asset: " + hexHash(a.hash) + " " + escape(a.path) + "\n";
    text += "size: " + std::to_string(f.width) + "x" + std::to_string(f.height) + "\n";
    text += "seed: " + std::to_string(f.seed) + "\n";
    text += "blocks: " + escape(f.blocks) + "\n";
    text += "settings: full-cycle=" + std::to_string(f.fullCycle) + "\n";
    if (f.exposure != 0.0f || f.srgb) text += "display: " + formatDisplay(f) + "\n";
    text += "passes: " + formatRanges(h.passes) + "\n";
    text += "requested: " + formatRange(h.requested) + "\n";
    text += "parts: " + std::to_string(h.parts) + "\n";
    text += "rays: " + std::to_string(h.rays) + "\n";
    text += "seconds: " + std::string(seconds) + "\n";
    text += "backend: " + escape(h.backend) + "\n";
    text += std::string("counts: ") + (uniform ? "uniform" : "per-pixel") + "\n";
    text += "data-bytes: " + std::to_string(data) + "\n\n";
    return text;
}

bool writeAll(FILE* f, const void* data, size_t size, Xxhash64& hash) {
    hash.update(data, size);
    return std::fwrite(data, 1, size, f) == size;
}

// --- reading -----------------------------------------------------------------------------------------------

// formatDisplay's "exposure=E view=linear|srgb", E finite and within SPEC §7's ±64 stops.
bool parseDisplay(const std::string& text, Fingerprint& f) {
    const size_t space = text.find(' ');
    if (text.rfind("exposure=", 0) != 0 || space == std::string::npos) return false;
    const std::string stops = text.substr(9, space - 9), view = text.substr(space + 1);
    char* end = nullptr;
    f.exposure = std::strtof(stops.c_str(), &end);
    f.srgb = view == "view=srgb";
    return !stops.empty() && *end == '\0' && std::fabs(f.exposure) <= kMaxStops &&
           (f.srgb || view == "view=linear");
}

bool parseU64(const std::string& text, uint64_t& out, int base = 10) {
    if (text.empty() || text.size() > 20) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtoull(text.c_str(), &end, base);
    return errno == 0 && *end == '\0' && text[0] != '-' && text[0] != '+' && text[0] != ' ';
}
bool parseU32(const std::string& text, uint32_t& out) {
    uint64_t v = 0;
    if (!parseU64(text, v) || v > UINT32_MAX) return false;
    out = (uint32_t)v;
    return true;
}
bool parseHash(const std::string& text, uint64_t& out) { return text.size() == 16 && parseU64(text, out, 16); }
bool parseRanges(const std::string& text, std::vector<PassRange>& out) {
    out.clear();
    size_t at = 0;
    while (at < text.size()) {
        size_t comma = text.find(',', at);
        if (comma == std::string::npos) comma = text.size();
        PassRange r;
        std::string why;
        if (!parsePassRange(text.substr(at, comma - at), r, why, UINT32_MAX)) return false;
        if (!out.empty() && r.first <= out.back().end) return false;  // joined and in order, as written
        out.push_back(r);
        at = comma + 1;
    }
    return !out.empty();
}

struct ParsedHeader {
    PartialHeader header;
    bool uniform = false;
    uint64_t dataBytes = 0;
    size_t headerBytes = 0;
};

// Parses the text up to the blank line; false with the reason (the caller adds the path).
bool parseHeader(const std::string& text, ParsedHeader& out, std::string& why) {
    const size_t end = text.find("\n\n");
    const std::string magicLine = std::string(kMagic) + " ";
    if (text.compare(0, magicLine.size(), magicLine) != 0) {
        why = "not a trazo partial file (it does not start with \"" + std::string(kMagic) + "\")";
        return false;
    }
    if (end == std::string::npos) {
        why = "not a trazo partial file: no end of header within " + std::to_string(kMaxHeaderBytes) + " bytes";
        return false;
    }
    out.headerBytes = end + 2;
    PartialHeader& h = out.header;
    Fingerprint& f = h.fingerprint;
    size_t at = 0;
    int line = 0;
    std::vector<std::string> seen;
    std::string counts;
    while (at < end) {
        size_t eol = text.find('\n', at);
        const std::string row = text.substr(at, eol - at);
        at = eol + 1;
        ++line;
        auto bad = [&](const std::string& what) {
            why = "header line " + std::to_string(line) + ": " + what + ": \"" + row + "\"";
            return false;
        };
        if (line == 1) {
            uint32_t version = 0;
            if (!parseU32(row.substr(magicLine.size()), version)) return bad("bad format version");
            if (version != kPartialFormatVersion)
                return bad("format version " + std::to_string(version) + "; this trazo reads version " +
                           std::to_string(kPartialFormatVersion));
            continue;
        }
        const size_t colon = row.find(": ");
        if (colon == std::string::npos) return bad("expected KEY: VALUE");
        const std::string key = row.substr(0, colon), value = row.substr(colon + 2);
        if (key != "asset") {
            for (const std::string& s : seen)
                if (s == key) return bad("repeated key");
            seen.push_back(key);
        }
        bool ok = true;
        if (key == "version") f.version = unescape(value);
        else if (key == "scene") f.scenePath = unescape(value);
        else if (key == "scene-xxh64") ok = parseHash(value, f.sceneHash);
        else if (key == "asset") {
            AssetHash a;
            ok = value.size() > 17 && value[16] == ' ' && parseHash(value.substr(0, 16), a.hash);
            a.path = ok ? unescape(value.substr(17)) : "";
            f.assets.push_back(a);
        } else if (key == "size") {
            const size_t x = value.find('x');
            ok = x != std::string::npos && parseU32(value.substr(0, x), f.width) &&
                 parseU32(value.substr(x + 1), f.height) && f.width >= 1 && f.height >= 1 &&
                 f.width <= (uint32_t)kMaxRenderSize && f.height <= (uint32_t)kMaxRenderSize;
        } else if (key == "seed") ok = parseU32(value, f.seed);
        else if (key == "blocks") f.blocks = unescape(value);
        else if (key == "settings") ok = value.rfind("full-cycle=", 0) == 0 && parseU32(value.substr(11), f.fullCycle);
        else if (key == "display") ok = parseDisplay(value, f);
        else if (key == "passes") ok = parseRanges(value, h.passes);
        else if (key == "requested") {
            std::string ignored;
            ok = parsePassRange(value, h.requested, ignored, UINT32_MAX);
        } else if (key == "parts") ok = parseU32(value, h.parts) && h.parts >= 1;
        else if (key == "rays") ok = parseU64(value, h.rays);
        else if (key == "seconds") {
            char* e = nullptr;
            h.seconds = std::strtod(value.c_str(), &e);
            ok = !value.empty() && *e == '\0';
        } else if (key == "backend") h.backend = unescape(value);
        else if (key == "counts") {
            counts = value;
            ok = value == "uniform" || value == "per-pixel";
            out.uniform = value == "uniform";
        } else if (key == "data-bytes") ok = parseU64(value, out.dataBytes);
        else return bad("unknown key");
        if (!ok) return bad("bad value");
    }
    for (const char* key : {"version", "scene", "scene-xxh64", "size", "seed", "blocks", "settings", "passes",
                            "requested", "parts", "rays", "seconds", "backend", "counts", "data-bytes"}) {
        bool found = false;
        for (const std::string& s : seen) found = found || s == key;
        if (!found) {
            why = std::string("header: no \"") + key + "\" line";
            return false;
        }
    }
    const uint64_t expected = dataBytes((uint64_t)f.width * f.height, out.uniform);
    if (out.dataBytes != expected) {
        why = "header: data-bytes " + std::to_string(out.dataBytes) + " does not match " + std::to_string(f.width) +
              "x" + std::to_string(f.height) + " pixels with " + counts + " counts (" + std::to_string(expected) + ")";
        return false;
    }
    return true;
}

// Opens `path`, reads its header, and checks the file's size: header + data + 8-byte checksum.
bool openPartial(const std::string& path, File& file, ParsedHeader& parsed, std::string& error) {
    std::string reason;
    const int fd = openRegularFile(path, reason);
    if (fd < 0) {
        error = path + ": " + reason;
        return false;
    }
    struct stat st {};
    if (fstat(fd, &st) != 0) {
        error = path + ": " + std::strerror(errno);
        ::close(fd);
        return false;
    }
    file = File(fdopen(fd, "rb"), &std::fclose);
    if (!file) {
        ::close(fd);
        error = path + ": " + std::strerror(errno);
        return false;
    }
    std::string text(std::min<uint64_t>((uint64_t)st.st_size, kMaxHeaderBytes), '\0');
    const size_t got = std::fread(text.data(), 1, text.size(), file.get());
    text.resize(got);
    if (got == (uint64_t)st.st_size && text.find("\n\n") == std::string::npos &&
        text.compare(0, std::strlen(kMagic), kMagic) == 0) {
        error = path + ": truncated: " + std::to_string(got) + " bytes, and its header does not end";
        return false;
    }
    if (!parseHeader(text, parsed, reason)) {
        error = path + ": " + reason;
        return false;
    }
    const uint64_t total = parsed.headerBytes + parsed.dataBytes + sizeof(uint64_t);
    if ((uint64_t)st.st_size < total) {
        error = path + ": truncated: " + std::to_string((uint64_t)st.st_size) + " bytes of " + std::to_string(total);
        return false;
    }
    if ((uint64_t)st.st_size > total) {
        error = path + ": " + std::to_string((uint64_t)st.st_size - total) + " bytes after the end of the data (" +
                std::to_string(total) + " expected)";
        return false;
    }
    if (std::fseek(file.get(), (long)parsed.headerBytes, SEEK_SET) != 0) {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

}  // namespace

bool hashSceneFiles(const Scene& scene, Fingerprint& out, std::string& error) {
    out.scenePath = scene.path;
    if (!hashFile(scene.path, out.sceneHash, error)) return false;
    out.assets.clear();
    auto add = [&](const std::string& path) {
        AssetHash a{path, 0};
        if (!hashFile(path, a.hash, error)) return false;
        out.assets.push_back(a);
        return true;
    };
    for (const Texture& t : scene.textures)
        if (!add(t.source)) return false;
    for (const Mesh& m : scene.meshes)
        if (!add(m.source)) return false;
    for (const Csg& c : scene.csgs)
        if (!add(c.source)) return false;
    return true;
}

std::string fingerprintDifference(const Fingerprint& a, const Fingerprint& b) {
    if (a.sceneHash != b.sceneHash)
        return "scene (" + a.scenePath + " xxh64 " + hexHash(a.sceneHash) + " vs " + b.scenePath + " xxh64 " +
               hexHash(b.sceneHash) + ")";
    if (a.assets.size() != b.assets.size())
        return "assets (" + std::to_string(a.assets.size()) + " files vs " + std::to_string(b.assets.size()) + ")";
    for (size_t i = 0; i < a.assets.size(); ++i)
        if (a.assets[i].hash != b.assets[i].hash)
            return "assets (" + a.assets[i].path + " xxh64 " + hexHash(a.assets[i].hash) + " vs " + b.assets[i].path +
                   " xxh64 " + hexHash(b.assets[i].hash) + ")";
    if (a.fullCycle != b.fullCycle)
        return "settings (full-cycle=" + std::to_string(a.fullCycle) + " vs full-cycle=" +
               std::to_string(b.fullCycle) + ")";
    if (a.width != b.width || a.height != b.height)
        return "size (" + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " + std::to_string(b.width) +
               "x" + std::to_string(b.height) + ")";
    if (a.seed != b.seed) return "seed (" + std::to_string(a.seed) + " vs " + std::to_string(b.seed) + ")";
    if (a.blocks != b.blocks) return "blocks (" + a.blocks + " vs " + b.blocks + ")";
    if (a.version != b.version) return "version (" + a.version + " vs " + b.version + ")";
    if (a.exposure != b.exposure || a.srgb != b.srgb)
        return "display (" + formatDisplay(a) + " vs " + formatDisplay(b) + ")";
    return "";
}

bool writePartialFile(const std::string& path, const PartialHeader& header, const std::vector<AccumPixel>& accum,
                      std::string& error) {
    const uint64_t pixels = (uint64_t)header.fingerprint.width * header.fingerprint.height;
    if (accum.size() != pixels) {
        error = "cannot write '" + path + "': the accumulation holds " + std::to_string(accum.size()) +
                " pixels, not " + std::to_string(pixels);
        return false;
    }
    const bool uniform = uniformCounts(accum);
    const std::string text = formatHeader(header, uniform, dataBytes(pixels, uniform));
    return replaceAtomically(path, [&](const std::string& temporary, std::string& why) {
        File f(std::fopen(temporary.c_str(), "wb"), &std::fclose);
        auto fail = [&] {
            why = "cannot write '" + path + "': " + std::strerror(errno ? errno : EIO);
            return false;
        };
        if (!f) return fail();
        Xxhash64 hash;
        bool ok = writeAll(f.get(), text.data(), text.size(), hash);
        if (uniform) {
            const double counts[2] = {accum[0].count, accum[0].countB};
            ok = ok && writeAll(f.get(), counts, sizeof counts, hash);
            std::vector<double> chunk;
            chunk.reserve(kChunkPixels * 6);
            for (size_t begin = 0; ok && begin < accum.size(); begin += kChunkPixels) {
                chunk.clear();
                const size_t end = std::min(accum.size(), begin + kChunkPixels);
                for (size_t i = begin; i < end; ++i) {
                    const AccumPixel& p = accum[i];
                    chunk.insert(chunk.end(), {p.sum[0], p.sum[1], p.sum[2], p.sumB[0], p.sumB[1], p.sumB[2]});
                }
                ok = writeAll(f.get(), chunk.data(), chunk.size() * sizeof(double), hash);
            }
        } else {
            for (size_t begin = 0; ok && begin < accum.size(); begin += kChunkPixels) {
                const size_t n = std::min(accum.size() - begin, kChunkPixels);
                ok = writeAll(f.get(), accum.data() + begin, n * sizeof(AccumPixel), hash);
            }
        }
        const uint64_t checksum = hash.digest();
        ok = ok && std::fwrite(&checksum, 1, sizeof checksum, f.get()) == sizeof checksum;
        ok = ok && std::fflush(f.get()) == 0;
        if (!ok) return fail();
        FILE* raw = f.release();
        if (std::fclose(raw) != 0) return fail();
        return true;
    }, error);
}

bool readPartialHeader(const std::string& path, PartialHeader& header, std::string& error) {
    File file(nullptr, &std::fclose);
    ParsedHeader parsed;
    if (!openPartial(path, file, parsed, error)) return false;
    header = parsed.header;
    return true;
}

bool readPartialPixels(const std::string& path, PartialHeader& header, const TakePixels& take, std::string& error) {
    File file(nullptr, &std::fclose);
    ParsedHeader parsed;
    if (!openPartial(path, file, parsed, error)) return false;
    const uint64_t pixels = (uint64_t)parsed.header.fingerprint.width * parsed.header.fingerprint.height;
    Xxhash64 hash;
    // The header as it stands in the file: re-read, since the parse above read it from a prefix.
    std::string text(parsed.headerBytes, '\0');
    std::rewind(file.get());
    bool ok = std::fread(text.data(), 1, text.size(), file.get()) == text.size();
    hash.update(text.data(), text.size());
    auto readAll = [&](void* data, size_t size) {
        if (std::fread(data, 1, size, file.get()) != size) return false;
        hash.update(data, size);
        return true;
    };
    std::vector<AccumPixel> chunk(kChunkPixels);
    if (parsed.uniform) {
        double counts[2] = {0, 0};
        ok = ok && readAll(counts, sizeof counts);
        std::vector<double> packed(kChunkPixels * 6);
        for (size_t begin = 0; ok && begin < pixels; begin += kChunkPixels) {
            const size_t n = std::min<size_t>(pixels - begin, kChunkPixels);
            ok = readAll(packed.data(), n * 6 * sizeof(double));
            for (size_t i = 0; ok && i < n; ++i) {
                const double* d = &packed[6 * i];
                chunk[i] = AccumPixel{{d[0], d[1], d[2]}, counts[0], {d[3], d[4], d[5]}, counts[1]};
            }
            if (ok) take(begin, chunk.data(), n);
        }
    } else {
        for (size_t begin = 0; ok && begin < pixels; begin += kChunkPixels) {
            const size_t n = std::min<size_t>(pixels - begin, kChunkPixels);
            ok = readAll(chunk.data(), n * sizeof(AccumPixel));
            if (ok) take(begin, chunk.data(), n);
        }
    }
    uint64_t stored = 0;
    ok = ok && std::fread(&stored, 1, sizeof stored, file.get()) == sizeof stored;
    if (!ok) {
        error = path + ": read error: " + std::strerror(errno ? errno : EIO);
        return false;
    }
    const uint64_t computed = hash.digest();
    if (stored != computed) {
        error = path + ": corrupt: its checksum is xxh64 " + hexHash(stored) + " but its contents hash to " +
                hexHash(computed);
        return false;
    }
    header = parsed.header;
    return true;
}

bool readPartialFile(const std::string& path, PartialHeader& header, std::vector<AccumPixel>& accum,
                     std::string& error) {
    PartialHeader h;
    if (!readPartialHeader(path, h, error)) return false;
    accum.resize((size_t)h.fingerprint.width * h.fingerprint.height);
    return readPartialPixels(path, header, [&](size_t first, const AccumPixel* pixels, size_t count) {
        if (first + count <= accum.size()) std::copy(pixels, pixels + count, accum.begin() + (ptrdiff_t)first);
    }, error);
}

}  // namespace trazo
