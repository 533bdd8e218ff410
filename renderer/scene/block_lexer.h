// Block lexer (host): splits a scene or CSG file into blocks of parameter lines (SPEC §1), with file:line.
#pragma once

#include <string>
#include <vector>

#include "scene/diagnostic.h"

namespace trazo {

// One value on a parameter line. A token that reads entirely as a number (including "nan", "inf" and
// out-of-range ones like 1e999, which read as ±inf) is a Number; the table decides whether it is allowed.
struct BlockValue {
    enum class Kind { Number, Name, Path } kind = Kind::Name;
    std::string text;     // as written; for a Path, without the quotes
    double number = 0.0;  // Number only
    int column = 0;       // 1-based column of the token's first character
};

struct ParameterLine {
    std::string name;
    std::vector<BlockValue> values;
    int line = 0;
    int column = 0;
};

struct Block {
    std::string identifier;  // empty for a '{' that had no name (already reported; readers skip it)
    SourceLocation where;    // the identifier's line
    std::vector<ParameterLine> parameters;
    bool terminated = true;  // false when its '}' is missing (already reported)
};

// Never throws; every syntax problem goes to `diags` with `file` and the line.
std::vector<Block> lexBlocks(const std::string& text, const std::string& file, Diagnostics& diags);

// Reads a whole file; on failure returns false and puts the OS reason (strerror) in `reason`.
bool readTextFile(const std::string& path, std::string& contents, std::string& reason);

// Opens and closes `path` to learn whether it can be read; on failure `reason` is the OS reason.
bool checkReadable(const std::string& path, std::string& reason);

// `written` relative to the folder of `namingFile` (unchanged when absolute), lexically normalised.
std::string resolveRelativePath(const std::string& namingFile, const std::string& written);

}  // namespace trazo
