// readWholeFile: open, fstat, read into a string of that size. writeTextFileAtomically: a stream into
// replaceAtomically's temporary.
#include "io/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/atomic_file.h"

namespace trazo {

namespace {

const char* fileTypeName(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a plain file";
}

// Empty when `info` is a regular file; otherwise the reason it is refused.
std::string refusal(const struct stat& info) {
    if (S_ISREG(info.st_mode)) return {};
    if (S_ISDIR(info.st_mode)) return std::strerror(EISDIR);
    return std::string("not a regular file (") + fileTypeName(info.st_mode) + ")";
}

std::string tooLarge(unsigned long long size, size_t limit) {
    return "file too large (" + std::to_string(size) + " bytes; the limit is " + std::to_string(limit) + " bytes)";
}

}  // namespace

int openRegularFile(const std::string& path, std::string& reason) {
    if (path.find('\0') != std::string::npos) {  // the OS would read the path only up to it
        reason = "the path contains a NUL byte";
        return -1;
    }
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) {
        reason = std::strerror(errno);
        return -1;
    }
    if (reason = refusal(info); !reason.empty()) return -1;
    // O_NONBLOCK: should the path be swapped for a FIFO between the stat and the open, the open still returns
    // (and the fstat refuses it). A regular file ignores the flag.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        reason = std::strerror(errno);
        return -1;
    }
    if (::fstat(fd, &info) != 0) {
        reason = std::strerror(errno);
        ::close(fd);
        return -1;
    }
    if (reason = refusal(info); !reason.empty()) {
        ::close(fd);
        return -1;
    }
    return fd;
}

bool readWholeFile(const std::string& path, std::string& contents, std::string& reason, size_t maxBytes) {
    const int fd = openRegularFile(path, reason);
    if (fd < 0) return false;
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        reason = std::strerror(errno);
        ::close(fd);
        return false;
    }
    const unsigned long long claimed = info.st_size > 0 ? (unsigned long long)info.st_size : 0;
    if (claimed > maxBytes) {  // refused before any allocation
        reason = tooLarge(claimed, maxBytes);
        ::close(fd);
        return false;
    }
    // The size is a hint (a growing file may differ): read until end of file, but never past maxBytes.
    std::string text;
    text.resize((size_t)claimed);
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
            if (used + (size_t)got > maxBytes) {
                reason = tooLarge(used + (size_t)got, maxBytes) + ", and still growing";
                ::close(fd);
                return false;
            }
            text.resize(std::min(std::max(text.size() * 2, text.size() + sizeof probe), maxBytes));
            std::memcpy(text.data() + used, probe, (size_t)got);
        }
        used += (size_t)got;
    }
    ::close(fd);
    text.resize(used);
    contents = std::move(text);
    return true;
}

std::string resolveRelativePath(const std::string& namingFile, const std::string& written) {
    const std::filesystem::path p(written);
    if (p.is_absolute()) return p.lexically_normal().string();
    return (std::filesystem::path(namingFile).parent_path() / p).lexically_normal().string();
}

bool writeTextFileAtomically(const std::string& path, const std::string& text, std::string& error) {
    return replaceAtomically(
        path,
        [&](const std::string& temporary, std::string& why) {
            std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
            if (file && (file << text) && file.flush()) return true;
            why = "cannot write '" + path + "': " + std::strerror(errno);
            return false;
        },
        error);
}

}  // namespace trazo
