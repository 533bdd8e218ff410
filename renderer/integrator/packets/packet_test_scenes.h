// Test helper (host): random scenes of spheres, boxes, cylinders, meshes and CSG solids, and points on their
// surfaces, for the packet traversals' tests (occluded_packet_test.cpp, nearest_packet_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "flatten/flatten.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

namespace trazo {
namespace test {

struct RandomScene {
    SceneArrays arrays;
    SceneView view;
};

// A random triangle soup in the unit cube, as an OBJ file.
inline std::string soupObj(std::mt19937& rng, int index) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const std::string path = test::tempPath("soup" + std::to_string(index) + ".obj");
    std::ofstream out(path);
    const int triangles = 12;
    for (int i = 0; i < 3 * triangles; ++i) out << "v " << u(rng) << " " << u(rng) << " " << u(rng) << "\n";
    for (int i = 0; i < triangles; ++i) out << "f " << 3 * i + 1 << " " << 3 * i + 2 << " " << 3 * i + 3 << "\n";
    return path;
}

// `extra`: scene blocks appended to the random ones.
inline RandomScene makeScene(uint32_t seed, const std::string& extra = "") {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-4.0f, 4.0f), size(0.2f, 2.0f), unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> kind(0, 9);
    auto vec = [&](std::uniform_real_distribution<float>& d) {
        std::ostringstream s;
        s << d(rng) << " " << d(rng) << " " << d(rng);
        return s.str();
    };
    std::ostringstream text;
    text << "Camera\n{\n    POV 0 0 12\n}\nMaterial\n{\n    Name white\n}\n";
    const int objects = 6 + int(seed % 30);
    for (int i = 0; i < objects; ++i) {
        const int k = kind(rng);
        if (k <= 2) {
            text << "Sphere\n{\n    Material white\n    Center " << vec(pos) << "\n    Radius " << size(rng) << "\n}\n";
        } else if (k <= 5) {
            text << "Box\n{\n    Material white\n    Scale " << vec(size) << "\n";
            if (k != 3) text << "    Rotation " << vec(unit) << " " << 3.0f * unit(rng) << "\n";  // k = 3: axis-aligned
            text << "    Translation " << vec(pos) << "\n}\n";
        } else if (k <= 7) {
            const std::string axis = k == 6 ? "0 1 0" : vec(unit);
            text << "Cylinder\n{\n    Material white\n    Base " << vec(pos) << "\n    Axis " << axis << "\n    Radius "
                 << 0.5f * size(rng) << "\n    Height " << size(rng) << "\n}\n";
        } else if (k == 8) {
            text << "Mesh\n{\n    Material white\n    Source \"" << soupObj(rng, i) << "\"\n    Translation " << vec(pos)
                 << "\n}\n";
        } else {
            text << "CSG\n{\n    Material white\n    Source \"" << test::sourcePath("scenes/csg_example.csg")
                 << "\"\n    Scale 0.5 0.5 0.5\n    Translation " << vec(pos) << "\n}\n";
        }
    }
    text << extra;
    Diagnostics diags;
    const Scene scene = readSceneText(text.str(), test::tempPath("random.scene"), diags);
    EXPECT_FALSE(diags.hasErrors()) << text.str();
    RandomScene out;
    out.arrays = flatten(scene).arrays;
    out.view = hostView(out.arrays);
    return out;
}

// A point on (or within rounding of) some object's surface, and that surface's normal there when it has
// an easy one (else zero).
inline Vec3 surfacePoint(const SceneView& view, std::mt19937& rng, Vec3& normal) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<uint32_t> pick(0, view.objects.count - 1);
    const ObjectRef& o = view.objects[pick(rng)];
    normal = Vec3(0.0f);
    switch (o.kind) {
        case ObjectKind::Sphere: {
            const SphereShape& s = view.spheres[o.index];
            normal = normalize(Vec3(unit(rng), unit(rng), unit(rng)));
            return s.center + normal * s.radius;
        }
        case ObjectKind::Box: {
            const BoxShape& b = view.boxes[o.index];
            Vec3 q(0.5f * unit(rng), 0.5f * unit(rng), 0.5f * unit(rng));
            const int axis = int(rng() % 3);
            q[axis] = rng() % 2 ? 0.5f : -0.5f;  // exactly on a face in object space
            Vec3 e(0.0f);
            e[axis] = q[axis] > 0.0f ? 1.0f : -1.0f;
            normal = normalize(b.objectFromWorld.applyTransposeToVector(e));
            return b.worldFromObject.applyToPoint(q);
        }
        case ObjectKind::Cylinder: {
            const CylinderShape& c = view.cylinders[o.index];
            const Vec3 e1 = anyOrthonormal(c.axis), e2 = cross(c.axis, e1);
            const float phi = 3.14159265f * unit(rng);
            normal = e1 * cosf(phi) + e2 * sinf(phi);
            return c.base + c.axis * (c.height * (0.5f + 0.5f * unit(rng))) + normal * c.radius;
        }
        case ObjectKind::Mesh: {
            const MeshShape& m = view.meshes[o.index];
            const MeshTriangle& t = view.triangles[m.triangleOffset + rng() % m.triangleCount];
            const float b1 = 0.5f * (unit(rng) + 1.0f), b2 = (1.0f - b1) * 0.5f * (unit(rng) + 1.0f);
            normal = normalize(cross(t.p1 - t.p0, t.p2 - t.p0));
            return t.p0 + (t.p1 - t.p0) * b1 + (t.p2 - t.p0) * b2;
        }
        case ObjectKind::Csg: {
            const CsgNodeData& root = view.csgNodes[view.csgs[o.index].firstNode + view.csgs[o.index].nodeCount - 1];
            return (root.boundsMin + root.boundsMax) * 0.5f;
        }
    }
    TRAZO_UNREACHABLE();  // a new kind: -Wswitch names it here
}

}  // namespace test
}  // namespace trazo
