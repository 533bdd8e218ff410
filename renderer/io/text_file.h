// Writing a text file all or nothing (host): a temporary beside it, then a rename, so a failure never leaves
// a half-written file and an existing file stays as it was.
#pragma once

#include <string>

namespace trazo {

// False with a plain reason in `error` when the file cannot be written or replaced.
bool writeTextFileAtomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace trazo
