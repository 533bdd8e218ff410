// Tests (host) that occludedPacket answers exactly as occluded() does ray by ray, at every ISA width this CPU
// runs (the kernels of backends/cpu/cpu_kernels.h) and in this translation unit's own build: random scenes of
// spheres, boxes, cylinders, meshes and CSG solids; origins in space and on surfaces; grazing rays, rays along
// faces, zero direction components, segments ending on a surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "backends/cpu/cpu_kernels.h"
#include "flatten/flatten.h"
#include "integrator/thesis/direct_light.h"
#include "integrator/packets/packet_test_scenes.h"
#include "scene/scene_reader.h"
#include "test_paths.h"

#if TRAZO_HOST_PACKETS
namespace trazo {
namespace {

using test::makeScene;
using test::RandomScene;
using test::surfacePoint;

struct Case {
    Vec3 origin;
    RayPacket packet;
    uint64_t active;
};

Case makeCase(const SceneView& view, std::mt19937& rng, int variant) {
    std::uniform_real_distribution<float> pos(-6.0f, 6.0f), unit(-1.0f, 1.0f), fraction(0.0f, 1.5f);
    Case c;
    Vec3 normal(0.0f);
    c.origin = variant % 3 == 0 ? Vec3(pos(rng), pos(rng), pos(rng)) : surfacePoint(view, rng, normal);
    if (variant % 3 == 2 && !isBlack(normal)) c.origin = offsetRayOrigin(c.origin, Vec3(1e-5f), normal, normal);
    for (int i = 0; i < kPacketRays; ++i) {
        Vec3 d;
        float tMax = INFINITY;
        Vec3 ignored;
        switch (rng() % 6) {
            case 0: d = Vec3(unit(rng), unit(rng), unit(rng)); break;
            case 1: {  // towards a surface point: a shadow ray's segment, sometimes ending on that surface
                const Vec3 target = surfacePoint(view, rng, ignored);
                d = target - c.origin;
                tMax = length(d) * (rng() % 2 ? 1.0f : fraction(rng));
                break;
            }
            case 2:  // grazing: along the surface at the origin
                d = isBlack(normal) ? Vec3(unit(rng), 0.0f, unit(rng)) : cross(normal, Vec3(unit(rng), unit(rng), unit(rng)));
                break;
            case 3: {  // axis directions, signed zeros included
                d = Vec3(0.0f);
                const int axis = int(rng() % 3);
                d[axis] = rng() % 2 ? 1.0f : -1.0f;
                if (rng() % 2) d[(axis + 1) % 3] = -0.0f;
                break;
            }
            case 4: d = Vec3(unit(rng), unit(rng), 0.0f); break;
            default: {  // one of 64 rays of an area light's block: targets on a small rectangle
                const Vec3 light(2.0f, 6.0f, 3.0f);
                d = light + Vec3(unit(rng), 0.0f, unit(rng)) - c.origin;
                tMax = length(d);
                break;
            }
        }
        if (!isBlack(d)) d = normalize(d);
        else d = Vec3(0.0f, 1.0f, 0.0f);
        c.packet.dx[i] = d.x;
        c.packet.dy[i] = d.y;
        c.packet.dz[i] = d.z;
        c.packet.tMax[i] = tMax;
    }
    c.active = variant % 4 == 3 ? (uint64_t(rng()) << 32 | rng()) : ~0ull;
    return c;
}

TEST(OccludedPacket, MatchesOccludedRayByRayOnEveryIsa) {
    uint64_t blockedSeen = 0, clearSeen = 0, compared = 0;
    for (uint32_t seed = 1; seed <= 40; ++seed) {
        const RandomScene scene = makeScene(seed);
        ASSERT_GT(scene.view.objects.count, 0u);
        std::mt19937 rng(seed * 7919u);
        for (int variant = 0; variant < 24; ++variant) {
            const Case c = makeCase(scene.view, rng, variant);
            uint64_t expected = 0;
            for (int i = 0; i < kPacketRays; ++i) {
                const Ray ray{c.origin, Vec3(c.packet.dx[i], c.packet.dy[i], c.packet.dz[i])};
                if ((c.active >> i & 1) && occluded(scene.view, ray, c.packet.tMax[i])) expected |= 1ull << i;
            }
            blockedSeen += __builtin_popcountll(expected);
            clearSeen += __builtin_popcountll(c.active & ~expected);
            ASSERT_EQ(occludedPacket(scene.view, c.origin, c.packet, c.active), expected)
                << "this build, seed " << seed << " variant " << variant;
            for (CpuIsa isa : kCpuIsas) {
                const CpuKernels* k = cpuKernelsFor(isa);
                if (!k) continue;
                ASSERT_EQ(k->occludedPacket(scene.view, c.origin, c.packet, c.active), expected)
                    << cpuIsaName(isa) << ", seed " << seed << " variant " << variant;
                ++compared;
            }
        }
    }
    // Both answers in numbers, or the comparison says little.
    EXPECT_GT(blockedSeen, 5000u);
    EXPECT_GT(clearSeen, 5000u);
    for (CpuIsa isa : kCpuIsas)
        if (!cpuKernelsFor(isa)) std::printf("occludedPacket: %s not compared: this CPU or build lacks it\n", cpuIsaName(isa));
    EXPECT_GT(compared, 0u);
}

// shadeCellsTogether (direct_light.h) against the loop over shadeFromPoint it replaces: the same sum, rays and
// rng dimension, bit for bit, over random shading points (on surfaces, shading normals tilted off the
// geometric ones so some cells lie behind or below), materials (matte, glossy, σ = 0, black lobes), lights
// (grids up to 16 × 16, blocks from 4 cells to the whole grid, across packet boundaries).
TEST(OccludedPacket, CellsShadedTogetherAsOneByOne) {
    uint64_t visibleSeen = 0, blockedSeen = 0;
    for (uint32_t seed = 1; seed <= 12; ++seed) {
        const RandomScene scene = makeScene(seed);
        std::mt19937 rng(seed * 104729u);
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f), pos(0.0f, 1.0f);
        for (int point = 0; point < 200; ++point) {
            AreaLightData light{};
            light.rect.center = Vec3(4.0f * unit(rng), 7.0f + unit(rng), 4.0f * unit(rng));
            light.rect.halfU = Vec3(0.5f + pos(rng), 0.0f, 0.0f);
            light.rect.halfV = Vec3(0.0f, 0.0f, 0.5f + pos(rng));
            light.rect.normal = Vec3(0.0f, -1.0f, 0.0f);
            light.color = Vec3(pos(rng), pos(rng), pos(rng));
            light.cellsU = 1 + rng() % 16;
            light.cellsV = 1 + rng() % 16;
            const uint32_t gridCells = light.cellsU * light.cellsV;
            MaterialData m{};
            m.diffuse = rng() % 5 ? Vec3(pos(rng), pos(rng), pos(rng)) : Vec3(0.0f);
            m.specular = rng() % 2 ? Vec3(pos(rng), pos(rng), pos(rng)) : Vec3(0.0f);
            m.roughness = rng() % 4 ? pos(rng) : 0.0f;
            Vec3 normal;
            Vec3 p = surfacePoint(scene.view, rng, normal);
            if (isBlack(normal)) normal = Vec3(0.0f, 1.0f, 0.0f);
            const Vec3 v = normalize(normal + Vec3(unit(rng), unit(rng), unit(rng)) * 0.8f);
            const Vec3 n = normalize(normal + Vec3(unit(rng), unit(rng), unit(rng)) * 0.3f);
            const ShadingPoint sp(p, offsetDistance(Vec3(1e-6f) * (1.0f + maxComponent(abs(p))), normal), normal, n, v);
            const PointBrdf brdf(sp, m);
            const StrataKey strata{seed, uint32_t(point), uint32_t(point % 3), 1u};
            const uint32_t target = std::max(kMinShadowPacket, 1 + uint32_t(rng() % gridCells));
            const StrataBlock cells = strata.block(kGridAreaLightBase, gridCells, rng() % 3 ? target : kWholeGrid);
            if (cells.size < kMinShadowPacket) continue;
            SampleStream one(seed, uint32_t(point), 0), together = one;
            uint32_t raysOne = 0, raysTogether = 0;
            Vec3 expected(0.0f);
            for (uint32_t j = 0; j < cells.size; ++j)
                expected += shadeFromPoint(scene.view, sp, brdf, cellPoint(light, cells.stratum(j), one), light.color,
                                           raysOne);
            const Vec3 got = shadeCellsTogether(scene.view, sp, brdf, light, cells, together, raysTogether);
            ASSERT_EQ(std::memcmp(&got, &expected, sizeof got), 0)
                << "seed " << seed << " point " << point << ": " << got.x << " vs " << expected.x;
            ASSERT_EQ(raysTogether, raysOne);
            ASSERT_EQ(together.dimension, one.dimension);
            blockedSeen += raysOne > 0 && isBlack(expected);
            visibleSeen += !isBlack(expected);
        }
    }
    EXPECT_GT(visibleSeen, 100u);
    EXPECT_GT(blockedSeen, 10u);
}

TEST(OccludedPacket, EmptySceneAndNoActiveRays) {
    Diagnostics diags;
    const Scene scene = readSceneText("Camera\n{\n    POV 0 0 5\n}\n", test::tempPath("empty.scene"), diags);
    const SceneArrays arrays = flatten(scene).arrays;
    RayPacket packet{};
    for (int i = 0; i < kPacketRays; ++i) packet.dx[i] = 1.0f, packet.tMax[i] = INFINITY;
    EXPECT_EQ(occludedPacket(hostView(arrays), Vec3(0.0f), packet, ~0ull), 0u);
    const RandomScene full = makeScene(3);
    EXPECT_EQ(occludedPacket(full.view, Vec3(0.0f), packet, 0u), 0u);
}

// Rays each from an origin of its own (RayOrigins): in space, on surfaces, just off them; towards a point light,
// surface points (segments ending on them) and anywhere. In this translation unit's build (the shipped scenes'
// bytes on every ISA are checked by the renders that use them: indirect light towards point lights).
TEST(OccludedPacket, OwnOriginsMatchOccludedRayByRay) {
    uint64_t blockedSeen = 0, clearSeen = 0;
    for (uint32_t seed = 1; seed <= 40; ++seed) {
        const RandomScene scene = makeScene(seed);
        std::mt19937 rng(seed * 104729u);
        std::uniform_real_distribution<float> pos(-6.0f, 6.0f), unit(-1.0f, 1.0f), fraction(0.0f, 1.5f);
        for (int variant = 0; variant < 24; ++variant) {
            RayOrigins origins;
            RayPacket packet;
            const Vec3 light(pos(rng), 6.0f, pos(rng));
            for (int i = 0; i < kPacketRays; ++i) {
                Vec3 normal(0.0f), ignored;
                Vec3 o = rng() % 3 == 0 ? Vec3(pos(rng), pos(rng), pos(rng)) : surfacePoint(scene.view, rng, normal);
                if (rng() % 2 && !isBlack(normal)) o = offsetRayOrigin(o, Vec3(1e-5f), normal, normal);
                Vec3 d;
                float tMax = INFINITY;
                switch (rng() % 3) {
                    case 0: d = light - o, tMax = length(d); break;
                    case 1: {
                        d = surfacePoint(scene.view, rng, ignored) - o;
                        tMax = length(d) * (rng() % 2 ? 1.0f : fraction(rng));
                        break;
                    }
                    default: d = Vec3(unit(rng), unit(rng), unit(rng)); break;
                }
                d = isBlack(d) ? Vec3(0.0f, 1.0f, 0.0f) : normalize(d);
                origins.ox[i] = o.x, origins.oy[i] = o.y, origins.oz[i] = o.z;
                packet.dx[i] = d.x, packet.dy[i] = d.y, packet.dz[i] = d.z;
                packet.tMax[i] = tMax;
            }
            const uint64_t active = variant % 4 == 3 ? (uint64_t(rng()) << 32 | rng()) : ~0ull;
            uint64_t expected = 0;
            for (int i = 0; i < kPacketRays; ++i) {
                const Ray ray{Vec3(origins.ox[i], origins.oy[i], origins.oz[i]),
                              Vec3(packet.dx[i], packet.dy[i], packet.dz[i])};
                if ((active >> i & 1) && occluded(scene.view, ray, packet.tMax[i])) expected |= 1ull << i;
            }
            blockedSeen += __builtin_popcountll(expected);
            clearSeen += __builtin_popcountll(active & ~expected);
            ASSERT_EQ(occludedPacket(scene.view, origins, packet, active), expected)
                << "seed " << seed << " variant " << variant;
        }
    }
    EXPECT_GT(blockedSeen, 5000u);
    EXPECT_GT(clearSeen, 5000u);
}

}  // namespace
}  // namespace trazo
#endif  // TRAZO_HOST_PACKETS
