// OBJ reader (host): tinyobjloader's callback reader for the data, fan-triangulated straight into MeshData
// (no attrib_t/shape_t copies, no stringstream copy of the text), and the contract of obj_reader.h checked
// once, on what tinyobjloader produced (checkParsedMesh). Beside the parse, a line check of our own gives
// the messages tinyobjloader cannot (it reads bad numbers and trailing text as 0, and indices with atoi);
// it reads the lines as tinyobjloader does (\n, \r\n or a lone \r), but nothing relies on it for memory
// safety. A problem the contract check finds is located afterwards by parsing the text again and stopping
// at the offending element (error path only). For a large file the line check and the parse run at once
// on two threads over the same text.
#include "scene/obj_reader.h"

#include <sys/mman.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cassert>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <new>
#include <optional>
#include <streambuf>
#include <string_view>
#include <thread>
#include <vector>

#include "core/huge_pages.h"
#include "io/text_file.h"
#include "scene/source_file.h"

namespace trazo {
namespace {

constexpr int kMaxReportedErrors = 20;  // a binary or foreign file would otherwise flood the output
constexpr int32_t kAbsent = -1;          // a corner without this attribute
// An index that resolved to before the file's start, or a position tinyobjloader read as 0 (text after a
// face's vertices): out of range by construction, so the contract check reports it.
constexpr int32_t kBadIndex = INT32_MIN;
const char* const kWhat[3] = {"vertex", "normal", "texture coordinate"};  // by Attribute
const char* const kWhatPlural[3] = {"vertices", "normals", "texture coordinates"};
enum Attribute { kPosition = 0, kNormal = 1, kUv = 2 };

int clampLine(int64_t line) { return (int)std::min<int64_t>(line, INT_MAX); }

// ---- Lines as tinyobjloader reads them (its safeGetline): each ended by \n, \r\n or a lone \r.

// Where the line starting at `start` ends (its terminator, or text.size()); `next` is where the next begins.
size_t lineEnd(std::string_view text, size_t start, size_t& next) {
    const char* p = text.data();
    const size_t n = text.size();
    const void* nl = std::memchr(p + start, '\n', n - start);
    size_t end = nl ? (size_t)(static_cast<const char*>(nl) - p) : n;
    if (const void* cr = std::memchr(p + start, '\r', end - start)) end = (size_t)(static_cast<const char*>(cr) - p);
    next = end == n ? n : (p[end] == '\r' && end + 1 < n && p[end + 1] == '\n' ? end + 2 : end + 1);
    return end;
}

struct LineSpan {
    int64_t number = 0;  // 1-based
    size_t start = 0, end = 0;
};

// The line that holds offset `pos` (error path only: walks from the start, or from `from`, a line at or
// before it).
LineSpan lineContaining(std::string_view text, size_t pos, LineSpan from = {1, 0, 0}) {
    LineSpan line = from.start <= pos ? from : LineSpan{1, 0, 0};
    for (;;) {
        size_t next;
        line.end = lineEnd(text, line.start, next);
        if (pos < next || next >= text.size()) return line;
        line.start = next;
        ++line.number;
    }
}

// A hint for a message at a line that a lone \r begins or ends: most editors do not count it as a break.
std::string loneCrHint(std::string_view text, size_t start, size_t end) {
    const bool after = start > 0 && text[start - 1] == '\r';
    const bool before = end < text.size() && text[end] == '\r' && !(end + 1 < text.size() && text[end + 1] == '\n');
    return after || before ? "lines counted as OBJ readers count them: a lone \\r also ends a line" : "";
}

// A word as it may appear in a message: at most 40 characters, anything but printable ASCII as '?' (a NUL
// would cut the message short, other bytes garble the terminal).
std::string printable(std::string_view word) {
    std::string out;
    for (size_t i = 0; i < word.size() && i < 40; ++i) out += word[i] >= 0x20 && word[i] < 0x7f ? word[i] : '?';
    if (word.size() > 40) out += "...";
    return out;
}

// The first line of `text` longer than kMaxObjLineBytes, or npos: a memchr pass over the \n lines, split
// at a lone \r only where one of them is too long.
size_t findOverlongLine(std::string_view text) {
    size_t start = 0;
    while (start < text.size()) {
        const void* nl = std::memchr(text.data() + start, '\n', text.size() - start);
        const size_t end = nl ? (size_t)(static_cast<const char*>(nl) - text.data()) : text.size();
        if (end - start > kMaxObjLineBytes) {
            for (size_t s = start, next; s < end; s = next)
                if (lineEnd(text, s, next) - s > kMaxObjLineBytes) return s;
        }
        start = end + 1;
    }
    return std::string_view::npos;
}

// ---- The line check: the form of every line, for the messages tinyobjloader cannot give.

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
        if (line[i] == ' ' || line[i] == '\t') {
            ++i;
            continue;
        }
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '#') ++i;
        words.push_back({line.substr(start, i - start), int(start) + 1});
    }
}

// A leading '+' once, as tinyobjloader and atoi take it ("+-1" they read as 0).
bool stripPlus(std::string_view& s) {
    if (s.empty() || s[0] != '+') return true;
    s.remove_prefix(1);
    return !s.empty() && s[0] != '+' && s[0] != '-';
}

bool parseReal(std::string_view s, double& out) {
    if (!stripPlus(s)) return false;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && ptr == s.data() + s.size() && !s.empty() && std::isfinite(float(out));
}

enum class IndexForm { Ok, Malformed, TooLarge };

// An index as atoi reads it wherever it fits an int; 64-bit throughout, never negated.
IndexForm parseIndex(std::string_view s, int64_t& out) {
    if (!stripPlus(s) || s.empty()) return IndexForm::Malformed;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ptr != s.data() + s.size()) return IndexForm::Malformed;
    if (ec == std::errc::result_out_of_range) return IndexForm::TooLarge;
    if (ec != std::errc()) return IndexForm::Malformed;
    return out < -(int64_t)kMaxObjElements || out > (int64_t)kMaxObjElements ? IndexForm::TooLarge : IndexForm::Ok;
}

class ObjChecker {
public:
    ObjChecker(std::string_view text, const std::string& file, Diagnostics& diags)
        : text_(text), file_(file), diags_(diags) {}

    void checkLine(size_t start, size_t end, int lineNumber) {
        const std::string_view line = text_.substr(start, end - start);
        lineStart_ = start;
        lineEnd_ = end;
        splitWords(line, words_);
        const std::vector<Word>& words = words_;
        if (words.empty()) return;
        const std::string_view keyword = words[0].text;
        if (keyword == "v") {
            checkNumbers(words, 3, 7, lineNumber, "a vertex");
        } else if (keyword == "vt") {
            checkNumbers(words, 1, 3, lineNumber, "a texture coordinate");
        } else if (keyword == "vn") {
            checkNumbers(words, 3, 3, lineNumber, "a normal");
        } else if (keyword == "f") {
            checkFace(words, lineNumber);
        }
        // Anything else (g, o, s, usemtl, mtllib, l, p, vp, ...) is ignored, as tinyobjloader does.
    }

    bool ok() const { return errors_ == 0; }
    bool full() const { return errors_ > kMaxReportedErrors; }

private:
    void error(SourceLocation at, std::string message) {
        if (++errors_ <= kMaxReportedErrors) {
            diags_.error(std::move(at), std::move(message), loneCrHint(text_, lineStart_, lineEnd_));
        } else if (errors_ == kMaxReportedErrors + 1) {
            diags_.error({file_, at.line, 0}, "too many errors; the rest of the file is not checked");
        }
    }

    void checkNumbers(const std::vector<Word>& words, size_t least, size_t most, int lineNumber, const char* what) {
        const size_t n = words.size() - 1;
        if (n < least || n > most) {
            error({file_, lineNumber, 0}, std::string(what) + " takes " + std::to_string(least) +
                                              (least == most ? "" : " to " + std::to_string(most)) +
                                              " numbers, got " + std::to_string(n));
            return;
        }
        for (size_t k = 1; k < words.size(); ++k) {
            double v;
            if (!parseReal(words[k].text, v)) {
                std::string message(1, '\'');  // built by appending: GCC 12 warns falsely on "'" + string
                message.append(printable(words[k].text)).append("' is not a finite number");
                error({file_, lineNumber, words[k].column}, std::move(message));
                return;
            }
        }
    }

    void checkFace(const std::vector<Word>& words, int lineNumber) {
        if (words.size() < 4) {
            error({file_, lineNumber, 0}, "a face needs at least 3 vertices, got " + std::to_string(words.size() - 1));
            return;
        }
        static const char* const kSlotWhat[3] = {"vertex", "texture coordinate", "normal"};  // v/t/n order
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
                error({file_, lineNumber, w.column}, "malformed face vertex '" + printable(w.text) + "'");
                return;
            }
            for (int slot = 0; slot < partCount; ++slot) {
                if (parts[slot].empty()) continue;
                int64_t index = 0;
                const IndexForm form = parseIndex(parts[slot], index);
                if (form == IndexForm::Malformed) {
                    error({file_, lineNumber, w.column}, "malformed face vertex '" + printable(w.text) + "'");
                    return;
                }
                if (form == IndexForm::TooLarge) {
                    error({file_, lineNumber, w.column},
                          std::string(kSlotWhat[slot]) + " index " + printable(parts[slot]) +
                              " is out of range (an OBJ file holds at most " + std::to_string(kMaxObjElements) + ")");
                    return;
                }
                if (index == 0) {
                    error({file_, lineNumber, w.column}, std::string(kSlotWhat[slot]) + " index 0 in '" +
                                                             printable(w.text) + "' (OBJ indices start at 1)");
                    return;
                }
            }
        }
    }

    std::string_view text_;
    const std::string& file_;
    Diagnostics& diags_;
    std::vector<Word> words_;
    size_t lineStart_ = 0, lineEnd_ = 0;
    int errors_ = 0;
};

bool checkObjText(std::string_view text, const std::string& file, Diagnostics& diags) {
    ObjChecker checker(text, file, diags);
    int64_t lineNumber = 0;
    for (size_t start = 0, next; start < text.size() && !checker.full(); start = next) {
        const size_t end = lineEnd(text, start, next);
        checker.checkLine(start, end, clampLine(++lineNumber));
    }
    return checker.ok();
}

// ---- The parse.

// A read-only streambuf over text in memory, for tinyobjloader's istream interface without a copy.
class TextStreambuf : public std::streambuf {
public:
    explicit TextStreambuf(std::string_view text) {
        char* begin = const_cast<char*>(text.data());  // get area only: never written through
        setg(begin, begin, begin + text.size());
    }
    size_t offset() const { return (size_t)(gptr() - eback()); }  // how far tinyobjloader has read
};

template <class Callbacks>
void parseWithTinyObj(std::string_view text, Callbacks& target, const TextStreambuf*& stream) {
    TextStreambuf buffer(text);
    stream = &buffer;
    std::istream in(&buffer);
    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = Callbacks::vertex;
    callbacks.normal_cb = Callbacks::normal;
    callbacks.texcoord_cb = Callbacks::texcoord;
    callbacks.index_cb = Callbacks::indices;
    std::string warnings, errors;
    // Without a material reader it has nothing to fail on; what it read is judged by the contract check.
    tinyobj::LoadObjWithCallback(in, callbacks, &target, nullptr, &warnings, &errors);
    stream = nullptr;
}

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
        adviseLargeAllocation(p, n * sizeof(T));
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) { ::munmap(p, n * sizeof(T)); }
    bool operator==(const PageAllocator&) const { return true; }
    bool operator!=(const PageAllocator&) const { return false; }
};

// Which limit of obj_reader.h a part of the file crossed (the first), or none.
enum class Overflow { None, Vertices, Normals, Uvs, Triangles };

// Mesh data from tinyobjloader's callbacks: positions, normals and uvs as they come, each face fanned into
// corners with its indices resolved (1-based, or negative: relative to what was read before the line). No
// index is judged here: one before the file's start becomes kBadIndex, and the contract check judges all.
// A builder for a later part of the file (relativeToEarlier) does not know how much came before it: its
// negative indices are left relative to its own start, to be offset when the parts are joined (fixups).
// Nothing is stored past a limit of obj_reader.h (the file is refused then).
template <template <class> class Alloc>
struct MeshBuilder {
    std::vector<Vec3, Alloc<Vec3>> positions, normals;
    std::vector<float, Alloc<float>> uvs;
    std::vector<MeshData::Corner, Alloc<MeshData::Corner>> corners;
    std::vector<uint32_t, Alloc<uint32_t>> fixups;  // 3 · corner + attribute (0 position, 1 normal, 2 uv)
    bool relativeToEarlier = false;
    bool allNormals = true, allUvs = true;
    Overflow overflow = Overflow::None;
    std::vector<MeshData::Corner> face;
    std::vector<uint8_t> faceRelative;  // per face corner: bit a = attribute a is relative to the part's start

    int32_t resolve(int raw, size_t count, bool& relative) const {
        relative = false;
        if (raw > 0) return (int32_t)(raw - 1);
        if (raw == 0) return kAbsent;
        const int64_t resolved = (int64_t)count + raw;  // count ≤ kMaxObjElements: no overflow
        if (relativeToEarlier) {
            relative = true;  // offset by what came before this part, at the join
            return (int32_t)resolved;
        }
        return resolved >= 0 ? (int32_t)resolved : kBadIndex;
    }
    bool full(size_t size, size_t limit, Overflow what) {
        if (size < limit) return false;
        if (overflow == Overflow::None) overflow = what;
        return true;
    }
    static void vertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
        MeshBuilder& b = *static_cast<MeshBuilder*>(self);
        if (!b.full(b.positions.size(), kMaxObjElements, Overflow::Vertices)) b.positions.push_back({x, y, z});
    }
    static void normal(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
        MeshBuilder& b = *static_cast<MeshBuilder*>(self);
        if (!b.full(b.normals.size(), kMaxObjElements, Overflow::Normals)) b.normals.push_back({x, y, z});
    }
    static void texcoord(void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
        MeshBuilder& b = *static_cast<MeshBuilder*>(self);
        if (b.full(b.uvs.size() / 2, kMaxObjElements, Overflow::Uvs)) return;
        b.uvs.push_back(u);
        b.uvs.push_back(v);
    }
    static void indices(void* selfIn, tinyobj::index_t* index, int count) {
        MeshBuilder& self = *static_cast<MeshBuilder*>(selfIn);
        if (count < 3) return;  // no triangle (the line check reports it)
        const size_t fanned = 3 * ((size_t)count - 2);
        if (self.full(self.corners.size() + fanned, 3 * kMaxObjTriangles + 1, Overflow::Triangles)) return;
        self.face.resize((size_t)count);
        self.faceRelative.assign((size_t)count, 0);
        for (int k = 0; k < count; ++k) {
            MeshData::Corner& c = self.face[(size_t)k];
            bool relative = false;
            c.position = index[k].vertex_index == 0  // read as 0: never a vertex
                             ? kBadIndex
                             : self.resolve(index[k].vertex_index, self.positions.size(), relative);
            uint8_t mask = relative ? 1 : 0;
            c.normal = self.resolve(index[k].normal_index, self.normals.size(), relative);
            mask |= relative ? 2 : 0;
            c.uv = self.resolve(index[k].texcoord_index, self.uvs.size() / 2, relative);
            mask |= relative ? 4 : 0;
            self.faceRelative[(size_t)k] = mask;
            self.allNormals = self.allNormals && index[k].normal_index != 0;
            self.allUvs = self.allUvs && index[k].texcoord_index != 0;
        }
        auto push = [&self](size_t k) {
            const uint32_t corner = (uint32_t)self.corners.size();
            self.corners.push_back(self.face[k]);
            for (uint32_t attribute = 0; attribute < 3; ++attribute)
                if (self.faceRelative[k] & (1u << attribute)) self.fixups.push_back(3 * corner + attribute);
        };
        for (size_t k = 1; k + 1 < (size_t)count; ++k) {  // fan around the polygon's first corner
            push(0);
            push(k);
            push(k + 1);
        }
    }
    const TextStreambuf* stream = nullptr;
};

// Appends a later part's data to the first's, offsetting its relative indices by what came before (one that
// still reaches before the file's start becomes kBadIndex).
void joinParts(MeshBuilder<std::allocator>& first, const MeshBuilder<PageAllocator>& later) {
    const int64_t before[3] = {(int64_t)first.positions.size(), (int64_t)first.normals.size(),
                               (int64_t)first.uvs.size() / 2};
    const size_t cornerBase = first.corners.size();
    first.positions.insert(first.positions.end(), later.positions.begin(), later.positions.end());
    first.normals.insert(first.normals.end(), later.normals.begin(), later.normals.end());
    first.uvs.insert(first.uvs.end(), later.uvs.begin(), later.uvs.end());
    first.corners.insert(first.corners.end(), later.corners.begin(), later.corners.end());
    first.allNormals = first.allNormals && later.allNormals;
    first.allUvs = first.allUvs && later.allUvs;
    if (first.overflow == Overflow::None) first.overflow = later.overflow;
    for (uint32_t f : later.fixups) {
        MeshData::Corner& c = first.corners[cornerBase + f / 3];
        int32_t& index = f % 3 == 0 ? c.position : (f % 3 == 1 ? c.normal : c.uv);
        const int64_t global = (int64_t)index + before[f % 3];
        index = global >= 0 && global <= INT32_MAX ? (int32_t)global : kBadIndex;
    }
}

// The parsed corners as MeshData keeps them, `corners` freed (they are three times the size of a file's
// position-only columns, and the file's text is still held).
MeshCorners cornerColumns(std::vector<MeshData::Corner>&& corners) {
    MeshCorners columns;
    columns.reserve(corners.size());
    for (const MeshData::Corner& c : corners) columns.push_back(c);
    std::vector<MeshData::Corner>().swap(corners);
    return columns;
}

// ---- The contract of obj_reader.h, checked in this one place.

struct Violation {
    enum Kind {
        TooMany,     // attribute (kPosition/kNormal/kUv) or 3 = triangles; ordinal: the first element past the limit
        Shape,       // corners not a multiple of 3, or an odd number of uv floats
        NoFaces,
        BadValue,    // attribute's element `ordinal` is not finite
        BadIndex,    // corner `ordinal`'s index of `attribute` is out of range
    } kind;
    int attribute = 0;
    size_t ordinal = 0;
};

constexpr int kTriangles = 3;  // Violation::attribute for TooMany of triangles

bool inRange(int32_t index, size_t count) { return index >= 0 && (size_t)index < count; }

// Appends up to `most` violations to `out`. `partialAttributes`: the data as parsed, before an attribute
// given on some corners only is dropped (a corner's index is then absent or in range, whatever the flag).
void checkMesh(const MeshData& m, bool partialAttributes, size_t most, std::vector<Violation>& out) {
    const size_t uvCount = m.uvs.size() / 2;
    const size_t counts[3] = {m.positions.size(), m.normals.size(), uvCount};
    for (int a = 0; a < 3; ++a)
        if (counts[a] > kMaxObjElements) out.push_back({Violation::TooMany, a, kMaxObjElements});
    if (m.corners.size() > 3 * kMaxObjTriangles) out.push_back({Violation::TooMany, kTriangles, 3 * kMaxObjTriangles});
    if (m.corners.size() % 3 != 0 || m.uvs.size() % 2 != 0) out.push_back({Violation::Shape});
    if (!out.empty()) return;
    if (m.corners.empty()) {
        out.push_back({Violation::NoFaces});
        return;
    }
    auto add = [&](Violation v) {
        out.push_back(v);
        return out.size() >= most;
    };
    for (size_t i = 0; i < m.positions.size(); ++i)
        if (!isFinite(m.positions[i]) && add({Violation::BadValue, kPosition, i})) return;
    for (size_t i = 0; i < m.normals.size(); ++i)
        if (!isFinite(m.normals[i]) && add({Violation::BadValue, kNormal, i})) return;
    for (size_t i = 0; i < uvCount; ++i)
        if (!(std::isfinite(m.uvs[2 * i]) && std::isfinite(m.uvs[2 * i + 1])) && add({Violation::BadValue, kUv, i}))
            return;
    const bool has[3] = {true, m.hasNormals, m.hasUvs};
    for (size_t i = 0; i < m.corners.size(); ++i) {
        const MeshData::Corner c = m.corners[i];
        const int32_t index[3] = {c.position, c.normal, c.uv};
        for (int a = 0; a < 3; ++a) {
            const bool ok = inRange(index[a], counts[a]) ? has[a] || partialAttributes
                                                         : index[a] == kAbsent && !has[a];
            if (!ok && add({Violation::BadIndex, a, i})) return;
        }
    }
}

// A violation in words, without a location (the mesh may not come from a file).
std::string describe(const Violation& v, const MeshData& m) {
    const size_t counts[3] = {m.positions.size(), m.normals.size(), m.uvs.size() / 2};
    switch (v.kind) {
        case Violation::TooMany:
            return v.attribute == kTriangles
                       ? "more than " + std::to_string(kMaxObjTriangles) + " triangles"
                       : "more than " + std::to_string(kMaxObjElements) + " " + kWhatPlural[v.attribute];
        case Violation::Shape:
            return "corners not a multiple of 3 (" + std::to_string(m.corners.size()) + ") or uv floats odd (" +
                   std::to_string(m.uvs.size()) + ")";
        case Violation::NoFaces:
            return "no faces";
        case Violation::BadValue:
            return std::string(kWhat[v.attribute]) + " " + std::to_string(v.ordinal) + " is not finite";
        case Violation::BadIndex: {
            const MeshData::Corner c = m.corners[v.ordinal];
            const int32_t index = v.attribute == kPosition ? c.position : v.attribute == kNormal ? c.normal : c.uv;
            const bool flagged = v.attribute == kNormal ? m.hasNormals : m.hasUvs;
            std::string s = "corner " + std::to_string(v.ordinal) + ": " + kWhat[v.attribute] + " index " +
                            std::to_string(index);
            if (v.attribute != kPosition && !flagged && inRange(index, counts[v.attribute]))
                return s + " given, but the mesh is flagged as without " + kWhatPlural[v.attribute];
            return s + " is out of range (the mesh has " + std::to_string(counts[v.attribute]) + ")";
        }
    }
    return "?";
}

// ---- Locating a violation in the text: tinyobjloader reads it again and stops at the element (errors only).

struct Located {
    Violation v;
    size_t offset = 0;  // how far tinyobjloader had read at the element: just past its line
    bool found = false;
    tinyobj::index_t raw{0, 0, 0};  // BadIndex: the face vertex's indices as tinyobjloader read them
    int polygonVertex = 0;          // BadIndex: which of the face's vertices (0-based)
    size_t before[3] = {0, 0, 0};   // BadIndex: v, vn, vt read before the face
};

class Locator {
public:
    explicit Locator(std::vector<Located>& items) : items_(items) {
        for (size_t i = 0; i < items.size(); ++i) {
            const Violation& v = items[i].v;
            if (v.kind == Violation::BadValue || (v.kind == Violation::TooMany && v.attribute != kTriangles))
                streams_[v.attribute].push_back(i);
            else if (v.kind == Violation::BadIndex || v.kind == Violation::TooMany)
                streams_[3].push_back(i);
        }
        for (auto& s : streams_)
            std::sort(s.begin(), s.end(),
                      [&](size_t a, size_t b) { return items_[a].v.ordinal < items_[b].v.ordinal; });
    }

    static void vertex(void* self, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t) {
        static_cast<Locator*>(self)->element(kPosition);
    }
    static void normal(void* self, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t) {
        static_cast<Locator*>(self)->element(kNormal);
    }
    static void texcoord(void* self, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t) {
        static_cast<Locator*>(self)->element(kUv);
    }
    static void indices(void* selfIn, tinyobj::index_t* index, int count) {
        Locator& self = *static_cast<Locator*>(selfIn);
        const size_t fanned = count >= 3 ? 3 * ((size_t)count - 2) : 0;
        std::vector<size_t>& s = self.streams_[3];
        while (self.cursor_[3] < s.size() && self.items_[s[self.cursor_[3]]].v.ordinal < self.seen_[3] + fanned) {
            Located& l = self.items_[s[self.cursor_[3]++]];
            const size_t local = l.v.ordinal - self.seen_[3];
            l.polygonVertex = local % 3 == 0 ? 0 : (int)(local / 3 + local % 3);
            l.raw = index[l.polygonVertex];
            std::copy(self.seen_, self.seen_ + 3, l.before);
            self.mark(l);
        }
        self.seen_[3] += fanned;
    }

    const TextStreambuf* stream = nullptr;

private:
    void element(int stream) {
        std::vector<size_t>& s = streams_[stream];
        while (cursor_[stream] < s.size() && items_[s[cursor_[stream]]].v.ordinal == seen_[stream])
            mark(items_[s[cursor_[stream]++]]);
        ++seen_[stream];
    }
    void mark(Located& l) {
        l.offset = stream ? stream->offset() : 0;
        l.found = stream != nullptr;
    }

    std::vector<Located>& items_;
    std::vector<size_t> streams_[4];  // v, vn, vt, corners: indices into items_, by ordinal
    size_t cursor_[4] = {0, 0, 0, 0};
    size_t seen_[4] = {0, 0, 0, 0};
};

// Reports `violations` of the mesh read from `text` at their lines (tinyobjloader reads the text again).
void reportViolations(const std::vector<Violation>& violations, const MeshData& mesh, std::string_view text,
                      const std::string& file, Diagnostics& diags) {
    std::vector<Located> items;
    for (const Violation& v : violations) items.push_back({v});
    Locator locator(items);
    parseWithTinyObj(text, locator, locator.stream);
    std::stable_sort(items.begin(), items.end(),
                     [](const Located& a, const Located& b) { return a.offset < b.offset; });
    const size_t counts[3] = {mesh.positions.size(), mesh.normals.size(), mesh.uvs.size() / 2};
    std::string previous;
    std::vector<Word> words;
    LineSpan line{1, 0, 0};  // the items are in file order: each line is found from the one before
    for (const Located& l : items) {
        SourceLocation at{file, 0, 0};
        std::string message, hint;
        if (l.found) {
            line = lineContaining(text, l.offset > 0 ? l.offset - 1 : 0, line);
            at.line = clampLine(line.number);
            hint = loneCrHint(text, line.start, line.end);
            if (l.v.kind == Violation::BadIndex) {
                splitWords(text.substr(line.start, line.end - line.start), words);
                if ((size_t)l.polygonVertex + 1 < words.size()) at.column = words[(size_t)l.polygonVertex + 1].column;
            }
        }
        switch (l.v.kind) {
            case Violation::TooMany:
                message = "OBJ file has " + describe(l.v, mesh) + " (the most the reader takes)";
                break;
            case Violation::Shape:
                message = "malformed OBJ file: " + describe(l.v, mesh);
                break;
            case Violation::NoFaces:
                message = "OBJ file has no faces";
                if (mesh.positions.empty())
                    hint = text.empty() ? "the file is empty" : "nor any vertex: is it an OBJ file?";
                break;
            case Violation::BadValue:
                message = std::string("a ") + kWhat[l.v.attribute] + " is not finite as read";
                break;
            case Violation::BadIndex: {
                const int raw = l.v.attribute == kPosition ? l.raw.vertex_index
                                : l.v.attribute == kNormal ? l.raw.normal_index
                                                           : l.raw.texcoord_index;
                const std::string what = kWhat[l.v.attribute];
                if (!l.found) {
                    message = "malformed OBJ file: " + describe(l.v, mesh);
                } else if (raw == 0) {
                    at.column = 0;  // one message for the line, however many vertices the text reads as
                    message = "malformed face: tinyobjloader reads text after its vertices (such as a # comment) "
                              "as " + what + " index 0";
                } else if (raw > 0) {
                    message = what + " index " + std::to_string(raw) + " is out of range (the file has " +
                              std::to_string(counts[l.v.attribute]) + ")";
                } else {
                    message = what + " index " + std::to_string(raw) + " is out of range (only " +
                              std::to_string(l.before[l.v.attribute]) + " before this line)";
                }
                break;
            }
        }
        const std::string key = std::to_string(at.line) + ":" + std::to_string(at.column) + message;
        if (key == previous) continue;  // a face's first corner is in each of its fan's triangles
        previous = key;
        diags.error(std::move(at), std::move(message), std::move(hint));
    }
}

}  // namespace

std::string objMeshContractViolation(const MeshData& mesh) {
    std::vector<Violation> violations;
    checkMesh(mesh, false, 1, violations);
    return violations.empty() ? std::string() : describe(violations.front(), mesh);
}

std::shared_ptr<const MeshData> readObjText(const std::string& text, const std::string& pathForMessages,
                                            Diagnostics& diags) {
    if (const size_t at = findOverlongLine(text); at != std::string::npos) {
        size_t next;
        const size_t end = lineEnd(text, at, next);
        diags.error({pathForMessages, clampLine(lineContaining(text, at).number), 0},
                    "line of " + std::to_string(end - at) + " bytes; the OBJ reader takes lines of at most " +
                        std::to_string(kMaxObjLineBytes));
        return nullptr;
    }
    // The check and the parse read the same text independently. On a large file, a worker thread checks
    // the whole text and then parses its last third while this thread parses the rest (the parse takes
    // about three times the check); the parts are cut at a line break (a \n: no \r\n is split).
    MeshBuilder<std::allocator> builder;
    bool checked = false;
    const size_t cut = text.size() >= (1u << 20) && std::thread::hardware_concurrency() > 1
                           ? text.find('\n', text.size() / 3 * 2)
                           : std::string::npos;
    if (cut != std::string::npos && cut + 1 < text.size()) {
        const size_t laterStart = cut + 1;
        Diagnostics checkDiags;
        MeshBuilder<PageAllocator> later;
        later.relativeToEarlier = true;
        std::thread worker([&] {
            checked = checkObjText(text, pathForMessages, checkDiags);
            if (checked) parseWithTinyObj(std::string_view(text).substr(laterStart), later, later.stream);
        });
        // The mesh is built on this thread: what a worker allocates from malloc stays in its own arena.
        parseWithTinyObj(std::string_view(text).substr(0, laterStart), builder, builder.stream);
        worker.join();
        for (Diagnostic& d : checkDiags.items) diags.items.push_back(std::move(d));
        if (checked) joinParts(builder, later);
    } else {
        checked = checkObjText(text, pathForMessages, diags);
        if (checked) parseWithTinyObj(text, builder, builder.stream);
    }
    if (!checked) return nullptr;

    auto mesh = std::make_shared<MeshData>();
    mesh->positions = std::move(builder.positions);
    mesh->normals = std::move(builder.normals);
    mesh->uvs = std::move(builder.uvs);
    mesh->corners = cornerColumns(std::move(builder.corners));
    mesh->hasNormals = builder.allNormals;
    mesh->hasUvs = builder.allUvs;

    // The contract, on what tinyobjloader produced (an attribute on some corners only is dropped after).
    std::vector<Violation> violations;
    if (builder.overflow != Overflow::None) {
        const int attribute = builder.overflow == Overflow::Vertices  ? kPosition
                              : builder.overflow == Overflow::Normals ? kNormal
                              : builder.overflow == Overflow::Uvs     ? kUv
                                                                      : kTriangles;
        violations.push_back({Violation::TooMany, attribute,
                              attribute == kTriangles ? 3 * kMaxObjTriangles : kMaxObjElements});
    } else {
        checkMesh(*mesh, true, kMaxReportedErrors, violations);
    }
    if (!violations.empty()) {
        reportViolations(violations, *mesh, text, pathForMessages, diags);
        return nullptr;
    }
    // A partial attribute is treated as absent, so that consumers need only the two flags.
    if (!mesh->hasNormals) mesh->corners.dropNormals();
    if (!mesh->hasUvs) mesh->corners.dropUvs();
    assert(objMeshContractViolation(*mesh).empty());
    return mesh;
}

std::shared_ptr<const MeshData> readObjFile(const std::string& path, Diagnostics& diags) {
    const std::optional<std::string> text = readSourceFile(path, "OBJ", kMaxTextFileBytes, diags);
    return text ? readObjText(*text, path, diags) : nullptr;
}

}  // namespace trazo
