// replaceAtomically(): the one way Trazo writes a file (host): into a temporary beside the target, renamed over
// it only when the whole write succeeded, so a failure never leaves a half-written file or a temporary behind
// and an existing file stays as it was.
#pragma once

#include <functional>
#include <string>

namespace trazo {

// What writes the contents: into the file at `temporary` (which it creates), false with the whole message in
// `error` when it could not.
using WriteTemporary = std::function<bool(const std::string& temporary, std::string& error)>;

// Calls `write` with a fresh temporary in `path`'s folder, hidden and unique across threads and processes
// (".NAME.tmp<pid>_<n>"), then renames it over `path`. On failure the temporary is removed and `error` holds
// write's message, or "cannot write 'PATH': cannot replace it: REASON" when the rename fails.
bool replaceAtomically(const std::string& path, const WriteTemporary& write, std::string& error);

}  // namespace trazo
