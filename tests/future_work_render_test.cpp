// SPEC §6's effects in whole renders, against closed forms and independent oracles: the Fresnel factor across a
// mirror-like plane in an emissive enclosure and through a glass slab seen head-on, the thin lens's circle of
// confusion and the flux of a small emitter it blurs, a glossy transmission cone that keeps what a clear slab
// lets through, each channel of a dispersing ball lens against its own trace in double precision, and a thick
// scattering slab against the half-space random walk's reflectance.
#include <gtest/gtest.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "render_harness.h"
#include "support/halfspace_walk.h"

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
        return settingsText(32, 32, 1, 0) + cameraText("0 0 10", "0 0 0", "1") +
               glassSlabBeforeWallText("Opacity 0\nRefractionIndex 1.5\nFresnel " + std::to_string(fresnel) + "\n", "1",
                                       "-5");
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
    const std::string scene = settingsText(16, 16, 3, 0) + cameraText("0 0 10", "0 0 0", "5") +
                              glassSlabBeforeWallText("Opacity 0\nRefractionIndex 1\nRefractionAngle 40\n", "1", "-3");
    const RenderedImage image = renderSceneText(scene, {.passes = 18});
    ASSERT_FALSE(image.pixels.empty());
    for (const Vec3& p : image.pixels) EXPECT_EQ(p.x, 1.0f);
}

// An emitter (Ke = 1) filling the box x ∈ [0, 100], |y| ≤ 50, z ∈ [front − 1, front]: the half-plane x > 0
// behind the object under test.
std::string halfPlaneLamp(double front) {
    return blackMaterialText("lamp", "EmissiveColor 1 1 1\n") +
           "Box\n{\nMaterial lamp\nScale 100 100 1\nTranslation 50 0 " + std::to_string(front - 0.5) + "\n}\n";
}

// Vectors in double for the independent traces below.
using D3 = std::array<double, 3>;
double dot3(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
D3 unit(const D3& a) {
    const double l = std::sqrt(dot3(a, a));
    return {a[0] / l, a[1] / l, a[2] / l};
}
D3 along(const D3& o, const D3& d, double t) { return {o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t}; }

// A glass slab of n = 1 (no bending; z from −0.1 to 0.1) with a 20° transmission cone (half-angle 10°) before
// an emitting box x ∈ [0, 100], z ∈ [−1.4, −0.4], seen along −z through a 2° field: each crossing of a face
// takes a direction in the cone about the ray's (θ uniform, φ uniform: SPEC §6), so the sharp edge of the
// emitter spreads into a profile. Its values against an independent Monte Carlo of the two cones in double precision
// (10⁵ paths a column, its own generator, the middle row's ray), column by column: the render's 24 rows × 72
// passes are 1 728 samples of 0 or 1 a column, a standard error of at most 0.012 (the rows' rays tilt by up to
// 1° from the middle one's, which lengthens their paths by 0.015 %); the bound is 4.5 of them (and the oracle's).
TEST(GlossyTransmissionRender, EdgeProfileMatchesAnIndependentTraceOfTheCones) {
    const int w = 48, h = 24;
    const std::string scene = settingsText(w, h, 3, 0) + cameraText("0 0 10", "0 0 0", "2") +
                              blackMaterialText("glass", "Opacity 0\nRefractionIndex 1\nRefractionAngle 20\n") +
                              "Box\n{\nMaterial glass\nScale 100 100 0.2\n}\n" + halfPlaneLamp(-0.4);
    const RenderedImage image = renderSceneText(scene, {.passes = 72});
    ASSERT_EQ(image.pixels.size(), size_t(w * h));
    const double halfAngle = 10.0 * M_PI / 180.0, t = std::tan(1.0 * M_PI / 180.0) * double(w) / double(h);
    std::mt19937_64 generator(2024);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    auto cone = [&](const D3& axis) {  // θ uniform in [0, half-angle), φ uniform, about the unit axis
        const D3 helper = std::abs(axis[0]) < 0.9 ? D3{1, 0, 0} : D3{0, 1, 0};
        const D3 t1 = unit({helper[1] * axis[2] - helper[2] * axis[1], helper[2] * axis[0] - helper[0] * axis[2],
                            helper[0] * axis[1] - helper[1] * axis[0]});
        const D3 t2 = {axis[1] * t1[2] - axis[2] * t1[1], axis[2] * t1[0] - axis[0] * t1[2],
                       axis[0] * t1[1] - axis[1] * t1[0]};
        const double theta = halfAngle * uniform(generator), phi = 2 * M_PI * uniform(generator);
        D3 d;
        for (int i = 0; i < 3; ++i)
            d[i] = axis[i] * std::cos(theta) + (t1[i] * std::cos(phi) + t2[i] * std::sin(phi)) * std::sin(theta);
        return d;
    };
    const int paths = 100000;
    int inProfile = 0;
    for (int x = 0; x < w; ++x) {
        const D3 d = unit({(2.0 * (x + 0.5) / w - 1) * t, 0, -1});
        int lit = 0;
        for (int k = 0; k < paths; ++k) {
            const D3 entry = along({0, 0, 10}, d, (10 - 0.1) / -d[2]);
            const D3 d1 = cone(d);
            const D3 exit = along(entry, d1, -0.2 / d1[2]);
            const D3 d2 = cone(d1);
            // The emitter is a box: a path that passes z = −0.4 at x < 0 may still meet its side face x = 0.
            const bool front = along(exit, d2, (-0.4 - exit[2]) / d2[2])[0] > 0;
            lit += front || along(exit, d2, (-1.4 - exit[2]) / d2[2])[0] > 0 ? 1 : 0;
        }
        const double expected = double(lit) / paths;
        double sum = 0;
        for (int y = 0; y < h; ++y) sum += image.at(x, y).x;
        const double mean = sum / h;
        const double samples = double(h) * 72;
        const double bound = 4.5 * std::sqrt(std::max(expected * (1 - expected), 1e-4) / samples) +
                             4.5 * std::sqrt(std::max(expected * (1 - expected), 1e-4) / paths);
        EXPECT_NEAR(mean, expected, bound) << "column " << x;
        if (expected > 0.05 && expected < 0.95) ++inProfile;
    }
    EXPECT_GT(inProfile, 10) << "the profile spans columns: the test sees the cones' shape";
}

// SPEC §6's per-channel index, in double: n_c = max(1, n + (n − 1)·(D/20)·(523655/λc² − 1.5168)).
double channelIndex(double n, double dispersion, int channel) {
    const double lambda = channel == 0 ? 611.0 : (channel == 1 ? 549.0 : 464.0);
    return std::max(1.0, n + (n - 1.0) * (dispersion / 20.0) * (523655.0 / (lambda * lambda) - 1.5168));
}

// Snell's refraction of unit d at unit normal n (facing d), η = n_in/n_out; false under total internal
// reflection and within 1% of it (cos²θt < 0.01), where single precision may decide either way.
bool refract3(const D3& d, const D3& n, double eta, D3& out) {
    const double c = -dot3(d, n), k = 1 - eta * eta * (1 - c * c);
    if (k < 0.01) return false;
    for (int i = 0; i < 3; ++i) out[i] = eta * d[i] + (eta * c - std::sqrt(k)) * n[i];
    return true;
}

// The far root of the unit sphere at the origin along o + t·d (d unit), or −1 when missed.
double unitSphere(const D3& o, const D3& d, bool far) {
    const double b = dot3(o, d), c = dot3(o, o) - 1, disc = b * b - c;
    if (disc < 0) return -1;
    return far ? -b + std::sqrt(disc) : -b - std::sqrt(disc);
}

// A ball lens (unit sphere, n = 1.5, Dispersion 4, Opacity 0, no Fresnel) before an emitting box x ∈ [0, 100],
// z ∈ [−4, −3]; no light, black background. Each pixel's camera ray, traced through the ball in double
// precision with each channel's own index, lands on the emitter or not: channel c of the pixel is 1 or 0. A dispersing ray carries one channel, each in turn over three passes with weight 3, so three
// passes give each channel exactly. Pixels whose trace lands within 1e-3 of the emitter's edge, or comes near
// total internal reflection, are not compared.
TEST(DispersionRender, EachChannelOfABallLensFollowsItsOwnIndex) {
    const int w = 64, h = 64;
    const double n = 1.5, dispersion = 4, wallZ = -3;
    const std::string scene = settingsText(w, h, 0, 0) + cameraText("0.3 0 6", "0.3 0 0", "24") +
                              blackMaterialText("glass", "Opacity 0\nRefractionIndex 1.5\nDispersion 4\n") +
                              "Sphere\n{\nMaterial glass\nCenter 0 0 0\nRadius 1\n}\n" + halfPlaneLamp(-3);
    const RenderedImage image = renderSceneText(scene, {.passes = 3});
    ASSERT_EQ(image.pixels.size(), size_t(w * h));
    const double t = std::tan(12.0 * M_PI / 180.0);
    int compared = 0, split = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // SPEC §3's pinhole ray through the pixel centre: forward −z, right +x, up +y.
            const D3 o = {0.3, 0, 6};
            const D3 d = unit({(2.0 * (x + 0.5) / w - 1) * t, (1 - 2.0 * (y + 0.5) / h) * t, -1});
            std::array<int, 3> expected{};
            bool comparable = true;
            for (int c = 0; c < 3 && comparable; ++c) {
                D3 p = o, dir = d;
                const double tIn = unitSphere(o, d, false);
                if (tIn > 0) {
                    const double nc = channelIndex(n, dispersion, c);
                    const D3 entry = along(o, d, tIn);
                    D3 inside, outside;
                    if (!refract3(d, entry, 1 / nc, inside)) comparable = false;
                    const double tOut = unitSphere(entry, inside, true);
                    const D3 exit = along(entry, inside, tOut);
                    if (!refract3(inside, {-exit[0], -exit[1], -exit[2]}, nc, outside)) comparable = false;
                    p = exit, dir = outside;
                }
                if (!comparable || dir[2] >= 0) {
                    comparable = false;
                    break;
                }
                // The emitter is a box of depth 1: a path that passes its front at x < 0 may meet its side x = 0.
                const double xWall = along(p, dir, (wallZ - p[2]) / dir[2])[0];
                const double xBack = along(p, dir, (wallZ - 1 - p[2]) / dir[2])[0];
                if (std::abs(xWall) < 1e-3 || std::abs(xBack) < 1e-3) comparable = false;
                expected[c] = xWall > 0 || xBack > 0 ? 1 : 0;
            }
            if (!comparable) continue;
            ++compared;
            if (expected[0] != expected[2]) ++split;
            const Vec3 pixel = image.at(x, y);
            EXPECT_NEAR(pixel.x, expected[0], 1e-6) << "red, pixel " << x << ", " << y;
            EXPECT_NEAR(pixel.y, expected[1], 1e-6) << "green, pixel " << x << ", " << y;
            EXPECT_NEAR(pixel.z, expected[2], 1e-6) << "blue, pixel " << x << ", " << y;
        }
    }
    EXPECT_GT(compared, w * h * 9 / 10);
    EXPECT_GT(split, 20) << "pixels where red and blue land on different sides of the edge: the test's power";
}

// A thick slab of a scattering material (no surface lobe: Kd is only the walk's albedo, Ks = 0) lit head-on by a
// distant point light and seen head-on: SPEC §6 gives R(Kd)·C per channel, R the reflectance of the
// half-space walk, whatever the mean free paths (a half-space has no length scale), so Kd = (0.5, 0.8, 1) shows
// R(0.5), R(0.8), R(1) for equal paths and for paths that differ per channel (drawn with one channel's and
// weighted per channel). A channel of mean free path 0 among positive ones scatters without end: 0.
// The references: Chandrasekhar's H-function for α ≤ 0.8 (exact), and for α = 1 the independent walk of
// tests/support (2·10⁵ walks). Each render's 32×32 pixels × 48 passes are independent walks; the bound is
// 4.5 standard errors of the pixels' mean (taken from the image) plus the oracle's own.
TEST(SubsurfaceRender, ThickSlabHeadOnShowsTheHalfSpaceReflectance) {
    double oracleError = 0;
    const double reference[3] = {halfspaceReflectanceChandrasekhar(0.5), halfspaceReflectanceChandrasekhar(0.8),
                                 halfspaceWalkReflectance(1.0, 200000, 7, &oracleError)};
    EXPECT_NEAR(reference[0], 0.147, 5e-4);  // the values SPEC §6 states
    EXPECT_NEAR(reference[1], 0.342, 5e-4);
    EXPECT_NEAR(reference[2], 0.919, 3e-3);
    for (const char* paths : {"1 1 1", "0.5 1 2", "0 1 2"}) {
        const std::string scene =
            "SceneSettings\n{\nRenderWidth 32\nRenderHeight 32\nReflectionQuality 0\nIndirectQuality 0\n}\n"
            "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 1\n}\n"
            "PointLight\n{\nPosition 0 0 100000\n}\n"
            "Material\n{\nName wax\nDiffuseColor 0.5 0.8 1\nSpecularColor 0 0 0\nScatteringDistance " +
            std::string(paths) + "\n}\n"
            "Box\n{\nMaterial wax\nScale 4000 4000 400\nTranslation 0 0 -200\n}\n";
        const RenderedImage image = renderSceneText(scene, {.passes = 48});
        ASSERT_FALSE(image.pixels.empty());
        const bool redOff = std::string(paths) == "0 1 2";
        for (int c = 0; c < 3; ++c) {
            double sum = 0, sum2 = 0;
            for (const Vec3& p : image.pixels) sum += p[c], sum2 += p[c] * p[c];
            const double count = double(image.pixels.size()), mean = sum / count;
            const double standardError = std::sqrt(std::max(0.0, sum2 / count - mean * mean) / count);
            const double expected = c == 0 && redOff ? 0.0 : reference[c];
            EXPECT_NEAR(mean, expected, 4.5 * standardError + 4.5 * (c == 2 ? oracleError : 0.0) + 1e-6)
                << "channel " << c << ", ScatteringDistance " << paths << ", standard error " << standardError;
        }
    }
}

}  // namespace
}  // namespace trazo::test
