// OBJ reader (host): a line check of our own (tinyobjloader reads bad numbers as 0 and reports index
// errors at the last line), and tinyobjloader's callback reader for the data, fan-triangulated straight
// into MeshData (no attrib_t/shape_t copies, no stringstream copy of the text). For a large file the two
// run at once on two threads over the same text; the data is kept only if the check passes, and every
// index is range-checked again against what tinyobjloader read.
#include "scene/obj_reader.h"

#include <sys/mman.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>
#include <new>
#include <streambuf>
#include <string_view>
#include <thread>
#include <vector>

#include "io/text_file.h"

namespace trazo {
namespace {

constexpr int kMaxReportedErrors = 20;  // a binary or foreign file would otherwise flood the output

struct Word {
    std::string_view text;
    int column;
};

// Into `words` (cleared; its capacity is kept from line to line).
void splitWords(std::string_view line, std::vector<Word>& words) {
    words.clear();
    size_t i = 0;
    while (i < line.size()) {
        if (line[i] == '#') break;
        if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
            ++i;
            continue;
        }
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#') ++i;
        words.push_back({line.substr(start, i - start), int(start) + 1});
    }
}

bool parseReal(std::string_view s, double& out) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && ptr == s.data() + s.size() && !s.empty() && std::isfinite(float(out));
}

bool parseIndex(std::string_view s, long& out) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && ptr == s.data() + s.size() && !s.empty();
}

// Checks every line; positive indices may point forward (tinyobjloader allows it), so they are checked
// against the final counts at the end, still with their own line.
class ObjChecker {
public:
    ObjChecker(const std::string& file, Diagnostics& diags) : file_(file), diags_(diags) {}

    void checkLine(std::string_view line, int lineNumber) {
        splitWords(line, words_);
        const std::vector<Word>& words = words_;
        if (words.empty()) return;
        const std::string_view keyword = words[0].text;
        if (keyword == "v") {
            if (checkNumbers(words, 3, 7, lineNumber, "a vertex")) ++counts_[0];
        } else if (keyword == "vt") {
            if (checkNumbers(words, 1, 3, lineNumber, "a texture coordinate")) ++counts_[1];
        } else if (keyword == "vn") {
            if (checkNumbers(words, 3, 3, lineNumber, "a normal")) ++counts_[2];
        } else if (keyword == "f") {
            checkFace(words, lineNumber);
        }
        // Anything else (g, o, s, usemtl, mtllib, l, p, vp, ...) is ignored, as tinyobjloader does.
    }

    bool finish() {
        static const char* const kWhat[3] = {"vertex", "texture coordinate", "normal"};
        for (const Forward& f : forward_) {
            if (f.index > counts_[f.slot]) {
                error({file_, f.line, f.column}, std::string(kWhat[f.slot]) + " index " + std::to_string(f.index) +
                                                     " is out of range (the file has " +
                                                     std::to_string(counts_[f.slot]) + ")");
            }
        }
        return errors_ == 0;
    }

private:
    struct Forward {
        int slot, line, column;
        long index;
    };

    void error(SourceLocation at, std::string message) {
        if (++errors_ <= kMaxReportedErrors) {
            diags_.error(std::move(at), std::move(message));
        } else if (errors_ == kMaxReportedErrors + 1) {
            diags_.error({file_, at.line, 0}, "too many errors; the rest of the file is not checked");
        }
    }

    bool checkNumbers(const std::vector<Word>& words, size_t least, size_t most, int lineNumber, const char* what) {
        const size_t n = words.size() - 1;
        if (n < least || n > most) {
            error({file_, lineNumber, 0}, std::string(what) + " takes " + std::to_string(least) +
                                              (least == most ? "" : " to " + std::to_string(most)) +
                                              " numbers, got " + std::to_string(n));
            return false;
        }
        for (size_t k = 1; k < words.size(); ++k) {
            double v;
            if (!parseReal(words[k].text, v)) {
                std::string message(1, '\'');  // built by appending: GCC 12 warns falsely on "'" + string
                message.append(words[k].text).append("' is not a finite number");
                error({file_, lineNumber, words[k].column}, std::move(message));
                return false;
            }
        }
        return true;
    }

    void checkFace(const std::vector<Word>& words, int lineNumber) {
        if (words.size() < 4) {
            error({file_, lineNumber, 0}, "a face needs at least 3 vertices, got " + std::to_string(words.size() - 1));
            return;
        }
        static const char* const kWhat[3] = {"vertex", "texture coordinate", "normal"};
        for (size_t k = 1; k < words.size(); ++k) {
            const Word& w = words[k];
            // v, v/t, v//n or v/t/n
            std::string_view parts[3];
            int partCount = 0;
            size_t start = 0;
            for (size_t i = 0; i <= w.text.size() && partCount <= 3; ++i) {
                if (i == w.text.size() || w.text[i] == '/') {
                    if (partCount < 3) parts[partCount] = w.text.substr(start, i - start);
                    ++partCount;
                    start = i + 1;
                }
            }
            const bool shapeOk = partCount <= 3 && !parts[0].empty() && !(partCount == 3 && parts[2].empty()) &&
                                 !(partCount == 2 && parts[1].empty());
            if (!shapeOk) {
                error({file_, lineNumber, w.column}, "malformed face vertex '" + std::string(w.text) + "'");
                return;
            }
            for (int slot = 0; slot < partCount; ++slot) {
                if (parts[slot].empty()) continue;
                long index;
                if (!parseIndex(parts[slot], index)) {
                    error({file_, lineNumber, w.column}, "malformed face vertex '" + std::string(w.text) + "'");
                    return;
                }
                if (index == 0) {
                    error({file_, lineNumber, w.column}, std::string(kWhat[slot]) + " index 0 in '" +
                                                             std::string(w.text) + "' (OBJ indices start at 1)");
                    return;
                }
                if (index < 0 && -index > counts_[slot]) {
                    error({file_, lineNumber, w.column},
                          std::string(kWhat[slot]) + " index " + std::to_string(index) + " is out of range (only " +
                              std::to_string(counts_[slot]) + " before this line)");
                    return;
                }
                if (index > counts_[slot]) forward_.push_back({slot, lineNumber, w.column, index});
            }
        }
    }

    const std::string& file_;
    Diagnostics& diags_;
    long counts_[3] = {0, 0, 0};  // v, vt, vn
    std::vector<Forward> forward_;
    std::vector<Word> words_;
    int errors_ = 0;
};

bool checkObjText(const std::string& text, const std::string& file, Diagnostics& diags) {
    ObjChecker checker(file, diags);
    size_t start = 0;
    int lineNumber = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        checker.checkLine(std::string_view(text).substr(start, end - start), ++lineNumber);
        start = end + 1;
    }
    return checker.finish();
}

// A read-only streambuf over text in memory, for tinyobjloader's istream interface without a copy.
class TextStreambuf : public std::streambuf {
public:
    explicit TextStreambuf(std::string_view text) {
        char* begin = const_cast<char*>(text.data());  // get area only: never written through
        setg(begin, begin, begin + text.size());
    }
    size_t offset() const { return (size_t)(gptr() - eback()); }  // how far tinyobjloader has read
};

// Vector storage straight from mmap, for what a worker thread builds: glibc keeps the pages of what a
// worker allocates in its own arena after they are freed, and these are tens of MB.
template <class T>
struct PageAllocator {
    using value_type = T;
    PageAllocator() = default;
    template <class U>
    PageAllocator(const PageAllocator<U>&) {}
    T* allocate(size_t n) {
        void* p = ::mmap(nullptr, n * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) { ::munmap(p, n * sizeof(T)); }
    bool operator==(const PageAllocator&) const { return true; }
    bool operator!=(const PageAllocator&) const { return false; }
};

// Mesh data from tinyobjloader's callbacks: positions, normals and uvs as they come, each face fanned into
// corners with its indices resolved (1-based, or negative: relative to what was read before the line).
// A builder for a later part of the file (relativeToEarlier) does not know how much came before it: its
// negative indices are left relative to its own start, to be offset when the parts are joined (fixups).
template <template <class> class Alloc>
struct MeshBuilder {
    std::vector<Vec3, Alloc<Vec3>> positions, normals;
    std::vector<float, Alloc<float>> uvs;
    std::vector<MeshData::Corner, Alloc<MeshData::Corner>> corners;
    std::vector<uint32_t, Alloc<uint32_t>> fixups;  // 3 · corner + component (0 position, 1 normal, 2 uv)
    bool relativeToEarlier = false;
    bool allNormals = true, allUvs = true;
    // The first face with an index the check did not see as tinyobjloader does (text after a face's
    // vertices, which tinyobjloader reads as index 0; a lone \r line break): where the reading stood then.
    bool badIndex = false;
    size_t badOffset = 0;
    const TextStreambuf* stream = nullptr;
    std::vector<MeshData::Corner> face;
    std::vector<uint8_t> faceRelative;  // per face corner: bit c = component c is relative to the part's start

    // Resolves one index; false when it is 0 (absent or unreadable) or reaches before the file's start.
    bool resolve(int raw, size_t count, int32_t& out, bool& relative) const {
        relative = raw < 0 && relativeToEarlier;  // offset by what came before this part, at the join
        if (raw > 0) {
            out = (int32_t)(raw - 1);
            return true;
        }
        if (raw == 0) {
            out = -1;
            return false;
        }
        out = (int32_t)((int64_t)count + raw);
        return relativeToEarlier || out >= 0;
    }
    static void vertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
        static_cast<MeshBuilder*>(self)->positions.push_back({x, y, z});
    }
    static void normal(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
        static_cast<MeshBuilder*>(self)->normals.push_back({x, y, z});
    }
    static void texcoord(void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
        MeshBuilder& b = *static_cast<MeshBuilder*>(self);
        b.uvs.push_back(u);
        b.uvs.push_back(v);
    }
    static void indices(void* selfIn, tinyobj::index_t* index, int count) {
        MeshBuilder& self = *static_cast<MeshBuilder*>(selfIn);
        self.face.resize((size_t)count);
        self.faceRelative.assign((size_t)count, 0);
        for (int k = 0; k < count; ++k) {
            MeshData::Corner& c = self.face[(size_t)k];
            bool ok = true, relative = false;
            ok = self.resolve(index[k].vertex_index, self.positions.size(), c.position, relative) && ok;
            uint8_t mask = relative ? 1 : 0;
            c.normal = -1;
            c.uv = -1;
            if (index[k].normal_index != 0) {
                ok = self.resolve(index[k].normal_index, self.normals.size(), c.normal, relative) && ok;
                mask |= relative ? 2 : 0;
            }
            if (index[k].texcoord_index != 0) {
                ok = self.resolve(index[k].texcoord_index, self.uvs.size() / 2, c.uv, relative) && ok;
                mask |= relative ? 4 : 0;
            }
            self.faceRelative[(size_t)k] = mask;
            if (!ok && !self.badIndex) {
                self.badIndex = true;
                self.badOffset = self.stream ? self.stream->offset() : 0;
            }
            self.allNormals = self.allNormals && index[k].normal_index != 0;
            self.allUvs = self.allUvs && index[k].texcoord_index != 0;
        }
        auto push = [&self](size_t k) {
            const uint32_t corner = (uint32_t)self.corners.size();
            self.corners.push_back(self.face[k]);
            for (uint32_t component = 0; component < 3; ++component)
                if (self.faceRelative[k] & (1u << component)) self.fixups.push_back(3 * corner + component);
        };
        for (size_t k = 1; k + 1 < (size_t)count; ++k) {  // fan around the polygon's first corner
            push(0);
            push(k);
            push(k + 1);
        }
    }
};

template <class Builder>
bool parseWithTinyObj(std::string_view text, Builder& builder) {
    TextStreambuf buffer(text);
    builder.stream = &buffer;
    std::istream in(&buffer);
    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = Builder::vertex;
    callbacks.normal_cb = Builder::normal;
    callbacks.texcoord_cb = Builder::texcoord;
    callbacks.index_cb = Builder::indices;
    std::string warnings, errors;
    const bool ok = tinyobj::LoadObjWithCallback(in, callbacks, &builder, nullptr, &warnings, &errors);
    builder.stream = nullptr;
    return ok;
}

// Appends a later part's data to the first's, offsetting its relative indices by what came before; false
// when one of them reaches before the file's start.
bool joinParts(MeshBuilder<std::allocator>& first, const MeshBuilder<PageAllocator>& later, size_t laterOffset) {
    const int64_t before[3] = {(int64_t)first.positions.size(), (int64_t)first.normals.size(),
                               (int64_t)first.uvs.size() / 2};
    const size_t cornerBase = first.corners.size();
    first.positions.insert(first.positions.end(), later.positions.begin(), later.positions.end());
    first.normals.insert(first.normals.end(), later.normals.begin(), later.normals.end());
    first.uvs.insert(first.uvs.end(), later.uvs.begin(), later.uvs.end());
    first.corners.insert(first.corners.end(), later.corners.begin(), later.corners.end());
    first.allNormals = first.allNormals && later.allNormals;
    first.allUvs = first.allUvs && later.allUvs;
    if (!first.badIndex && later.badIndex) {
        first.badIndex = true;
        first.badOffset = laterOffset + later.badOffset;
    }
    bool ok = true;
    for (uint32_t f : later.fixups) {
        MeshData::Corner& c = first.corners[cornerBase + f / 3];
        int32_t& index = f % 3 == 0 ? c.position : (f % 3 == 1 ? c.normal : c.uv);
        const int64_t global = (int64_t)index + before[f % 3];
        ok = ok && global >= 0;
        index = (int32_t)global;
    }
    return ok;
}

}  // namespace

std::shared_ptr<const MeshData> readObjText(const std::string& text, const std::string& pathForMessages,
                                            Diagnostics& diags) {
    // The check and the parse read the same text independently. On a large file, a worker thread checks
    // the whole text and then parses its last third while this thread parses the rest (the parse takes
    // about three times the check); the parts are cut at a line break.
    MeshBuilder<std::allocator> builder;
    bool parsed = false, checked = false, joined = true;
    const size_t cut = text.size() >= (1u << 20) && std::thread::hardware_concurrency() > 1
                           ? text.find('\n', text.size() / 3 * 2)
                           : std::string::npos;
    if (cut != std::string::npos && cut + 1 < text.size()) {
        const size_t laterStart = cut + 1;
        Diagnostics checkDiags;
        MeshBuilder<PageAllocator> later;
        later.relativeToEarlier = true;
        bool laterParsed = false;
        std::thread worker([&] {
            checked = checkObjText(text, pathForMessages, checkDiags);
            if (checked) laterParsed = parseWithTinyObj(std::string_view(text).substr(laterStart), later);
        });
        // The mesh is built on this thread: what a worker allocates from malloc stays in its own arena.
        parsed = parseWithTinyObj(std::string_view(text).substr(0, laterStart), builder);
        worker.join();
        for (Diagnostic& d : checkDiags.items) diags.items.push_back(std::move(d));
        if (checked) {
            parsed = parsed && laterParsed;
            joined = joinParts(builder, later, laterStart);
        }
    } else {
        checked = checkObjText(text, pathForMessages, diags);
        if (checked) parsed = parseWithTinyObj(text, builder);
    }
    if (!checked) return nullptr;
    if (!parsed) {
        diags.error({pathForMessages, 0, 0}, "malformed OBJ file");
        return nullptr;
    }
    if (builder.badIndex) {
        // The face's line: tinyobjloader had read it through its line break.
        const size_t end = builder.badOffset > 0 ? builder.badOffset - 1 : 0;
        const int line = 1 + (int)std::count(text.begin(), text.begin() + (ptrdiff_t)std::min(end, text.size()), '\n');
        diags.error({pathForMessages, line, 0}, "malformed face: tinyobjloader reads an index 0 or out of range here "
                                                "(text after the face's vertices, such as a # comment?)");
        return nullptr;
    }
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = std::move(builder.positions);
    mesh->normals = std::move(builder.normals);
    mesh->uvs = std::move(builder.uvs);
    mesh->corners = std::move(builder.corners);
    // Every index within what tinyobjloader itself read (negative ones were checked as they were resolved,
    // or at the join; positive ones may point forward).
    bool inRange = joined;
    for (const MeshData::Corner& c : mesh->corners) {
        if (!inRange) break;
        inRange = c.position >= 0 && (size_t)c.position < mesh->positions.size() &&
                  (c.normal < 0 || (size_t)c.normal < mesh->normals.size()) &&
                  (c.uv < 0 || (size_t)c.uv < mesh->uvs.size() / 2);
    }
    if (!inRange) {
        diags.error({pathForMessages, 0, 0}, "malformed OBJ file: a face index is out of range as tinyobjloader "
                                             "reads the lines (line breaks other than \\n or \\r\\n?)");
        return nullptr;
    }
    if (mesh->corners.empty()) {
        diags.error({pathForMessages, 0, 0}, "OBJ file has no faces");
        return nullptr;
    }
    mesh->hasNormals = builder.allNormals;
    mesh->hasUvs = builder.allUvs;
    // A partial attribute is treated as absent, so that consumers need only the two flags.
    if (!mesh->hasNormals || !mesh->hasUvs) {
        for (MeshData::Corner& c : mesh->corners) {
            if (!mesh->hasNormals) c.normal = -1;
            if (!mesh->hasUvs) c.uv = -1;
        }
    }
    return mesh;
}

std::shared_ptr<const MeshData> readObjFile(const std::string& path, Diagnostics& diags) {
    std::string text, reason;
    if (!readWholeFile(path, text, reason)) {
        diags.error({path, 0, 0}, "cannot read OBJ file: " + reason);
        return nullptr;
    }
    return readObjText(text, path, diags);
}

}  // namespace trazo
