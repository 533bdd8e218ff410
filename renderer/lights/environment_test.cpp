// The environment of SPEC §7 against its definition: the map's mapping and rotation, sampleEnvironment's pdf
// and radiance against pdfEnvironment and environmentRadiance, the pdf's integral and support, a χ² test of its
// directions, and the irradiance it estimates against quadrature, a small bright sun included.
#include "lights/environment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "flatten/environment_tables.h"
#include "support/chi_square.h"
#include "support/counter_uniform.h"
#include "support/sphere_patch.h"

namespace trazo {
namespace {

constexpr double kPi = 3.14159265358979323846;

// SPEC §7's inverse, written out here: the world direction whose map coordinates are (u, v) under the rotation.
Vec3 mapDirection(double u, double v, double rotationDegrees) {
    const double theta = kPi * v, phi = 2.0 * kPi * (u - 0.5), r = rotationDegrees * kPi / 180.0;
    const double x = std::sin(theta) * std::sin(phi), z = -std::sin(theta) * std::cos(phi);  // d′
    return Vec3(float(std::cos(r) * x + std::sin(r) * z), float(std::cos(theta)),
                float(-std::sin(r) * x + std::cos(r) * z));  // d′ turned by +rotation about +Y
}

// A map of width × height texels, texel (i, j) (j = 0 the top row) the mean of f(u, v) over n × n points of it,
// stored as TextureImage stores it (row 0 the bottom).
TextureImage makeMap(int width, int height, const std::function<Vec3(double, double)>& f, int n = 1) {
    TextureImage image;
    image.width = width;
    image.height = height;
    image.texels.resize(size_t(width) * height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            Vec3 sum(0.0f);
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) sum += f((i + (a + 0.5) / n) / width, (j + (b + 0.5) / n) / height);
            image.texels[size_t(height - 1 - j) * width + i] = sum / float(n * n);
        }
    return image;
}

// A clear sky as generate_sky draws it: a gradient above the horizon, dark ground below, and a sun disk of angular
// radius sunDegrees and radiance sunRadiance at elevation 35° (u = 0.35), its texels the disk's cover of them
// (32 × 32 points each, so the sun's power does not depend on where the texel grid falls).
TextureImage sunSky(int width, int height, double sunDegrees, double sunRadiance) {
    const Vec3 sun = mapDirection(0.35, 0.5 - 35.0 / 180.0, 0.0);
    const double cosSun = std::cos(sunDegrees * kPi / 180.0);
    TextureImage image = makeMap(width, height, [](double u, double v) {
        const Vec3 d = mapDirection(u, v, 0.0);
        if (d.y < 0.0f) return Vec3(0.1f, 0.085f, 0.07f);
        const float t = std::sqrt(d.y);
        return (Vec3(0.75f, 0.85f, 1.0f) * (1.0f - t) + Vec3(0.12f, 0.28f, 0.75f) * t) * 0.35f;
    });
    const double reach = std::cos(sunDegrees * kPi / 180.0 + 3.0 * kPi / height);  // texels the disk may touch
    constexpr int kPoints = 32;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            if (dot(mapDirection((i + 0.5) / width, (j + 0.5) / height, 0.0), sun) < reach) continue;
            int inside = 0;
            for (int a = 0; a < kPoints; ++a)
                for (int b = 0; b < kPoints; ++b) {
                    const Vec3 d =
                        mapDirection((i + (a + 0.5) / kPoints) / width, (j + (b + 0.5) / kPoints) / height, 0.0);
                    inside += dot(d, sun) >= cosSun ? 1 : 0;
                }
            image.texels[size_t(height - 1 - j) * width + i] +=
                Vec3(1.0f, 0.95f, 0.85f) * float(sunRadiance * inside / (kPoints * kPoints));
        }
    return image;
}

// The flattened environment and its view (the view points into the arrays: neither is copied).
struct Environment {
    SceneArrays arrays;
    SceneView view{};
    Environment(Vec3 background, float rotationDegrees, const TextureImage* image) {
        appendEnvironment(background, rotationDegrees, image, arrays);
        view = hostView(arrays);
    }
    Environment(const Environment&) = delete;
    const EnvironmentData& data() const { return arrays.environment.at(0); }
};

// Environments every sampling test runs on.
struct Case {
    const char* name;
    std::shared_ptr<TextureImage> image;  // null: no map
    Vec3 background;
    float rotation;
};

std::vector<Case> cases() {
    auto map = [](TextureImage image) { return std::make_shared<TextureImage>(std::move(image)); };
    // One lit texel, in the seam column and the top row: its bilinear footprint crosses the seam and the pole.
    TextureImage corner = makeMap(16, 8, [](double, double) { return Vec3(0.0f); });
    corner.texels[size_t(7) * 16 + 0] = Vec3(5.0f, 1.0f, 0.0f);
    corner.texels[size_t(3) * 16 + 9] = Vec3(0.0f, 0.0f, 2.0f);
    return {
        {"uniform", nullptr, Vec3(0.5f, 1.0f, 2.0f), 0.0f},
        {"sun sky", map(sunSky(256, 128, 0.5, 30000.0)), Vec3(1.0f), 30.0f},
        {"two texels", map(corner), Vec3(1.0f, 2.0f, 0.5f), -70.0f},
        {"5 x 3", map(makeMap(5, 3, [](double u, double v) { return Vec3(float(u + v), float(1.0 - v), 0.5f); })),
         Vec3(1.0f), 0.0f},
        {"4096 x 64 gradient",  // more texels than the grid's columns: merged into cells
         map(makeMap(4096, 64, [](double u, double v) { return Vec3(float(u * v * v), 0.2f, float(v)); })), Vec3(1.0f),
         10.0f},
    };
}

// ∫ g dω over the sphere, by midpoints of a (u, v) grid `refine` times finer than the sampling grid (its cells
// whole inside each grid cell) with dω = 2π² sin θ du dv.
double integrateOverMap(const EnvironmentData& env, float rotation, const std::function<double(Vec3)>& g,
                        uint32_t refineU, uint32_t refineV) {
    const uint32_t nu = env.cols * refineU, nv = env.rows * refineV;
    double sum = 0.0;
    for (uint32_t j = 0; j < nv; ++j) {
        const double v = (j + 0.5) / nv, sinTheta = std::sin(kPi * v);
        for (uint32_t i = 0; i < nu; ++i) sum += g(mapDirection((i + 0.5) / nu, v, rotation)) * sinTheta;
    }
    return sum * 2.0 * kPi * kPi / (double(nu) * nv);
}

TEST(EnvironmentMapping, ForwardIsTheMapCentreAndTheAxesAreWhereSpecSaysSo) {
    EnvironmentData env{};
    env.cosRotation = 1.0f;
    const EnvironmentUv forward = environmentUv(env, Vec3(0.0f, 0.0f, -1.0f));
    EXPECT_FLOAT_EQ(forward.u, 0.5f);
    EXPECT_FLOAT_EQ(forward.v, 0.5f);
    EXPECT_FLOAT_EQ(environmentUv(env, Vec3(0.0f, 1.0f, 0.0f)).v, 0.0f) << "+Y: the top row";
    EXPECT_FLOAT_EQ(environmentUv(env, Vec3(0.0f, -1.0f, 0.0f)).v, 1.0f) << "−Y: the bottom row";
    EXPECT_FLOAT_EQ(environmentUv(env, Vec3(1.0f, 0.0f, 0.0f)).u, 0.75f);
    EXPECT_FLOAT_EQ(environmentUv(env, Vec3(-1.0f, 0.0f, 0.0f)).u, 0.25f);
    EXPECT_FLOAT_EQ(environmentUv(env, normalize(Vec3(0.0f, 1.0f, -1.0f))).v, 0.25f);
    // environmentDirection is environmentUv's inverse, and the SPEC's inverse written out above.
    CounterUniform uniform(3);
    for (int k = 0; k < 1000; ++k) {
        const float u = uniform(0.01f, 0.99f), v = uniform(0.01f, 0.99f);
        const Vec3 d = environmentDirection(env, u, v), spec = mapDirection(u, v, 0.0);
        EXPECT_NEAR(length(d - spec), 0.0f, 2e-6f);
        const EnvironmentUv back = environmentUv(env, d);
        EXPECT_NEAR(back.u, u, 2e-6f);
        EXPECT_NEAR(back.v, v, 2e-6f);
    }
}

// A map of three bands: red top row, blue bottom row, green between. +Y reads red and −Y blue (clamped at the
// poles, not wrapped), the horizon green, and half-way between the top two rows' centres their mean.
TEST(EnvironmentMapping, TheTopRowIsUpAndTexelsAreBilinear) {
    const TextureImage bands = makeMap(8, 4, [](double, double v) {
        return v < 0.25 ? Vec3(1.0f, 0.0f, 0.0f) : (v > 0.75 ? Vec3(0.0f, 0.0f, 1.0f) : Vec3(0.0f, 1.0f, 0.0f));
    });
    const Environment e(Vec3(2.0f), 0.0f, &bands);
    auto expectRadiance = [&](Vec3 d, Vec3 want) {
        const Vec3 got = environmentRadiance(e.view, normalize(d));
        EXPECT_NEAR(got.x, want.x, 1e-5f) << d.x << " " << d.y << " " << d.z;
        EXPECT_NEAR(got.y, want.y, 1e-5f) << d.x << " " << d.y << " " << d.z;
        EXPECT_NEAR(got.z, want.z, 1e-5f) << d.x << " " << d.y << " " << d.z;
    };
    expectRadiance(Vec3(0.0f, 1.0f, 0.0f), Vec3(2.0f, 0.0f, 0.0f));
    expectRadiance(Vec3(0.3f, 1.0f, 0.2f), Vec3(2.0f, 0.0f, 0.0f));  // v = 0.03: inside the top row's clamp
    expectRadiance(Vec3(0.0f, -1.0f, 0.0f), Vec3(0.0f, 0.0f, 2.0f));
    expectRadiance(Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, 2.0f, 0.0f));
    expectRadiance(Vec3(0.0f, 1.0f, -1.0f), Vec3(1.0f, 1.0f, 0.0f));  // v = 0.25: between rows 0 and 1
    EXPECT_EQ(environmentRadiance(Environment(Vec3(0.0f), 0.0f, &bands).view, Vec3(0.0f, 1.0f, 0.0f)).x, 0.0f)
        << "a black background: no environment";
}

// SPEC §7 reads the map at d′ = d turned by −EnvironmentRotation about +Y: a right-handed turn of 90° takes −Z to
// −X, so with EnvironmentRotation 90 the map's centre (a bright lobe about d′ = −Z) is seen towards −X.
TEST(EnvironmentMapping, RotationTurnsTheMapAboutY) {
    const TextureImage lobe = makeMap(64, 32, [](double u, double v) {
        const float c = std::max(0.0f, -mapDirection(u, v, 0.0).z);
        return Vec3(std::pow(c, 8.0f));
    });
    const Environment still(Vec3(1.0f), 0.0f, &lobe), turned(Vec3(1.0f), 90.0f, &lobe);
    EXPECT_GT(environmentRadiance(still.view, Vec3(0.0f, 0.0f, -1.0f)).x, 0.9f);
    EXPECT_LT(environmentRadiance(still.view, Vec3(-1.0f, 0.0f, 0.0f)).x, 1e-3f);
    EXPECT_GT(environmentRadiance(turned.view, Vec3(-1.0f, 0.0f, 0.0f)).x, 0.9f);
    EXPECT_LT(environmentRadiance(turned.view, Vec3(0.0f, 0.0f, -1.0f)).x, 1e-3f);
    CounterUniform uniform(5);
    for (int k = 0; k < 200; ++k) {
        const Vec3 d = uniform.direction();
        const Vec3 back(-d.z, d.y, d.x);  // d turned by −90° about +Y
        EXPECT_NEAR(environmentRadiance(turned.view, d).x, environmentRadiance(still.view, back).x, 1e-5f);
    }
}

// sampleEnvironment's pdf is the density of the cell it drew; pdfEnvironment finds the cell again from the direction.
// They agree but where float rounding of the direction puts a sample drawn within about 1e-5 of a cell's edge into
// its neighbour (a set of measure 0; the sample keeps the density it was drawn with): at most 1 in 2000 samples.
TEST(EnvironmentSampling, SamplesCarryPdfEnvironmentAndEnvironmentRadiance) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Environment e(c.background, c.rotation, c.image.get());
        const EnvironmentData& env = e.data();
        CounterUniform uniform(11);
        int taken = 0, atAnEdge = 0;
        constexpr int kSamples = 20000;
        for (int k = 0; k < kSamples; ++k) {
            const float u1 = uniform(0.0f, 1.0f), u2 = uniform(0.0f, 1.0f);
            const LightSample s = sampleEnvironment(e.view, u1, u2);
            if (!(s.pdf > 0.0f)) continue;
            ++taken;
            ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
            ASSERT_FALSE(s.delta);
            ASSERT_EQ(s.distance, INFINITY);
            const Vec3 radiance = environmentRadiance(e.view, s.wi);
            ASSERT_EQ(s.radiance.x, radiance.x);
            ASSERT_EQ(s.radiance.z, radiance.z);
            const float pdf = pdfEnvironment(e.view, s.wi);
            if (std::fabs(pdf - s.pdf) <= 1e-5f * s.pdf) continue;
            const EnvironmentUv uv = environmentUv(env, s.wi);
            const double x = double(uv.u) * env.cols, y = double(uv.v) * env.rows;
            EXPECT_LT(std::min({x - std::floor(x), std::ceil(x) - x, y - std::floor(y), std::ceil(y) - y}), 1e-3)
                << k << ": pdf " << s.pdf << " where pdfEnvironment gives " << pdf;
            ++atAnEdge;
        }
        EXPECT_EQ(taken, kSamples) << "every sample has a direction with a density";
        EXPECT_LE(atAnEdge, kSamples / 2000);
    }
}

TEST(EnvironmentSampling, PdfIntegratesToOne) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Environment e(c.background, c.rotation, c.image.get());
        auto pdf = [&](Vec3 w) { return double(pdfEnvironment(e.view, w)); };
        if (e.data().rows == 0) {
            EXPECT_NEAR(test::SpherePatch{Vec3(0.0f, 1.0f, 0.0f)}.integral(pdf), 1.0, 1e-4);
            continue;
        }
        // The pdf is constant over each grid cell in (u, v): midpoints of whole sub-cells integrate it exactly.
        EXPECT_NEAR(integrateOverMap(e.data(), c.rotation, pdf, 2, 2), 1.0, 1e-4);
    }
    // A smooth map, on SpherePatch's θ–φ grid about +Y, which knows nothing of the map's cells.
    const TextureImage smooth = makeMap(128, 64, [](double u, double v) { return Vec3(float(0.2 + u * (1.0 - v))); });
    const Environment e(Vec3(1.0f), 20.0f, &smooth);
    EXPECT_NEAR(test::SpherePatch{Vec3(0.0f, 1.0f, 0.0f)}.integral([&](Vec3 w) { return pdfEnvironment(e.view, w); },
                                                                   1024, 1024),
                1.0, 2e-3);
}

// Exact support: wherever the bilinear radiance is not 0 the pdf is positive, including the cells a lit texel's
// bilinear footprint reaches beyond its own (across the seam and into the pole's clamp); far from every lit
// texel the pdf is 0, as is the radiance.
TEST(EnvironmentSampling, PdfIsPositiveExactlyWhereThereIsRadiance) {
    const Case c = cases()[2];  // two texels
    const Environment e(c.background, c.rotation, c.image.get());
    const uint32_t n = 8 * 16;  // 8 points a texel
    int lit = 0, dark = 0;
    for (uint32_t j = 0; j < n / 2; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const Vec3 d = mapDirection((i + 0.5) / n, (j + 0.5) / (n / 2), c.rotation);
            const bool radiance = !isBlack(environmentRadiance(e.view, d));
            const float pdf = pdfEnvironment(e.view, d);
            if (radiance) {
                EXPECT_GT(pdf, 0.0f) << i << " " << j;
            }
            lit += radiance ? 1 : 0;
            dark += pdf == 0.0f ? 1 : 0;
        }
    EXPECT_GT(lit, 8 * 8 * 2) << "two texels' footprints";
    EXPECT_GT(dark, int(n * n / 2) * 3 / 4) << "most of the map has no radiance, and no density";
}

// A χ² histogram: samples in Mitsuba's 50 × 101 cells of world azimuth ψ = atan2(x, −z) × cos θ, and each cell's
// expected count from pdfEnvironment integrated exactly over it. ψ reads the map at u = 0.5 + (ψ + rotation)/(2π)
// (mod 1) and cos θ at v = acos(cos θ)/π, so each cell is a rectangle in (u, v), cut here at the sampling grid's
// lines into pieces over which pdf·sin θ is constant. `sun`: the expected counts of pieces brighter than 1000.
struct Histogram {
    static constexpr int kPhi = kChiSquarePhiBins, kCos = kChiSquareResolution;
    std::vector<double> observed, expected, sun;

    Histogram(const Environment& e, float rotation, int samples)
        : observed(kPhi * kCos, 0.0), expected(kPhi * kCos, 0.0), sun(kPhi * kCos, 0.0) {
        CounterUniform uniform(17);
        for (int k = 0; k < samples; ++k) {
            const float u1 = uniform(0.0f, 1.0f), u2 = uniform(0.0f, 1.0f);
            const Vec3 w = sampleEnvironment(e.view, u1, u2).wi;
            const int i = std::min(kPhi - 1, int((std::atan2(double(w.x), -double(w.z)) + kPi) / (2.0 * kPi) * kPhi));
            const int j = std::min(kCos - 1, int((double(w.y) + 1.0) / 2.0 * kCos));
            observed[j * kPhi + i] += 1.0;
        }
        const EnvironmentData& env = e.data();
        for (int j = 0; j < kCos; ++j) {
            const double v0 = std::acos(std::min(1.0, -1.0 + 2.0 * (j + 1) / kCos)) / kPi;
            const double v1 = std::acos(-1.0 + 2.0 * j / kCos) / kPi;
            for (int i = 0; i < kPhi; ++i) {
                const double ua = double(i) / kPhi + rotation / 360.0;  // 0.5 + (ψ + rotation)/(2π), ψ = −π + 2πi/50
                for (int part = 0; part < 2; ++part) {  // the rectangle wrapped into [0, 1): at most two parts
                    const double u0 = std::max(0.0, ua - std::floor(ua) - part),
                                 u1 = ua - std::floor(ua) - part + 1.0 / kPhi;
                    if (!(u1 > u0)) continue;
                    for (uint32_t gy = uint32_t(v0 * env.rows); gy < env.rows && gy < v1 * env.rows; ++gy)
                        for (uint32_t gx = uint32_t(u0 * env.cols); gx < env.cols && gx < u1 * env.cols; ++gx) {
                            const double pu0 = std::max(u0, double(gx) / env.cols),
                                         pu1 = std::min(u1, (gx + 1.0) / env.cols);
                            const double pv0 = std::max(v0, double(gy) / env.rows),
                                         pv1 = std::min(v1, (gy + 1.0) / env.rows);
                            if (!(pu1 > pu0 && pv1 > pv0)) continue;
                            const Vec3 w = mapDirection(0.5 * (pu0 + pu1), 0.5 * (pv0 + pv1), rotation);
                            const double sinTheta = std::sqrt(double(w.x) * w.x + double(w.z) * w.z);
                            const double count = pdfEnvironment(e.view, w) * 2.0 * kPi * kPi * sinTheta * (pu1 - pu0) *
                                                 (pv1 - pv0) * samples;
                            expected[j * kPhi + i] += count;
                            if (environmentRadiance(e.view, w).x > 1000.0f) sun[j * kPhi + i] += count;
                        }
                }
            }
        }
    }
};

// Pearson's χ² (support/chi_square.h: cells expecting fewer than 5 pooled, α = 0.01) of sampleEnvironment's
// directions against pdfEnvironment: 10⁶ of the sun sky (turned by 30°), and 3·10⁵ of the two-texel and 5 × 3
// maps, whose 64 × 32 grids are coarse enough beside the histogram's cells to show a density wrong inside a grid
// cell. Power: the sun's pieces (radiance above 1000) draw 74 % of the sun sky's samples. A pdf that gave them 2 %
// more (the rest 5.6 % fewer) raises χ² by about 1140 in expectation, 11 times the null's spread √(2·dof) ≈ 100,
// and must be rejected (it raises it by 1190 here); 1 % more would raise it by about 285 (2.9 σ: power about 0.7
// at α = 0.01).
TEST(EnvironmentSampling, DirectionsFollowThePdf) {
    const std::vector<Case> all = cases();
    for (const int which : {1, 2, 3}) {
        const Case& c = all[which];
        SCOPED_TRACE(c.name);
        const Environment e(c.background, c.rotation, c.image.get());
        const Histogram h(e, c.rotation, which == 1 ? kChiSquareSamples : 300000);
        const ChiSquareResult r = chiSquareTest(h.observed, h.expected);
        EXPECT_TRUE(r.accepts(kChiSquareSignificance))
            << "χ² " << r.statistic << " over " << r.dof << " dof, p " << r.pValue << " " << r.failure;
        std::cout << "[ χ²        ] " << c.name << ": " << r.statistic << " over " << r.dof << " dof, p = " << r.pValue
                  << "\n";
        if (which != 1) continue;

        double sun = 0.0;
        for (double s : h.sun) sun += s;
        ASSERT_GT(sun, 0.5 * kChiSquareSamples) << "the sun draws most samples";
        std::vector<double> wrong(h.expected.size());
        const double rest = (kChiSquareSamples - 1.02 * sun) / (kChiSquareSamples - sun);
        for (size_t k = 0; k < wrong.size(); ++k) wrong[k] = h.sun[k] * 1.02 + (h.expected[k] - h.sun[k]) * rest;
        const ChiSquareResult w = chiSquareTest(h.observed, wrong);
        EXPECT_FALSE(w.accepts(kChiSquareSignificance)) << "χ² " << w.statistic << " over " << w.dof << " dof";
        std::cout << "[ χ²        ] the sun's share 2 % off (" << sun / kChiSquareSamples
                  << " of the samples): " << w.statistic << " over " << w.dof << " dof, p = " << w.pValue << "\n";
    }
}

// E[L·cos/pdf] against the quadrature of the irradiance ∫ L·max(0, n·ω) dω within 0.5 %, for surfaces facing up
// and towards the sun sky's sun (−0.81, 0.57, −0.09 once turned by 30°). The quadrature takes midpoints of a (u, v)
// grid whose lines hold every texel centre, so the bilinear L is a polynomial inside each of its cells: 32 a texel side
// for the small maps (the kink of max(0, n·ω) across a lit texel needs them: 8 were 1.5 % off), 8 for the sun sky, and
// 1 every 8 × 1 texels for the smooth 4096 × 64 map.
TEST(EnvironmentSampling, IrradianceEstimateMatchesQuadrature) {
    const Vec3 normals[] = {Vec3(0.0f, 1.0f, 0.0f), normalize(Vec3(-0.8f, 0.6f, -0.2f))};
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Environment e(c.background, c.rotation, c.image.get());
        const bool sun = c.image && c.image->width == 256, large = c.image && c.image->width > 1024;
        for (const Vec3 n : normals) {
            auto irradiance = [&](Vec3 w) {
                return double(environmentRadiance(e.view, w).y) * std::max(0.0f, dot(n, w));
            };
            double quadrature = kPi * c.background.y;
            if (c.image) {
                EnvironmentData texels = e.data();
                texels.cols = uint32_t(c.image->width) / (large ? 8 : 1);
                texels.rows = uint32_t(c.image->height);
                const uint32_t per = large ? 1 : (sun ? 8 : 32);
                quadrature = integrateOverMap(texels, c.rotation, irradiance, per, per);
            }
            // Batches of 2·10⁵ samples until the standard error is under 0.15 % (a 0.5 % bias shows at 3.3 σ).
            CounterUniform uniform(23);
            double sum = 0.0, sum2 = 0.0, mean = 0.0, error = INFINITY;
            int samples = 0;
            while (samples < 8000000 && !(error < 0.0015 * quadrature)) {
                for (int k = 0; k < 200000; ++k) {
                    const float u1 = uniform(0.0f, 1.0f), u2 = uniform(0.0f, 1.0f);
                    const LightSample s = sampleEnvironment(e.view, u1, u2);
                    const double x = s.pdf > 0.0f ? double(s.radiance.y) * std::max(0.0f, dot(n, s.wi)) / s.pdf : 0.0;
                    sum += x;
                    sum2 += x * x;
                }
                samples += 200000;
                mean = sum / samples;
                error = std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples);
            }
            EXPECT_LT(error, 0.0015 * quadrature) << samples << " samples";
            EXPECT_NEAR(mean, quadrature, 0.005 * quadrature) << "standard error " << error;
        }
    }
}

// The "a small bright sun must converge in tens of passes": the 512 × 256 sky of scenes/assets (a 0.5°
// sun, 1.4 texels across, giving 90 % of the irradiance) lights a horizontal surface. 400 estimates of 256
// samples each: their RMS relative error must be under 3.5 % (it is 2.9 %), where uniform directions (the same
// environment, no importance) are above 100 % (850 %).
TEST(EnvironmentSampling, SmallBrightSunConvergesInAFewHundredSamples) {
    const TextureImage sky = sunSky(512, 256, 0.5, 30000.0);
    const Environment e(Vec3(1.0f), 0.0f, &sky);
    const Vec3 up(0.0f, 1.0f, 0.0f);
    auto irradiance = [&](Vec3 w) { return double(environmentRadiance(e.view, w).y) * std::max(0.0f, w.y); };
    EnvironmentData texels = e.data();
    texels.cols = 512;
    texels.rows = 256;
    const double truth = integrateOverMap(texels, 0.0f, irradiance, 4, 4);
    constexpr int kEstimates = 400, kSamples = 256;
    CounterUniform uniform(29);
    double importance = 0.0, blind = 0.0;
    for (int k = 0; k < kEstimates; ++k) {
        double a = 0.0, b = 0.0;
        for (int s = 0; s < kSamples; ++s) {
            const float u1 = uniform(0.0f, 1.0f), u2 = uniform(0.0f, 1.0f);
            const LightSample ls = sampleEnvironment(e.view, u1, u2);
            if (ls.pdf > 0.0f) a += double(ls.radiance.y) * std::max(0.0f, dot(up, ls.wi)) / ls.pdf;
            const float y = 1.0f - 2.0f * u1, r = std::sqrt(std::max(0.0f, 1.0f - y * y));
            const Vec3 w(r * std::cos(2.0f * float(kPi) * u2), y, r * std::sin(2.0f * float(kPi) * u2));
            b += irradiance(w) * 4.0 * kPi;
        }
        importance += (a / kSamples - truth) * (a / kSamples - truth);
        blind += (b / kSamples - truth) * (b / kSamples - truth);
    }
    const double rmsImportance = std::sqrt(importance / kEstimates) / truth;
    const double rmsBlind = std::sqrt(blind / kEstimates) / truth;
    EXPECT_LT(rmsImportance, 0.035);
    EXPECT_GT(rmsBlind, 1.0);
    std::cout << "[ sun       ] irradiance " << truth << ", RMS relative error at " << kSamples
              << " samples: " << rmsImportance << " importance-sampled, " << rmsBlind << " uniform\n";
}

// Large maps are sampled on a bounded grid, small ones on a finer one (two cells a texel); a black environment is
// not stored.
TEST(EnvironmentTables, GridIsBoundedAndBlackIsNoEnvironment) {
    auto flat = [](int width, int height) {
        TextureImage image;
        image.width = width;
        image.height = height;
        image.texels.assign(size_t(width) * height, Vec3(1.0f));
        return image;
    };
    std::vector<float> cdf;
    const TextureImage wide = flat(5000, 40), tall = flat(40, 3000), tiny = flat(5, 3), mid = flat(300, 200);
    const EnvironmentData w = environmentTables(Vec3(1.0f), 0.0f, 0, &wide, cdf);
    EXPECT_EQ(w.cols, kMaxEnvironmentCols);
    EXPECT_EQ(w.rows, 80u);
    EXPECT_EQ(cdf.size(), size_t(w.rows + 1) + size_t(w.rows) * (w.cols + 1));
    const EnvironmentData t = environmentTables(Vec3(1.0f), 0.0f, 0, &tall, cdf);
    EXPECT_EQ(t.cols, 80u);
    EXPECT_EQ(t.rows, kMaxEnvironmentRows);
    const EnvironmentData m = environmentTables(Vec3(1.0f), 0.0f, 0, &mid, cdf);
    EXPECT_EQ(m.cols, 600u);
    EXPECT_EQ(m.rows, 400u);
    const EnvironmentData small = environmentTables(Vec3(1.0f), 0.0f, 0, &tiny, cdf);
    EXPECT_EQ(small.cols, kMinEnvironmentCols);
    EXPECT_EQ(small.rows, kMinEnvironmentRows);
    for (const EnvironmentData& env : {w, t, m, small}) EXPECT_NEAR(env.power, 4.0 * kPi, 1e-5) << "white: 4π";
    EXPECT_NEAR(environmentTables(Vec3(0.0f, 1.0f, 0.0f), 0.0f, -1, nullptr, cdf).power, 4.0 * kPi * 0.7152, 1e-5);

    const TextureImage black = makeMap(8, 4, [](double, double) { return Vec3(0.0f); });
    EXPECT_TRUE(Environment(Vec3(1.0f), 0.0f, &black).arrays.environment.empty());
    EXPECT_TRUE(Environment(Vec3(0.0f), 0.0f, nullptr).arrays.environment.empty());
    const Environment none(Vec3(0.0f), 0.0f, &tiny);
    EXPECT_TRUE(none.arrays.texels.empty() && none.arrays.environmentCdf.empty());
    EXPECT_EQ(sampleEnvironment(none.view, 0.5f, 0.5f).pdf, 0.0f);
    EXPECT_EQ(pdfEnvironment(none.view, Vec3(0.0f, 1.0f, 0.0f)), 0.0f);
}

}  // namespace
}  // namespace trazo
