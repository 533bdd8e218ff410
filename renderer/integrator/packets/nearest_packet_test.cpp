// Tests (host) that a packet of camera rays traced together (tracePacket, nearestPacket) answers exactly
// as intersectScene does ray by ray, at every ISA width this CPU runs and in this translation unit's own build:
// random scenes of spheres, boxes, cylinders, meshes and CSG solids, with a light rectangle and two objects at
// the same place (ties); rays towards surface points, box faces and edges, along axes with signed zeros. And
// that renderSample given those hits returns the very sample it computes itself.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "backends/cpu/cpu_kernels.h"
#include "integrator/thesis/direct_light.h"
#include "integrator/packets/packet_test_scenes.h"

#if TRAZO_HOST_PACKETS
#include "integrator/packets/camera_packet.h"

namespace trazo {
namespace {

// A light rectangle among the objects, and a sphere and a box twice over: rays that meet them meet two objects
// at the same t, which only the scalar order settles.
constexpr const char* kExtras =
    "AreaLight\n{\n    Position 0.5 1 3\n    Direction 0 0 1\n    Width 2\n    Height 1.5\n}\n"
    "Sphere\n{\n    Material white\n    Center -2 1 2\n    Radius 0.7\n}\n"
    "Sphere\n{\n    Material white\n    Center -2 1 2\n    Radius 0.7\n}\n"
    "Box\n{\n    Material white\n    Scale 1 0.5 2\n    Translation 2 -1 1\n}\n"
    "Box\n{\n    Material white\n    Scale 1 0.5 2\n    Translation 2 -1 1\n}\n";

// A packet of rays from origin: towards surface points (exactly on box faces and edges among them), random,
// and along axes with signed zeros. Some lanes inactive when `partial`.
uint64_t makeRays(const SceneView& view, Vec3 origin, std::mt19937& rng, bool partial, RayPacket& rays) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < kPacketRays; ++i) {
        Vec3 d, normal;
        switch (rng() % 4) {
            case 0: d = Vec3(unit(rng), unit(rng), unit(rng)); break;
            case 1: {
                d = Vec3(0.0f);
                const int axis = int(rng() % 3);
                d[axis] = rng() % 2 ? 1.0f : -1.0f;
                if (rng() % 2) d[(axis + 1) % 3] = -0.0f;
                break;
            }
            default: d = test::surfacePoint(view, rng, normal) - origin; break;
        }
        d = isBlack(d) ? Vec3(0.0f, 0.0f, -1.0f) : normalize(d);
        rays.dx[i] = d.x;
        rays.dy[i] = d.y;
        rays.dz[i] = d.z;
        rays.tMax[i] = INFINITY;
    }
    return partial ? (uint64_t(rng()) << 32 | rng()) : ~0ull;
}

// The fields of intersectScene's answer that the integrator reads: all of them, but the triangle and
// barycentrics of a hit that is not on a mesh (surfaceAt reads those of mesh hits only).
void expectSameHit(const SceneView& view, const TracedRay& got, bool found, const SurfaceHit& expected,
                   const char* where, uint32_t seed, int lane) {
    ASSERT_EQ(got.found, found) << where << ", seed " << seed << " lane " << lane;
    if (!found) return;
    const SurfaceHit& g = got.hit;
    ASSERT_EQ(std::memcmp(&g.t, &expected.t, sizeof g.t), 0) << where << ", seed " << seed << " lane " << lane;
    ASSERT_EQ(std::memcmp(&g.normal, &expected.normal, sizeof g.normal), 0) << where << ", seed " << seed;
    ASSERT_EQ(g.object, expected.object) << where << ", seed " << seed << " lane " << lane;
    if (g.object == kNoObject) {
        ASSERT_EQ(g.areaLight, expected.areaLight);
    } else if (view.objects[g.object].kind == ObjectKind::Mesh) {
        ASSERT_EQ(g.triangle, expected.triangle);
        ASSERT_EQ(std::memcmp(&g.b1, &expected.b1, sizeof g.b1), 0);
        ASSERT_EQ(std::memcmp(&g.b2, &expected.b2, sizeof g.b2), 0);
    }
}

TEST(NearestPacket, CameraHitsMatchIntersectSceneOnEveryIsa) {
    uint64_t hitsSeen = 0, missesSeen = 0, lightSeen = 0, compared = 0;
    for (uint32_t seed = 1; seed <= 40; ++seed) {
        const test::RandomScene scene = test::makeScene(seed, kExtras);
        std::mt19937 rng(seed * 6151u);
        std::uniform_real_distribution<float> pos(-6.0f, 6.0f);
        for (int variant = 0; variant < 24; ++variant) {
            const Vec3 origin = variant % 2 ? Vec3(0.0f, 0.0f, 12.0f) : Vec3(pos(rng), pos(rng), pos(rng));
            RayPacket rays;
            const uint64_t active = makeRays(scene.view, origin, rng, variant % 4 == 3, rays);
            bool found[kPacketRays];
            SurfaceHit expected[kPacketRays];
            for (int i = 0; i < kPacketRays; ++i) {
                if (!(active >> i & 1)) continue;
                found[i] = intersectScene(scene.view, Ray{origin, Vec3(rays.dx[i], rays.dy[i], rays.dz[i])}, INFINITY,
                                          expected[i]);
                hitsSeen += found[i];
                missesSeen += !found[i];
                lightSeen += found[i] && expected[i].object == kNoObject;
            }
            TracedRay got[kPacketRays];
            RayPacket copy = rays;
            tracePacket(scene.view, origin, copy, active, got);
            for (int i = 0; i < kPacketRays; ++i)
                if (active >> i & 1) expectSameHit(scene.view, got[i], found[i], expected[i], "this build", seed, i);
            for (CpuIsa isa : kCpuIsas) {
                const CpuKernels* k = cpuKernelsFor(isa);
                if (!k) continue;
                copy = rays;
                k->cameraPackets().tracePacket(scene.view, origin, copy, active, got);
                for (int i = 0; i < kPacketRays; ++i)
                    if (active >> i & 1)
                        expectSameHit(scene.view, got[i], found[i], expected[i], cpuIsaName(isa), seed, i);
                ++compared;
            }
        }
    }
    EXPECT_GT(hitsSeen, 20000u);
    EXPECT_GT(missesSeen, 5000u);
    EXPECT_GT(lightSeen, 50u);
    EXPECT_GT(compared, 0u);
}

// Rays each with an origin of its own, as a block of shading points sends its indirect directions: origins on
// surfaces (moved off them as ShadingPoint does, and exactly on them), in space and at one shared point, some
// lanes left out; each answer is intersectScene's for Ray{origin i, direction i}.
TEST(NearestPacket, OwnOriginsMatchIntersectScene) {
    uint64_t hitsSeen = 0, missesSeen = 0, compared = 0;
    for (uint32_t seed = 1; seed <= 40; ++seed) {
        const test::RandomScene scene = test::makeScene(seed, kExtras);
        std::mt19937 rng(seed * 7919u);
        std::uniform_real_distribution<float> pos(-6.0f, 6.0f), unit(-1.0f, 1.0f);
        for (int variant = 0; variant < 12; ++variant) {
            RayPacket rays;
            RayOrigins origins;
            const uint64_t active = makeRays(scene.view, Vec3(0.0f, 0.0f, 12.0f), rng, variant % 3 == 2, rays);
            for (int i = 0; i < kPacketRays; ++i) {
                Vec3 origin(0.0f, 0.0f, 12.0f), normal;
                switch ((i + variant) % 4) {
                    case 0: origin = Vec3(pos(rng), pos(rng), pos(rng)); break;
                    case 1: origin = test::surfacePoint(scene.view, rng, normal); break;
                    case 2: {
                        const Vec3 p = test::surfacePoint(scene.view, rng, normal);
                        if (!isBlack(normal)) origin = offsetRayOrigin(p, abs(p) * 1e-6f, normal, normal);
                        else origin = p;
                        // Directions about that normal, as indirect light sends them.
                        Vec3 d = normalize(Vec3(unit(rng), unit(rng), unit(rng)));
                        if (!isBlack(normal) && dot(d, normal) < 0.0f) d = -d;
                        rays.dx[i] = d.x, rays.dy[i] = d.y, rays.dz[i] = d.z;
                        break;
                    }
                    default: break;  // the shared point
                }
                origins.ox[i] = origin.x, origins.oy[i] = origin.y, origins.oz[i] = origin.z;
            }
            bool found[kPacketRays];
            SurfaceHit expected[kPacketRays];
            for (int i = 0; i < kPacketRays; ++i) {
                if (!(active >> i & 1)) continue;
                const Ray ray{Vec3(origins.ox[i], origins.oy[i], origins.oz[i]), Vec3(rays.dx[i], rays.dy[i], rays.dz[i])};
                found[i] = intersectScene(scene.view, ray, INFINITY, expected[i]);
                hitsSeen += found[i];
                missesSeen += !found[i];
            }
            TracedRay got[kPacketRays];
            tracePacket(scene.view, origins, rays, active, got);
            for (int i = 0; i < kPacketRays; ++i) {
                if (!(active >> i & 1)) continue;
                expectSameHit(scene.view, got[i], found[i], expected[i], "own origins", seed, i);
                ASSERT_EQ(std::memcmp(&got[i].ray.origin.x, &origins.ox[i], sizeof(float)), 0);
                ++compared;
            }
        }
    }
    EXPECT_GT(hitsSeen, 10000u);
    EXPECT_GT(missesSeen, 3000u);
    EXPECT_GT(compared, 25000u);
}

// Ties are left to intersectScene; a unique nearest object is the packet's own answer.
TEST(NearestPacket, TiesAreRedoneAndOthersAnswered) {
    const test::RandomScene scene = test::makeScene(5, kExtras);
    RayPacket rays;
    const Vec3 origin(-2.0f, 1.0f, 12.0f);  // straight at the doubled sphere, and beside it
    for (int i = 0; i < kPacketRays; ++i) {
        const Vec3 d = normalize(Vec3(i < 32 ? 0.0f : 0.3f, i < 32 ? 0.0f : 0.9f, -1.0f));
        rays.dx[i] = d.x, rays.dy[i] = d.y, rays.dz[i] = d.z, rays.tMax[i] = INFINITY;
    }
    NearestHits nearest;
    nearestPacket(scene.view, origin, rays, ~0ull, nearest);
    EXPECT_EQ(nearest.redo & 0xffffffffull, 0xffffffffull);
}

// renderSample given tracePacket's hits returns its own sample, rays and all, bit for bit.
TEST(NearestPacket, RenderSampleWithGivenHitsIsTheSame) {
    uint32_t compared = 0;
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        const test::RandomScene scene = test::makeScene(seed, kExtras);
        const CameraFrame camera = makeCameraFrame(Vec3(0.0f, 1.0f, 12.0f), Vec3(0.0f), 50.0f, 64, 48);
        FrameParams frame{};
        frame.camera = camera;
        frame.seed = seed;
        frame.sampleWeight = 1.0f;
        frame.blocks = StrataBlocks{};
        for (uint32_t by = 0; by < camera.height; by += 8) {
            for (uint32_t bx = 0; bx < camera.width; bx += 8) {
                RayPacket rays;
                for (int i = 0; i < kPacketRays; ++i) {
                    const Ray r = centreCameraRay(camera, bx + i % 8, by + i / 8);
                    rays.dx[i] = r.direction.x, rays.dy[i] = r.direction.y, rays.dz[i] = r.direction.z;
                    rays.tMax[i] = INFINITY;
                }
                TracedRay hits[kPacketRays];
                tracePacket(scene.view, camera.origin, rays, ~0ull, hits);
                for (int i = 0; i < kPacketRays; ++i) {
                    uint32_t raysOne = 0, raysGiven = 0;
                    const uint32_t px = bx + i % 8, py = by + i / 8;
                    const Vec3 one = thesisSample<kSpecialisedFeatures>(scene.view, frame, px, py, 0, raysOne);
                    const Vec3 given =
                        thesisSample<kSpecialisedFeatures>(scene.view, frame, px, py, 0, raysGiven, &hits[i]);
                    ASSERT_EQ(std::memcmp(&one, &given, sizeof one), 0) << "seed " << seed << " pixel " << px << ", " << py;
                    ASSERT_EQ(raysOne, raysGiven);
                    ++compared;
                }
            }
        }
    }
    EXPECT_EQ(compared, 6u * 64u * 48u);
}

}  // namespace
}  // namespace trazo
#endif  // TRAZO_HOST_PACKETS
