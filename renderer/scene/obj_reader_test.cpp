// Tests of the OBJ reader: attributes, fan triangulation, negative indices, and malformed lines with their lines.
#include "scene/obj_reader.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>

#include "test_paths.h"

namespace trazo {
namespace {

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

TEST(ObjReader, TriangleWithAllAttributes) {
    Diagnostics diags;
    const auto mesh = readObjFile(test::writeTempFile("full.obj",
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

TEST(ObjReader, PolygonsAreFanTriangulated) {
    Diagnostics diags;
    // A quad whose diagonal 1-3 is the shorter one: a "shorter diagonal" split would give (0,1,3),(1,2,3).
    const auto mesh = readObjText("v 0 0 0\nv 10 0 0\nv 10 1 0\nv 9 9 0\nv -1 5 0\n"
                                  "f 1 2 3 4\nf 1 2 3 4 5\n",
                                  "fan.obj", diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    const std::vector<Tri> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    EXPECT_EQ(positionTriangles(*mesh), expected);
}

TEST(ObjReader, NegativeIndicesCountBackFromTheCurrentLine) {
    Diagnostics diags;
    const auto mesh = readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -1 -2\n", "neg.obj", diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    const std::vector<Tri> expected = {{0, 1, 2}, {0, 3, 2}};
    EXPECT_EQ(positionTriangles(*mesh), expected);
}

TEST(ObjReader, MissingNormalsAndUvs) {
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
    for (const MeshData::Corner c : partial->corners) EXPECT_EQ(c.normal, -1);
    EXPECT_FALSE(diags.hasErrors());

    // An attribute no corner keeps takes no memory: 4 bytes a corner for positions only, 12 with both.
    EXPECT_EQ(plain->corners.heapBytes(), 4 * plain->corners.size());
    EXPECT_EQ(partial->corners.heapBytes(), 4 * partial->corners.size());
    const auto both =
        readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nf 1/1/1 2/1/1 3/1/1\n", "both.obj", diags);
    ASSERT_TRUE(both);
    EXPECT_EQ(both->corners.heapBytes(), 12 * both->corners.size());
}

// MeshCorners keeps a column per attribute, made at the first corner that has one: whatever the order of
// pushes, sets, pops and drops, it reads as the list of corners stored one by one would.
TEST(MeshCorners, ReadsAsTheListOfItsCorners) {
    MeshCorners corners;
    std::vector<MeshData::Corner> model;
    auto expectSame = [&](int step) {
        ASSERT_EQ(corners.size(), model.size()) << "step " << step;
        for (size_t i = 0; i < model.size(); ++i) {
            const MeshData::Corner c = corners[i];
            EXPECT_EQ(c.position, model[i].position) << "step " << step << ", corner " << i;
            EXPECT_EQ(c.normal, model[i].normal) << "step " << step << ", corner " << i;
            EXPECT_EQ(c.uv, model[i].uv) << "step " << step << ", corner " << i;
            EXPECT_EQ(corners.normal(i), model[i].normal);
            EXPECT_EQ(corners.uv(i), model[i].uv);
        }
    };
    uint32_t state = 12345;
    auto next = [&](uint32_t n) {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) % n;
    };
    auto randomIndex = [&] { return next(2) ? -1 : (int32_t)next(100); };  // absent half the time
    auto randomCorner = [&] { return MeshData::Corner{(int32_t)next(100), randomIndex(), randomIndex()}; };
    for (int step = 0; step < 400; ++step) {
        const uint32_t op = next(20);
        if (op < 12 || model.empty()) {
            const MeshData::Corner c = op % 3 == 0 ? MeshData::Corner{(int32_t)next(100), -1, -1} : randomCorner();
            corners.push_back(c);
            model.push_back(c);
        } else if (op < 16) {
            const size_t i = next((uint32_t)model.size());
            const MeshData::Corner c = randomCorner();
            corners.set(i, c);
            model[i] = c;
        } else if (op < 18) {
            corners.pop_back();
            model.pop_back();
        } else if (op == 18) {
            corners.dropNormals();
            for (MeshData::Corner& c : model) c.normal = -1;
        } else {
            corners.dropUvs();
            for (MeshData::Corner& c : model) c.uv = -1;
        }
        expectSame(step);
    }
    corners.assign(5, {3, -1, 4});
    model.assign(5, {3, -1, 4});
    expectSame(-1);
    corners = {{1, 2, -1}, {0, -1, -1}};
    model = {{1, 2, -1}, {0, -1, -1}};
    expectSame(-2);
    corners.clear();
    EXPECT_TRUE(corners.empty());
}

TEST(ObjReader, ForwardReferencesAreAllowed) {
    Diagnostics diags;
    const auto mesh = readObjText("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "fwd.obj", diags);
    ASSERT_TRUE(mesh) << firstError(diags);
    EXPECT_EQ(mesh->corners.size(), 3u);
}

struct BadObj {
    const char* text;
    const char* expected;  // the first error, formatted
};

class ObjReaderError : public ::testing::TestWithParam<BadObj> {};

TEST_P(ObjReaderError, ReportsTheObjLine) {
    Diagnostics diags;
    EXPECT_FALSE(readObjText(GetParam().text, "bad.obj", diags));
    EXPECT_EQ(firstError(diags), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, ObjReaderError,
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
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "bad.obj: error: OBJ file has no faces"},
        BadObj{"", "bad.obj: error: OBJ file has no faces (the file is empty)"},
        BadObj{"hello\nworld\n", "bad.obj: error: OBJ file has no faces (nor any vertex: is it an OBJ file?)"}));

// Indices that do not fit what atoi (tinyobjloader) reads are refused as written, before tinyobjloader
// wraps them (4294967297 would read as 1); -9223372036854775808 is never negated.
INSTANTIATE_TEST_SUITE_P(
    HugeIndices, ObjReaderError,
    ::testing::Values(
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n",
               "bad.obj:4:7: error: vertex index -9223372036854775808 is out of range (an OBJ file holds at most "
               "67108864)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9223372036854775807\n",
               "bad.obj:4:7: error: vertex index 9223372036854775807 is out of range (an OBJ file holds at most "
               "67108864)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999999\n",
               "bad.obj:4:7: error: vertex index 99999999999999999999999999 is out of range (an OBJ file holds at "
               "most 67108864)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n",
               "bad.obj:4:7: error: vertex index 4294967297 is out of range (an OBJ file holds at most 67108864)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n",
               "bad.obj:4:7: error: vertex index 2147483648 is out of range (an OBJ file holds at most 67108864)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//-2147483649\n",
               "bad.obj:5:13: error: normal index -2147483649 is out of range (an OBJ file holds at most 67108864)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/67108865\n",
               "bad.obj:5:11: error: texture coordinate index 67108865 is out of range (an OBJ file holds at most "
               "67108864)"},
        // Within the limit but past the file: judged on what tinyobjloader read.
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 67108864\n",
               "bad.obj:4:7: error: vertex index 67108864 is out of range (the file has 3)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -2147483648\n",
               "bad.obj:4:7: error: vertex index -2147483648 is out of range (an OBJ file holds at most 67108864)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -67108864\n",
               "bad.obj:4:7: error: vertex index -67108864 is out of range (only 3 before this line)"}));

// Normal and uv indices are judged like positions, on every corner, whether or not the attribute is kept
// (one given on some faces only is dropped, but an index out of range is still an error).
INSTANTIATE_TEST_SUITE_P(
    AttributeIndices, ObjReaderError,
    ::testing::Values(
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n",
               "bad.obj:5:8: error: normal index 2 is out of range (the file has 1)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//-2 2//1 3//1\n",
               "bad.obj:5:3: error: normal index -2 is out of range (only 1 before this line)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n",
               "bad.obj:4:3: error: normal index 1 is out of range (the file has 0)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf 1/-3 2/1 3/2\n",
               "bad.obj:6:3: error: texture coordinate index -3 is out of range (only 2 before this line)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//9 2//1 3//1\nf 1 2 3\n",
               "bad.obj:5:3: error: normal index 9 is out of range (the file has 1)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\nf 1/1 2/5 3/1\n",
               "bad.obj:6:7: error: texture coordinate index 5 is out of range (the file has 1)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4 5\n",
               "bad.obj:4:9: error: vertex index 4 is out of range (the file has 3)"}));

// Lines, words and bytes that a hostile file may hold: each a located error, never a crash.
INSTANTIATE_TEST_SUITE_P(
    HostileBytes, ObjReaderError,
    ::testing::Values(
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 # note\n",
               "bad.obj:4: error: malformed face: tinyobjloader reads text after its vertices (such as a # comment) "
               "as vertex index 0"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 +-3\n", "bad.obj:4:7: error: malformed face vertex '+-3'"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/\n", "bad.obj:4:7: error: malformed face vertex '3/'"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -\n", "bad.obj:4:7: error: malformed face vertex '-'"},
        BadObj{"v 0 0 0\nv 1 0 0\nv +-1 1 0\nf 1 2 3\n", "bad.obj:3:3: error: '+-1' is not a finite number"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 \x01\xff\nf 1 2 3\n", "bad.obj:3:7: error: '?\?' is not a finite number"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1e39\nf 1//1 2//1 3//1\n",
               "bad.obj:4:8: error: '1e39' is not a finite number"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 inf\nf 1/1 2/1 3/1\n",
               "bad.obj:4:6: error: 'inf' is not a finite number"}));

TEST(ObjReader, NulBytesNeverCutAMessage) {
    Diagnostics diags;
    const char raw[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\0\nf 1 2 3\n";
    const std::string text(raw, sizeof raw - 1);
    EXPECT_FALSE(readObjText(text, "nul.obj", diags));
    EXPECT_EQ(firstError(diags), "nul.obj:3:7: error: '0?' is not a finite number");
}

TEST(ObjReader, OverlongLinesAreRefusedBeforeTheyAreParsed) {
    Diagnostics diags;
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf" + std::string(kMaxObjLineBytes, ' ') + "1 2 3\n";
    EXPECT_FALSE(readObjText(text, "long.obj", diags));
    EXPECT_EQ(firstError(diags), "long.obj:4: error: line of " + std::to_string(kMaxObjLineBytes + 6) +
                                     " bytes; the OBJ reader takes lines of at most " +
                                     std::to_string(kMaxObjLineBytes));
    // A long \n line cut short by lone \r breaks is as many lines for tinyobjloader: accepted.
    std::string manyLines = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    while (manyLines.size() <= kMaxObjLineBytes + 100) manyLines += "f 1 2 3\r";
    Diagnostics fine;
    EXPECT_TRUE(readObjText(manyLines, "cr.obj", fine)) << firstError(fine);
}

// Every mesh the reader returns keeps the contract of obj_reader.h.
TEST(ObjReader, AcceptedMeshesKeepTheContract) {
    for (const char* text : {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 2\n",
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf -3 -2 -1\n",
                             "f 1/1/1 2/1/1 3/1/1 4/1/1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\n",
                             "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n"}) {
        Diagnostics diags;
        const auto mesh = readObjText(text, "ok.obj", diags);
        ASSERT_TRUE(mesh) << text << firstError(diags);
        EXPECT_EQ(objMeshContractViolation(*mesh), "") << text;
    }
}

// The contract check itself, on meshes made by hand.
TEST(ObjMeshContract, NamesTheFirstViolation) {
    MeshData good;
    good.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    good.corners = {{0, -1, -1}, {1, -1, -1}, {2, -1, -1}};
    EXPECT_EQ(objMeshContractViolation(good), "");

    MeshData m = good;
    m.corners.set(1, {3, -1, -1});
    EXPECT_EQ(objMeshContractViolation(m), "corner 1: vertex index 3 is out of range (the mesh has 3)");
    m = good;
    m.corners.set(2, {-1, -1, -1});
    EXPECT_EQ(objMeshContractViolation(m), "corner 2: vertex index -1 is out of range (the mesh has 3)");
    m = good;
    m.normals = {Vec3(0, 0, 1)};
    m.corners.set(0, {0, 0, -1});  // a normal on one corner, the mesh flagged as without
    EXPECT_EQ(objMeshContractViolation(m),
              "corner 0: normal index 0 given, but the mesh is flagged as without normals");
    m.hasNormals = true;  // flagged, but corners 1 and 2 have none
    EXPECT_EQ(objMeshContractViolation(m), "corner 1: normal index -1 is out of range (the mesh has 1)");
    m = good;
    m.hasUvs = true;
    m.uvs = {0, 0};
    for (size_t i = 0; i < m.corners.size(); ++i) m.corners.set(i, {m.corners.position(i), -1, 1});
    EXPECT_EQ(objMeshContractViolation(m), "corner 0: texture coordinate index 1 is out of range (the mesh has 1)");
    m = good;
    m.positions[1].y = std::numeric_limits<float>::infinity();
    EXPECT_EQ(objMeshContractViolation(m), "vertex 1 is not finite");
    m = good;
    m.uvs = {0, 0, 1};
    EXPECT_NE(objMeshContractViolation(m), "");
    m = good;
    m.corners.pop_back();
    EXPECT_NE(objMeshContractViolation(m), "");
    m = good;
    m.corners.clear();
    EXPECT_EQ(objMeshContractViolation(m), "no faces");
}

TEST(ObjReader, UnreadableFileNamesPathAndReason) {
    Diagnostics diags;
    EXPECT_FALSE(readObjFile("/nonexistent/trazo/x.obj", diags));
    EXPECT_EQ(firstError(diags), "/nonexistent/trazo/x.obj: error: cannot read OBJ file: No such file or directory");
}

// tinyobjloader also breaks lines at a lone \r: a face or vertex behind one is read and checked like any other
// (once it reached the mesh with an index past what was read, as index 8 of 3 positions), and reported at
// its line as the reader counts them.
TEST(ObjReader, FacesBehindALoneCarriageReturnAreRangeChecked) {
    const char* const kHint = " (lines counted as OBJ readers count them: a lone \\r also ends a line)";
    const std::pair<const char*, std::string> cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nx\rf 1 2 9\n",
         "cr.obj:6:7: error: vertex index 9 is out of range (the file has 3)" + std::string(kHint)},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# comment\rf 1 2 -5\n",
         "cr.obj:6:7: error: vertex index -5 is out of range (only 3 before this line)" + std::string(kHint)},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\ng part\rf 1//1 2//1 3//7\n",
         "cr.obj:7:13: error: normal index 7 is out of range (the file has 1)" + std::string(kHint)},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n# c\rf 1/1 2/1 3/4\n",
         "cr.obj:7:11: error: texture coordinate index 4 is out of range (the file has 1)" + std::string(kHint)},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ng a\rv 1e39 0 0\n",
         "cr.obj:6:3: error: '1e39' is not a finite number" + std::string(kHint)},
        {"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\rf 1 2 4\r",  // a classic Mac file: every line ends at \r
         "cr.obj:5:7: error: vertex index 4 is out of range (the file has 3)" + std::string(kHint)},
    };
    for (const auto& [text, expected] : cases) {
        Diagnostics diags;
        EXPECT_FALSE(readObjText(text, "cr.obj", diags)) << text;
        EXPECT_EQ(firstError(diags), expected);
    }
}

// tinyobjloader reads text after a face's vertices (a comment) as a vertex index 0: reported at its line.
TEST(ObjReader, CommentAfterAFaceIsReportedAtItsLine) {
    Diagnostics diags;
    EXPECT_FALSE(readObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3 # note\n", "c.obj", diags));
    EXPECT_EQ(firstError(diags).rfind("c.obj:5: error: malformed face", 0), 0u) << firstError(diags);
}

// A text of a megabyte or more is checked and parsed on two threads: the same mesh, the same first error.
TEST(ObjReader, LargeTextsReadAsSmallOnes) {
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

    // A face in the last third, behind a lone \r, reaching before the file's start: found at the join.
    const int lines = (n + 1) * (n + 1) + 2 * n * n;
    Diagnostics hidden;
    EXPECT_FALSE(readObjText(grid + "# x\rf 1 2 -" + std::to_string((n + 1) * (n + 1) + 1) + "\n", "grid.obj", hidden));
    EXPECT_EQ(firstError(hidden).rfind("grid.obj:" + std::to_string(lines + 2) + ":7: error: vertex index -" +
                                           std::to_string((n + 1) * (n + 1) + 1) + " is out of range (only " +
                                           std::to_string((n + 1) * (n + 1)) + " before this line)",
                                       0),
              0u)
        << firstError(hidden);

    Diagnostics bad;
    EXPECT_FALSE(readObjText(grid + "v 1 oops 2\n", "grid.obj", bad));
    EXPECT_EQ(firstError(bad), "grid.obj:" + std::to_string((n + 1) * (n + 1) + 2 * n * n + 1) +
                                   ":5: error: 'oops' is not a finite number");
}

TEST(ObjReader, ManyErrorsAreCapped) {
    std::string text;
    for (int i = 0; i < 100; ++i) text += "v a b c\n";
    Diagnostics diags;
    EXPECT_FALSE(readObjText(text, "many.obj", diags));
    EXPECT_EQ(diags.items.size(), 21u);  // 20 errors, then one saying the rest is not checked
}

// The reproducers through the command line: the render exits with status 2 naming the OBJ file's line,
// writes no image, and never crashes (run under ASan + UBSan too).
TEST(ObjReaderCli, HostileMeshesStopTheRenderWithTheirLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# c\rf 1 2 9\n", "m.obj:6:7: error: vertex index 9"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\ng g\rf 1//1 2//1 3//7\n",
         "m.obj:7:13: error: normal index 7"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n",
         "m.obj:4:7: error: vertex index -9223372036854775808"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n", "m.obj:4:7: error: vertex index 4294967297"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n", "m.obj:5:11: error: texture coordinate index 2"},
    };
    const std::string dir = test::tempPath("obj_cli");
    std::filesystem::create_directories(dir);
    const std::string scene = dir + "/s.scene", image = dir + "/out.png", errors = dir + "/stderr.txt";
    std::ofstream(scene) << "SceneSettings\n{\n RenderWidth 8\n RenderHeight 8\n}\nCamera\n{\n POV 0 0 5\n}\n"
                            "PointLight\n{\n Position 0 5 5\n}\nMesh\n{\n Source \"m.obj\"\n}\n";
    for (const auto& [obj, expected] : cases) {
        std::ofstream(dir + "/m.obj", std::ios::binary) << obj;
        std::filesystem::remove(image);
        const std::string command = test::trazoBinary() + " --render " + scene + " -o " + image +
                                    " --quiet --spp 1 --backend cpu 2>" + errors + " >/dev/null";
        const int raw = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(raw)) << obj;
        EXPECT_EQ(WEXITSTATUS(raw), 2) << obj;
        const std::string stderrText = test::readFileText(errors);
        EXPECT_NE(stderrText.find(dir + "/" + expected), std::string::npos) << stderrText;
        EXPECT_FALSE(std::filesystem::exists(image)) << obj;
    }
}

}  // namespace
}  // namespace trazo
