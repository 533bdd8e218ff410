// SPEC §7's light transport in whole renders, against its closed forms: the furnaces (Lambertian and mirror
// enclosures that emit and reflect, at three bounce limits), the unit sphere lit from its centre, a rectangle
// light over a Lambertian plane (the configuration factor of a parallel rectangle), and the three LightSampling
// estimators agreeing on a scene with every kind of light. Each check states its power: the tolerance is at
// least four standard errors of the estimate, measured from independent pixels or seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render_harness.h"

namespace trazo::test {
namespace {

struct Estimate {
    double mean = 0, standardError = 0;
};

// The mean over every pixel and channel, and its standard error from the spread of the pixels, which are
// independent estimates of the same value where the image is uniform (the furnaces).
Estimate uniformImageMean(const RenderedImage& image) {
    double sum = 0, sum2 = 0;
    for (const Vec3& p : image.pixels) {
        const double v = (double(p.x) + p.y + p.z) / 3.0;
        sum += v;
        sum2 += v * v;
    }
    const double n = double(image.pixels.size());
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1))};
}

std::string settings(const std::string& lines) {
    return "SceneSettings\n{\nRenderWidth 16\nRenderHeight 16\nIntegrator path\n" + lines + "}\n";
}

// The camera inside a sphere of radius 10 whose material emits 1 and reflects `reflect` (its other lines).
std::string enclosure(int maxBounces, const std::string& reflect) {
    return settings("MaxBounces " + std::to_string(maxBounces) + "\n") +
           "Camera\n{\nPOV 0 0 0\nPOI 0.3 0.2 -1\nFOV 70\n}\n"
           "Material\n{\nName wall\nEmissiveColor 1 1 1\nRoughness 0\n" + reflect + "}\n"
           "Sphere\n{\nMaterial wall\nRadius 10\n}\n";
}

// Σ_{k=0}^{B+1} ρ^k (SPEC §7 Checks).
double furnaceValue(double rho, int maxBounces) {
    double sum = 0, term = 1;
    for (int k = 0; k <= maxBounces + 1; ++k, term *= rho) sum += term;
    return sum;
}

void expectNear(const Estimate& e, double expected, double relative, const char* what) {
    EXPECT_LT(e.standardError, relative * expected / 4) << what << ": too few samples for the tolerance";
    EXPECT_NEAR(e.mean, expected, relative * expected) << what << " (standard error " << e.standardError << ")";
}

TEST(PathFurnace, LambertianEnclosureSumsTheBounces) {
    const std::string lambert = "DiffuseColor 0.5 0.5 0.5\nSpecularColor 0 0 0\n";
    for (const int bounces : {0, 2, 64}) {
        const Estimate e = uniformImageMean(renderSceneText(enclosure(bounces, lambert), {.passes = 512}));
        expectNear(e, furnaceValue(0.5, bounces), 0.005, ("MaxBounces " + std::to_string(bounces)).c_str());
    }
    const std::string bright = "DiffuseColor 0.8 0.8 0.8\nSpecularColor 0 0 0\n";
    expectNear(uniformImageMean(renderSceneText(enclosure(64, bright), {.passes = 2048})), furnaceValue(0.8, 64),
               0.005, "albedo 0.8");
}

TEST(PathFurnace, MirrorEnclosureSumsTheBounces) {
    const std::string mirror = "DiffuseColor 0 0 0\nSpecularColor 0.5 0.5 0.5\nReflectionAmount 1\n";
    for (const int bounces : {0, 2, 64}) {
        const Estimate e = uniformImageMean(renderSceneText(enclosure(bounces, mirror), {.passes = 512}));
        expectNear(e, furnaceValue(0.5, bounces), 0.005, ("MaxBounces " + std::to_string(bounces)).c_str());
    }
}

// A unit sphere of Kd 0.5 seen from its centre, a point light of intensity π there: irradiance π, so the first
// bounce shows ρ·π/π = 0.5 and every further one half the last.
TEST(PathTransport, SphereLitFromItsCentre) {
    auto scene = [](int bounces) {
        return settings("MaxBounces " + std::to_string(bounces) + "\n") +
               "Camera\n{\nPOV 0 0 0\nPOI 0.3 0.2 -1\nFOV 70\n}\n"
               "Material\n{\nName wall\nDiffuseColor 0.5 0.5 0.5\nSpecularColor 0 0 0\nRoughness 0\n}\n"
               "Sphere\n{\nMaterial wall\nRadius 1\n}\n"
               "PointLight\n{\nPosition 0 0 0\nColor 3.14159265 3.14159265 3.14159265\n}\n";
    };
    const Estimate direct = uniformImageMean(renderSceneText(scene(0), {.passes = 1}));
    EXPECT_NEAR(direct.mean, 0.5, 1e-5);
    expectNear(uniformImageMean(renderSceneText(scene(64), {.passes = 1024})), 1.0, 0.005, "MaxBounces 64");
}

// A square light of side 2 and radiance 1, 1 above a Lambertian plane of albedo 0.5 facing it: under its centre
// the irradiance is 4π·F(1, 1, 1) = 1.740840 (the configuration factor of a parallel rectangle), so the plane
// shows 0.5·1.740840/π = 0.277063. The camera sees a patch 0.01 across about that point (where E is within
// 0.01 % of its centre value), under each LightSampling.
TEST(PathTransport, RectangleLightOverALambertianPlane) {
    for (const char* sampling : {"mis", "nee", "bsdf"}) {
        const std::string scene =
            settings(std::string("MaxBounces 0\nLightSampling ") + sampling + "\n") +
            "Camera\n{\nPOV 0 0.5 3\nPOI 0 0 0\nFOV 0.2\n}\n"
            "Material\n{\nName floor\nDiffuseColor 0.5 0.5 0.5\nSpecularColor 0 0 0\nRoughness 0\n}\n"
            "Box\n{\nMaterial floor\nScale 40 1 40\nTranslation 0 -0.5 0\n}\n"
            "AreaLight\n{\nPosition 0 1 0\nDirection 0 -1 0\nWidth 2\nHeight 2\nColor 1 1 1\n}\n";
        const Estimate e = uniformImageMean(renderSceneText(scene, {.passes = std::string(sampling) == "bsdf" ? 4096u : 1024u}));
        expectNear(e, 0.277063, 0.005, sampling);
    }
}

// One scene with every kind of light (point, area, emissive sphere, uniform background) over Lambertian,
// glossy, mirror and glass surfaces: the three estimators' images have the same mean, within 0.5 %, the
// standard error from four seeds each.
TEST(PathTransport, LightSamplingChoicesAgree) {
    auto scene = [](const char* sampling) {
        return std::string("SceneSettings\n{\nRenderWidth 24\nRenderHeight 16\nIntegrator path\nMaxBounces 8\n") +
               "BackgroundColor 0.2 0.25 0.3\nLightSampling " + sampling + "\n}\n" +
               "Camera\n{\nPOV 0 2 6\nPOI 0 0.5 0\nFOV 50\n}\n"
               "Material\n{\nName floor\nDiffuseColor 0.6 0.6 0.6\nSpecularColor 0 0 0\nRoughness 0.3\n}\n"
               "Material\n{\nName gloss\nDiffuseColor 0.2 0.3 0.6\nSpecularColor 0.5 0.5 0.5\nRoughness 0.2\n}\n"
               "Material\n{\nName glass\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nOpacity 0\nRefractionIndex 1.5\n"
               "Fresnel 1\n}\n"
               "Material\n{\nName lamp\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nEmissiveColor 4 3 2\n}\n"
               "Box\n{\nMaterial floor\nScale 10 1 10\nTranslation 0 -0.5 0\n}\n"
               "Sphere\n{\nMaterial gloss\nCenter -1 0.7 0\nRadius 0.7\n}\n"
               "Sphere\n{\nMaterial glass\nCenter 1 0.6 0.5\nRadius 0.6\n}\n"
               "Sphere\n{\nMaterial lamp\nCenter 0 2.5 -2\nRadius 0.3\n}\n"
               "PointLight\n{\nPosition 2 3 2\nColor 4 4 4\n}\n"
               "AreaLight\n{\nPosition -1 3 1\nDirection 0 -1 0\nWidth 1\nHeight 1\nColor 3 3 3\n}\n";
    };
    std::vector<Estimate> estimates;
    for (const char* sampling : {"mis", "nee", "bsdf"}) {
        std::vector<double> means;
        for (uint32_t seed = 1; seed <= 4; ++seed)
            means.push_back(uniformImageMean(renderSceneText(scene(sampling), {.passes = 1024, .seed = seed})).mean);
        double sum = 0, sum2 = 0;
        for (double m : means) sum += m, sum2 += m * m;
        const double mean = sum / 4;
        estimates.push_back({mean, std::sqrt(std::max(0.0, sum2 / 4 - mean * mean) / 3)});
    }
    for (size_t i = 1; i < estimates.size(); ++i) {
        const double se = std::hypot(estimates[0].standardError, estimates[i].standardError);
        EXPECT_LT(se, 0.005 * estimates[0].mean / 3) << "too few samples for the tolerance";
        EXPECT_NEAR(estimates[i].mean, estimates[0].mean, 0.005 * estimates[0].mean)
            << (i == 1 ? "nee" : "bsdf") << " against mis (standard error " << se << ")";
    }
}

}  // namespace
}  // namespace trazo::test
