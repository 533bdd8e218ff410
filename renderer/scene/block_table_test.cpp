// Tests of the block tables against SPEC.md's text (§3 blocks and parameters with defaults, §4 CSG blocks), and
// of every row's extract → format → read → apply round trip.
#include "scene/block_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "test_paths.h"

namespace trazo {
namespace {

const std::string kDocsSpec = TRAZO_SOURCE_DIR "/docs/SPEC.md";
const std::string kSharedSpec = TRAZO_SOURCE_DIR "/../shared/SPEC.md";

// From `start` to `end`, or to the end of the text when no `end` follows (the last section).
std::string section(const std::string& spec, const std::string& start, const std::string& end) {
    const size_t a = spec.find(start);
    if (a == std::string::npos) return {};
    const size_t b = spec.find(end, a);
    return spec.substr(a, b == std::string::npos ? std::string::npos : b - a);
}

// What SPEC says about one parameter: "—" (required), a bracketed default, or "" (none).
struct SpecParam {
    std::string name;
    std::string defaultText;
};

// The default in the text after a parameter's name: "—" (required), else the first bracketed value that is not
// "[decided …]" or "[ext…]", else "".
std::string defaultIn(const std::string& after) {
    std::string defaultText;
    if (after.find("—") != std::string::npos) defaultText = "—";
    static const std::regex kBracket(R"(\[([^\]]*)\])");
    for (std::sregex_iterator it(after.begin(), after.end(), kBracket), e; it != e; ++it) {
        const std::string b = (*it)[1].str();
        if (b.rfind("decided", 0) == 0 || b.rfind("ext", 0) == 0) continue;
        return b;
    }
    return defaultText;
}

// The parameters a paragraph names: the backticked names of its first sentence ("`A/B/C`" names three), and
// Box's transforms where that sentence says "transforms as for Box".
std::vector<SpecParam> paragraphParams(std::string sentence) {
    static const std::regex kSentenceEnd(R"(\.(\s|$))");
    std::smatch end;
    if (std::regex_search(sentence, end, kSentenceEnd)) sentence.resize(size_t(end.position(0)));
    std::vector<SpecParam> params;
    size_t pos = 0;
    while ((pos = sentence.find('`', pos)) != std::string::npos) {
        const size_t close = sentence.find('`', pos + 1);
        const std::string inside = sentence.substr(pos + 1, close - pos - 1);
        size_t stop = sentence.find_first_of("`;", close + 1);
        if (stop == std::string::npos) stop = sentence.size();
        const std::string defaultText = defaultIn(sentence.substr(close + 1, stop - close - 1));
        std::istringstream names(inside.substr(0, inside.find(' ')));
        std::string name;
        while (std::getline(names, name, '/')) params.push_back({name, defaultText});
        pos = close + 1;
    }
    if (sentence.find("transforms as for Box") != std::string::npos) {
        for (const char* t : {"Translation", "Rotation", "Scale"}) params.push_back({t, ""});
    }
    return params;
}

using SpecBlocks = std::map<std::string, std::vector<SpecParam>>;

// Each line of `text` that `lineForm` matches whole gives block m[1] the parameters of the paragraph m[2], less
// what `remarks` matches (where given).
SpecBlocks specParams(const std::string& text, const std::regex& lineForm, const std::regex* remarks = nullptr) {
    SpecBlocks blocks;
    std::istringstream lines(text);
    std::string line;
    std::smatch m;
    while (std::getline(lines, line)) {
        if (!std::regex_match(line, m, lineForm)) continue;
        const std::vector<SpecParam> params =
            paragraphParams(remarks ? std::regex_replace(m[2].str(), *remarks, "") : m[2].str());
        std::vector<SpecParam>& into = blocks[m[1].str()];
        into.insert(into.end(), params.begin(), params.end());
    }
    return blocks;
}

// §3 paragraphs look like "**Sphere** — `Material` name; `Center` [0 0 0]; `Radius` [1]. More text."
SpecBlocks specBlocks(const std::string& text) {
    static const std::regex kHead(R"(^\*\*(\w+)\*\* — (.*)$)");
    return specParams(text, kHead);
}

// §6 adds parameters to §3's blocks in lines like "- **Fresnel** (Material): `Fresnel` 0|1 [0]. More text.",
// once parenthesised remarks (which may quote other names) are dropped.
SpecBlocks specFutureWork(const std::string& text) {
    static const std::regex kItem(R"(^- \*\*[^*]+\*\* \((\w+)\): (.*)$)");
    static const std::regex kRemark(R"( \([^()]*\))");
    return specParams(text, kItem, &kRemark);
}

// §7 adds its settings in one paragraph: "**Settings** (SceneSettings): `Integrator` thesis|path [thesis]; …".
SpecBlocks specPhysical(const std::string& text) {
    static const std::regex kParagraph(R"(^\*\*[^*]+\*\* \((\w+)\): (.*)$)");
    static const std::regex kRemark(R"( \([^()]*\))");
    return specParams(text, kParagraph, &kRemark);
}

// A default SPEC states in words where the table has none: no value ("none"), or one that depends on another
// setting ("linear under thesis, srgb under path").
bool saysNoValue(const std::string& specDefault) {
    return specDefault == "none" || specDefault.find(" under ") != std::string::npos;
}

// As the reader stores them: floats. The tables' default texts are scene.h's float initialisers written with
// %.9g ("0.899999976"), SPEC's are decimal ("0.9"); both read to the same float.
std::vector<float> numbers(const std::string& s) {
    std::vector<float> v;
    std::istringstream in(s);
    double x;
    while (in >> x) v.push_back(float(x));
    return v;
}

void expectTablesMatch(const std::string& specPath) {
    const std::string spec = test::readFileText(specPath);
    ASSERT_FALSE(spec.empty()) << specPath;
    auto blocks = specBlocks(section(spec, "## 3. Blocks", "## 4."));
    ASSERT_EQ(blocks.size(), sceneBlocks().size()) << "SPEC §3 and the table list different blocks";
    for (const auto& [block, params] : specFutureWork(section(spec, "## 6.", "\n## 7."))) {
        ASSERT_TRUE(blocks.count(block)) << "§6 adds to a block §3 does not have: " << block;
        blocks[block].insert(blocks[block].end(), params.begin(), params.end());
    }
    const SpecBlocks physical = specPhysical(section(spec, "## 7.", "\n## 8."));
    ASSERT_EQ(physical.size(), 1u) << "§7 adds its settings in one paragraph";
    for (const auto& [block, params] : physical) {
        ASSERT_TRUE(blocks.count(block)) << "§7 adds to a block §3 does not have: " << block;
        blocks[block].insert(blocks[block].end(), params.begin(), params.end());
    }
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
            if (saysNoValue(p.defaultText)) {
                EXPECT_EQ(mine, "") << block << "." << p.name;
            } else if (!param->choices.empty()) {
                EXPECT_EQ(mine, p.defaultText) << block << "." << p.name;
            } else if (p.defaultText == "—" || mine == "—" || p.defaultText.empty() || mine.empty()) {
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
    EXPECT_EQ(test::readFileText(kDocsSpec), test::readFileText(kSharedSpec)) << "copy ../shared/SPEC.md to docs/SPEC.md";
}

TEST(BlockTable, SpecParserReadsTheExpectedShapes) {
    // Guards the test's own parser: a few facts read by eye from SPEC §3.
    const auto blocks = specBlocks(section(test::readFileText(kDocsSpec), "## 3. Blocks", "## 4."));
    ASSERT_TRUE(blocks.count("AreaLight"));
    ASSERT_EQ(blocks.at("AreaLight").size(), 7u);
    EXPECT_EQ(blocks.at("AreaLight").back().name, "Subdivision");
    EXPECT_EQ(blocks.at("AreaLight").back().defaultText, "5 5");
    EXPECT_EQ(blocks.at("Texture").at(0).defaultText, "—");
    EXPECT_EQ(blocks.at("Mesh").size(), 5u);
    EXPECT_EQ(blocks.at("Material").size(), 13u);
    const auto added = specFutureWork(section(test::readFileText(kDocsSpec), "## 6.", "\n## 7."));
    ASSERT_TRUE(added.count("Camera") && added.count("Material"));
    ASSERT_EQ(added.at("Camera").size(), 3u);
    EXPECT_EQ(added.at("Camera").at(1).name, "FocalDistance");
    EXPECT_EQ(added.at("Camera").at(2).defaultText, "3");
    ASSERT_EQ(added.at("Material").size(), 4u);  // Fresnel, RefractionAngle, Dispersion, ScatteringDistance
    EXPECT_EQ(added.at("Material").at(2).name, "Dispersion");
    EXPECT_EQ(added.at("Material").at(3).defaultText, "0 0 0");
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

// A value of the row other than its default that the reader accepts: default + 3.25 (else − 0.75) in each
// value, kept inside the row's checks (fitToCheck), so that Antialiasing becomes 4 and Opacity 0.25.
template <class Target>
ParamValue otherValue(const ParamSpec<Target>& row, const ParamValue& base) {
    for (double step : {3.25, -0.75}) {
        ParamValue v = base;
        v.text = row.info.kind == ValueKind::Path ? "/tmp/trazo-rows/sub/file.png"
                 : row.info.choices.empty()       ? "someName"
                                                  : std::string(row.info.choices.back());
        for (int i = 0; i < row.info.count; ++i) v.numbers[size_t(i)] += step;
        EXPECT_TRUE(fitToCheck(row.info, v)) << row.info.name;
        if (v.numbers != base.numbers || row.info.kind == ValueKind::Name || row.info.kind == ValueKind::Path) return v;
    }
    ADD_FAILURE() << row.info.name << ": no other value";
    return base;
}

template <class Target>
std::vector<ParamValue> extracted(const ParamSpec<Target>& row, const Target& target) {
    std::vector<ParamValue> values;
    row.extract(target, values);
    return values;
}

// The written line of every value reads back (lexBlocks, readParameters) to the same extracted values.
template <class Target>
void expectReadsBack(const ParamSpec<Target>& row, const Target& written, std::span<const ParamSpec<Target>> table,
                     const char* what) {
    const std::string scenePath = "/tmp/trazo-rows/rows.scene";
    const std::vector<ParamValue> values = extracted(row, written);
    std::string text = "Block\n{\n";
    for (const ParamValue& v : values)
        text += "    " + std::string(row.info.name) + " " + formatValues(row.info, v, scenePath) + "\n";
    text += "}\n";
    Diagnostics diags;
    const std::vector<Block> blocks = lexBlocks(text, scenePath, diags);
    ASSERT_EQ(blocks.size(), 1u);
    Target back{};
    readParameters(blocks[0], table, back, diags);
    for (const Diagnostic& d : diags.items) {
        // Another row's requirement is not this row's business.
        if (d.message.rfind("missing required", 0) != 0) ADD_FAILURE() << row.info.name << ": " << formatDiagnostic(d);
    }
    const std::vector<ParamValue> again = extracted(row, back);
    ASSERT_EQ(again.size(), values.size()) << row.info.name << " (" << what << ")\n" << text;
    for (size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(again[i].numbers, values[i].numbers) << row.info.name << " (" << what << ")\n" << text;
        const std::string expected = row.info.kind == ValueKind::Path ? resolveRelativePath(scenePath, again[i].text)
                                                                       : again[i].text;
        EXPECT_EQ(expected, values[i].text) << row.info.name << " (" << what << ")";
    }
}

template <class Target>
void expectEveryRowReadsBack(std::span<const ParamSpec<Target>> table) {
    for (const ParamSpec<Target>& row : table) {
        const Target defaults{};
        std::vector<ParamValue> base = extracted(row, defaults);
        if (!row.info.required && !row.info.accumulates) {
            EXPECT_EQ(base.size(), row.info.defaultText.empty() ? 0u : 1u) << row.info.name;
        }
        if (!row.info.required) expectReadsBack(row, defaults, table, "default");  // required: no default
        // Non-default: one changed value, or for an accumulating row two steps.
        Target changed{};
        const ParamValue seed = base.empty() ? ParamValue{} : base[0];
        ParamValue v = otherValue(row, seed);
        if (row.info.kind == ValueKind::Real && row.info.count >= 3 && base.empty()) {
            v.numbers = {0.5, -2, 1e-7, 0.25};  // a transform: no zero component, a non-zero axis
        }
        row.apply(changed, v);
        if (row.info.accumulates) {
            v.numbers[0] = 7;
            row.apply(changed, v);
        }
        const std::vector<ParamValue> now = extracted(row, changed);
        ASSERT_FALSE(now.empty()) << row.info.name;
        if (!base.empty()) {
            EXPECT_FALSE(now[0].numbers == base[0].numbers && now[0].text == base[0].text) << row.info.name;
        }
        expectReadsBack(row, changed, table, "changed");
    }
}

TEST(BlockTable, EveryRowWritesWhatItReadsBack) {
    expectEveryRowReadsBack(sceneSettingsTable());
    expectEveryRowReadsBack(cameraTable());
    expectEveryRowReadsBack(textureTable());
    expectEveryRowReadsBack(materialTable());
#define TRAZO_X(Shape, array, Kind, keyword) expectEveryRowReadsBack(objectTable<Kind>());
    TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, Kind, ...) expectEveryRowReadsBack(lightTable<Kind>());
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    expectEveryRowReadsBack(csgSphereTable());
    expectEveryRowReadsBack(csgBoxTable());
    expectEveryRowReadsBack(csgCylinderTable());
    expectEveryRowReadsBack(csgOperationTable());
}

TEST(BlockTable, DefaultTextsComeFromTheStructInitialisers) {
    // A few read by eye from scene.h: the tables hold no default of their own.
    auto find = [](std::string_view block, std::string_view name) {
        for (const BlockInfo& b : sceneBlocks())
            for (const ParamInfo& p : b.params)
                if (b.name == block && p.name == name) return p.defaultText;
        return std::string("absent");
    };
    EXPECT_EQ(find("AreaLight", "Subdivision"), "5 5");
    EXPECT_EQ(find("Material", "DiffuseColor"), "0.899999976 0.899999976 0.899999976");
    EXPECT_EQ(find("Camera", "POV"), "0 0 10");
    EXPECT_EQ(find("Texture", "Source"), "—");
    EXPECT_EQ(find("Box", "Rotation"), "");
    EXPECT_EQ(find("Sphere", "Material"), "");
}

TEST(BlockTable, ShapeAndTransformRowsAreSharedWithCsgNodes) {
    auto names = [](const auto& table) {
        std::vector<std::string_view> n;
        for (const auto& row : table) n.push_back(row.info.name);
        return n;
    };
    auto without = [](std::vector<std::string_view> n, std::string_view drop) {
        n.erase(std::remove(n.begin(), n.end(), drop), n.end());
        return n;
    };
    const std::vector<std::string_view> transforms = {"Translation", "Rotation", "Scale"};
    std::vector<std::string_view> sphere = without(names(objectTable<Sphere>()), "Material");
    sphere.insert(sphere.end(), transforms.begin(), transforms.end());
    EXPECT_EQ(names(csgSphereTable()), sphere);
    std::vector<std::string_view> cylinder = without(names(objectTable<Cylinder>()), "Material");
    cylinder.insert(cylinder.end(), transforms.begin(), transforms.end());
    EXPECT_EQ(names(csgCylinderTable()), cylinder);
    EXPECT_EQ(names(csgBoxTable()), without(names(objectTable<Box>()), "Material"));
}

}  // namespace
}  // namespace trazo
