// Parameter values back to text (host): numbers with enough digits to read back bit for bit, paths relative
// to the scene's folder so a saved scene still finds its files when the folder moves.
#include "scene/param_format.h"

#include <cstdio>
#include <filesystem>

namespace trazo {
namespace {

std::string quotedPath(const std::string& path, const std::string& scenePath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path target = fs::absolute(fs::path(path), ec).lexically_normal();
    const fs::path folder = fs::absolute(fs::path(scenePath), ec).parent_path().lexically_normal();
    const fs::path relative = target.lexically_relative(folder);
    std::string quoted = (relative.empty() ? target : relative).generic_string();
    quoted.insert(quoted.begin(), '"');  // (not "\"" + …: GCC 12 warns falsely on that with -O2)
    quoted.push_back('"');
    return quoted;
}

}  // namespace

std::string formatReal(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", double(v));
    return buffer;
}

std::string formatValues(const ParamInfo& info, const ParamValue& value, const std::string& scenePath) {
    switch (info.kind) {
        case ValueKind::Name: return value.text;
        case ValueKind::Path: return quotedPath(value.text, scenePath);
        case ValueKind::Real:
        case ValueKind::Int: break;
    }
    std::string text;
    for (int i = 0; i < info.count; ++i) {
        if (i > 0) text += ' ';
        text += info.kind == ValueKind::Int ? std::to_string(value.integer(i)) : formatReal(value.real(i));
    }
    return text;
}

}  // namespace trazo
