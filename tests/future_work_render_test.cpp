// SPEC §6's effects in whole renders, against closed forms: the Fresnel factor across a mirror-like plane in an
// emissive enclosure and through a glass slab seen head-on, the thin lens's circle of confusion and the flux
// of a small emitter it blurs, and a glossy transmission cone that keeps what a clear slab lets through.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render_harness.h"

namespace trazo::test {
namespace {

// The unpolarised dielectric reflectance in double precision, from Snell's law (independent of shading/fresnel.h).
double fresnelReference(double cosI, double n1, double n2) {
    const double sinT = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
    if (sinT >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sinT * sinT);
    const double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const double rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

// Inside a sphere that only emits (Ke = 1), a plane y = 0 of a material that is nothing but a Fresnel mirror
// (Kd = 0, Ks = 1, ReflectionAmount 1, n = 1.5): every reflected ray finds the enclosure, so a pixel shows
// a = ReflectionAmount·F(θ) with θ its camera ray's angle to the plane's normal.
TEST(FresnelRender, MirrorInAnEmissiveEnclosureShowsFOfEachPixelsAngle) {
    const std::string scene =
        "SceneSettings\n{\nRenderWidth 48\nRenderHeight 32\nReflectionQuality 1\nReflectionSteps 1\nIndirectQuality 0\n}\n"
        "Camera\n{\nPOV 0 3 6\nPOI 0 0 -2\nFOV 60\n}\n"
        "Material\n{\nName fresnel\nDiffuseColor 0 0 0\nSpecularColor 1 1 1\nReflectionAmount 1\n"
        "RefractionIndex 1.5\nFresnel 1\n}\n"
        "Material\n{\nName sky\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nEmissiveColor 1 1 1\n}\n"
        "Box\n{\nMaterial fresnel\nTranslation 0 -0.5 0\nScale 200 1 200\n}\n"
        "Sphere\n{\nMaterial sky\nCenter 0 0 0\nRadius 150\n}\n";
    const RenderedImage image = renderSceneText(scene, {.passes = 1});
    ASSERT_EQ(image.pixels.size(), size_t(48 * 32));
    // The camera's rays as SPEC §3 defines them (pixel centres), in double.
    const double pov[3] = {0, 3, 6}, poi[3] = {0, 0, -2};
    double w[3] = {poi[0] - pov[0], poi[1] - pov[1], poi[2] - pov[2]};
    const double wl = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (double& c : w) c /= wl;
    double u[3] = {-w[2], 0, w[0]};  // forward × (0, 1, 0)
    const double ul = std::sqrt(u[0] * u[0] + u[2] * u[2]);
    u[0] /= ul, u[2] /= ul;
    const double v[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double t = std::tan(30.0 * M_PI / 180.0), aspect = 48.0 / 32.0;
    int onPlane = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 48; ++x) {
            const double sx = (2.0 * (x + 0.5) / 48 - 1) * t * aspect, sy = (1 - 2.0 * (y + 0.5) / 32) * t;
            double d[3];
            for (int i = 0; i < 3; ++i) d[i] = w[i] + u[i] * sx + v[i] * sy;
            const double dl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (d[1] >= -1e-3 * dl) continue;  // towards the sky, or too grazing to hit the plane's inside
            const double hit = -3.0 / (d[1] / dl);  // distance to y = 0
            if (hit > 90.0) continue;               // beyond the plane's edge at ±100
            ++onPlane;
            const double f = fresnelReference(-d[1] / dl, 1.0, 1.5);
            EXPECT_NEAR(image.at(x, y).x, f, 2e-5 + 1e-4 * f) << "pixel " << x << ", " << y;
        }
    }
    EXPECT_GT(onPlane, 600);  // most of the lower half sees the plane, from F ≈ 0.04 up towards grazing
}

// A glass slab (n = 1.5, Opacity 0, Fresnel) before a wall that only emits, seen head-on through a 1° field of
// view: each pass of light through an interface keeps 1 − F, F = 0.04, and the internal reflections sum to
// (1 − F)²·Σ F^(2k) = (1 − F)/(1 + F) = 0.923077 (SPEC §6). Inside, each interface reflects or transmits at
// random (probabilities F, 1 − F), so a sample is 0.96 or 0: σ ≈ 0.185, and 65 536 samples give a standard
// error of 7.3e-4; the bound is 4 of them.
TEST(FresnelRender, GlassSlabHeadOnTransmitsOneMinusFOverOnePlusF) {
    auto slab = [](int fresnel) {
        return "SceneSettings\n{\nRenderWidth 32\nRenderHeight 32\nReflectionQuality 1\nIndirectQuality 0\n}\n"
               "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 1\n}\n"
               "Material\n{\nName glass\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nOpacity 0\nRefractionIndex 1.5\n"
               "Fresnel " + std::to_string(fresnel) + "\n}\n"
               "Material\n{\nName wall\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nEmissiveColor 1 1 1\n}\n"
               "Box\n{\nMaterial glass\nScale 100 100 1\n}\n"
               "Box\n{\nMaterial wall\nTranslation 0 0 -5\nScale 1000 1000 1\n}\n";
    };
    const RenderedImage clear = renderSceneText(slab(0), {.passes = 2});
    for (const Vec3& p : clear.pixels) ASSERT_EQ(p.x, 1.0f) << "without Fresnel the slab lets everything through";
    const RenderedImage image = renderSceneText(slab(1), {.passes = 64});
    double sum = 0;
    for (const Vec3& p : image.pixels) sum += p.y;
    EXPECT_NEAR(sum / double(image.pixels.size()), 0.96 / 1.04, 4 * 7.3e-4);
}

// A small emitter (a sphere of radius s, Ke = 1) on the axis at depth z, the lens (radius r) focused at f: the
// image of the point is a uniform disk, the circle of confusion, of radius r·|z − f|/z on the focal plane
// (SPEC §6), convolved with the emitter's own disk. Second moments of uniform disks add (R²/2 each), so
// R_coc² = 2·M2 − R_s². The lens moves light and makes none: the image's sum equals the pinhole's.
TEST(DepthOfFieldRender, CircleOfConfusionAndTheEmittersFlux) {
    const double z = 10, f = 5, r = 0.3, s = 0.15, halfFov = 10.0 * M_PI / 180.0;
    const int size = 128;
    auto scene = [&](double aperture) {
        return "SceneSettings\n{\nRenderWidth 128\nRenderHeight 128\nReflectionQuality 0\nIndirectQuality 0\n"
               "Antialiasing 16\n}\n"
               "Camera\n{\nPOV 0 0 0\nPOI 0 0 -1\nFOV 20\nAperture " + std::to_string(aperture) +
               "\nFocalDistance " + std::to_string(f) + "\nLensQuality 3\n}\n"
               "Material\n{\nName lamp\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nEmissiveColor 1 1 1\n}\n"
               "Sphere\n{\nMaterial lamp\nCenter 0 0 -10\nRadius " + std::to_string(s) + "\n}\n";
    };
    // One antialiasing position and one lens stratum a pass: 16 passes are the pinhole's full grid, 288 twice
    // every pairing of the 16 positions with the lens's 18 strata. Each of the ~800 pixels the blur reaches is
    // then a mean of 288 samples that hit or miss (p ≈ 0.1): the image's sum has a standard error of about 0.5
    // on ~90, the bound below 3.5 of them.
    const RenderedImage pinhole = renderSceneText(scene(0), {.passes = 16});
    const RenderedImage lens = renderSceneText(scene(r), {.passes = 288});
    auto moments = [&](const RenderedImage& image, double& sum, double& m2) {
        sum = 0, m2 = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const double dx = x + 0.5 - size / 2, dy = y + 0.5 - size / 2, value = image.at(x, y).x;
                sum += value;
                m2 += value * (dx * dx + dy * dy);
            }
        m2 /= sum;
    };
    double pinholeSum, pinholeM2, lensSum, lensM2;
    moments(pinhole, pinholeSum, pinholeM2);
    moments(lens, lensSum, lensM2);
    const double pixelsPerUnitAtFocus = (size / 2) / (f * std::tan(halfFov));
    const double emitterRadius = s / (z * std::tan(halfFov)) * (size / 2);  // its pinhole image, in pixels
    const double coc = r * std::abs(z - f) / z * pixelsPerUnitAtFocus;      // 10.9 pixels
    EXPECT_NEAR(pinholeSum, M_PI * emitterRadius * emitterRadius, 0.03 * pinholeSum) << "the pinhole's emitter";
    EXPECT_NEAR(lensSum, pinholeSum, 0.02 * pinholeSum) << "flux through the lens";
    EXPECT_NEAR(std::sqrt(2 * lensM2 - emitterRadius * emitterRadius), coc, 0.03 * coc) << "circle of confusion";
}

// Aperture 0 and every other §6 parameter at 0 (written out) render the §5 image bit for bit.
TEST(FutureWorkRender, EveryParameterAtZeroIsTheSection5Image) {
    const std::string settings =
        "SceneSettings\n{\nRenderWidth 24\nRenderHeight 16\nReflectionQuality 2\nIndirectQuality 1\n}\n"
        "PointLight\n{\nPosition 2 4 6\n}\n"
        "Material\n{\nName floor\nReflectionAmount 0.5\nReflectionAngle 10\n}\n";
    const std::string objects =
        "Sphere\n{\nMaterial glass\nCenter 0 0 0\nRadius 1\n}\n"
        "Box\n{\nMaterial floor\nTranslation 0 -1.5 0\nScale 10 1 10\n}\n";
    const std::string section5 = settings + "Camera\n{\nPOV 0 1 6\n}\n" +
                                 "Material\n{\nName glass\nOpacity 0.2\nRefractionIndex 1.4\nReflectionAmount 0.3\n}\n" +
                                 objects;
    const std::string zeros = settings + "Camera\n{\nPOV 0 1 6\nAperture 0\nFocalDistance 3\nLensQuality 5\n}\n" +
                              "Material\n{\nName glass\nOpacity 0.2\nRefractionIndex 1.4\nReflectionAmount 0.3\n"
                              "Fresnel 0\nRefractionAngle 0\nDispersion 0\nScatteringDistance 0 0 0\n}\n" +
                              objects;
    const RenderedImage a = renderSceneText(section5, {.passes = 3});
    const RenderedImage b = renderSceneText(zeros, {.passes = 3});
    ASSERT_FALSE(a.pixels.empty());
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        ASSERT_EQ(a.pixels[i].x, b.pixels[i].x) << i;
        ASSERT_EQ(a.pixels[i].y, b.pixels[i].y) << i;
        ASSERT_EQ(a.pixels[i].z, b.pixels[i].z) << i;
    }
}

// A glass slab of n = 1 (no bending) with a 40° transmission cone before a wall that only emits: every direction
// of the cone about a near-head-on ray crosses both faces and finds the wall, so the glossy slab passes all
// the light a clear one does. A direction wrongly taken as staying inside, or lost on the way, shows as < 1.
TEST(GlossyTransmissionRender, ConeThroughAClearSlabKeepsTheLight) {
    const std::string scene =
        "SceneSettings\n{\nRenderWidth 16\nRenderHeight 16\nReflectionQuality 3\nIndirectQuality 0\n}\n"
        "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 5\n}\n"
        "Material\n{\nName glass\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nOpacity 0\nRefractionIndex 1\n"
        "RefractionAngle 40\n}\n"
        "Material\n{\nName wall\nDiffuseColor 0 0 0\nSpecularColor 0 0 0\nEmissiveColor 1 1 1\n}\n"
        "Box\n{\nMaterial glass\nScale 100 100 1\n}\n"
        "Box\n{\nMaterial wall\nTranslation 0 0 -3\nScale 1000 1000 1\n}\n";
    const RenderedImage image = renderSceneText(scene, {.passes = 18});
    ASSERT_FALSE(image.pixels.empty());
    for (const Vec3& p : image.pixels) EXPECT_EQ(p.x, 1.0f);
}

}  // namespace
}  // namespace trazo::test
