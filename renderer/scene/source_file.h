// readSourceFile(): the whole text of a scene, CSG or OBJ file for its reader, or one error at the file (host).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "scene/diagnostic.h"

namespace trazo {

// The text of `path` (readWholeFile, at most `maxBytes`); when it cannot be read, nullopt after the error
// "cannot read KIND file: REASON" at the file itself (line 0), KIND being "scene", "CSG" or "OBJ".
std::optional<std::string> readSourceFile(const std::string& path, const char* kind, size_t maxBytes,
                                          Diagnostics& diags);

}  // namespace trazo
