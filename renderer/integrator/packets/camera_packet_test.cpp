// Tests (host) of the camera blocks shaded together (camera_block.h), for scenes lit by point lights with and without
// indirect light: shadeBlock is renderSample given the same hits, bit for bit (and, without indirect light, one value
// in every pass), and the CPU backend's packet tile renderer, which shades such blocks together, adds what the
// one-pixel-at-a-time tile renderer adds, at every ISA width this CPU runs. Random scenes of every object kind, two
// point lights, matte, glossy, specular-only, emitting and half-transparent materials, objects twice at one place
// (ties), IndirectQuality 1 to 6 with blocks of 1 direction to the whole grid.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "backends/cpu/cpu_kernels.h"
#include "integrator/packets/packet_test_scenes.h"

#if TRAZO_HOST_PACKETS
#include "integrator/thesis/camera_block.h"
#include "integrator/packets/camera_packet.h"

namespace trazo {
namespace {

constexpr const char* kExtras =
    "PointLight\n{\n    Position 1 6 5\n    Color 0.9 0.8 0.7\n}\n"
    "PointLight\n{\n    Position -3 -2 6\n    Color 0.3 0.3 0.4\n}\n"
    "Material\n{\n    Name glossy\n    DiffuseColor 0.2 0.5 0.7\n    SpecularColor 0.6 0.6 0.6\n    Roughness 0.3\n}\n"
    "Material\n{\n    Name smooth\n    DiffuseColor 0.8 0.1 0.1\n    Roughness 0\n}\n"
    "Material\n{\n    Name chrome\n    DiffuseColor 0 0 0\n    SpecularColor 0.7 0.7 0.7\n    Roughness 0.2\n}\n"
    "Material\n{\n    Name lamp\n    DiffuseColor 0 0 0\n    EmissiveColor 0.9 0.9 0.2\n}\n"
    "Material\n{\n    Name veil\n    DiffuseColor 0.5 0.5 0.5\n    Opacity 0.5\n    RefractionIndex 1\n}\n"
    "Sphere\n{\n    Material glossy\n    Center -2 1 2\n    Radius 0.7\n}\n"
    "Sphere\n{\n    Material glossy\n    Center -2 1 2\n    Radius 0.7\n}\n"
    "Sphere\n{\n    Material chrome\n    Center 0.5 -1.2 1.2\n    Radius 0.6\n}\n"
    "Sphere\n{\n    Material lamp\n    Center 2.5 2.5 1\n    Radius 0.5\n}\n"
    "Box\n{\n    Material smooth\n    Scale 1 0.5 2\n    Translation 2 -1 1\n}\n"
    "Box\n{\n    Material smooth\n    Scale 1 0.5 2\n    Translation 2 -1 1\n}\n"
    "Box\n{\n    Material veil\n    Scale 3 3 0.1\n    Translation -1 -2 3\n}\n";

constexpr FeatureMask kDirectOnly = 0;
static_assert(directOnlySample<kDirectOnly>() && !directOnlySample<kFeatureIndirect>() &&
              !directOnlySample<kFeatureAreaLights>() && !directOnlySample<kFeatureReflection>() &&
              !directOnlySample<kFeatureRefraction>() && !directOnlySample<kAllSampleFeatures>());
static_assert(blockShadingServes<kDirectOnly>() && blockShadingServes<kFeatureIndirect>() &&
              !blockShadingServes<kFeatureIndirect | kFeatureAreaLights>() &&
              !blockShadingServes<kFeatureIndirect | kFeatureReflection>() &&
              !blockShadingServes<kAllSampleFeatures>());

FrameParams frameFor(const CameraFrame& camera, uint32_t seed) {
    FrameParams frame{};
    frame.camera = camera;
    frame.seed = seed;
    frame.sampleWeight = 1.0f;
    frame.blocks = StrataBlocks{};
    frame.halfBlock = 1;  // odd passes in the second half, so both halves are compared
    return frame;
}

// shadeBlock<F> of every 8×8 block of a 48×40 image against thesisSample<F> given the same hits, in passes `passes`;
// `withFrame` sets the frame up. Counts the pixels compared and the lit ones.
template <FeatureMask F, class Setup>
void expectBlocksAreRenderSample(std::initializer_list<uint32_t> passes, const Setup& withFrame, uint32_t& compared,
                                 uint32_t& lit) {
    for (uint32_t seed = 1; seed <= 8; ++seed) {
        test::RandomScene scene = test::makeScene(seed, kExtras);
        ASSERT_EQ(scene.view.pointLights.count, 2u);
        const CameraFrame camera = makeCameraFrame(Vec3(0.0f, 1.0f, 12.0f), Vec3(0.0f), 50.0f, 48, 40);
        FrameParams frame = frameFor(camera, seed);
        withFrame(seed, scene.view, frame);
        for (uint32_t by = 0; by < camera.height; by += 8) {
            for (uint32_t bx = 0; bx < camera.width; bx += 8) {
                RayPacket rays;
                uint32_t imageX[kPacketRays], imageY[kPacketRays];
                // Some blocks with lanes left out (as at an image's edge), the rest whole.
                const uint64_t active = (bx + by) % 24 == 8 ? 0x0f0f0f0f00ff00ffull : ~0ull;
                for (int i = 0; i < kPacketRays; ++i) {
                    imageX[i] = bx + i % 8, imageY[i] = by + i / 8;
                    const Ray r = centreCameraRay(camera, imageX[i], imageY[i]);
                    rays.dx[i] = r.direction.x, rays.dy[i] = r.direction.y, rays.dz[i] = r.direction.z;
                    rays.tMax[i] = INFINITY;
                }
                TracedRay hits[kPacketRays];
                tracePacket(scene.view, camera.origin, rays, active, hits);
                for (uint32_t pass : passes) {
                    Vec3 color[kPacketRays];
                    const uint32_t blockRays =
                        shadeBlock<F>(scene.view, frame, hits, imageX, imageY, active, pass, color);
                    uint32_t raysOne = 0;
                    for (uint64_t m = active; m; m &= m - 1) {
                        const int i = __builtin_ctzll(m);
                        const Vec3 one =
                            thesisSample<F>(scene.view, frame, imageX[i], imageY[i], pass, raysOne, &hits[i]);
                        ASSERT_EQ(std::memcmp(&one, &color[i], sizeof one), 0)
                            << "seed " << seed << " pixel " << imageX[i] << ", " << imageY[i] << " pass " << pass;
                        lit += one.x + one.y + one.z > 0.0f;
                        ++compared;
                    }
                    ASSERT_EQ(raysOne, blockRays) << "seed " << seed << " block " << bx << ", " << by;
                }
            }
        }
    }
}

TEST(CameraPacket, DirectOnlyBlocksAreRenderSampleInEveryPass) {
    uint32_t compared = 0, lit = 0;
    const auto asMade = [](uint32_t, SceneView&, FrameParams&) {};
    expectBlocksAreRenderSample<kDirectOnly>({0u, 1u, 7u}, asMade, compared, lit);
    EXPECT_GT(compared, 30000u);
    EXPECT_GT(lit, 6000u);  // and many not lit: shadows, the sky
    EXPECT_LT(lit, compared - 6000u);
    // One value in every pass: pass 7's colours are pass 0's (shadeBlock ignores the pass here).
    const test::RandomScene scene = test::makeScene(3, kExtras);
    const CameraFrame camera = makeCameraFrame(Vec3(0.0f, 1.0f, 12.0f), Vec3(0.0f), 50.0f, 8, 8);
    const FrameParams frame = frameFor(camera, 3);
    for (uint32_t i = 0; i < 64; ++i) {
        uint32_t a = 0, b = 0;
        const Vec3 first = thesisSample<kDirectOnly>(scene.view, frame, i % 8, i / 8, 0, a);
        const Vec3 later = thesisSample<kDirectOnly>(scene.view, frame, i % 8, i / 8, 7, b);
        ASSERT_EQ(std::memcmp(&first, &later, sizeof first), 0);
    }
}

TEST(CameraPacket, IndirectBlocksAreRenderSample) {
    uint32_t compared = 0, lit = 0;
    // IndirectQuality 1, 2, 3, 6 (2q² = 2 to 72 directions a point: a packet holds parts of several points'
    // directions, and 72 do not fit one), blocks of 1, 5 and the whole grid, strata windows on and off.
    const uint32_t qualities[] = {1u, 2u, 3u, 6u}, targets[] = {1u, 5u, kWholeGrid};
    const auto vary = [&](uint32_t seed, SceneView& view, FrameParams& frame) {
        view.settings.indirectQuality = qualities[seed % 4];
        view.settings.colorBleeding = seed % 2 ? 4.0f : 0.5f;
        frame.blocks.indirect = targets[seed % 3];
        frame.strataWindow = seed % 2 ? 0u : 2u * 2u * qualities[seed % 4] * qualities[seed % 4];
    };
    expectBlocksAreRenderSample<kFeatureIndirect>({0u, 1u, 5u}, vary, compared, lit);
    EXPECT_GT(compared, 30000u);
    EXPECT_GT(lit, 6000u);
}

// The packet tile renderers of the block-shaded variants add, in each of several passes, what the plain tile
// renderers add: the whole AccumPixel (both halves) bit for bit, and the same ray count, on every ISA path.
TEST(CameraPacket, BlockTilesAddWhatThePlainTilesAdd) {
    int paths = 0;
    for (CpuIsa isa : kCpuIsas) {
        for (const uint32_t variant : {sampleVariantFor(IntegratorKind::Thesis, kDirectOnly),
                                       sampleVariantFor(IntegratorKind::Thesis, kFeatureIndirect)}) {
            const CpuKernels* kernels = cpuKernelsFor(isa);
            if (!kernels) continue;
            const TileRenderFn inPackets = kernels->cameraPackets().renderTile[variant];
            ASSERT_NE(inPackets, nullptr) << cpuIsaName(isa);
            ++paths;
            for (uint32_t seed = 1; seed <= 4; ++seed) {
                test::RandomScene scene = test::makeScene(seed, kExtras);
                scene.view.settings.indirectQuality = seed % 2 ? 3u : 1u;
                const CameraFrame camera = makeCameraFrame(Vec3(0.0f, 1.0f, 12.0f), Vec3(0.0f), 50.0f, 37, 29);
                const FrameParams frame = frameFor(camera, seed);
                const Tile tile{0, 0, camera.width, camera.height};  // blocks cut at both edges
                std::vector<AccumPixel> plain(camera.width * camera.height, AccumPixel{});
                std::vector<AccumPixel> packed = plain;
                const uint64_t plainRays = kernels->renderTile[variant](scene.view, frame, tile, 2, 3, plain.data());
                const uint64_t packedRays = inPackets(scene.view, frame, tile, 2, 3, packed.data());
                EXPECT_EQ(plainRays, packedRays) << cpuIsaName(isa) << " seed " << seed;
                ASSERT_EQ(std::memcmp(plain.data(), packed.data(), plain.size() * sizeof(AccumPixel)), 0)
                    << cpuIsaName(isa) << " variant " << variant << " seed " << seed;
            }
        }
    }
    EXPECT_GE(paths, 2);  // two variants on at least one path
}

}  // namespace
}  // namespace trazo
#endif  // TRAZO_HOST_PACKETS
