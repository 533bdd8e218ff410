// Block lexer (host): line-based, as the thesis's reader was; braces, quotes and `#` comments anywhere.
#include "scene/block_lexer.h"

#include "io/text_file.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace trazo {
namespace {

struct Token {
    std::string text;
    int column = 0;
    bool quoted = false;
    bool isBrace(char c) const { return !quoted && text.size() == 1 && text[0] == c; }
};

// Numbers as the tables will see them: the whole token must read as a number. Out-of-range values become
// ±inf (or 0 on underflow) so that the reader reports them as non-finite instead of misreading them.
bool parseNumber(const std::string& text, double& out) {
    const char* first = text.data();
    const char* last = first + text.size();
    if (first != last && *first == '+') ++first;
    if (first == last) return false;
    auto [ptr, ec] = std::from_chars(first, last, out);
    if (ptr != last) return false;
    if (ec == std::errc::result_out_of_range) {
        out = std::strtod(text.c_str(), nullptr);  // HUGE_VAL or a tiny value, as C defines them
        return true;
    }
    return ec == std::errc();
}

std::vector<Token> tokenize(const std::string& line, int lineNumber, const std::string& file,
                            Diagnostics& diags) {
    std::vector<Token> tokens;
    size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        if (c == '#') break;  // [ext] comments anywhere
        const int column = static_cast<int>(i) + 1;
        if (c == '"') {
            const size_t close = line.find('"', i + 1);
            if (close == std::string::npos) {
                diags.error({file, lineNumber, column}, "unterminated quoted path");
                tokens.push_back({line.substr(i + 1), column, true});
                break;
            }
            tokens.push_back({line.substr(i + 1, close - i - 1), column, true});
            i = close + 1;
            continue;
        }
        if (c == '{' || c == '}') {
            tokens.push_back({std::string(1, c), column, false});
            ++i;
            continue;
        }
        const size_t end = line.find_first_of(" \t\r\f\v#{}\"", i);
        const size_t stop = end == std::string::npos ? line.size() : end;
        tokens.push_back({line.substr(i, stop - i), column, false});
        i = stop;
    }
    return tokens;
}

BlockValue toValue(const Token& t) {
    BlockValue v;
    v.text = t.text;
    v.column = t.column;
    if (t.quoted) {
        v.kind = BlockValue::Kind::Path;
    } else if (parseNumber(t.text, v.number)) {
        v.kind = BlockValue::Kind::Number;
    } else {
        v.kind = BlockValue::Kind::Name;
    }
    return v;
}

ParameterLine toParameter(const std::vector<Token>& tokens, size_t count, int lineNumber) {
    ParameterLine p;
    p.name = tokens[0].text;
    p.line = lineNumber;
    p.column = tokens[0].column;
    for (size_t k = 1; k < count; ++k) p.values.push_back(toValue(tokens[k]));
    return p;
}

// The state machine: outside a block, after an identifier awaiting '{', or inside a block.
class Lexer {
public:
    Lexer(const std::string& file, Diagnostics& diags) : file_(file), diags_(diags) {}

    void feed(const std::vector<Token>& tokens, int lineNumber) {
        if (inside_) {
            feedInside(tokens, lineNumber);
        } else {
            feedOutside(tokens, lineNumber);
        }
        previousLine_ = lineNumber;
    }

    std::vector<Block> finish() {
        if (inside_) {
            reportUnterminated("the end of the file");
            closeBlock();
        }
        if (!pending_.empty()) {
            diags_.error({file_, pendingLine_, 0}, "expected '{' after '" + pending_ + "'");
        }
        return std::move(blocks_);
    }

private:
    void openBlock(const std::string& identifier, int line) {
        current_ = Block{};
        current_.identifier = identifier;
        current_.where = {file_, line, 0};
        inside_ = true;
    }

    void closeBlock() {
        blocks_.push_back(std::move(current_));
        current_ = Block{};
        inside_ = false;
    }

    void reportUnterminated(const std::string& before) {
        current_.terminated = false;
        const std::string name = current_.identifier.empty() ? "block" : "block '" + current_.identifier + "'";
        diags_.error(current_.where, "unterminated " + name + " (no '}' before " + before + ")");
    }

    void feedOutside(const std::vector<Token>& tokens, int lineNumber) {
        if (!pending_.empty()) {
            const std::string name = std::exchange(pending_, {});
            if (tokens.size() == 1 && tokens[0].isBrace('{')) {
                openBlock(name, pendingLine_);
                return;
            }
            diags_.error({file_, pendingLine_, 0}, "expected '{' after '" + name + "'");
        }
        const Token& first = tokens[0];
        if (first.isBrace('{')) {
            diags_.error({file_, lineNumber, first.column}, "'{' without a block name");
            openBlock("", lineNumber);
            if (tokens.size() > 1) afterBrace(tokens, 1, lineNumber);
            return;
        }
        if (first.isBrace('}')) {
            diags_.error({file_, lineNumber, first.column}, "stray '}' outside a block");
            return;
        }
        if (!first.quoted && tokens.size() == 1) {
            pending_ = first.text;
            pendingLine_ = lineNumber;
            return;
        }
        if (!first.quoted && tokens[1].isBrace('{')) {
            openBlock(first.text, lineNumber);
            if (tokens.size() > 2) afterBrace(tokens, 2, lineNumber);
            return;
        }
        diags_.error({file_, lineNumber, first.column}, "text outside a block: '" + joined(tokens) + "'");
    }

    // Text after an opening brace on the same line: reported, then read as if it were on its own line.
    void afterBrace(const std::vector<Token>& tokens, size_t from, int lineNumber) {
        diags_.error({file_, lineNumber, tokens[from].column}, "unexpected text after '{'");
        feedInside(std::vector<Token>(tokens.begin() + static_cast<long>(from), tokens.end()), lineNumber);
    }

    void feedInside(const std::vector<Token>& tokens, int lineNumber) {
        const Token& first = tokens[0];
        if (first.isBrace('}')) {
            if (tokens.size() > 1) {
                diags_.error({file_, lineNumber, tokens[1].column}, "unexpected text after '}'");
            }
            closeBlock();
            return;
        }
        // A '{' inside a block means the previous block lost its '}': report it, then start the new one.
        size_t brace = 0;
        while (brace < tokens.size() && !tokens[brace].isBrace('{')) ++brace;
        if (brace < tokens.size()) {
            reportUnterminated("line " + std::to_string(lineNumber));
            std::string name;
            int nameLine = lineNumber;
            if (brace == 1 && !first.quoted) {
                name = first.text;
            } else if (brace == 0 && !current_.parameters.empty() && current_.parameters.back().values.empty() &&
                       current_.parameters.back().line == previousLine_) {
                // "Identifier" alone on the previous line was read as a parameter; it names the new block.
                name = current_.parameters.back().name;
                nameLine = current_.parameters.back().line;
                current_.parameters.pop_back();
            }
            closeBlock();
            openBlock(name, nameLine);
            if (tokens.size() > brace + 1) afterBrace(tokens, brace + 1, lineNumber);
            return;
        }
        size_t count = tokens.size();
        for (size_t k = 1; k < tokens.size(); ++k) {
            if (tokens[k].isBrace('}')) {
                count = k;
                break;
            }
        }
        if (first.quoted) {
            diags_.error({file_, lineNumber, first.column}, "expected a parameter name, got a quoted path");
        } else {
            current_.parameters.push_back(toParameter(tokens, count, lineNumber));
        }
        if (count < tokens.size()) {
            diags_.error({file_, lineNumber, tokens[count].column}, "'}' must be on its own line");
            closeBlock();
        }
    }

    static std::string joined(const std::vector<Token>& tokens) {
        std::string s;
        for (const Token& t : tokens) {
            if (!s.empty()) s += ' ';
            s += t.quoted ? "\"" + t.text + "\"" : t.text;
        }
        return s;
    }

    const std::string& file_;
    Diagnostics& diags_;
    std::vector<Block> blocks_;
    Block current_;
    bool inside_ = false;
    std::string pending_;
    int pendingLine_ = 0;
    int previousLine_ = 0;
};

}  // namespace

std::vector<Block> lexBlocks(const std::string& text, const std::string& file, Diagnostics& diags) {
    Lexer lexer(file, diags);
    size_t start = 0;
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;  // UTF-8 byte-order mark
    int lineNumber = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        ++lineNumber;
        const std::vector<Token> tokens = tokenize(text.substr(start, end - start), lineNumber, file, diags);
        if (!tokens.empty()) lexer.feed(tokens, lineNumber);
        start = end + 1;
    }
    return lexer.finish();
}

bool checkReadable(const std::string& path, std::string& reason) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        reason = std::strerror(EISDIR);  // opening a folder succeeds on Linux; reading it does not
        return false;
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        reason = std::strerror(errno != 0 ? errno : ENOENT);
        return false;
    }
    return true;
}

bool readTextFile(const std::string& path, std::string& contents, std::string& reason) {
    if (!checkReadable(path, reason)) return false;
    return readWholeFile(path, contents, reason);  // one read into a string of the file's size (OBJ files are large)
}

std::string resolveRelativePath(const std::string& namingFile, const std::string& written) {
    const std::filesystem::path p(written);
    if (p.is_absolute()) return p.lexically_normal().string();
    return (std::filesystem::path(namingFile).parent_path() / p).lexically_normal().string();
}

}  // namespace trazo
