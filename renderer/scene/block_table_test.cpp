// Tests of the block tables against SPEC.md's text (§3 blocks and parameters with defaults, §4 CSG blocks).
#include "scene/block_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace trazo {
namespace {

const std::string kDocsSpec = TRAZO_SOURCE_DIR "/docs/SPEC.md";
const std::string kSharedSpec = TRAZO_SOURCE_DIR "/../shared/SPEC.md";

std::string readAll(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string section(const std::string& spec, const std::string& start, const std::string& end) {
    const size_t a = spec.find(start);
    const size_t b = spec.find(end, a == std::string::npos ? 0 : a);
    if (a == std::string::npos || b == std::string::npos) return {};
    return spec.substr(a, b - a);
}

// What SPEC says about one parameter: "—" (required), a bracketed default, or "" (none).
struct SpecParam {
    std::string name;
    std::string defaultText;
};

// §3 paragraphs look like "**Sphere** — `Material` name; `Center` [0 0 0]; `Radius` [1]. More text."
// The parameters are the backticked names of the first sentence; "`A/B/C`" names three; "transforms as for
// Box" names Box's transforms.
std::map<std::string, std::vector<SpecParam>> specBlocks(const std::string& text) {
    std::map<std::string, std::vector<SpecParam>> blocks;
    static const std::regex kHead(R"(^\*\*(\w+)\*\* — (.*)$)");
    static const std::regex kSentenceEnd(R"(\.(\s|$))");
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (!std::regex_match(line, m, kHead)) continue;
        std::string sentence = m[2].str();
        std::smatch end;
        if (std::regex_search(sentence, end, kSentenceEnd)) sentence.resize(size_t(end.position(0)));
        std::vector<SpecParam>& params = blocks[m[1].str()];
        size_t pos = 0;
        while ((pos = sentence.find('`', pos)) != std::string::npos) {
            const size_t close = sentence.find('`', pos + 1);
            const std::string inside = sentence.substr(pos + 1, close - pos - 1);
            size_t stop = sentence.find_first_of("`;", close + 1);
            if (stop == std::string::npos) stop = sentence.size();
            const std::string after = sentence.substr(close + 1, stop - close - 1);
            std::string defaultText;
            if (after.find("—") != std::string::npos) defaultText = "—";
            static const std::regex kBracket(R"(\[([^\]]*)\])");
            for (std::sregex_iterator it(after.begin(), after.end(), kBracket), e; it != e; ++it) {
                const std::string b = (*it)[1].str();
                if (b.rfind("decided", 0) == 0 || b.rfind("ext", 0) == 0) continue;
                defaultText = b;
                break;
            }
            std::istringstream names(inside.substr(0, inside.find(' ')));
            std::string name;
            while (std::getline(names, name, '/')) params.push_back({name, defaultText});
            pos = close + 1;
        }
        if (sentence.find("transforms as for Box") != std::string::npos) {
            for (const char* t : {"Translation", "Rotation", "Scale"}) params.push_back({t, ""});
        }
    }
    return blocks;
}

std::vector<double> numbers(const std::string& s) {
    std::vector<double> v;
    std::istringstream in(s);
    double x;
    while (in >> x) v.push_back(x);
    return v;
}

void expectTablesMatch(const std::string& specPath) {
    const std::string spec = readAll(specPath);
    ASSERT_FALSE(spec.empty()) << specPath;
    const auto blocks = specBlocks(section(spec, "## 3. Blocks", "## 4."));
    ASSERT_EQ(blocks.size(), sceneBlocks().size()) << "SPEC §3 and the table list different blocks";
    for (const BlockInfo& table : sceneBlocks()) {
        const std::string block(table.name);
        const auto it = blocks.find(block);
        ASSERT_NE(it, blocks.end()) << "block " << block << " is not in SPEC §3";
        std::set<std::string> inSpec, inTable;
        for (const SpecParam& p : it->second) inSpec.insert(p.name);
        for (const ParamInfo& p : table.params) inTable.insert(std::string(p.name));
        EXPECT_EQ(inSpec, inTable) << "parameters of " << block;
        for (const SpecParam& p : it->second) {
            const auto param = std::find_if(table.params.begin(), table.params.end(),
                                            [&](const ParamInfo& q) { return q.name == p.name; });
            if (param == table.params.end()) continue;
            const std::string mine(param->defaultText);
            if (p.defaultText == "—" || mine == "—" || p.defaultText.empty() || mine.empty()) {
                EXPECT_EQ(mine, p.defaultText) << block << "." << p.name;
            } else {
                EXPECT_EQ(numbers(mine), numbers(p.defaultText)) << block << "." << p.name;
            }
        }
    }

    // §4: primitives as in §3 without Material, plus transforms; operations with the four child fields.
    const std::string csg = section(spec, "## 4. CSG files", "## 5.");
    ASSERT_FALSE(csg.empty());
    for (const char* name : {"`Union`", "`Difference`", "`Intersection`", "`LeftType`", "`LeftIndex`",
                             "`RightType`", "`RightIndex`", "`Sphere`", "`Box`", "`Cylinder`"}) {
        EXPECT_NE(csg.find(name), std::string::npos) << name;
    }
    const std::set<std::string> transforms = {"Translation", "Rotation", "Scale"};
    for (const BlockInfo& table : csgBlocks()) {
        std::set<std::string> expected = transforms;
        if (table.name == "Union" || table.name == "Difference" || table.name == "Intersection") {
            expected.insert({"LeftType", "LeftIndex", "RightType", "RightIndex"});
        } else {
            for (const SpecParam& p : blocks.at(std::string(table.name)))
                if (p.name != "Material") expected.insert(p.name);
        }
        std::set<std::string> inTable;
        for (const ParamInfo& p : table.params) inTable.insert(std::string(p.name));
        EXPECT_EQ(inTable, expected) << "CSG block " << table.name;
    }
}

TEST(BlockTable, MatchesTheSpecCopyInDocs) { expectTablesMatch(kDocsSpec); }

// The tables are checked against docs/SPEC.md; the project's shared folder, where a checkout has one, holds
// the spec it is copied from.
TEST(BlockTable, DocsCopyOfTheSpecIsCurrent) {
    if (!std::filesystem::exists(kSharedSpec)) GTEST_SKIP() << kSharedSpec << " is absent (a fresh clone)";
    EXPECT_EQ(readAll(kDocsSpec), readAll(kSharedSpec)) << "copy ../shared/SPEC.md to docs/SPEC.md";
}

TEST(BlockTable, SpecParserReadsTheExpectedShapes) {
    // Guards the test's own parser: a few facts read by eye from SPEC §3.
    const auto blocks = specBlocks(section(readAll(kDocsSpec), "## 3. Blocks", "## 4."));
    ASSERT_TRUE(blocks.count("AreaLight"));
    ASSERT_EQ(blocks.at("AreaLight").size(), 7u);
    EXPECT_EQ(blocks.at("AreaLight").back().name, "Subdivision");
    EXPECT_EQ(blocks.at("AreaLight").back().defaultText, "5 5");
    EXPECT_EQ(blocks.at("Texture").at(0).defaultText, "—");
    EXPECT_EQ(blocks.at("Mesh").size(), 5u);
    EXPECT_EQ(blocks.at("Material").size(), 13u);
}

TEST(BlockTable, EveryTableNameIsUniqueAndDocumented) {
    for (const auto* set : {&sceneBlocks(), &csgBlocks()}) {
        for (const BlockInfo& b : *set) {
            std::set<std::string_view> names;
            for (const ParamInfo& p : b.params) {
                EXPECT_TRUE(names.insert(p.name).second) << b.name << "." << p.name;
                EXPECT_FALSE(p.doc.empty()) << b.name << "." << p.name;
                EXPECT_GE(p.count, 1);
            }
        }
    }
}

TEST(BlockTable, DidYouMeanPicksTheClosestName) {
    const std::vector<std::string_view> names = {"Center", "Radius", "Material"};
    EXPECT_EQ(didYouMean("Radus", names), "did you mean 'Radius'?");
    EXPECT_EQ(didYouMean("radius", names), "did you mean 'Radius'?");
    EXPECT_EQ(didYouMean("Materail", names), "did you mean 'Material'?");
    EXPECT_EQ(didYouMean("Completely", names), "");
    EXPECT_EQ(didYouMean("Spher", blockNames(sceneBlocks())), "did you mean 'Sphere'?");
}

TEST(BlockTable, TwoWordSynonyms) {
    EXPECT_EQ(twoWordSynonym("Roll", "Angle"), "RollAngle");
    EXPECT_EQ(twoWordSynonym("Reflection", "Angle"), "ReflectionAngle");
    EXPECT_EQ(twoWordSynonym("Reflection", "Amount"), "ReflectionAmount");
    EXPECT_EQ(twoWordSynonym("Right", "Type"), "");
}

}  // namespace
}  // namespace trazo
