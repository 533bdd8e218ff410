// Block lexer (host): splits a scene or CSG file into blocks of parameter lines (SPEC §1), with file:line.
#pragma once

#include <string>
#include <vector>

#include "io/text_file.h"
#include "scene/diagnostic.h"

namespace trazo {

// Limits on a scene or CSG text (SPEC §2, "Limits"), beyond the file size (kMaxSceneFileBytes): a longer line
// or token is an error at its line, and after kMaxLexerErrors syntax errors the rest of the file is not read.
// The longest meaningful line is a parameter with a path (a path is at most PATH_MAX = 4096 bytes on Linux).
inline constexpr size_t kMaxLineBytes = 64 * 1024;
inline constexpr size_t kMaxTokenBytes = 4096;
inline constexpr int kMaxLexerErrors = 100;

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
    bool complete = true;    // false when a line of it was refused (too long, NUL byte; already reported)
};

// Never throws; every syntax problem goes to `diags` with `file` and the line. Iterative: no input nests the
// call stack, and a NUL byte outside a comment is an error (it would cut paths and messages short).
std::vector<Block> lexBlocks(const std::string& text, const std::string& file, Diagnostics& diags);

}  // namespace trazo
