// The environment's tables (host): the EnvironmentData and the CDFs that lights/environment.h samples, built from
// BackgroundColor, EnvironmentRotation and the map (SPEC §7).
#pragma once

#include <cstdint>
#include <vector>

#include "flatten/scene_arrays.h"
#include "lights/environment.h"
#include "scene/scene.h"

namespace trazo {

// The sampling grid: two cells a texel each way, so the piecewise-constant pdf follows the bilinear radiance inside
// a texel (environment_test.cpp's 1.4-texel sun: an RMS error of 2.9 % at 256 samples, 4.7 % with one cell a
// texel), within bounds: at least
// 64 × 32 cells, at most 2048 × 1024 (8 MiB of CDF, built in about 10 operations a texel whatever the map; a
// larger map's texels share cells, merged exactly).
constexpr uint32_t kEnvironmentCellsPerTexel = 2;
constexpr uint32_t kMinEnvironmentCols = 64, kMaxEnvironmentCols = 2048;
constexpr uint32_t kMinEnvironmentRows = 32, kMaxEnvironmentRows = 1024;

// The environment with the map `image` (null: none, M = 1), whose texels are SceneView::textures[textureIndex].
// Appends its CDFs to `cdf` (cdfOffset is cdf's size before). Each grid cell's weight is the exact integral over
// the cell of the bilinear M's luminance (after |BackgroundColor|, component by component), times the row's mean
// sin θ: positive wherever M ≠ 0 somewhere in the cell, so the pdf covers what bilinear filtering spreads into
// neighbouring cells, across the u seam and up to the poles. power is 0 when the environment is black everywhere.
EnvironmentData environmentTables(Vec3 background, float rotationDegrees, int32_t textureIndex,
                                  const TextureImage* image, std::vector<float>& cdf);

// Adds the environment to `out`: its map's texels as one more texture (after the materials' textures), its CDFs
// and its element of `environment`. Nothing when it is black everywhere (`environment` stays empty).
void appendEnvironment(Vec3 background, float rotationDegrees, const TextureImage* image, SceneArrays& out);

}  // namespace trazo
