// OBJ reader (host): a line check of our own (tinyobjloader reads bad numbers as 0 and reports index
// errors at the last line), and tinyobjloader's callback reader for the data, fan-triangulated straight
// into MeshData (no attrib_t/shape_t copies, no stringstream copy of the text). For a large file the two
// run at once on two threads over the same text; the data is kept only if the check passes, and every
// index is range-checked again against what tinyobjloader read.
#include "scene/obj_reader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>
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

// MeshData from tinyobjloader's callbacks: positions, normals and uvs as they come, each face fanned into
// corners with its indices resolved (1-based, or negative: relative to what was read before the line).
struct MeshBuilder {
    MeshData mesh;
    bool allNormals = true, allUvs = true;
    // The first face with an index the check did not see as tinyobjloader does (text after a face's
    // vertices, which tinyobjloader reads as index 0; a lone \r line break): where the reading stood then.
    bool badIndex = false;
    size_t badOffset = 0;
    const TextStreambuf* stream = nullptr;
    std::vector<MeshData::Corner> face;

    static int32_t resolve(int raw, size_t count) {
        if (raw > 0) return (int32_t)(raw - 1);
        if (raw < 0 && (size_t)(-(int64_t)raw) <= count) return (int32_t)((int64_t)count + raw);
        return -1;
    }
    static void vertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
        static_cast<MeshBuilder*>(self)->mesh.positions.push_back({x, y, z});
    }
    static void normal(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
        static_cast<MeshBuilder*>(self)->mesh.normals.push_back({x, y, z});
    }
    static void texcoord(void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
        std::vector<float>& uvs = static_cast<MeshBuilder*>(self)->mesh.uvs;
        uvs.push_back(u);
        uvs.push_back(v);
    }
    static void indices(void* selfIn, tinyobj::index_t* index, int count) {
        MeshBuilder& self = *static_cast<MeshBuilder*>(selfIn);
        MeshData& m = self.mesh;
        self.face.resize((size_t)count);
        for (int k = 0; k < count; ++k) {
            MeshData::Corner& c = self.face[(size_t)k];
            c.position = resolve(index[k].vertex_index, m.positions.size());
            c.normal = index[k].normal_index == 0 ? -1 : resolve(index[k].normal_index, m.normals.size());
            c.uv = index[k].texcoord_index == 0 ? -1 : resolve(index[k].texcoord_index, m.uvs.size() / 2);
            if ((c.position < 0 || (index[k].normal_index != 0 && c.normal < 0) ||
                 (index[k].texcoord_index != 0 && c.uv < 0)) && !self.badIndex) {
                self.badIndex = true;
                self.badOffset = self.stream ? self.stream->offset() : 0;
            }
            self.allNormals = self.allNormals && c.normal >= 0;
            self.allUvs = self.allUvs && c.uv >= 0;
        }
        for (int k = 1; k + 1 < count; ++k) {  // fan around the polygon's first corner
            m.corners.push_back(self.face[0]);
            m.corners.push_back(self.face[(size_t)k]);
            m.corners.push_back(self.face[(size_t)k + 1]);
        }
    }
};

bool parseWithTinyObj(const std::string& text, MeshBuilder& builder) {
    TextStreambuf buffer(text);
    builder.stream = &buffer;
    std::istream in(&buffer);
    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = MeshBuilder::vertex;
    callbacks.normal_cb = MeshBuilder::normal;
    callbacks.texcoord_cb = MeshBuilder::texcoord;
    callbacks.index_cb = MeshBuilder::indices;
    std::string warnings, errors;
    const bool ok = tinyobj::LoadObjWithCallback(in, callbacks, &builder, nullptr, &warnings, &errors);
    builder.stream = nullptr;
    return ok;
}

}  // namespace

std::shared_ptr<const MeshData> readObjText(const std::string& text, const std::string& pathForMessages,
                                            Diagnostics& diags) {
    // The check and the parse read the same text independently; on a large file they share the cores.
    MeshBuilder builder;
    bool parsed = false;
    bool checked = false;
    if (text.size() >= (1u << 20) && std::thread::hardware_concurrency() > 1) {
        // The mesh is built on this thread: what a worker allocates stays in its own malloc arena, whose
        // pages glibc keeps after they are freed (the vectors' growth would leave megabytes resident).
        Diagnostics checkDiags;
        std::thread checker([&] { checked = checkObjText(text, pathForMessages, checkDiags); });
        parsed = parseWithTinyObj(text, builder);
        checker.join();
        for (Diagnostic& d : checkDiags.items) diags.items.push_back(std::move(d));
    } else {
        checked = checkObjText(text, pathForMessages, diags);
        if (checked) parsed = parseWithTinyObj(text, builder);
    }
    if (!checked) return nullptr;
    MeshData& mesh = builder.mesh;
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
    // Every index within what tinyobjloader itself read (what the resolution above checked already for
    // relative ones; positive ones may point forward).
    for (const MeshData::Corner& c : mesh.corners) {
        if ((size_t)c.position >= mesh.positions.size() || (c.normal >= 0 && (size_t)c.normal >= mesh.normals.size()) ||
            (c.uv >= 0 && (size_t)c.uv >= mesh.uvs.size() / 2)) {
            diags.error({pathForMessages, 0, 0}, "malformed OBJ file: a face index is out of range as tinyobjloader "
                                                 "reads the lines (line breaks other than \\n or \\r\\n?)");
            return nullptr;
        }
    }
    if (mesh.corners.empty()) {
        diags.error({pathForMessages, 0, 0}, "OBJ file has no faces");
        return nullptr;
    }
    mesh.hasNormals = builder.allNormals;
    mesh.hasUvs = builder.allUvs;
    // A partial attribute is treated as absent, so that consumers need only the two flags.
    if (!mesh.hasNormals || !mesh.hasUvs) {
        for (MeshData::Corner& c : mesh.corners) {
            if (!mesh.hasNormals) c.normal = -1;
            if (!mesh.hasUvs) c.uv = -1;
        }
    }
    return std::make_shared<MeshData>(std::move(mesh));
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
