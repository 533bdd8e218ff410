// Every light kind of the list (lights/light_kind_list.h), made by the editor's newObject and flattened by its
// appendLight, against SPEC §7's reading of a light: sampleLi's pdf is what pdfLi gives for its direction, pdfLi
// integrates to 1 over the directions that see the light (0 everywhere for a delta light), and the irradiance
// sampleLi estimates is the one integrated over the sphere. A new kind is covered by its row.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>

#include "flatten/scene_arrays.h"
#include "lights/visit_light.h"
#include "scene/kinds/light_kind_model.h"
#include "support/sphere_patch.h"

namespace trazo {
namespace {

// The kind's light as the editor adds it at `at` (size 1, colour (2, 1, 0.5)), flattened by its appendLight.
template <class Kind, class Data>
Data flattened(Vec3 at) {
    SceneArrays arrays;
    Kind light = *newObject(KindTag<Kind>{}, at, 1.0f);
    light.color = Vec3(2.0f, 1.0f, 0.5f);
    appendLight(light, arrays);
    Data out{};
#define TRAZO_X(D, array, ...) \
    if constexpr (std::is_same_v<D, Data>) out = arrays.array.at(0);
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    return out;
}

template <class Kind, class Data>
void expectSpecReading(const char* keyword) {
    SCOPED_TRACE(keyword);
    const Data light = flattened<Kind, Data>(Vec3(0.3f, 2.0f, -0.2f));
    const Vec3 points[] = {Vec3(0.0f), Vec3(1.5f, 0.5f, 0.7f), Vec3(-2.0f, -1.0f, 3.0f), Vec3(0.2f, 3.0f, 0.1f)};
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const Vec3 p : points) {
        const LightSample first = sampleLi(light, p, 0.5f, 0.5f);
        if (first.delta) {
            EXPECT_EQ(first.pdf, 1.0f);
            EXPECT_EQ(pdfLi(light, p, first.wi), 0.0f) << "no BSDF direction finds a delta light";
            EXPECT_EQ(arrivingLi(light, p, first.wi).x, 0.0f);
            continue;
        }
        // sampleLi's pdf and radiance are what pdfLi and arrivingLi give for its direction.
        double irradiance = 0.0;
        constexpr int kSamples = 20000;
        for (int s = 0; s < kSamples; ++s) {
            const LightSample ls = sampleLi(light, p, u(rng), u(rng));
            if (!(ls.pdf > 0.0f)) continue;
            EXPECT_NEAR(pdfLi(light, p, ls.wi), ls.pdf, 2e-3f * ls.pdf);
            EXPECT_NEAR(arrivingLi(light, p, ls.wi).x, ls.radiance.x, 1e-6f);
            irradiance += ls.radiance.x * std::fabs(ls.wi.y) / ls.pdf;  // on a plane facing ±Y
        }
        irradiance /= kSamples;
        const Vec3 toward = normalize(lightBounds(light).centroid() - p);
        const test::SpherePatch around{toward};  // a fine θ grid: a small light's directions crowd about it
        EXPECT_NEAR(around.integral([&](Vec3 w) { return pdfLi(light, p, w); }, 1200), 1.0, 5e-3);
        const double integrated =
            around.integral([&](Vec3 w) { return arrivingLi(light, p, w).x * std::fabs(w.y); }, 1200);
        EXPECT_NEAR(irradiance, integrated, 0.02 * integrated + 1e-6);
    }
}

TEST(LightKinds, EveryKindReadsAsSpecSection7) {
#define TRAZO_X(Data, array, Kind, keyword, ...) expectSpecReading<Kind, Data>(keyword);
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
}

// The closed forms: a point light's radiance is I / r² (delta), an area light's front emits Color and its back
// nothing (SPEC §7's one-sided emitter).
TEST(LightKinds, PointFallsOffAndAreaEmitsFromItsFront) {
    const PointLightData point{Vec3(0.0f, 2.0f, 0.0f), Vec3(8.0f)};
    const LightSample ls = sampleLi(point, Vec3(0.0f), 0.3f, 0.7f);
    EXPECT_TRUE(ls.delta);
    EXPECT_FLOAT_EQ(ls.radiance.x, 2.0f);
    EXPECT_FLOAT_EQ(ls.distance, 2.0f);
    EXPECT_FLOAT_EQ(ls.wi.y, 1.0f);

    AreaLight host;  // faces -Y from y = 2
    host.position = Vec3(0.0f, 2.0f, 0.0f);
    host.color = Vec3(3.0f);
    const AreaLightData area = areaLightData(host);
    EXPECT_FLOAT_EQ(areaLightArea(area), 1.0f);
    EXPECT_FLOAT_EQ(sampleLi(area, Vec3(0.0f), 0.5f, 0.5f).radiance.x, 3.0f) << "below: its front";
    EXPECT_EQ(sampleLi(area, Vec3(0.0f, 4.0f, 0.0f), 0.5f, 0.5f).radiance.x, 0.0f) << "above: its back";
    // Straight below the centre, at distance 2: pdf = r² / (A cos) = 4.
    EXPECT_FLOAT_EQ(sampleLi(area, Vec3(0.0f), 0.5f, 0.5f).pdf, 4.0f);
}

}  // namespace
}  // namespace trazo
