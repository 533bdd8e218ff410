// Tests of the CSG reader: SPEC §4 references, the seed's example, and every tree error with its line.
#include "scene/csg_reader.h"

#include <gtest/gtest.h>

#include "test_paths.h"
#include "test_scenes.h"

namespace trazo {
namespace {

using Kind = CsgNode::Kind;

std::string errorsOf(const Diagnostics& d) { return test::listedDiagnostics(d, true); }

TEST(CsgReader, SeedExampleBuildsTheThesisTree) {
    Diagnostics diags;
    const auto tree = readCsgFile(test::sourcePath("scenes/csg_example.csg"), diags);
    ASSERT_TRUE(tree) << errorsOf(diags);
    EXPECT_TRUE(diags.items.empty());
    ASSERT_EQ(tree->nodes.size(), 9u);  // Box, Sphere, 3 Cylinders, Intersection, 2 Unions, Difference
    // (Box ∩ Sphere) − ((CylX ∪ CylY) ∪ CylZ); nodes keep file order.
    const CsgNode& root = tree->nodes[size_t(tree->root)];
    EXPECT_EQ(tree->root, 8);
    EXPECT_EQ(root.kind, Kind::Difference);
    EXPECT_EQ(root.left, 5);
    EXPECT_EQ(root.right, 7);
    EXPECT_EQ(tree->nodes[5].kind, Kind::Intersection);
    EXPECT_EQ(tree->nodes[5].left, 0);   // Box 0
    EXPECT_EQ(tree->nodes[5].right, 1);  // Sphere 0
    EXPECT_EQ(tree->nodes[6].left, 2);   // Cylinder 0
    EXPECT_EQ(tree->nodes[6].right, 3);  // Cylinder 1
    EXPECT_EQ(tree->nodes[7].left, 6);   // Union 0
    EXPECT_EQ(tree->nodes[7].right, 4);  // Cylinder 2
    EXPECT_EQ(tree->nodes[1].radius, 1.35f);
    EXPECT_EQ(tree->nodes[1].center.y, 1.0f);
    EXPECT_EQ(tree->nodes[4].axis.z, 1.0f);
    EXPECT_EQ(tree->nodes[4].height, 10.0f);
    ASSERT_EQ(tree->nodes[0].transforms.size(), 2u);
    EXPECT_EQ(tree->nodes[0].transforms[0].kind, TransformStep::Kind::Scale);
    EXPECT_EQ(tree->nodes[0].transforms[1].kind, TransformStep::Kind::Translation);
    EXPECT_EQ(tree->nodes[0].where.line, 12);
}

TEST(CsgReader, OperationTypeCountsAllOperations) {
    Diagnostics diags;
    const auto tree = readCsgText(
        "Sphere {\n}\nBox {\n}\nCylinder {\n}\n"
        "Intersection {\n LeftType Sphere\n LeftIndex 0\n RightType Box\n RightIndex 0\n}\n"
        "Union {\n LeftType Operation\n LeftIndex 0\n RightType Cylinder\n RightIndex 0\n Translation 0 1 0\n}\n",
        "op.csg", diags);
    ASSERT_TRUE(tree) << errorsOf(diags);
    EXPECT_EQ(tree->root, 4);
    EXPECT_EQ(tree->nodes[4].left, 3);
    ASSERT_EQ(tree->nodes[4].transforms.size(), 1u);
    EXPECT_EQ(tree->nodes[4].transforms[0].value.y, 1.0f);
}

TEST(CsgReader, PrimitivesTakeTransformsAndIgnoreMaterial) {
    Diagnostics diags;
    const auto tree = readCsgText("Sphere\n{\n Material matWhite\n Scale 1 2 1\n Rotation 0 0 1 0.5\n}\n", "e.csg", diags);
    ASSERT_TRUE(tree) << errorsOf(diags);
    EXPECT_EQ(tree->root, 0);
    ASSERT_EQ(tree->nodes[0].transforms.size(), 2u);
    EXPECT_EQ(tree->nodes[0].transforms[1].kind, TransformStep::Kind::Rotation);
    EXPECT_EQ(tree->nodes[0].transforms[1].angle, 0.5f);
    ASSERT_EQ(diags.items.size(), 1u);
    EXPECT_EQ(formatDiagnostic(diags.items[0]),
              "e.csg:3: warning: Material is ignored in a CSG file (the scene's CSG block gives the material)");
}

struct BadCsg {
    const char* name;
    std::string text;
    std::string expected;  // one of the errors, formatted
};

class CsgReaderError : public ::testing::TestWithParam<BadCsg> {};

TEST_P(CsgReaderError, ReportsTheCsgLine) {
    Diagnostics diags;
    EXPECT_FALSE(readCsgText(GetParam().text, "t.csg", diags));
    EXPECT_NE(errorsOf(diags).find(GetParam().expected + "\n"), std::string::npos) << errorsOf(diags);
}

const std::string kTwoSpheres = "Sphere {\n}\nSphere {\n}\n";  // lines 1-4

std::string operation(const char* kind, const char* lt, int li, const char* rt, int ri) {
    return std::string(kind) + " {\n LeftType " + lt + "\n LeftIndex " + std::to_string(li) + "\n RightType " + rt +
           "\n RightIndex " + std::to_string(ri) + "\n}\n";
}

std::string manySpheres(int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += "Sphere {\n}\n";
    return s;
}

std::string chainOfUnions(int spheres) {
    // Union k joins Union k-1 (or Sphere 0) with Sphere k: a tree of 2·spheres − 1 nodes.
    std::string s = manySpheres(spheres);
    for (int k = 1; k < spheres; ++k) s += operation("Union", k == 1 ? "Sphere" : "Union", k == 1 ? 0 : k - 2, "Sphere", k);
    return s;
}

INSTANTIATE_TEST_SUITE_P(
    Errors, CsgReaderError,
    ::testing::Values(
        BadCsg{"UnknownType", kTwoSpheres + operation("Union", "Spere", 0, "Sphere", 1),
               "t.csg:6: error: unknown node type 'Spere' (did you mean 'Sphere'?)"},
        BadCsg{"MissingField", kTwoSpheres + "Union {\n LeftType Sphere\n LeftIndex 0\n RightType Sphere\n}\n",
               "t.csg:5: error: missing required parameter 'RightIndex' in Union"},
        BadCsg{"IndexOutOfRange", kTwoSpheres + operation("Union", "Sphere", 0, "Sphere", 2),
               "t.csg:9: error: RightIndex 2 is out of range (the file has 2 Sphere blocks)"},
        BadCsg{"OperationIndexOutOfRange", kTwoSpheres + operation("Union", "Operation", 1, "Sphere", 1),
               "t.csg:7: error: LeftIndex 1 is out of range (the file has 1 operation block)"},
        BadCsg{"NegativeIndex", kTwoSpheres + operation("Union", "Sphere", -1, "Sphere", 1),
               "t.csg:7:12: error: LeftIndex must not be negative, got -1"},
        BadCsg{"SelfReference", kTwoSpheres + operation("Union", "Union", 0, "Sphere", 1),
               "t.csg:7: error: cycle: Union 0 uses itself"},
        BadCsg{"Cycle",
               kTwoSpheres + operation("Union", "Union", 1, "Sphere", 0) + operation("Union", "Union", 0, "Sphere", 1),
               "t.csg:5: error: no root (every node is used by an operation); cycle: Union 0 contains itself"},
        BadCsg{"CycleBesideARoot",
               manySpheres(3) + operation("Union", "Union", 1, "Sphere", 0) + operation("Union", "Union", 0, "Sphere", 1),
               "t.csg:7: error: cycle: Union 0 contains itself"},
        BadCsg{"SeveralRoots", kTwoSpheres + "Box {\n}\n" + operation("Union", "Sphere", 0, "Sphere", 1),
               "t.csg:7: error: several roots: the nodes at lines 5 and 7 are used by no operation"},
        BadCsg{"SharedNode", kTwoSpheres + operation("Union", "Sphere", 0, "Sphere", 1) +
                                 operation("Intersection", "Sphere", 1, "Union", 0),
               "t.csg:13: error: Sphere 1 is already used by the operation at line 5 (a CSG file describes a "
               "tree; nodes cannot be shared)"},
        BadCsg{"UnknownBlock", "Spehre {\n}\n", "t.csg:1: error: unknown block 'Spehre' in a CSG file (did you mean 'Sphere'?)"},
        BadCsg{"BadRadius", "Sphere {\n Radius 0\n}\n", "t.csg:2:9: error: Radius must be positive, got 0"},
        BadCsg{"ZeroScale", "Box {\n Scale 1 0 1\n}\n",
               "t.csg:2:10: error: Scale component must not be zero (a singular transform)"},
        BadCsg{"Empty", "# nothing\n", "t.csg: error: CSG file has no nodes"},
        BadCsg{"TooManyNodes", chainOfUnions(33),
               // the 65th node is the 32nd Union: after 33 two-line spheres and 31 six-line unions
               "t.csg:" + std::to_string(2 * 33 + 6 * 31 + 1) +
                   ": error: too many CSG nodes: the file has 65, at most 64 are supported"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CsgReader, TheLargestTreeUnderTheLimitIsAccepted) {
    Diagnostics diags;
    // A binary tree has an odd number of nodes: 32 spheres + 31 unions = 63 is the largest within 64.
    const auto tree = readCsgText(chainOfUnions(32), "t.csg", diags);
    ASSERT_TRUE(tree) << errorsOf(diags);
    EXPECT_EQ(tree->nodes.size(), size_t(kMaxCsgNodes - 1));
    EXPECT_EQ(tree->root, 62);
}

TEST(CsgReader, UnreadableFileNamesPathAndReason) {
    Diagnostics diags;
    EXPECT_FALSE(readCsgFile("/nonexistent/trazo/t.csg", diags));
    EXPECT_EQ(errorsOf(diags), "/nonexistent/trazo/t.csg: error: cannot read CSG file: No such file or directory\n");
}

}  // namespace
}  // namespace trazo
