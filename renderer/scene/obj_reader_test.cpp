// Tests of the OBJ reader: attributes, fan triangulation, negative indices, and malformed lines with their lines.
#include "scene/obj_reader.h"

#include <gtest/gtest.h>

#include <fstream>

#include "test_paths.h"

namespace trazo {
namespace {

std::string writeObj(const std::string& name, const std::string& text) {
    const std::string path = test::tempPath(name);
    std::ofstream(path) << text;
    return path;
}

std::string firstError(const Diagnostics& d) {
    for (const Diagnostic& x : d.items)
        if (x.severity == Severity::Error) return formatDiagnostic(x);
    return "(no error)";
}

using Tri = std::array<int, 3>;
std::vector<Tri> positionTriangles(const MeshData& m) {
    std::vector<Tri> t;
    for (size_t i = 0; i + 2 < m.corners.size(); i += 3)
        t.push_back({m.corners[i].position, m.corners[i + 1].position, m.corners[i + 2].position});
    return t;
}

TEST(ObjReaderTest, TriangleWithAllAttributes) {
    Diagnostics diags;
    const auto mesh = readObjFile(writeObj("full.obj",
                                           "# a triangle\n"
                                           "o thing\ng group\ns 1\nmtllib missing.mtl\nusemtl nothing\n"
                                           "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                           "vt 0 0\nvt 1 0\nvt 0 1 0\n"
                                           "vn 0 0 1\n"
                                           "f 1/1/1 2/2/1 3/3/1\n"),
                                  diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    EXPECT_FALSE(diags.hasErrors());
    ASSERT_EQ(mesh->positions.size(), 3u);
    EXPECT_EQ(mesh->positions[1].x, 1.0f);
    EXPECT_EQ(mesh->positions[2].y, 1.0f);
    ASSERT_EQ(mesh->normals.size(), 1u);
    EXPECT_EQ(mesh->normals[0].z, 1.0f);
    ASSERT_EQ(mesh->uvs.size(), 6u);
    EXPECT_EQ(mesh->uvs[2], 1.0f);
    EXPECT_EQ(mesh->uvs[5], 1.0f);
    ASSERT_EQ(mesh->corners.size(), 3u);
    EXPECT_EQ(mesh->corners[1].position, 1);
    EXPECT_EQ(mesh->corners[1].uv, 1);
    EXPECT_EQ(mesh->corners[1].normal, 0);
    EXPECT_TRUE(mesh->hasNormals);
    EXPECT_TRUE(mesh->hasUvs);
}

TEST(ObjReaderTest, PolygonsAreFanTriangulated) {
    Diagnostics diags;
    // A quad whose diagonal 1-3 is the shorter one: a "shorter diagonal" split would give (0,1,3),(1,2,3).
    const auto mesh = readObjText("v 0 0 0\nv 10 0 0\nv 10 1 0\nv 9 9 0\nv -1 5 0\n"
                                  "f 1 2 3 4\nf 1 2 3 4 5\n",
                                  "fan.obj", diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    const std::vector<Tri> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    EXPECT_EQ(positionTriangles(*mesh), expected);
}

TEST(ObjReaderTest, NegativeIndicesCountBackFromTheCurrentLine) {
    Diagnostics diags;
    const auto mesh = readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -1 -2\n", "neg.obj", diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    const std::vector<Tri> expected = {{0, 1, 2}, {0, 3, 2}};
    EXPECT_EQ(positionTriangles(*mesh), expected);
}

TEST(ObjReaderTest, MissingNormalsAndUvs) {
    Diagnostics diags;
    const auto plain = readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "plain.obj", diags);
    ASSERT_TRUE(plain);
    EXPECT_FALSE(plain->hasNormals);
    EXPECT_FALSE(plain->hasUvs);
    EXPECT_EQ(plain->corners[0].normal, -1);
    EXPECT_EQ(plain->corners[0].uv, -1);

    const auto normalsOnly = readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n", "n.obj", diags);
    ASSERT_TRUE(normalsOnly);
    EXPECT_TRUE(normalsOnly->hasNormals);
    EXPECT_FALSE(normalsOnly->hasUvs);

    // Normals on one face only count as missing: every corner's normal index becomes -1.
    const auto partial =
        readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 2\n", "p.obj", diags);
    ASSERT_TRUE(partial);
    EXPECT_FALSE(partial->hasNormals);
    for (const auto& c : partial->corners) EXPECT_EQ(c.normal, -1);
    EXPECT_FALSE(diags.hasErrors());
}

TEST(ObjReaderTest, ForwardReferencesAreAllowed) {
    Diagnostics diags;
    const auto mesh = readObjText("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "fwd.obj", diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    EXPECT_EQ(mesh->corners.size(), 3u);
}

struct BadObj {
    const char* text;
    const char* expected;  // the first error, formatted
};

class ObjReaderErrorTest : public ::testing::TestWithParam<BadObj> {};

TEST_P(ObjReaderErrorTest, ReportsTheObjLine) {
    Diagnostics diags;
    EXPECT_FALSE(readObjText(GetParam().text, "bad.obj", diags));
    EXPECT_EQ(firstError(diags), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, ObjReaderErrorTest,
    ::testing::Values(
        BadObj{"v 0 0 0\nv 1 0 0\nv 1 abc 0\nf 1 2 3\n", "bad.obj:3:5: error: 'abc' is not a finite number"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 1 nan 0\nf 1 2 3\n", "bad.obj:3:5: error: 'nan' is not a finite number"},
        BadObj{"v 0 0\n", "bad.obj:1: error: a vertex takes 3 to 7 numbers, got 2"},
        BadObj{"vn 0 1\n", "bad.obj:1: error: a normal takes 3 numbers, got 2"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\n\n# comment\nf 1 2 9\n",
               "bad.obj:6:7: error: vertex index 9 is out of range (the file has 3)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n",
               "bad.obj:4:7: error: vertex index -4 is out of range (only 3 before this line)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
               "bad.obj:4:3: error: vertex index 0 in '0' (OBJ indices start at 1)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n",
               "bad.obj:5:7: error: texture coordinate index 2 is out of range (the file has 1)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//4 2//1 3//1\nvn 0 0 1\n",
               "bad.obj:4:3: error: normal index 4 is out of range (the file has 1)"},
        BadObj{"v 0 0 0\nv 1 0 0\nf 1 2\n", "bad.obj:3: error: a face needs at least 3 vertices, got 2"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x3\n", "bad.obj:4:7: error: malformed face vertex 'x3'"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "bad.obj:4:3: error: malformed face vertex '1/1/1/1'"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "bad.obj: error: OBJ file has no faces"}));

TEST(ObjReaderTest, UnreadableFileNamesPathAndReason) {
    Diagnostics diags;
    EXPECT_FALSE(readObjFile("/nonexistent/trazo/x.obj", diags));
    EXPECT_EQ(firstError(diags), "/nonexistent/trazo/x.obj: error: cannot read OBJ file: No such file or directory");
}

// tinyobjloader also breaks lines at a lone \r, which the line check does not: a face hidden behind one
// must not reach the mesh with an index past what was read (it once did, as index 8 of 3 positions).
TEST(ObjReaderTest, FacesBehindALoneCarriageReturnAreRangeChecked) {
    for (const char* text : {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nx\rf 1 2 9\n",
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nx\rf 1 2 -5\n"}) {
        Diagnostics diags;
        EXPECT_FALSE(readObjText(text, "cr.obj", diags)) << text;
        EXPECT_TRUE(diags.hasErrors());
    }
}

// tinyobjloader reads text after a face's vertices (a comment) as a vertex index 0: reported at its line.
TEST(ObjReaderTest, CommentAfterAFaceIsReportedAtItsLine) {
    Diagnostics diags;
    EXPECT_FALSE(readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3 # note\n", "c.obj", diags));
    EXPECT_EQ(firstError(diags).rfind("c.obj:5: error: malformed face", 0), 0u) << firstError(diags);
}

// A text of a megabyte or more is checked and parsed on two threads: the same mesh, the same first error.
TEST(ObjReaderTest, LargeTextsReadAsSmallOnes) {
    std::string grid;
    const int n = 300;  // (n + 1)² vertices, 2n² triangles: about 2.5 MB
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) grid += "v " + std::to_string(i) + " " + std::to_string(j) + " 0.5\n";
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = i * (n + 1) + j + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
            grid += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\nf -1 -" +
                    std::to_string(n + 2) + " " + std::to_string(d) + "\n";
        }
    ASSERT_GE(grid.size(), 1u << 20);
    Diagnostics diags;
    const auto mesh = readObjText(grid, "grid.obj", diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    ASSERT_EQ(mesh->positions.size(), size_t((n + 1) * (n + 1)));
    ASSERT_EQ(mesh->corners.size(), size_t(6 * n * n));
    EXPECT_EQ(mesh->positions.back().x, float(n));
    const size_t last = mesh->corners.size() - 3;  // the last face: f -1 -(n+2) d, with -1 the last vertex
    EXPECT_EQ(mesh->corners[last].position, (n + 1) * (n + 1) - 1);
    EXPECT_EQ(mesh->corners[last + 1].position, (n + 1) * (n + 1) - n - 2);

    Diagnostics bad;
    EXPECT_FALSE(readObjText(grid + "v 1 oops 2\n", "grid.obj", bad));
    EXPECT_EQ(firstError(bad), "grid.obj:" + std::to_string((n + 1) * (n + 1) + 2 * n * n + 1) +
                                   ":5: error: 'oops' is not a finite number");
}

TEST(ObjReaderTest, ManyErrorsAreCapped) {
    std::string text;
    for (int i = 0; i < 100; ++i) text += "v a b c\n";
    Diagnostics diags;
    EXPECT_FALSE(readObjText(text, "many.obj", diags));
    EXPECT_EQ(diags.items.size(), 21u);  // 20 errors, then one saying the rest is not checked
}

}  // namespace
}  // namespace trazo
