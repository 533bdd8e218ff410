// Whole text files (host): read in one piece, and written all or nothing (a temporary beside the target,
// then a rename, so a failure never leaves a half-written file and an existing file stays as it was).
#pragma once

#include <string>

namespace trazo {

// The whole file in `contents`, read straight into a string of the file's size (no stream buffer copies:
// a mesh can be tens of MB). False with a plain reason (strerror's words; a folder gives EISDIR's).
bool readWholeFile(const std::string& path, std::string& contents, std::string& reason);

// False with a plain reason in `error` when the file cannot be written or replaced.
bool writeTextFileAtomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace trazo
