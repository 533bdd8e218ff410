// readWholeFile: open, fstat, read into a string of that size. writeTextFileAtomically: temporary file in the
// target's folder, flushed, then renamed over the target.
#include "io/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace trazo {

bool readWholeFile(const std::string& path, std::string& contents, std::string& reason) {
    errno = 0;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        reason = std::strerror(errno != 0 ? errno : ENOENT);
        return false;
    }
    struct stat info {};
    if (::fstat(fd, &info) != 0 || S_ISDIR(info.st_mode)) {
        reason = std::strerror(S_ISDIR(info.st_mode) ? EISDIR : errno);  // a folder opens on Linux; it does not read
        ::close(fd);
        return false;
    }
    // The size is a hint (a pipe or a growing file may differ): read until end of file whatever it said.
    std::string text;
    text.resize(S_ISREG(info.st_mode) && info.st_size > 0 ? (size_t)info.st_size : 0);
    size_t used = 0;
    for (;;) {
        char probe[4096];
        const bool full = used == text.size();  // at the expected end: look for more in a small buffer
        const ssize_t got = full ? ::read(fd, probe, sizeof probe) : ::read(fd, text.data() + used, text.size() - used);
        if (got < 0) {
            if (errno == EINTR) continue;
            reason = std::strerror(errno);
            ::close(fd);
            return false;
        }
        if (got == 0) break;
        if (full) {
            text.resize(std::max(text.size() * 2, text.size() + sizeof probe));
            std::memcpy(text.data() + used, probe, (size_t)got);
        }
        used += (size_t)got;
    }
    ::close(fd);
    text.resize(used);
    contents = std::move(text);
    return true;
}

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
