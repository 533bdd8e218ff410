// writeTextFileAtomically: temporary file in the target's folder, flushed, then renamed over the target.
#include "io/text_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace trazo {

bool writeTextFileAtomically(const std::string& path, const std::string& text, std::string& error) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::string hidden = target.filename().string();
    hidden.insert(hidden.begin(), '.');  // (not "." + …: GCC 12 warns falsely on that with -O2)
    const fs::path temporary = target.parent_path() / (hidden + ".tmp-trazo");
    std::error_code ec;
    {
        std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
        if (!file || !(file << text) || !file.flush()) {
            error = "cannot write '" + path + "': " + std::strerror(errno);
            file.close();
            fs::remove(temporary, ec);
            return false;
        }
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        error = "cannot write '" + path + "': " + ec.message();
        fs::remove(temporary, ec);
        return false;
    }
    return true;
}

}  // namespace trazo
