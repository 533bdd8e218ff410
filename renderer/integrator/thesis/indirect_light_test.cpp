// Tests (host) that indirect light with its directions traced as packets (indirectLightTogether) is the
// one-ray-at-a-time loop (indirectLightOneByOne) bit for bit: the sum, the random numbers drawn and the rays
// counted. Random scenes of spheres, boxes, cylinders, meshes and CSG solids (the last two traced again ray by
// ray inside the packet code), point lights, matte, glossy, specular-only and textured materials, objects twice at
// one place (ties), shading points seen from a camera, block sizes from 1 direction to more than one packet.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "integrator/thesis/indirect_light.h"
#include "integrator/packets/packet_test_scenes.h"
#include "integrator/thesis/thesis_integrator.h"
#include "integrator/sample_variants.h"

#if TRAZO_HOST_PACKETS

namespace trazo {
namespace {

// Two point lights; matte, glossy, specular-only and textured materials (the last shaded by shadingPointAlong at Q,
// the rest in lanes); objects twice at one place (ties).
std::string extras() {
    return std::string("PointLight\n{\n    Position 1 6 5\n    Color 0.9 0.8 0.7\n}\n"
                       "PointLight\n{\n    Position -3 -2 6\n    Color 0.3 0.3 0.4\n}\n"
                       "Texture\n{\n    Name face\n    Source \"") +
           test::sourcePath("scenes/assets/head_diffuse.png") +
           "\"\n}\n"
           "Material\n{\n    Name glossy\n    DiffuseColor 0.2 0.5 0.7\n    SpecularColor 0.6 0.6 0.6\n"
           "    Roughness 0.3\n}\n"
           "Material\n{\n    Name chrome\n    DiffuseColor 0 0 0\n    SpecularColor 0.7 0.7 0.7\n    Roughness 0.2\n}\n"
           "Material\n{\n    Name printed\n    DiffuseTexture face\n    DiffuseColor 1 1 1\n}\n"
           "Sphere\n{\n    Material glossy\n    Center -2 1 2\n    Radius 0.7\n}\n"
           "Sphere\n{\n    Material glossy\n    Center -2 1 2\n    Radius 0.7\n}\n"
           "Sphere\n{\n    Material chrome\n    Center 0.5 -1.2 1.2\n    Radius 0.6\n}\n"
           "Sphere\n{\n    Material printed\n    Center 1.5 2 0.5\n    Radius 0.8\n}\n"
           "Box\n{\n    Material white\n    Scale 1 0.5 2\n    Translation 2 -1 1\n}\n"
           "Box\n{\n    Material white\n    Scale 1 0.5 2\n    Translation 2 -1 1\n}\n";
}

// Point lights, indirect light and the rest: every feature but area lights, whose draws would interleave.
constexpr FeatureMask kFeatures = kSpecialisedFeatures & ~kFeatureAreaLights;

TEST(IndirectLight, TogetherIsOneByOneBitForBit) {
    uint32_t compared = 0, packetsOfTwo = 0;
    for (uint32_t seed = 1; seed <= 8; ++seed) {
        test::RandomScene scene = test::makeScene(seed, extras());
        ASSERT_EQ(scene.view.areaLights.count, 0u);
        const CameraFrame camera = makeCameraFrame(Vec3(0.0f, 1.0f, 12.0f), Vec3(0.0f), 50.0f, 24, 18);
        for (uint32_t q : {1u, 2u, 3u, 6u}) {  // 2q² = 2, 8, 18, 72 directions (72: a packet and a part)
            scene.view.settings.indirectQuality = q;
            for (uint32_t target : {1u, 5u, kWholeGrid}) {
                for (uint32_t py = 0; py < camera.height; ++py) {
                    for (uint32_t px = 0; px < camera.width; ++px) {
                        float x, y;
                        antialiasingPosition(1, 0, px, py, x, y);
                        const Ray ray = generateCameraRay(camera, x, y);
                        SurfaceHit hit;
                        if (!intersectScene(scene.view, ray, INFINITY, hit) || hit.object == kNoObject) continue;
                        const ObjectRef& o = scene.view.objects[hit.object];
                        const MaterialData& m = scene.view.materials[o.material];
                        const SurfacePoint s = surfaceAt(scene.view, o, hit, pointAt(ray, hit.t), false);
                        const ShadingPoint sp =
                            facingShadingPoint(pointAt(ray, hit.t), hitPointError(ray, hit.t), ray.direction, s);
                        const uint32_t pixel = py * camera.width + px;
                        const StrataKey strata{seed, pixel, target, kSampleTreeRoot};
                        const StrataBlock directions = strata.block(kGridIndirect, 2 * q * q, target);
                        const StrataKey atQ = strata.child(kBranchIndirect);
                        StrataBlocks blocks;
                        blocks.indirect = target;
                        SampleStream one(seed, pixel, q), together(seed, pixel, q);
                        uint32_t raysOne = 0, raysTogether = 0;
                        const Vec3 a = indirectLightOneByOne<kFeatures>(scene.view, sp, m, directions, atQ, blocks,
                                                                         one, raysOne);
                        const Vec3 b =
                            indirectLightTogether<kFeatures>(scene.view, sp, m, directions, together, raysTogether);
                        ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0)
                            << "seed " << seed << " q " << q << " target " << target << " pixel " << px << ", " << py
                            << ": " << a.x << " " << a.y << " " << a.z << " against " << b.x << " " << b.y << " "
                            << b.z;
                        ASSERT_EQ(one.dimension, together.dimension);
                        ASSERT_EQ(raysOne, raysTogether);
                        ++compared;
                        if (directions.size > (uint32_t)kPacketRays) ++packetsOfTwo;
                    }
                }
            }
        }
    }
    EXPECT_GT(compared, 3000u);  // the test's reach: shading points compared
    EXPECT_GT(packetsOfTwo, 100u);
}

// The rule that chooses the packets: no area lights in F, enough directions, no meshes or CSG solids.
TEST(IndirectLight, PacketsApplyOnlyWhereTheirAnswerIsTheLoops) {
    const test::RandomScene plain = test::makeScene(3, extras());
    SceneView view = plain.view;
    view.meshes.count = 0;
    view.csgs.count = 0;
    EXPECT_TRUE(indirectPacketsApply<kFeatures>(view, kMinIndirectPacket));
    EXPECT_FALSE(indirectPacketsApply<kFeatures>(view, kMinIndirectPacket - 1));
    EXPECT_FALSE(indirectPacketsApply<kFeatures | kFeatureAreaLights>(view, 18));
    view.meshes.count = 1;
    EXPECT_FALSE(indirectPacketsApply<kFeatures>(view, 18));
    view.meshes.count = 0;
    view.csgs.count = 1;
    EXPECT_FALSE(indirectPacketsApply<kFeatures>(view, 18));
}

}  // namespace
}  // namespace trazo
#endif  // TRAZO_HOST_PACKETS
