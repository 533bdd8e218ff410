// Block lexer (host): line-based, as the thesis's reader was; braces, quotes and `#` comments anywhere.
#include "scene/block_lexer.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <utility>

namespace trazo {
namespace {

struct Token {
    std::string text;
    int column = 0;
    bool quoted = false;
    bool isBrace(char c) const { return !quoted && text.size() == 1 && text[0] == c; }
};

// Every syntax error of one file goes through here, so that a hostile file (100 000 stray braces) gives a
// bounded report: after kMaxLexerErrors the lexer says so once and reads no further.
class Reporter {
public:
    Reporter(const std::string& file, Diagnostics& diags) : file_(file), diags_(diags) {}

    void error(int line, int column, std::string message) {
        if (stopped_) return;
        if (++count_ > kMaxLexerErrors) {
            diags_.error({file_, reading_, 0}, "too many syntax errors (more than " + std::to_string(kMaxLexerErrors) +
                                               "); the rest of the file is not read");
            stopped_ = true;
            return;
        }
        diags_.error({file_, line, column}, std::move(message));
    }
    void error(const SourceLocation& where, std::string message) { error(where.line, where.column, std::move(message)); }
    bool stopped() const { return stopped_; }
    const std::string& file() const { return file_; }
    void reading(int line) { reading_ = line; }  // the line being read, where "too many" is reported

private:
    const std::string& file_;
    Diagnostics& diags_;
    int count_ = 0;
    int reading_ = 0;
    bool stopped_ = false;
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

std::string tooLong(const char* what, size_t size, size_t limit) {
    return std::string(what) + " too long (" + std::to_string(size) + " bytes; the limit is " +
           std::to_string(limit) + " bytes)";
}

// The tokens of one line (at most kMaxLineBytes, checked by the caller). False, after reporting, when the line
// cannot be read: a NUL byte (it would cut every path and message short) or a token over kMaxTokenBytes.
bool tokenize(std::string_view line, int lineNumber, Reporter& report, std::vector<Token>& tokens) {
    tokens.clear();
    size_t i = 0;
    auto add = [&](size_t from, size_t size, int column, bool quoted) {
        if (size > kMaxTokenBytes) {
            report.error(lineNumber, column, tooLong(quoted ? "quoted path" : "token", size, kMaxTokenBytes));
            return false;
        }
        const std::string_view text = line.substr(from, size);
        if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
            report.error(lineNumber, static_cast<int>(from + nul) + 1, "NUL byte in the text (not allowed)");
            return false;
        }
        tokens.push_back({std::string(text), column, quoted});
        return true;
    };
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
            if (close == std::string_view::npos) {
                report.error(lineNumber, column, "unterminated quoted path");
                return add(i + 1, line.size() - i - 1, column, true);
            }
            if (!add(i + 1, close - i - 1, column, true)) return false;
            i = close + 1;
            continue;
        }
        if (c == '{' || c == '}') {
            tokens.push_back({std::string(1, c), column, false});
            ++i;
            continue;
        }
        const size_t end = line.find_first_of(" \t\r\f\v#{}\"", i);
        const size_t stop = end == std::string_view::npos ? line.size() : end;
        if (!add(i, stop - i, column, false)) return false;
        i = stop;
    }
    return true;
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

ParameterLine toParameter(const std::vector<Token>& tokens, size_t from, size_t count, int lineNumber) {
    ParameterLine p;
    p.name = tokens[from].text;
    p.line = lineNumber;
    p.column = tokens[from].column;
    for (size_t k = from + 1; k < count; ++k) p.values.push_back(toValue(tokens[k]));
    return p;
}

// The state machine: outside a block, after an identifier awaiting '{', or inside a block. Blocks do not nest
// (SPEC §1), so there is no depth to track: a '{' inside a block ends the block before it (reported). The
// rest of a line after a '{' is read in a loop over the same tokens, never by recursion, so a line of many
// braces costs neither stack nor copies.
class Lexer {
public:
    explicit Lexer(Reporter& report) : report_(report), file_(report.file()) {}

    void feed(const std::vector<Token>& tokens, int lineNumber) {
        if (inside_) {
            feedInside(tokens, 0, lineNumber);
        } else {
            feedOutside(tokens, lineNumber);
        }
        previousLine_ = lineNumber;
    }

    // A line refused by the limits (already reported): the block it was in lacks whatever that line said.
    void refused() {
        if (inside_) current_.complete = false;
    }

    std::vector<Block> finish() {
        if (inside_) {
            reportUnterminated("the end of the file");
            closeBlock();
        }
        if (!pending_.empty()) report_.error(pendingLine_, 0, "expected '{' after '" + pending_ + "'");
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
        report_.error(current_.where, "unterminated " + name + " (no '}' before " + before + ")");
    }

    void feedOutside(const std::vector<Token>& tokens, int lineNumber) {
        if (!pending_.empty()) {
            const std::string name = std::exchange(pending_, {});
            if (tokens.size() == 1 && tokens[0].isBrace('{')) {
                openBlock(name, pendingLine_);
                return;
            }
            report_.error(pendingLine_, 0, "expected '{' after '" + name + "'");
        }
        const Token& first = tokens[0];
        if (first.isBrace('{')) {
            report_.error(lineNumber, first.column, "'{' without a block name");
            openBlock("", lineNumber);
            if (tokens.size() > 1) afterBrace(tokens, 1, lineNumber);
            return;
        }
        if (first.isBrace('}')) {
            report_.error(lineNumber, first.column, "stray '}' outside a block");
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
        report_.error(lineNumber, first.column, "text outside a block: '" + joined(tokens) + "'");
    }

    // Text after an opening brace on the same line: reported, then read as if it were on its own line.
    void afterBrace(const std::vector<Token>& tokens, size_t from, int lineNumber) {
        report_.error(lineNumber, tokens[from].column, "unexpected text after '{'");
        feedInside(tokens, from, lineNumber);
    }

    // tokens[from…] inside a block; loops (instead of recursing) over the text after each '{' on the line.
    void feedInside(const std::vector<Token>& tokens, size_t from, int lineNumber) {
        while (!report_.stopped()) {
            const Token& first = tokens[from];
            if (first.isBrace('}')) {
                if (tokens.size() > from + 1) {
                    report_.error(lineNumber, tokens[from + 1].column, "unexpected text after '}'");
                }
                closeBlock();
                return;
            }
            // A '{' inside a block means the previous block lost its '}': report it, then start the new one.
            size_t brace = from;
            while (brace < tokens.size() && !tokens[brace].isBrace('{')) ++brace;
            if (brace < tokens.size()) {
                reportUnterminated("line " + std::to_string(lineNumber));
                std::string name;
                int nameLine = lineNumber;
                if (brace == from + 1 && !first.quoted) {
                    name = first.text;
                } else if (brace == from && !current_.parameters.empty() &&
                           current_.parameters.back().values.empty() &&
                           current_.parameters.back().line == previousLine_) {
                    // "Identifier" alone on the previous line was read as a parameter; it names the new block.
                    name = current_.parameters.back().name;
                    nameLine = current_.parameters.back().line;
                    current_.parameters.pop_back();
                }
                closeBlock();
                openBlock(name, nameLine);
                if (tokens.size() <= brace + 1) return;
                report_.error(lineNumber, tokens[brace + 1].column, "unexpected text after '{'");
                from = brace + 1;
                continue;
            }
            size_t count = tokens.size();
            for (size_t k = from + 1; k < tokens.size(); ++k) {
                if (tokens[k].isBrace('}')) {
                    count = k;
                    break;
                }
            }
            if (first.quoted) {
                report_.error(lineNumber, first.column, "expected a parameter name, got a quoted path");
            } else {
                current_.parameters.push_back(toParameter(tokens, from, count, lineNumber));
            }
            if (count < tokens.size()) {
                report_.error(lineNumber, tokens[count].column, "'}' must be on its own line");
                closeBlock();
            }
            return;
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

    Reporter& report_;
    const std::string& file_;
    std::vector<Block> blocks_;
    Block current_;
    bool inside_ = false;
    std::string pending_;
    int pendingLine_ = 0;
    int previousLine_ = 0;
};

}  // namespace

std::vector<Block> lexBlocks(const std::string& text, const std::string& file, Diagnostics& diags) {
    Reporter report(file, diags);
    if (text.size() > kMaxSceneFileBytes) {  // (the readers refuse such a file before reading it)
        report.error(0, 0, tooLong("text", text.size(), kMaxSceneFileBytes));
        return {};
    }
    Lexer lexer(report);
    const std::string_view all(text);
    size_t start = 0;
    if (all.substr(0, 3) == "\xEF\xBB\xBF") start = 3;  // UTF-8 byte-order mark
    int lineNumber = 0;  // cannot overflow: kMaxSceneFileBytes < INT_MAX
    std::vector<Token> tokens;
    while (start <= all.size() && !report.stopped()) {
        size_t end = all.find('\n', start);
        if (end == std::string_view::npos) end = all.size();
        report.reading(++lineNumber);
        if (end - start > kMaxLineBytes) {
            report.error(lineNumber, 0, tooLong("line", end - start, kMaxLineBytes));
            lexer.refused();
        } else if (!tokenize(all.substr(start, end - start), lineNumber, report, tokens)) {
            lexer.refused();
        } else if (!tokens.empty()) {
            lexer.feed(tokens, lineNumber);
        }
        start = end + 1;
    }
    return lexer.finish();
}

}  // namespace trazo
