// replaceAtomically(): a unique hidden temporary in the target's folder, filled by the caller, then renamed.
#include "io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <system_error>

namespace trazo {

namespace fs = std::filesystem;

namespace {

// A name no other writer (thread or process) in the folder uses: hidden, with pid and a counter.
fs::path temporaryPathFor(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    const fs::path dir = target.parent_path();
    for (;;) {
        // Appended piece by piece: `"." + std::string&&` trips GCC 12's false -Wrestrict (PR 105329).
        std::string name = ".";
        name += target.filename().string();
        name += ".tmp";
        name += std::to_string(getpid());
        name += '_';
        name += std::to_string(counter.fetch_add(1));
        fs::path candidate = dir / name;
        std::error_code ec;
        if (!fs::exists(candidate, ec)) return candidate;
    }
}

}  // namespace

bool replaceAtomically(const std::string& path, const WriteTemporary& write, std::string& error) {
    const fs::path target(path);
    const fs::path temporary = temporaryPathFor(target);
    std::error_code ec;
    if (!write(temporary.string(), error)) {
        fs::remove(temporary, ec);
        return false;
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        error = "cannot write '" + path + "': cannot replace it: " + ec.message();
        fs::remove(temporary, ec);
        return false;
    }
    return true;
}

}  // namespace trazo
