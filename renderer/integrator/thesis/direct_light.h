// Direct(P) of SPEC §5: point lights with hard shadows, area lights by a block of jittered cells per pass.
#pragma once

#include "core/host_simd.h"
#include "integrator/strata.h"
#include "integrator/thesis/shade_from_point.h"
#if TRAZO_HOST_PACKETS
#include "integrator/thesis/direct_light_lanes.h"
#endif

namespace trazo {

// F: the scene's specialised feature bits (sample_variants.h); without kFeatureAreaLights the area-light
// loop is compiled out. lightBlock: the StrataBlocks target for the area lights' cells at this point;
// rotation: StrataKey::block's (the index of the indirect direction that found this point).
template <FeatureMask F>
TRAZO_HD Vec3 directLight(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                          const StrataKey& strata, uint32_t lightBlock, uint32_t rotation, SampleStream& rng,
                          uint32_t& rays) {
    Vec3 sum(0.0f);
    const PointBrdf brdf(sp, m);
    if (!brdf.reflects()) return sum;  // Shade is 0 for every light: no shadow rays
    for (uint32_t i = 0; i < scene.pointLights.count; ++i) {
        const PointLightData& light = scene.pointLights[i];
        sum += shadeFromPoint(scene, sp, brdf, light.position, light.color, rays);
    }
    if constexpr ((F & kFeatureAreaLights) != 0) {
    for (uint32_t i = 0; i < scene.areaLights.count; ++i) {
        const AreaLightData& light = scene.areaLights[i];
        const StrataBlock cells =
            strata.block(kGridAreaLightBase + i, light.cellsU * light.cellsV, lightBlock, rotation);
        Vec3 lightSum(0.0f);
#if TRAZO_HOST_PACKETS
        if (cells.size >= kMinShadowPacket) {
            lightSum = shadeCellsTogether(scene, sp, brdf, light, cells, rng, rays);
        } else
#endif
        for (uint32_t j = 0; j < cells.size; ++j)
            lightSum += shadeFromPoint(scene, sp, brdf, cellPoint(light, cells.stratum(j), rng), light.color, rays);
        sum += cells.size == 1 ? lightSum : lightSum / float(cells.size);
    }
    }
    return sum;
}

}  // namespace trazo
