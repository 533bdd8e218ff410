// The BSDF of SPEC §7 against its own definition: each sampler's directions follow its pdf (χ²), the pdf
// integrates to the share of directions the lobes keep, sample weights average to the albedo that evalCos
// integrates to, the reflecting lobes are reciprocal and no lobe returns more than arrives.
#include "shading/bsdf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "support/sphere_patch.h"

namespace trazo {
namespace {

MaterialData material(Vec3 kd, Vec3 ks, float roughness) {
    MaterialData m{};
    m.diffuse = kd;
    m.specular = ks;
    m.roughness = roughness;
    m.opacity = 1.0f;
    m.refractionIndex = 1.0f;
    for (int32_t& t : m.textures) t = kNoTexture;
    return m;
}

const Vec3 kN(0.0f, 0.0f, 1.0f);

Bsdf bsdfOf(const MaterialData& m, bool entering = true) {
    const ShadingPoint sp(Vec3(0.0f), 0.0f, kN, kN, kN);
    return makeBsdf(m, sp, entering);
}

Vec3 directionAt(float cosTheta, float phi) {
    const float s = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return Vec3(s * std::cos(phi), s * std::sin(phi), cosTheta);
}

using Patch = test::SpherePatch;

struct Case {
    const char* name;
    MaterialData m;
    Vec3 wo;
    Patch patch;  // where the lobes send directions
};

std::vector<Case> nonDeltaCases() {
    const Vec3 oblique = normalize(Vec3(0.6f, 0.0f, 0.8f));
    std::vector<Case> cases;
    cases.push_back({"lambert", material(Vec3(0.8f), Vec3(0.0f), 0.0f), oblique});
    cases.push_back({"oren-nayar", material(Vec3(0.8f), Vec3(0.0f), 0.8f), oblique});
    cases.push_back({"glossy", material(Vec3(0.0f), Vec3(0.9f), 0.3f), kN});
    cases.push_back({"glossy oblique", material(Vec3(0.0f), Vec3(0.9f), 0.2f), oblique});
    cases.push_back({"diffuse + glossy", material(Vec3(0.5f), Vec3(0.5f), 0.4f), oblique});
    MaterialData cone = material(Vec3(0.0f), Vec3(1.0f), 0.5f);
    cone.reflectionAmount = 1.0f;
    cone.reflectionHalfAngle = 0.2f;
    cases.push_back({"reflection cone", cone, kN, Patch{kN, 0.25f}});
    MaterialData glass = material(Vec3(0.0f), Vec3(0.0f), 0.5f);
    glass.opacity = 0.0f;
    glass.refractionIndex = 1.5f;
    glass.refractionHalfAngle = 0.15f;
    cases.push_back({"transmission cone", glass, kN, Patch{-kN, 0.2f}});
    return cases;
}

TEST(Bsdf, PdfIntegratesToTheShareOfDirectionsKept) {
    for (const Case& c : nonDeltaCases()) {
        const Bsdf b = bsdfOf(c.m);
        const double total = c.patch.integral([&](Vec3 wi) { return b.pdf(c.wo, wi); });
        // Microfacet and cone directions below the surface are lost: a little under 1 at most.
        EXPECT_LE(total, 1.005) << c.name;
        EXPECT_GE(total, 0.97) << c.name;
    }
}

// χ² of 200 000 samples in 16 × 32 (θ, φ) cells of the case's patch against the pdf integrated over each cell; cells expecting
// fewer than 5 are pooled. Rejects at about 5 standard deviations of χ²: a pdf that is wrong by 5% over a tenth of
// the sphere's mass shifts χ² by about 50 σ at this count, so the test has power near 1 for such errors.
TEST(Bsdf, SamplesFollowThePdf) {
    constexpr int kCos = 16, kPhi = 32, kSamples = 200000;
    for (const Case& c : nonDeltaCases()) {
        const Bsdf b = bsdfOf(c.m);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        std::vector<double> observed(kCos * kPhi, 0.0), expected(kCos * kPhi, 0.0);
        const ConeFrame f = coneFrame(c.patch.axis);
        auto cell = [&](Vec3 w) {
            const double theta = std::acos(std::clamp(double(dot(w, f.axis)), -1.0, 1.0));
            double phi = std::atan2(double(dot(w, f.t2)), double(dot(w, f.t1)));
            if (phi < 0.0) phi += 2.0 * M_PI;
            if (theta >= c.patch.thetaMax) return -1;
            const int i = std::min(kCos - 1, int(theta / c.patch.thetaMax * kCos));
            const int j = std::min(kPhi - 1, int(phi / (2.0 * M_PI) * kPhi));
            return i * kPhi + j;
        };
        int kept = 0;
        for (int s = 0; s < kSamples; ++s) {
            BsdfSample bs;
            const float l = u(rng), u1 = u(rng), u2 = u(rng);
            if (!b.sample(c.wo, l, u1, u2, bs)) continue;
            ++kept;
            const int k = cell(bs.wi);
            ASSERT_GE(k, 0) << c.name << ": a direction outside the lobes' patch";
            observed[k] += 1.0;
        }
        constexpr int kSub = 12;  // each cell's integral from a 12 × 12 grid inside it
        const double dTheta = c.patch.thetaMax / (kCos * kSub), dPhi = 2.0 * M_PI / (kPhi * kSub);
        for (int i = 0; i < kCos * kSub; ++i) {
            const double theta = (i + 0.5) * dTheta;
            for (int j = 0; j < kPhi * kSub; ++j) {
                const double w = b.pdf(c.wo, c.patch.at(theta, (j + 0.5) * dPhi)) * std::sin(theta) * dTheta * dPhi;
                expected[(i / kSub) * kPhi + j / kSub] += w * kSamples;
            }
        }
        double chi2 = 0.0, pooledObs = 0.0, pooledExp = 0.0;
        int dof = -1;
        for (size_t k = 0; k < observed.size(); ++k) {
            if (expected[k] < 5.0) {
                pooledObs += observed[k];
                pooledExp += expected[k];
                continue;
            }
            chi2 += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
            ++dof;
        }
        if (pooledExp >= 5.0) {
            chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
            ++dof;
        }
        ASSERT_GT(dof, 10) << c.name;
        EXPECT_LT(chi2, dof + 5.0 * std::sqrt(2.0 * dof)) << c.name << ": χ² " << chi2 << " over " << dof << " dof";
        EXPECT_GT(kept, kSamples / 2) << c.name;
    }
}

// The sample weights average to ∫ f·|cos| dω: what a path tracer's estimate of reflected light relies on.
TEST(Bsdf, SampleWeightsAverageToTheAlbedo) {
    for (const Case& c : nonDeltaCases()) {
        const Bsdf b = bsdfOf(c.m);
        const double albedo = c.patch.integral([&](Vec3 wi) { return b.evalCos(c.wo, wi).x; });
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        double sum = 0.0;
        constexpr int kSamples = 400000;
        for (int s = 0; s < kSamples; ++s) {
            BsdfSample bs;
            const float l = u(rng), u1 = u(rng), u2 = u(rng);
            if (b.sample(c.wo, l, u1, u2, bs)) sum += bs.weight.x;
        }
        EXPECT_NEAR(sum / kSamples, albedo, 0.01 + 0.01 * albedo) << c.name;
    }
}

TEST(Bsdf, ReflectingLobesAreReciprocal) {
    MaterialData m = material(Vec3(0.7f), Vec3(0.6f), 0.45f);
    m.fresnel = 1u;
    m.refractionIndex = 1.5f;
    const Bsdf b = bsdfOf(m);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.05f, 0.999f), phi(0.0f, 2.0f * kPi);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 wo = directionAt(u(rng), phi(rng)), wi = directionAt(u(rng), phi(rng));
        const float fwd = b.evalCos(wo, wi).x / wi.z, back = b.evalCos(wi, wo).x / wo.z;
        EXPECT_NEAR(fwd, back, 2e-4f * std::max(1.0f, fwd)) << i;
    }
}

// White lobes: ∫ f·cos ≤ 1 from every direction (the grid integral's error is well under 0.5%).
TEST(Bsdf, NoLobeReflectsMoreThanArrives) {
    std::vector<MaterialData> whites;
    for (float sigma : {0.0f, 0.5f, 1.0f}) whites.push_back(material(Vec3(1.0f), Vec3(0.0f), sigma));
    for (float r : {0.02f, 0.3f, 1.0f}) whites.push_back(material(Vec3(0.0f), Vec3(1.0f), r));
    MaterialData cone = material(Vec3(0.0f), Vec3(1.0f), 0.5f);
    cone.reflectionAmount = 1.0f;
    cone.reflectionHalfAngle = 0.3f;
    whites.push_back(cone);
    for (const MaterialData& m : whites) {
        const Bsdf b = bsdfOf(m);
        for (float cosO : {1.0f, 0.7f, 0.3f, 0.05f}) {
            const Vec3 wo = directionAt(cosO, 0.3f);
            const Patch patch{b.mirror(wo), m.reflectionAmount > 0.0f ? 0.35f : kPi};  // fine where lobes peak
            const double albedo = patch.integral([&](Vec3 wi) { return b.evalCos(wo, wi).x; });
            EXPECT_LE(albedo, 1.005) << "roughness " << m.roughness << " cos " << cosO;
        }
    }
    // Lambert's albedo is exactly Kd.
    const Bsdf lambert = bsdfOf(material(Vec3(0.6f), Vec3(0.0f), 0.0f));
    EXPECT_NEAR(Patch{}.integral([&](Vec3 wi) { return lambert.evalCos(kN, wi).x; }), 0.6, 1e-3);
}

TEST(Bsdf, DeltaLobesSampleTheirOneDirection) {
    MaterialData mirror = material(Vec3(0.0f), Vec3(0.8f), 0.5f);
    mirror.reflectionAmount = 1.0f;
    const Vec3 wo = normalize(Vec3(0.6f, 0.0f, 0.8f));
    BsdfSample s;
    ASSERT_TRUE(bsdfOf(mirror).sample(wo, 0.5f, 0.5f, 0.5f, s));
    EXPECT_TRUE(s.delta);
    EXPECT_NEAR(s.wi.x, -0.6f, 1e-6f);
    EXPECT_NEAR(s.wi.z, 0.8f, 1e-6f);
    EXPECT_NEAR(s.weight.x, 0.8f, 1e-6f);
    EXPECT_EQ(bsdfOf(mirror).evalCos(wo, s.wi).x, 0.0f) << "a delta lobe has no value to evaluate";

    MaterialData glass = material(Vec3(0.0f), Vec3(0.0f), 0.5f);
    glass.opacity = 0.0f;
    glass.refractionIndex = 1.5f;
    ASSERT_TRUE(bsdfOf(glass).sample(kN, 0.5f, 0.5f, 0.5f, s));
    EXPECT_NEAR(s.wi.z, -1.0f, 1e-6f) << "normal incidence goes straight through";
    EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);

    // With Fresnel, the share reflected is F: (0.5/2.5)² = 0.04 at normal incidence from air into 1.5.
    glass.fresnel = 1u;
    const Bsdf fresnelGlass = bsdfOf(glass);
    int reflected = 0;
    constexpr int kDraws = 100000;
    for (int i = 0; i < kDraws; ++i) {
        ASSERT_TRUE(fresnelGlass.sample(kN, 0.5f, (i + 0.5f) / kDraws, 0.5f, s));
        reflected += s.wi.z > 0.0f;
    }
    EXPECT_NEAR(double(reflected) / kDraws, 0.04, 1e-3);
    // Leaving the glass beyond the critical angle (41.8°): total internal reflection.
    const Bsdf leaving = bsdfOf(glass, false);
    ASSERT_TRUE(leaving.sample(directionAt(0.5f, 0.0f), 0.5f, 0.99f, 0.5f, s));
    EXPECT_GT(s.wi.z, 0.0f);
}

}  // namespace
}  // namespace trazo
