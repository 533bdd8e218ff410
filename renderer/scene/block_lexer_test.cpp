// Tests of the block lexer: layout, comments, value kinds, and syntax errors with their lines.
#include "scene/block_lexer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace trazo {
namespace {

using Lines = std::vector<std::string>;

Lines formatted(const Diagnostics& d) {
    Lines out;
    for (const Diagnostic& x : d.items) out.push_back(formatDiagnostic(x));
    return out;
}

TEST(BlockLexer, BraceOnIdentifierLineOrNextLine) {
    Diagnostics diags;
    const auto blocks = lexBlocks("Sphere {\n  Radius 2\n}\n\nBox\n{\n  Scale 1 2 3\n}\n", "a.scene", diags);
    EXPECT_TRUE(diags.items.empty()) << formatted(diags)[0];
    ASSERT_EQ(blocks.size(), 2u);
    EXPECT_EQ(blocks[0].identifier, "Sphere");
    EXPECT_EQ(blocks[0].where.line, 1);
    EXPECT_EQ(blocks[0].where.file, "a.scene");
    ASSERT_EQ(blocks[0].parameters.size(), 1u);
    EXPECT_EQ(blocks[0].parameters[0].name, "Radius");
    EXPECT_EQ(blocks[0].parameters[0].line, 2);
    EXPECT_EQ(blocks[0].parameters[0].column, 3);
    EXPECT_EQ(blocks[1].identifier, "Box");
    EXPECT_EQ(blocks[1].where.line, 5);
    ASSERT_EQ(blocks[1].parameters.size(), 1u);
    EXPECT_EQ(blocks[1].parameters[0].values.size(), 3u);
    EXPECT_EQ(blocks[1].parameters[0].line, 7);
}

TEST(BlockLexer, CommentsAnywhereAndBlankLines) {
    Diagnostics diags;
    const std::string text =
        "# header comment\n"
        "#no space after the hash\n"
        "Sphere # after the identifier\n"
        "\n"
        "# between identifier and brace\n"
        "{ # after the brace\n"
        "    # inside\n"
        "    Center 1 2 3 # after values\n"
        "\t\n"
        "    #Radius 9\n"
        "} # after the closing brace\n"
        "# trailing\n";
    const auto blocks = lexBlocks(text, "c.scene", diags);
    EXPECT_TRUE(diags.items.empty()) << formatted(diags)[0];
    ASSERT_EQ(blocks.size(), 1u);
    EXPECT_EQ(blocks[0].where.line, 3);
    ASSERT_EQ(blocks[0].parameters.size(), 1u);
    EXPECT_EQ(blocks[0].parameters[0].name, "Center");
    EXPECT_EQ(blocks[0].parameters[0].values.size(), 3u);
    EXPECT_EQ(blocks[0].parameters[0].line, 8);
}

TEST(BlockLexer, ValueKindsAndColumns) {
    Diagnostics diags;
    const auto blocks =
        lexBlocks("Mesh\n{\n Source \"my dir/a#b.obj\"\n Material mat1\n Scale -0.5 2e-3 +1\n}\n", "m.scene", diags);
    EXPECT_TRUE(diags.items.empty());
    ASSERT_EQ(blocks.size(), 1u);
    const auto& p = blocks[0].parameters;
    ASSERT_EQ(p.size(), 3u);
    ASSERT_EQ(p[0].values.size(), 1u);
    EXPECT_EQ(p[0].values[0].kind, BlockValue::Kind::Path);
    EXPECT_EQ(p[0].values[0].text, "my dir/a#b.obj");  // '#' inside quotes is not a comment
    EXPECT_EQ(p[0].values[0].column, 9);
    EXPECT_EQ(p[1].values[0].kind, BlockValue::Kind::Name);
    EXPECT_EQ(p[1].values[0].text, "mat1");
    ASSERT_EQ(p[2].values.size(), 3u);
    EXPECT_EQ(p[2].values[0].kind, BlockValue::Kind::Number);
    EXPECT_DOUBLE_EQ(p[2].values[0].number, -0.5);
    EXPECT_DOUBLE_EQ(p[2].values[1].number, 2e-3);
    EXPECT_DOUBLE_EQ(p[2].values[2].number, 1.0);
    EXPECT_EQ(p[2].values[1].column, 13);
}

TEST(BlockLexer, NonFiniteTokensAreNumbers) {
    Diagnostics diags;
    const auto blocks = lexBlocks("Sphere\n{\n Center nan inf 1e999\n}\n", "n.scene", diags);
    ASSERT_EQ(blocks.size(), 1u);
    const auto& v = blocks[0].parameters[0].values;
    ASSERT_EQ(v.size(), 3u);
    for (const BlockValue& x : v) EXPECT_EQ(x.kind, BlockValue::Kind::Number) << x.text;
    EXPECT_TRUE(std::isnan(v[0].number));
    EXPECT_TRUE(std::isinf(v[1].number));
    EXPECT_TRUE(std::isinf(v[2].number));
}

TEST(BlockLexer, WindowsLineEndingsAndByteOrderMark) {
    Diagnostics diags;
    const auto blocks = lexBlocks("\xEF\xBB\xBFSphere\r\n{\r\n Radius 2\r\n}\r\n", "w.scene", diags);
    EXPECT_TRUE(diags.items.empty());
    ASSERT_EQ(blocks.size(), 1u);
    EXPECT_EQ(blocks[0].identifier, "Sphere");
    ASSERT_EQ(blocks[0].parameters.size(), 1u);
    EXPECT_EQ(blocks[0].parameters[0].values.size(), 1u);
}

// A block as "Identifier:line params=N", with " unterminated" where its '}' is missing.
std::string blockSummary(const Block& b) {
    return b.identifier + ":" + std::to_string(b.where.line) + " params=" + std::to_string(b.parameters.size()) +
           (b.terminated ? "" : " unterminated");
}

// A syntax error: the text (as s.scene), every diagnostic it gives, and the blocks recovered (blockSummary).
struct SyntaxCase {
    const char* name;
    std::string text;
    Lines errors;
    Lines blocks;
};

void PrintTo(const SyntaxCase& c, std::ostream* os) { *os << c.name; }

class BlockLexerSyntax : public ::testing::TestWithParam<SyntaxCase> {};

TEST_P(BlockLexerSyntax, ReportsEachErrorAndRecoversTheBlocks) {
    Diagnostics diags;
    const auto blocks = lexBlocks(GetParam().text, "s.scene", diags);
    EXPECT_EQ(formatted(diags), GetParam().errors);
    Lines recovered;
    for (const Block& b : blocks) recovered.push_back(blockSummary(b));
    EXPECT_EQ(recovered, GetParam().blocks);
}

INSTANTIATE_TEST_SUITE_P(
    BlockLexer, BlockLexerSyntax,
    ::testing::Values(
        // The Camera block is closed by nobody: reported at its own line, and recovered as two blocks ("Sphere"
        // is not kept as a parameter of Camera).
        SyntaxCase{"UnterminatedBlockAtEndOfFile",
                   "Camera\n{\n FOV 30\n\nSphere\n{\n Radius 1\n",
                   {"s.scene:1: error: unterminated block 'Camera' (no '}' before line 6)",
                    "s.scene:5: error: unterminated block 'Sphere' (no '}' before the end of the file)"},
                   {"Camera:1 params=1 unterminated", "Sphere:5 params=1 unterminated"}},
        SyntaxCase{"UnterminatedBeforeSameLineBrace",
                   "Camera {\n FOV 30\nSphere {\n Radius 1\n}\n",
                   {"s.scene:1: error: unterminated block 'Camera' (no '}' before line 3)"},
                   {"Camera:1 params=1 unterminated", "Sphere:3 params=1"}},
        SyntaxCase{"StrayBraceAndTextOutsideBlocks",
                   "Sphere\n{\n}\n}\nRadius 1\n\"x.obj\"\n",
                   {"s.scene:4:1: error: stray '}' outside a block",
                    "s.scene:5:1: error: text outside a block: 'Radius 1'",
                    "s.scene:6:1: error: text outside a block: '\"x.obj\"'"},
                   {"Sphere:1 params=0"}},
        SyntaxCase{"BraceWithoutNameAndUnterminatedQuote",
                   "{\n Radius 1\n}\nMesh {\n Source \"a.obj\n}\n",
                   {"s.scene:1:1: error: '{' without a block name", "s.scene:5:9: error: unterminated quoted path"},
                   {":1 params=1", "Mesh:4 params=1"}},
        SyntaxCase{"ClosingBraceAfterValues",
                   "Sphere {\n Radius 1 }\nBox {\n}\n",
                   {"s.scene:2:11: error: '}' must be on its own line"},
                   {"Sphere:1 params=1", "Box:3 params=0"}},
        SyntaxCase{"IdentifierWithoutBraceAtTheEnd",
                   "Sphere {\n}\nBox\n",
                   {"s.scene:3: error: expected '{' after 'Box'"},
                   {"Sphere:1 params=0"}}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(BlockLexer, IdentifierWithoutBrace) {
    Diagnostics diags;
    lexBlocks("Sphere\nRadius 1\n", "i.scene", diags);
    ASSERT_GE(diags.items.size(), 1u);
    EXPECT_EQ(formatDiagnostic(diags.items[0]), "i.scene:1: error: expected '{' after 'Sphere'");
}

}  // namespace
}  // namespace trazo

// Hostile input (issue 18): bounded work, no recursion, and every refusal at its file:line.
namespace trazo {
namespace {

// 100 000 '{' lines used to be read as 100 000 unterminated blocks (and the same on one line recursed once a
// brace): now the report stops after kMaxLexerErrors, saying so at the line where it stopped.
TEST(BlockLexerHostile, HundredThousandNestedBracesGiveABoundedReport) {
    std::string text = "Sphere\n";
    for (int i = 0; i < 100000; ++i) text += "{\n";
    Diagnostics diags;
    lexBlocks(text, "nest.scene", diags);
    ASSERT_EQ(diags.items.size(), size_t(kMaxLexerErrors) + 1);
    EXPECT_EQ(formatDiagnostic(diags.items[0]), "nest.scene:1: error: unterminated block 'Sphere' (no '}' before line 3)");
    EXPECT_EQ(formatDiagnostic(diags.items.back()),
              "nest.scene:103: error: too many syntax errors (more than 100); the rest of the file is not read");
}

TEST(BlockLexerHostile, ManyBracesOnOneLineAreReadInALoop) {
    std::string line;
    while (7 + line.size() + 2 <= kMaxLineBytes) line += "{ ";  // "Sphere " + line fits in a line
    Diagnostics diags;
    lexBlocks("Sphere " + line + "\n}\n", "one.scene", diags);
    EXPECT_EQ(diags.items.size(), size_t(kMaxLexerErrors) + 1);
    EXPECT_EQ(diags.items[0].where.line, 1);
    // Below the error cap the same line keeps being read: 20 braces, each an unterminated block.
    std::string few;
    for (int i = 0; i < 20; ++i) few += "{ ";
    Diagnostics some;
    const auto blocks = lexBlocks("Sphere " + few + "Radius 1\n}\n", "few.scene", some);
    ASSERT_EQ(blocks.size(), 20u);
    EXPECT_EQ(blocks.back().parameters.size(), 1u);
    EXPECT_TRUE(blocks.back().terminated);
}

TEST(BlockLexerHostile, LineOverTheLimitIsAnErrorAtItsLine) {
    const std::string ok(kMaxLineBytes - 2, 'x');
    Diagnostics fine;
    auto blocks = lexBlocks("Sphere {\n #" + ok + "\n Radius 2\n}\n", "fine.scene", fine);
    EXPECT_TRUE(fine.items.empty());  // a line of exactly kMaxLineBytes is read
    const std::string over(kMaxLineBytes - 8, '1');  // " Radius " + over + "\r" = limit + 1 bytes
    Diagnostics diags;
    blocks = lexBlocks("Sphere {\n Radius " + over + "\r\n Radius 2\n}\n", "long.scene", diags);
    EXPECT_EQ(formatted(diags), Lines({"long.scene:2: error: line too long (65537 bytes; the limit is 65536 bytes)"}));
    ASSERT_EQ(blocks.size(), 1u);
    ASSERT_EQ(blocks[0].parameters.size(), 1u);  // the long line is skipped, the rest is read
    EXPECT_EQ(blocks[0].parameters[0].line, 3);
}

TEST(BlockLexerHostile, TokenOverTheLimitIsAnErrorAtItsColumn) {
    Diagnostics fine;
    lexBlocks("Mesh {\n Source \"" + std::string(kMaxTokenBytes, 'a') + "\"\n}\n", "fine.scene", fine);
    EXPECT_TRUE(fine.items.empty());
    Diagnostics diags;
    lexBlocks("Mesh {\n Source \"" + std::string(kMaxTokenBytes + 1, 'a') + "\"\n Name " +
                  std::string(kMaxTokenBytes + 1, 'b') + "\n}\n",
              "tok.scene", diags);
    EXPECT_EQ(formatted(diags),
              Lines({"tok.scene:2:9: error: quoted path too long (4097 bytes; the limit is 4096 bytes)",
                     "tok.scene:3:7: error: token too long (4097 bytes; the limit is 4096 bytes)"}));
}

TEST(BlockLexerHostile, NulByteIsAnErrorExceptInAComment) {
    const char raw[] = "Mesh {\n Source \"a\0b.obj\"\n Material m\0x\n # \0 comment\n}\n";
    Diagnostics diags;
    const auto blocks = lexBlocks(std::string(raw, sizeof raw - 1), "nul.scene", diags);
    EXPECT_EQ(formatted(diags),
              Lines({"nul.scene:2:11: error: NUL byte in the text (not allowed)",
                     "nul.scene:3:12: error: NUL byte in the text (not allowed)"}));
    ASSERT_EQ(blocks.size(), 1u);
    EXPECT_TRUE(blocks[0].parameters.empty());
    EXPECT_FALSE(blocks[0].complete);  // so that no "missing required parameter 'Source'" follows
}

}  // namespace
}  // namespace trazo
