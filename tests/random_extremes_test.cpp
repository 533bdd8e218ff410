// Random scenes at the bounds of docs/LIMITS.md, rendered in-process: every pixel of every image is finite and not
// negative. Each scene mixes the object kinds, materials of SPEC §5–§6 with values drawn on a log scale up to their
// bounds (colours to 1e12, radii to 1e19, indices to 1e30, subsurface albedos to 1 with mean free paths from 1e-6
// to 1e6, depth of field focused to 1e30), point and area lights far and near. A subsurface albedo of 1e6 once
// overflowed a walk's albedo^k to NaN; such values are now refused (SPEC §6), and a sample that is not finite adds
// nothing to its pixel (AccumPixel::add), so this sweep holds every pixel to a real value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "render_harness.h"

namespace trazo::test {
namespace {

class ExtremeScene {
public:
    explicit ExtremeScene(unsigned seed) : rng_(seed) {}

    std::string text() {
        std::ostringstream s;
        s << "SceneSettings\n{\nRenderWidth 12\nRenderHeight 12\nReflectionQuality " << pick(0, 3)
          << "\nIndirectQuality " << pick(0, 2) << "\nReflectionSteps " << pick(0, 6) << "\n}\n";
        s << "Camera\n{\nPOV " << vec(20) << "\nPOI 0 0 0\nFOV " << uniform(5, 120);
        if (chance(0.3)) s << "\nAperture " << logUniform(1e-4, 1) << "\nFocalDistance " << logUniform(1e-3, 1e30);
        s << "\n}\n";
        for (int i = 0; i < 3; ++i) s << material(i);
        for (int i = 0, lights = pick(1, 3); i < lights; ++i) {
            if (chance(0.5))
                s << "PointLight\n{\nPosition " << vec(chance(0.2) ? 1e18 : 50) << "\nColor " << colour() << "\n}\n";
            else
                s << "AreaLight\n{\nPosition " << vec(30) << "\nDirection 0 -1 0\nWidth " << logUniform(1e-6, 50)
                  << "\nHeight " << logUniform(1e-6, 50) << "\nColor " << colour() << "\nSubdivision 2 2\n}\n";
        }
        for (int i = 0, objects = pick(2, 5); i < objects; ++i) s << object(pick(0, 2));
        return s.str();
    }

private:
    std::mt19937 rng_;

    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    double logUniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
    int pick(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
    bool chance(double p) { return uniform(0, 1) < p; }
    std::string vec(double reach) {
        std::ostringstream s;
        s << uniform(-reach, reach) << " " << uniform(-reach, reach) << " " << uniform(-reach, reach);
        return s.str();
    }
    // A colour component: mostly ordinary, sometimes at the bound of 1e12, never negative.
    double component() { return chance(0.2) ? logUniform(1, 1e12) : uniform(0, 1); }
    std::string colour() {
        std::ostringstream s;
        s << component() << " " << component() << " " << component();
        return s.str();
    }
    // Material m<index>.
    std::string material(int index) {
        std::ostringstream s;
        const bool scatters = chance(0.4);
        s << "Material\n{\nName m" << index << "\nDiffuseColor ";
        if (scatters) s << uniform(0, 1) << " " << uniform(0, 1) << " " << uniform(0.9, 1);
        else s << colour();
        s << "\nSpecularColor " << colour() << "\nRoughness " << logUniform(1e-4, 10) << "\nOpacity " << uniform(0, 1)
          << "\nRefractionIndex " << (chance(0.3) ? logUniform(1, 1e30) : logUniform(0.1, 4))
          << "\nReflectionAmount " << uniform(0, 1) << "\nReflectionAngle " << (chance(0.5) ? 0.0 : uniform(0, 180))
          << "\nFresnel " << pick(0, 1) << "\nDispersion " << (chance(0.3) ? uniform(0, 20) : 0.0);
        if (chance(0.3)) s << "\nEmissiveColor " << colour();
        if (scatters) {
            s << "\nScatteringDistance " << logUniform(1e-6, 1e6) << " " << logUniform(1e-6, 1e6) << " "
              << (chance(0.2) ? 0.0 : logUniform(1e-6, 1e6));
        }
        s << "\n}\n";
        return s.str();
    }
    // An object of material m<material>.
    std::string object(int material) {
        std::ostringstream s;
        const double size = chance(0.2) ? logUniform(1e-6, 1e19) : logUniform(0.1, 5);
        switch (pick(0, 2)) {
            case 0:
                s << "Sphere\n{\nMaterial m" << material << "\nCenter " << vec(5) << "\nRadius " << size << "\n}\n";
                break;
            case 1:
                s << "Box\n{\nMaterial m" << material << "\nScale " << logUniform(1e-19, 1e18) << " "
                  << std::min(size, 1e18) << " "
                  << logUniform(0.01, 10) << "\nRotation 1 2 3 " << uniform(0, 6.3) << "\nTranslation " << vec(5)
                  << "\n}\n";
                break;
            default:
                s << "Cylinder\n{\nMaterial m" << material << "\nBase " << vec(5) << "\nAxis " << vec(1)
                  << "\nHeight " << logUniform(1e-6, 1e6) << "\nRadius " << size << "\n}\n";
        }
        return s.str();
    }
};

TEST(RandomExtremes, EveryPixelIsFiniteAndNotNegative) {
    int rendered = 0;
    for (unsigned seed = 1; seed <= 60; ++seed) {
        const std::string scene = ExtremeScene(seed).text();
        const RenderedImage image = renderSceneText(scene, {.passes = 2, .seed = seed});
        ASSERT_EQ(image.pixels.size(), 144u) << "seed " << seed << " did not render:\n" << scene;
        ++rendered;
        for (size_t i = 0; i < image.pixels.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                const float v = image.pixels[i][c];
                ASSERT_TRUE(std::isfinite(v) && v >= 0.0f)
                    << "seed " << seed << ", pixel " << i << ", channel " << c << ": " << v << "\n" << scene;
            }
        }
    }
    EXPECT_EQ(rendered, 60);
}

}  // namespace
}  // namespace trazo::test
