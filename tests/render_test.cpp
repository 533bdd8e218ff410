// Whole-pipeline renders (reader, flatten, CPU backend, resolve) against closed forms and oracles.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "render_harness.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

struct DVec {
    double x, y, z;
};
DVec operator-(DVec a, DVec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
DVec operator+(DVec a, DVec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
DVec operator*(DVec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(DVec a, DVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
DVec normalized(DVec a) { return a * (1.0 / std::sqrt(dot(a, a))); }

// Pixel-centre camera ray direction in double precision, from SPEC §3 (vertical FOV, +Y up, pixel (0,0)
// top-left), for a camera on the +Z axis looking at the origin. Independent of camera_frame.h.
DVec pixelDirection(int i, int j, int w, int h, double fovDegrees, double ox = 0.5, double oy = 0.5) {
    const double t = std::tan(0.5 * fovDegrees * M_PI / 180.0);
    const double sx = (2.0 * (i + ox) / w - 1.0) * t * double(w) / h;
    const double sy = (1.0 - 2.0 * (j + oy) / h) * t;
    return normalized({sx, sy, -1.0});
}

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// A Lambertian wall (front face z = 0) under a point light, camera at distance `scale`·10; every length
// is multiplied by `scale`.
std::string wallScene(double scale, int antialiasing = 1) {
    const std::string s = num(scale);
    return "SceneSettings\n{\nRenderWidth 48\nRenderHeight 32\nReflectionQuality 0\nIndirectQuality 0\n"
           "Antialiasing " + std::to_string(antialiasing) + "\n}\n"
           "Camera\n{\nPOV 0 0 " + num(10 * scale) + "\nPOI 0 0 0\nFOV 40\n}\n"
           "Material\n{\nName wall\nDiffuseColor 0.7 0.5 0.3\nSpecularColor 0 0 0\nRoughness 0\n}\n"
           "Box\n{\nMaterial wall\nTranslation 0 0 -0.5\nScale " + num(100 * scale) + " " + num(100 * scale) + " " + s +
           "\n}\n"
           "PointLight\n{\nPosition " + num(1.5 * scale) + " " + num(-2 * scale) + " " + num(3 * scale) +
           "\nColor 0.9 0.8 1.0\n}\n";
}

// SPEC §5: a white-ish Lambertian wall (σ = 0) lit by a point light: pixel = albedo · cos θ · colour.
TEST(RenderClosedForm, PointLightOverLambertianWall) {
    const RenderedImage image = renderSceneText(wallScene(1.0), {});
    ASSERT_EQ(image.width, 48);
    const DVec pov{0, 0, 10}, light{1.5, -2, 3};
    double worst = 0;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const DVec d = pixelDirection(i, j, image.width, image.height, 40.0);
            const DVec p = pov + d * (-pov.z / d.z);
            const double c = normalized(light - p).z;
            const Vec3 got = image.at(i, j);
            worst = std::max({worst, std::abs(got.x - 0.7 * 0.9 * c), std::abs(got.y - 0.5 * 0.8 * c),
                              std::abs(got.z - 0.3 * 1.0 * c)});
        }
    EXPECT_LT(worst, 2e-5);
}

// Antialiasing k² averages the k×k sub-pixel centres (SPEC §5 Pixel): after one cycle of k² passes each
// pixel is exactly that mean, whatever order the passes visited them in.
TEST(RenderClosedForm, AntialiasingAveragesTheSubPixelCentres) {
    for (int k : {2, 4}) {
        const RenderedImage image = renderSceneText(wallScene(1.0, k * k), {.passes = uint32_t(k * k)});
        ASSERT_EQ(image.width, 48);
        const DVec pov{0, 0, 10}, light{1.5, -2, 3};
        double worst = 0;
        for (int j = 0; j < image.height; ++j)
            for (int i = 0; i < image.width; ++i) {
                double mean = 0;
                for (int a = 0; a < k; ++a)
                    for (int b = 0; b < k; ++b) {
                        const DVec d = pixelDirection(i, j, image.width, image.height, 40.0, (a + 0.5) / k, (b + 0.5) / k);
                        mean += normalized(light - (pov + d * (-pov.z / d.z))).z / (k * k);
                    }
                worst = std::max(worst, std::abs(image.at(i, j).x - 0.7 * 0.9 * mean));
            }
        EXPECT_LT(worst, 2e-5) << "Antialiasing " << k * k;
    }
}

// No shadow acne and no scale-dependent epsilon: the same scene at 1e-3 and 1e4 times the size renders
// the same image (shadow rays leave the wall at every scale).
TEST(RenderRobustness, SameImageAtEveryScale) {
    const RenderedImage unit = renderSceneText(wallScene(1.0), {});
    for (double scale : {1e-3, 1e4}) {
        const RenderedImage scaled = renderSceneText(wallScene(scale), {});
        ASSERT_EQ(scaled.pixels.size(), unit.pixels.size());
        EXPECT_LT(rmse(unit, scaled), 1e-4) << "scale " << scale;
        float minimum = 1;
        for (const Vec3& p : scaled.pixels) minimum = std::min(minimum, p.x);
        EXPECT_GT(minimum, 0.05f) << "a black (self-shadowed) pixel at scale " << scale;
    }
}

// A fully transparent tilted glass slab (n = 1.5) in front of the lit wall: each pixel shows the wall point
// reached by refracting the camera ray twice by Snell's law, computed here in double precision.
TEST(RenderRefraction, TiltedSlabFollowsSnellsLaw) {
    const double angle = 0.5, n = 1.5;
    const std::string scene =
        settingsText(24, 24, 0, 0) + cameraText("0 0 10", "0 0 0", "16") +
        "Material\n{\nName wall\nDiffuseColor 1 1 1\nSpecularColor 0 0 0\nRoughness 0\n}\n"
        "Material\n{\nName glass\nDiffuseColor 1 1 1\nSpecularColor 0 0 0\nOpacity 0\nRefractionIndex 1.5\n}\n"
        "Box\n{\nMaterial wall\nScale 100 100 1\nTranslation 0 0 -5.5\n}\n"
        "Box\n{\nMaterial glass\nScale 6 6 1\nRotation 0 1 0 0.5\n}\n"
        "PointLight\n{\nPosition 0.3 0.2 -2.5\nColor 1 1 1\n}\n";
    const RenderedImage image = renderSceneText(scene, {});
    ASSERT_EQ(image.width, 24);

    // Slab normal: +Z rotated by `angle` about +Y.
    const DVec normal{std::sin(angle), 0, std::cos(angle)}, light{0.3, 0.2, -2.5}, pov{0, 0, 10};
    auto refract = [](DVec d, DVec nFacing, double eta) {
        const double cosI = -dot(d, nFacing);
        const double k = 1 - eta * eta * (1 - cosI * cosI);
        return normalized(d * eta + nFacing * (eta * cosI - std::sqrt(k)));
    };
    double worst = 0;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            DVec d = pixelDirection(i, j, image.width, image.height, 16.0);
            // Front face: plane dot(normal, x) = 0.5; back face: dot(normal, x) = -0.5.
            DVec p = pov + d * ((0.5 - dot(normal, pov)) / dot(normal, d));
            d = refract(d, normal, 1.0 / n);
            p = p + d * ((-0.5 - dot(normal, p)) / dot(normal, d));
            d = refract(d, normal, n);
            p = p + d * ((-5.0 - p.z) / d.z);
            const double expected = normalized(light - p).z;
            worst = std::max(worst, std::abs(image.at(i, j).x - expected));
        }
    EXPECT_LT(worst, 5e-5);
}

// A facing plate in front of the camera, lit head-on by a point light at the camera: with σ = 0 and no
// specular term, its direct light is Kd·C·cos θ; the rest of SPEC §5's colour formula is checked around it.
std::string plateScene(const std::string& material) {
    return "SceneSettings\n{\nRenderWidth 1\nRenderHeight 1\nBackgroundColor 0.2 0.4 0.6\n"
           "ReflectionQuality 1\nReflectionSteps 1\nIndirectQuality 0\n}\n"
           "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 10\n}\n"
           "Material\n{\nName plate\n" + material + "}\n"
           "Box\n{\nMaterial plate\nScale 10 10 0.1\n}\n"
           "PointLight\n{\nPosition 0 0 10\nColor 0.5 0.5 0.5\n}\n";
}

// Emission is added on top of everything: with no light reaching it, a surface shows exactly Ke.
TEST(RenderClosedForm, EmissiveSurfaceShowsItsColour) {
    const RenderedImage image = renderSceneText(
        plateScene("DiffuseColor 0 0 0\nSpecularColor 0 0 0\nEmissiveColor 0.3 0.6 0.9\n"), {});
    EXPECT_FLOAT_EQ(image.at(0, 0).x, 0.3f);
    EXPECT_FLOAT_EQ(image.at(0, 0).z, 0.9f);
}

// c = Direct·(1 − a) + Ks ⊙ R·a with a = ReflectionAmount ([decided] lerp order): the mirror ray goes back
// past the camera and returns the background.
TEST(RenderClosedForm, ReflectionBlendsByReflectionAmount) {
    const RenderedImage image = renderSceneText(
        plateScene("DiffuseColor 0.8 0.8 0.8\nSpecularColor 0.5 1 1\nRoughness 0\nReflectionAmount 0.25\n"), {});
    // Specular term at normal incidence: CT = 1/(4m²) with m = 0.01, times Ks and the light colour.
    const double ct = 1.0 / (4 * 0.01 * 0.01);
    const double directR = 0.5 * (0.8 + 0.5 * ct), directG = 0.5 * (0.8 + 1.0 * ct);
    EXPECT_NEAR(image.at(0, 0).x, 0.75 * directR + 0.25 * 0.5 * 0.2, 1e-3 * directR);
    EXPECT_NEAR(image.at(0, 0).y, 0.75 * directG + 0.25 * 1.0 * 0.4, 1e-3 * directG);
}

// c·Opacity + T·(1 − Opacity): a thin plate of index 1 lets the background through unchanged.
TEST(RenderClosedForm, OpacityBlendsWithTransmission) {
    const RenderedImage image = renderSceneText(
        plateScene("DiffuseColor 0.8 0.8 0.8\nSpecularColor 0 0 0\nRoughness 0\nOpacity 0.25\n"), {});
    EXPECT_NEAR(image.at(0, 0).x, 0.25 * 0.5 * 0.8 + 0.75 * 0.2, 1e-5);
    EXPECT_NEAR(image.at(0, 0).z, 0.25 * 0.5 * 0.8 + 0.75 * 0.6, 1e-5);
}

// A glass solid made by CSG refracts like glass: a sphere intersected with a box that contains it is
// the sphere, so both scenes must render the same image (refraction in, out and total internal reflection).
TEST(RenderRefraction, GlassCsgSolidRefractsLikeThePlainSolid) {
    std::ofstream(tempPath("lens.csg")) << "Sphere\n{\n    Center 0.2 0.1 0\n    Radius 1.5\n}\n"
                                           "Box\n{\n    Scale 5 5 5\n}\n"
                                           "Intersection\n{\n    LeftType Sphere\n    LeftIndex 0\n"
                                           "    RightType Box\n    RightIndex 0\n}\n";
    const std::string common =
        "SceneSettings\n{\nRenderWidth 32\nRenderHeight 32\nReflectionQuality 0\nIndirectQuality 0\n}\n"
        "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 25\n}\n"
        "Material\n{\nName wall\nDiffuseColor 1 1 1\nSpecularColor 0 0 0\nRoughness 0\n}\n"
        "Material\n{\nName glass\nDiffuseColor 1 1 1\nSpecularColor 0 0 0\nOpacity 0\nRefractionIndex 1.5\n}\n"
        "Box\n{\nMaterial wall\nScale 100 100 1\nTranslation 0 0 -5.5\n}\n"
        "PointLight\n{\nPosition 0.3 0.2 -2.5\nColor 1 1 1\n}\n";
    const RenderedImage plain =
        renderSceneText(common + "Sphere\n{\nMaterial glass\nCenter 0.2 0.1 0\nRadius 1.5\n}\n", {});
    const RenderedImage csg = renderSceneText(common + "CSG\n{\nMaterial glass\nSource \"lens.csg\"\n}\n", {});
    ASSERT_EQ(plain.pixels.size(), csg.pixels.size());
    EXPECT_LT(rmse(plain, csg), 1e-4);
    double sum = 0;
    for (const Vec3& p : csg.pixels) sum += p.x;
    EXPECT_GT(sum / csg.pixels.size(), 0.05);  // the wall is seen through the glass
}

std::string areaLightScene(int passesHint, int width) {
    (void)passesHint;
    return "SceneSettings\n{\nRenderWidth " + std::to_string(width) + "\nRenderHeight " + std::to_string(width) +
           "\nReflectionQuality 0\nIndirectQuality 0\n}\n"
           "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 30\n}\n"
           "Material\n{\nName wall\nDiffuseColor 1 1 1\nSpecularColor 0 0 0\nRoughness 0\n}\n"
           "Box\n{\nMaterial wall\nScale 100 100 1\nTranslation 0 0 -0.5\n}\n"
           "Sphere\n{\nMaterial wall\nCenter 0.4 0.3 1\nRadius 0.6\n}\n"
           "AreaLight\n{\nPosition 0 0 3\nDirection 0 0 -1\nWidth 2\nHeight 1\nSubdivision 4 2\nColor 1 1 1\n}\n";
}

// The area light converges to the mean of Shade over its rectangle (SPEC §5), here integrated by a
// fine midpoint rule in double precision on the wall pixels the sphere does not shadow.
TEST(RenderClosedForm, AreaLightConvergesToTheRectangleMean) {
    const RenderedImage image = renderSceneText(areaLightScene(0, 16), {.passes = 8 * 64});
    ASSERT_EQ(image.width, 16);
    const DVec pov{0, 0, 10}, sphere{0.4, 0.3, 1};
    int checked = 0;
    double worst = 0;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
            const DVec d = pixelDirection(i, j, 16, 16, 30.0);
            const DVec p = pov + d * (-pov.z / d.z);
            double sum = 0;
            bool shadowed = false;
            const int m = 200;
            for (int a = 0; a < m && !shadowed; ++a)
                for (int b = 0; b < m; ++b) {
                    const DVec x{-1 + 2 * (a + 0.5) / m, -0.5 + (b + 0.5) / m, 3};
                    const DVec l = normalized(x - p);
                    // Skip pixels whose light is partly blocked by the sphere (or that see the sphere).
                    const DVec oc = p - sphere;
                    const double bq = dot(oc, l), cq = dot(oc, oc) - 0.36;
                    if (bq * bq - cq > 0 && -bq > 0) {
                        shadowed = true;
                        break;
                    }
                    sum += l.z;
                }
            // Pixels that see the light rectangle (z = 3, |x| ≤ 1, |y| ≤ 0.5) show its colour instead.
            const DVec onLight = pov + d * ((3.0 - pov.z) / d.z);
            if (std::abs(onLight.x) <= 1.0 && std::abs(onLight.y) <= 0.5) {
                EXPECT_EQ(image.at(i, j).x, 1.0f);
                continue;
            }
            const DVec toSphere = sphere - pov;
            const double along = dot(toSphere, d);
            if (shadowed || dot(toSphere, toSphere) - along * along < 0.36 * 1.2) continue;
            ++checked;
            worst = std::max(worst, std::abs(image.at(i, j).x - sum / (m * m)));
        }
    EXPECT_GT(checked, 40);
    EXPECT_LT(worst, 4e-3);
}

// Light rectangles are visible: a camera ray that hits one returns the light's colour.
TEST(RenderClosedForm, AreaLightRectangleIsVisible) {
    const std::string scene =
        "SceneSettings\n{\nRenderWidth 9\nRenderHeight 9\nBackgroundColor 0.1 0.2 0.3\n}\n"
        "Camera\n{\nPOV 0 0 10\nPOI 0 0 0\nFOV 10\n}\n"
        "AreaLight\n{\nPosition 0 0 0\nDirection 0 0 1\nWidth 0.5\nHeight 0.5\nColor 0.25 0.5 0.75\n}\n";
    const RenderedImage image = renderSceneText(scene, {});
    EXPECT_FLOAT_EQ(image.at(4, 4).y, 0.5f);
    EXPECT_FLOAT_EQ(image.at(0, 0).z, 0.3f);
}

// Same seed ⇒ identical image, whatever the thread count; another seed ⇒ another image.
TEST(RenderDeterminism, SameSeedSameImageForAnyThreadCount) {
    const std::string scene = areaLightScene(0, 40);
    const RenderedImage one = renderSceneText(scene, {.passes = 6, .threads = 1, .seed = 11});
    for (unsigned threads : {2u, 3u, 8u}) {
        const RenderedImage other = renderSceneText(scene, {.passes = 6, .threads = threads, .seed = 11});
        ASSERT_EQ(one.pixels.size(), other.pixels.size());
        for (size_t i = 0; i < one.pixels.size(); ++i) {
            ASSERT_EQ(one.pixels[i].x, other.pixels[i].x) << "pixel " << i << " threads " << threads;
            ASSERT_EQ(one.pixels[i].z, other.pixels[i].z);
        }
        EXPECT_EQ(one.rays, other.rays);
    }
    EXPECT_GT(rmse(one, renderSceneText(scene, {.passes = 6, .threads = 2, .seed = 12})), 1e-4);
}

// Progressive convergence: the RMSE against a long reference falls roughly as 1/√passes.
TEST(RenderConvergence, ErrorFallsAsInverseSquareRootOfPasses) {
    const std::string scene = areaLightScene(0, 24);
    const RenderedImage reference = renderSceneText(scene, {.passes = 8 * 256, .seed = 99});
    std::vector<double> logPasses, logError;
    for (uint32_t passes : {2u, 4u, 8u, 16u, 32u}) {
        // Average the squared error over a few seeds to steady the estimate.
        double mse = 0;
        for (uint32_t seed = 1; seed <= 4; ++seed) {
            const double e = rmse(renderSceneText(scene, {.passes = passes, .seed = seed}), reference);
            mse += e * e / 4;
        }
        logPasses.push_back(std::log(double(passes)));
        logError.push_back(0.5 * std::log(mse));
    }
    // Least-squares slope of log(error) against log(passes).
    const double n = double(logPasses.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < logPasses.size(); ++i) {
        sx += logPasses[i], sy += logError[i], sxx += logPasses[i] * logPasses[i], sxy += logPasses[i] * logError[i];
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    // Cycling the light's strata makes the estimate partly stratified, so it converges a little faster
    // than independent samples would (-0.5); a bias or a stuck stratum would flatten the slope.
    EXPECT_GT(slope, -0.85);
    EXPECT_LT(slope, -0.4);
    RecordProperty("slope", std::to_string(slope));
    std::printf("convergence slope %.3f\n", slope);
}

}  // namespace
}  // namespace trazo::test
