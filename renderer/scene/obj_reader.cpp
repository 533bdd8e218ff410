// OBJ reader (host): a line check of our own (tinyobjloader reads bad numbers as 0 and reports index
// errors at the last line), then tinyobjloader for the data, then fan triangulation into MeshData.
#include "scene/obj_reader.h"

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <regex>
#include <string_view>
#include <vector>

#include "scene/block_lexer.h"

namespace trazo {
namespace {

constexpr int kMaxReportedErrors = 20;  // a binary or foreign file would otherwise flood the output

struct Word {
    std::string_view text;
    int column;
};

std::vector<Word> splitWords(std::string_view line) {
    std::vector<Word> words;
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
    return words;
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
        const std::vector<Word> words = splitWords(line);
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

int lineOf(const std::string& message) {
    static const std::regex kLine(R"(line:?\s*(\d+))");
    std::smatch m;
    return std::regex_search(message, m, kLine) ? std::stoi(m[1].str()) : 0;
}

std::string firstLine(std::string s) {
    const size_t end = s.find_first_of("\r\n");
    if (end != std::string::npos) s.resize(end);
    return s;
}

}  // namespace

std::shared_ptr<const MeshData> readObjText(const std::string& text, const std::string& pathForMessages,
                                            Diagnostics& diags) {
    if (!checkObjText(text, pathForMessages, diags)) return nullptr;

    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // tinyobjloader splits quads by their shorter diagonal; SPEC asks for a fan
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config)) {
        const std::string& why = reader.Error();
        diags.error({pathForMessages, lineOf(why), 0}, why.empty() ? "malformed OBJ file" : firstLine(why));
        return nullptr;
    }

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    auto mesh = std::make_shared<MeshData>();
    for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
        mesh->positions.push_back({attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
    }
    for (size_t i = 0; i + 2 < attrib.normals.size(); i += 3) {
        mesh->normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});
    }
    mesh->uvs.assign(attrib.texcoords.begin(), attrib.texcoords.end());

    bool allNormals = true, allUvs = true;
    auto corner = [&](const tinyobj::index_t& x) {
        allNormals = allNormals && x.normal_index >= 0;
        allUvs = allUvs && x.texcoord_index >= 0;
        return MeshData::Corner{x.vertex_index, x.normal_index, x.texcoord_index};
    };
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        size_t base = 0;
        for (const unsigned int n : shape.mesh.num_face_vertices) {
            for (size_t k = 1; k + 1 < n; ++k) {  // fan around the polygon's first corner
                mesh->corners.push_back(corner(shape.mesh.indices[base]));
                mesh->corners.push_back(corner(shape.mesh.indices[base + k]));
                mesh->corners.push_back(corner(shape.mesh.indices[base + k + 1]));
            }
            base += n;
        }
    }
    if (mesh->corners.empty()) {
        diags.error({pathForMessages, 0, 0}, "OBJ file has no faces");
        return nullptr;
    }
    mesh->hasNormals = allNormals;
    mesh->hasUvs = allUvs;
    // A partial attribute is treated as absent, so that consumers need only the two flags.
    for (MeshData::Corner& c : mesh->corners) {
        if (!allNormals) c.normal = -1;
        if (!allUvs) c.uv = -1;
    }
    return mesh;
}

std::shared_ptr<const MeshData> readObjFile(const std::string& path, Diagnostics& diags) {
    std::string text, reason;
    if (!readTextFile(path, text, reason)) {
        diags.error({path, 0, 0}, "cannot read OBJ file: " + reason);
        return nullptr;
    }
    return readObjText(text, path, diags);
}

}  // namespace trazo
