// The thin lens of SPEC §6: the lens strata (χ² uniformity, equal areas, tiling), the focal plane, the circle
// of confusion, and aperture 0 as the pinhole bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "core/rng.h"
#include "integrator/thin_lens.h"
#include "support/chi_square.h"

namespace trazo {
namespace {

constexpr double kPi = 3.14159265358979323846;

float unitFloat(std::mt19937_64& rng) { return bitsToUnitFloat(uint32_t(rng() >> 32)); }

// The area of [x0, x1] × [y0, y1] inside the unit disk, exactly: the height min(y1, s) − max(y0, −s) with
// s = √(1 − x²) is a + b·s between the x where s meets y0 or y1, and ∫s dx = ½(x s + asin x).
double rectangleDiskArea(double x0, double x1, double y0, double y1) {
    std::vector<double> xs = {std::max(x0, -1.0), std::min(x1, 1.0)};
    if (xs[0] >= xs[1]) return 0.0;
    for (double y : {y0, y1})
        if (std::abs(y) <= 1.0)  // y = ±1 touches the circle at x = 0
            for (double x : {-std::sqrt(1.0 - y * y), std::sqrt(1.0 - y * y)})
                if (x > xs[0] && x < xs[1]) xs.push_back(x);
    std::sort(xs.begin(), xs.end());
    auto s = [](double x) { return std::sqrt(std::max(0.0, 1.0 - x * x)); };
    auto integralS = [&](double x) { return 0.5 * (x * s(x) + std::asin(std::clamp(x, -1.0, 1.0))); };
    double area = 0.0;
    for (size_t k = 0; k + 1 < xs.size(); ++k) {
        const double a = xs[k], b = xs[k + 1], m = 0.5 * (a + b), sm = s(m);
        const bool topIsCircle = sm < y1, bottomIsCircle = -sm > y0;
        if ((topIsCircle ? sm : y1) <= (bottomIsCircle ? -sm : y0)) continue;  // empty column
        const double constant = (topIsCircle ? 0.0 : y1) - (bottomIsCircle ? 0.0 : y0);
        const double circles = (topIsCircle ? 1.0 : 0.0) + (bottomIsCircle ? 1.0 : 0.0);
        area += constant * (b - a) + circles * (integralS(b) - integralS(a));
    }
    return area;
}

// Mitsuba's PlanarDomain over [−1, 1]² at 101 × 101 cells; expected count = samples · area ∩ disk / π.
constexpr int kRes = kChiSquareResolution;

std::vector<double> expectedDiskCounts(int samples) {
    std::vector<double> e(kRes * kRes);
    for (int iy = 0; iy < kRes; ++iy)
        for (int ix = 0; ix < kRes; ++ix) {
            const double x0 = -1.0 + 2.0 * ix / kRes, y0 = -1.0 + 2.0 * iy / kRes;
            e[iy * kRes + ix] = samples * rectangleDiskArea(x0, x0 + 2.0 / kRes, y0, y0 + 2.0 / kRes) / kPi;
        }
    return e;
}

template <class Sampler>
ChiSquareResult diskChiSquare(Sampler sampler, uint32_t q, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<double> observed(kRes * kRes, 0.0);
    const uint32_t strata = 2u * q * q;
    for (int i = 0; i < kChiSquareSamples; ++i) {
        const uint32_t stratum = uint32_t(rng() % strata);
        const float u1 = unitFloat(rng), u2 = unitFloat(rng);
        float x, y;
        sampler(stratum, q, u1, u2, x, y);
        const int ix = std::clamp(int((x + 1.0f) * 0.5f * kRes), 0, kRes - 1);
        const int iy = std::clamp(int((y + 1.0f) * 0.5f * kRes), 0, kRes - 1);
        observed[iy * kRes + ix] += 1.0;
    }
    return chiSquareTest(observed, expectedDiskCounts(kChiSquareSamples));
}

// Plausible mistakes: ρ = u (the square root forgotten: rings of equal width, crowding the centre), and ρ linear
// between the right ring radii (equal-area rings, but crowding each ring's inner edge).
void lensWithoutSquareRoot(uint32_t s, uint32_t q, float u1, float u2, float& x, float& y) {
    const uint32_t ring = s / (2 * q), sector = s % (2 * q);
    const float rho = (ring + u1) / q, phi = (sector + u2) * float(kPi) / q;
    x = rho * cosf(phi);
    y = rho * sinf(phi);
}
void lensLinearInRing(uint32_t s, uint32_t q, float u1, float u2, float& x, float& y) {
    const uint32_t ring = s / (2 * q), sector = s % (2 * q);
    const float inner = sqrtf(float(ring) / q), outer = sqrtf(float(ring + 1) / q);
    const float rho = inner + u1 * (outer - inner), phi = (sector + u2) * float(kPi) / q;
    x = rho * cosf(phi);
    y = rho * sinf(phi);
}

TEST(LensStrata, RectangleDiskAreaIsExact) {
    EXPECT_NEAR(rectangleDiskArea(-1, 1, -1, 1), kPi, 1e-14);
    EXPECT_NEAR(rectangleDiskArea(0, 1, 0, 1), kPi / 4, 1e-14);
    EXPECT_NEAR(rectangleDiskArea(-0.5, 0.5, -0.5, 0.5), 1.0, 1e-14);
    EXPECT_NEAR(rectangleDiskArea(0.6, 1, -2, 2), std::acos(0.6) - 0.6 * 0.8, 1e-14);  // a circular segment
    double total = 0.0;
    for (double e : expectedDiskCounts(1)) total += e;
    EXPECT_NEAR(total, 1.0, 1e-12);
}

// (a) Uniform on the disk with random strata: 10⁶ samples, 101 × 101 cells, α = 0.01 Šidák over the three q.
// Power: at 8145 dof and this level a non-centrality of ≈ 700 is rejected with 99% probability, i.e. a density
// whose relative error has an rms of ~2.7% over the cells. Measured over 20 seeds at q = 3: ρ = √(t^1.02) for
// ρ = √t (t = (i + u1)/q) is rejected 12 times in 20, √(t^1.03) 20 times; the two mistakes of the next test give
// χ² ≈ 2.2·10⁶ and 6.4·10⁵. The sampler itself: 0 rejections in 40 seeds.
TEST(LensStrata, UniformOnTheDiskChiSquare) {
    const uint32_t qs[] = {1, 3, 8};
    const double level = sidakLevel(kChiSquareSignificance, 3);
    for (uint32_t q : qs) {
        const ChiSquareResult r = diskChiSquare(lensStratumPoint, q, 1000 + q);
        EXPECT_TRUE(r.accepts(level)) << "q " << q << ": χ² " << r.statistic << ", dof " << r.dof << ", p "
                                      << r.pValue << " " << r.failure;
        EXPECT_GT(r.dof, 7500);
    }
}

TEST(LensStrata, ChiSquareRejectsWrongRadii) {
    const double level = sidakLevel(kChiSquareSignificance, 3);
    const ChiSquareResult noRoot = diskChiSquare(lensWithoutSquareRoot, 3, 77);
    EXPECT_FALSE(noRoot.accepts(level)) << "χ² " << noRoot.statistic << " p " << noRoot.pValue;
    const ChiSquareResult linear = diskChiSquare(lensLinearInRing, 3, 78);
    EXPECT_FALSE(linear.accepts(level)) << "χ² " << linear.statistic << " p " << linear.pValue;
    EXPECT_GT(linear.statistic, linear.dof + 10.0 * std::sqrt(2.0 * linear.dof));  // not a near miss
}

// (b) Each stratum: its points stay in its ring and sector, and its area (the integral of the map's Jacobian
// over (u1, u2), by central differences on a 64 × 64 grid) is π/(2q²). The 2q² strata are distinct (i, j)
// pairs covering every ring and sector, so they tile the disk.
TEST(LensStrata, StrataHaveEqualAreaAndTileTheDisk) {
    std::mt19937_64 rng(5);
    for (uint32_t q = 1; q <= 8; ++q) {
        const uint32_t strata = 2 * q * q;
        std::vector<int> seen(strata, 0);
        for (uint32_t s = 0; s < strata; ++s) {
            const uint32_t i = s / (2 * q), j = s % (2 * q);
            ++seen[i * 2 * q + j];
            const double rho2Lo = double(i) / q, rho2Hi = double(i + 1) / q;
            const double phiLo = kPi * j / q, phiHi = kPi * (j + 1) / q;
            auto check = [&](float u1, float u2) {
                float x, y;
                lensStratumPoint(s, q, u1, u2, x, y);
                const double rho2 = double(x) * x + double(y) * y;
                double phi = std::atan2(double(y), double(x));
                if (phi < phiLo - 1e-5) phi += 2.0 * kPi;
                EXPECT_GE(rho2, rho2Lo - 1e-6) << "stratum " << s << " of q " << q;
                EXPECT_LE(rho2, rho2Hi + 1e-6) << "stratum " << s << " of q " << q;
                if (rho2 > 1e-10) {  // the centre has no angle
                    EXPECT_GE(phi, phiLo - 1e-5) << "stratum " << s << " of q " << q;
                    EXPECT_LE(phi, phiHi + 1e-5) << "stratum " << s << " of q " << q;
                }
            };
            for (int k = 0; k < 200; ++k) check(unitFloat(rng), unitFloat(rng));
            const float below1 = 0.99999994f;  // the largest float < 1
            for (float u1 : {0.0f, below1})
                for (float u2 : {0.0f, below1}) check(u1, u2);

            constexpr int n = 64;
            constexpr double h = 1e-3;
            double area = 0.0;
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) {
                    const double u1 = (a + 0.5) / n, u2 = (b + 0.5) / n;
                    float x1p, y1p, x1m, y1m, x2p, y2p, x2m, y2m;
                    lensStratumPoint(s, q, float(u1 + h), float(u2), x1p, y1p);
                    lensStratumPoint(s, q, float(u1 - h), float(u2), x1m, y1m);
                    lensStratumPoint(s, q, float(u1), float(u2 + h), x2p, y2p);
                    lensStratumPoint(s, q, float(u1), float(u2 - h), x2m, y2m);
                    const double dxdu1 = (x1p - x1m) / (2 * h), dydu1 = (y1p - y1m) / (2 * h);
                    const double dxdu2 = (x2p - x2m) / (2 * h), dydu2 = (y2p - y2m) / (2 * h);
                    area += std::abs(dxdu1 * dydu2 - dydu1 * dxdu2) / (n * n);
                }
            EXPECT_NEAR(area, kPi / strata, 2e-3 * kPi / strata) << "stratum " << s << " of q " << q;
        }
        for (int count : seen) EXPECT_EQ(count, 1);
    }
}

// The cameras of the focus tests: far from the origin, tilted, looking straight down, wide and narrow.
std::vector<CameraFrame> testCameras() {
    return {makeCameraFrame(Vec3(0, 0, 0), Vec3(0, 0, -1), 60.0f, 640, 480),
            makeCameraFrame(Vec3(3, 1, -2), Vec3(-1, 0.5f, 4), 45.0f, 512, 512),
            makeCameraFrame(Vec3(100, 250, -40), Vec3(98, 248, -35), 90.0f, 800, 300),
            makeCameraFrame(Vec3(0, 5, 0), Vec3(0, 0, 0), 20.0f, 320, 240)};
}

// Where a ray meets the plane at distance f along forward from the camera, in double.
struct Hit {
    double p[3];
};
Hit focalPlaneHit(const CameraFrame& c, const Ray& r, double f) {
    auto d = [](Vec3 a, Vec3 b) { return double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z; };
    const double o[3] = {double(r.origin.x) - c.origin.x, double(r.origin.y) - c.origin.y, double(r.origin.z) - c.origin.z};
    const double oForward = o[0] * c.forward.x + o[1] * c.forward.y + o[2] * c.forward.z;
    const double t = (f - oForward) / d(r.direction, c.forward);
    return Hit{{o[0] + t * r.direction.x, o[1] + t * r.direction.y, o[2] + t * r.direction.z}};  // relative to POV
}

// (c) All lens rays of one image position meet on the focal plane, at the pinhole ray's point there.
TEST(ThinLens, RaysOfOnePixelMeetOnTheFocalPlane) {
    std::mt19937_64 rng(9);
    double worst = 0.0;
    for (const CameraFrame& c : testCameras())
        for (float f : {0.5f, 5.0f, 37.0f})
            for (float aperture : {0.01f, 0.2f, 1.5f})
                for (int k = 0; k < 40; ++k) {
                    const float x = unitFloat(rng) * c.width, y = unitFloat(rng) * c.height;
                    const Hit pinhole = focalPlaneHit(c, generateCameraRay(c, x, y), f);
                    for (int l = 0; l < 16; ++l) {
                        float lx, ly;
                        lensStratumPoint(uint32_t(rng() % 18), 3, unitFloat(rng), unitFloat(rng), lx, ly);
                        const Ray r = thinLensRay(c, x, y, aperture, f, lx, ly);
                        ASSERT_NEAR(length(r.direction), 1.0f, 1e-6f);
                        // The origin is on the lens: in the plane through POV across forward, within the aperture.
                        const Vec3 o = r.origin - c.origin;
                        EXPECT_NEAR(dot(o, c.forward), 0.0f, 1e-5f * (1.0f + length(c.origin)));
                        EXPECT_LE(length(o), aperture * (1.0f + 1e-5f) + 1e-5f * length(c.origin));
                        const Hit h = focalPlaneHit(c, r, f);
                        double e = 0.0;
                        for (int a = 0; a < 3; ++a) e += (h.p[a] - pinhole.p[a]) * (h.p[a] - pinhole.p[a]);
                        // Float error grows with the camera's distance from the origin and with f.
                        const double tolerance = 2e-6 * (f + aperture) + 2e-7 * length(c.origin);
                        EXPECT_LT(std::sqrt(e), tolerance) << "f " << f << " aperture " << aperture;
                        worst = std::max(worst, std::sqrt(e) / tolerance);
                    }
                }
    EXPECT_LT(worst, 1.0);
}

// A lens that aims at the point at distance f along the pinhole ray (a focal sphere, not a plane) is the usual
// mistake: its rays miss the pinhole ray's point on the plane off the axis.
TEST(ThinLens, FocalPlaneCheckRejectsAFocalSphere) {
    const CameraFrame c = testCameras()[1];
    const float f = 5.0f, x = 10.0f, y = 20.0f;  // near a corner: d·forward ≈ 0.87
    const Ray pinhole = generateCameraRay(c, x, y);
    const Vec3 lens = c.right * 0.2f;
    const Ray sphere{c.origin + lens, normalize(pinhole.direction * f - lens)};
    const Hit a = focalPlaneHit(c, sphere, f), b = focalPlaneHit(c, pinhole, f);
    double e = 0.0;
    for (int k = 0; k < 3; ++k) e += (a.p[k] - b.p[k]) * (a.p[k] - b.p[k]);
    EXPECT_GT(std::sqrt(e), 100.0 * 2e-6 * (f + 0.2f));
}

// (d) A point X at depth z is seen through the rim of a lens of radius r by the image positions whose focal-plane
// points lie on a circle of radius r·|z − f|/z about X's pinhole image: the rays from the rim through those
// points pass through X. On the axis and off it, in front of and behind the focal plane.
TEST(ThinLens, CircleOfConfusion) {
    const CameraFrame c = makeCameraFrame(Vec3(1, 2, 3), Vec3(1, 2, -7), 50.0f, 600, 400);
    const double f = 10.0, r = 0.1;
    auto toImage = [&](const double p[3], float& x, float& y) {  // focal-plane point (relative to POV) → pixels
        const double sx = (p[0] * c.right.x + p[1] * c.right.y + p[2] * c.right.z) / f;
        const double sy = (p[0] * c.up.x + p[1] * c.up.y + p[2] * c.up.z) / f;
        x = float((sx / (double(c.tanHalfFovY) * c.aspect) + 1.0) * 0.5 * c.width);
        y = float((1.0 - sy / c.tanHalfFovY) * 0.5 * c.height);
    };
    for (double z : {5.0, 8.0, 12.0, 20.0, 100.0})
        for (double lateral : {0.0, 1.5}) {  // on the axis; off it along right and up
            double X[3];  // relative to POV
            for (int a = 0; a < 3; ++a) X[a] = z * c.forward[a] + lateral * (c.right[a] + 0.5 * c.up[a]);
            double image[3];  // X's pinhole image on the focal plane
            for (int a = 0; a < 3; ++a) image[a] = X[a] * f / z;
            const double expectedRadius = r * std::abs(z - f) / z;
            if (lateral == 0.0 && z == 5.0) {
                EXPECT_NEAR(expectedRadius, 0.1, 1e-15);  // r·|5 − 10|/5
            }
            for (int k = 0; k < 32; ++k) {
                const double phi = 2.0 * kPi * k / 32;
                const float lx = float(std::cos(phi)), ly = float(std::sin(phi));
                double lens[3], focus[3];
                for (int a = 0; a < 3; ++a) lens[a] = r * (double(lx) * c.right[a] + double(ly) * c.up[a]);
                for (int a = 0; a < 3; ++a) focus[a] = lens[a] + (X[a] - lens[a]) * f / z;  // lens → X, met at depth f
                double radius2 = 0.0;
                for (int a = 0; a < 3; ++a) radius2 += (focus[a] - image[a]) * (focus[a] - image[a]);
                EXPECT_NEAR(std::sqrt(radius2), expectedRadius, 1e-7 * r);  // right, up and (lx, ly) unit to floats
                float x, y;
                toImage(focus, x, y);
                const Ray ray = thinLensRay(c, x, y, float(r), float(f), lx, ly);
                // The distance from X to the ray.
                double w[3], along = 0.0, miss2 = 0.0;
                for (int a = 0; a < 3; ++a) w[a] = X[a] - (double(ray.origin[a]) - c.origin[a]);
                for (int a = 0; a < 3; ++a) along += w[a] * ray.direction[a];
                for (int a = 0; a < 3; ++a) miss2 += (w[a] - along * ray.direction[a]) * (w[a] - along * ray.direction[a]);
                EXPECT_LT(std::sqrt(miss2), 1e-6 * z) << "z " << z << " lateral " << lateral << " φ " << phi;
            }
            // And the centre pixel's rim rays cross depth z at r·|f − z|/f from the axis (the blur at X's depth).
            if (lateral == 0.0) {
                const Ray rim = thinLensRay(c, 0.5f * c.width, 0.5f * c.height, float(r), float(f), 1.0f, 0.0f);
                const double t = z / dot(rim.direction, c.forward);
                double off2 = 0.0;
                for (int a = 0; a < 3; ++a) {
                    const double p = double(rim.origin[a]) - c.origin[a] + t * rim.direction[a] - X[a];
                    off2 += p * p;
                }
                EXPECT_NEAR(std::sqrt(off2), r * std::abs(f - z) / f, 1e-6 * z) << "z " << z;
            }
        }
}

// (e) Aperture 0 is the pinhole camera, bit for bit, whatever the focal distance and lens point.
TEST(ThinLens, ApertureZeroIsThePinholeBitForBit) {
    std::mt19937_64 rng(13);
    for (const CameraFrame& c : testCameras())
        for (int k = 0; k < 2000; ++k) {
            const float x = unitFloat(rng) * c.width, y = unitFloat(rng) * c.height;
            const Ray pinhole = generateCameraRay(c, x, y);
            for (float f : {0.0f, 1.0f, 123.0f}) {
                const Ray r = thinLensRay(c, x, y, 0.0f, f, unitFloat(rng) * 2 - 1, unitFloat(rng) * 2 - 1);
                ASSERT_EQ(std::memcmp(&r, &pinhole, sizeof r), 0);
            }
        }
    // A tiny aperture is not the pinhole's bits, but its ray is the pinhole's to float precision.
    const CameraFrame c = testCameras()[1];
    const Ray tiny = thinLensRay(c, 100.0f, 200.0f, 1e-7f, 5.0f, 1.0f, 0.0f), pinhole = generateCameraRay(c, 100.0f, 200.0f);
    EXPECT_NEAR(length(tiny.direction - pinhole.direction), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace trazo
