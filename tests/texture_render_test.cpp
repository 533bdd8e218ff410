// Textures through the whole pipeline: a diffuse texture multiplies the colour texel by texel, a flat
// normal map changes nothing, a constant tilted normal map tilts the shading normal by the hand-computed angle.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "image/image_writer.h"
#include "render_harness.h"
#include "test_paths.h"

namespace trazo::test {
namespace {

std::string writeTexture(const std::string& name, int w, int h, const std::vector<Vec3>& topDown) {
    const std::string path = tempPath(name);
    std::string error;
    EXPECT_TRUE(writeImage(path, w, h, topDown, error)) << error;
    return path;
}

// The +Z face of a unit box fills the view (orthographic-like: far camera, narrow FOV); a point light at the
// camera lights it head-on, so with σ = 0 and no specular a pixel is Kd · texture · (N·L ≈ 1).
std::string faceScene(const std::string& textureLines, const std::string& materialLines) {
    return "SceneSettings\n{\nRenderWidth 16\nRenderHeight 16\nReflectionQuality 0\nIndirectQuality 0\n}\n"
           "Camera\n{\nPOV 0 0 1000\nPOI 0 0 0\nFOV 0.0572958\n}\n" + textureLines +
           "Material\n{\nName m\nDiffuseColor 1 1 1\nSpecularColor 0 0 0\nRoughness 0\n" + materialLines + "}\n"
           "Box\n{\nMaterial m\n}\n"
           "PointLight\n{\nPosition 0 0 1000\nColor 1 1 1\n}\n";
}

// A 2×2 texture seen through 16×16 pixels: each quadrant of the image is (close to) one texel, with the
// image's top-left quadrant showing the texture's top-left texel (uv origin bottom-left, v up on the face).
TEST(TextureRender, DiffuseTextureMultipliesTheColour) {
    const std::vector<Vec3> texels{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 0)};  // top row first
    const std::string path = writeTexture("quad.png", 2, 2, texels);
    const RenderedImage image = renderSceneText(
        faceScene("Texture\n{\nName checker\nSource \"" + path + "\"\n}\n", "DiffuseTexture checker\n"), {});
    ASSERT_EQ(image.width, 16);
    // Pixel (4,4) sits at uv ≈ (0.28, 0.72), 1/16 of a texel from the top-left texel's centre: bilinear
    // weight 0.94² on it. (Near the image's edges the repeat wrap blends in the opposite side.)
    const Vec3 topLeft = image.at(4, 4), topRight = image.at(11, 4), bottomLeft = image.at(4, 11);
    EXPECT_GT(topLeft.x, 0.8f);
    EXPECT_LT(topLeft.y + topLeft.z, 0.2f);
    EXPECT_GT(topRight.y, 0.8f);
    EXPECT_GT(bottomLeft.z, 0.8f);
    // The centre pixel pair straddles uv = (½, ½): the mean of all four texels, (0.5, 0.5, 0.25).
    const Vec3 centre = (image.at(7, 7) + image.at(8, 8) + image.at(7, 8) + image.at(8, 7)) * 0.25f;
    EXPECT_NEAR(centre.x, 0.5f, 0.02f);
    EXPECT_NEAR(centre.y, 0.5f, 0.02f);
    EXPECT_NEAR(centre.z, 0.25f, 0.02f);
}

TEST(TextureRender, FlatNormalMapLeavesTheImageUnchanged) {
    const std::string path = writeTexture("flat.exr", 4, 4, std::vector<Vec3>(16, Vec3(0.5f, 0.5f, 1.0f)));
    const std::string lights = "PointLight\n{\nPosition 0.3 0.2 0.8\nColor 1 1 1\n}\n";
    const RenderedImage plain = renderSceneText(faceScene("", "") + lights, {});
    const RenderedImage mapped = renderSceneText(
        faceScene("Texture\n{\nName flat\nSource \"" + path + "\"\n}\n", "NormalTexture flat\n") + lights, {});
    ASSERT_EQ(plain.pixels.size(), mapped.pixels.size());
    EXPECT_LT(rmse(plain, mapped), 1e-6);
}

// m = (sin 30°, 0, cos 30°) in the face's (tangent = +X, bitangent = +Y) frame: the head-on light now sees
// N·L = cos 30°. A second light along the tilted normal sees N·L = 1 (difference: exactly that light's term).
TEST(TextureRender, TiltedNormalMapShadesByTheHandComputedAngle) {
    const float s = 0.5f, c = std::sqrt(3.0f) / 2.0f;
    const std::string path = writeTexture("tilt.exr", 4, 4, std::vector<Vec3>(16, Vec3(0.5f + 0.5f * s, 0.5f, 0.5f + 0.5f * c)));
    const RenderedImage image = renderSceneText(
        faceScene("Texture\n{\nName tilt\nSource \"" + path + "\"\n}\n", "NormalTexture tilt\n"), {});
    ASSERT_EQ(image.width, 16);
    for (const Vec3& p : image.pixels) EXPECT_NEAR(p.x, c, 4e-4f);  // the light is 1000 away: ±0.5 mrad across the face
}

}  // namespace
}  // namespace trazo
