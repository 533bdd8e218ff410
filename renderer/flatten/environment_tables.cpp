// The environment's sampling tables (host): exact cell integrals of the bilinear map, then a marginal CDF over the
// grid's rows and one CDF per row, as lights/environment.h reads them.
#include "flatten/environment_tables.h"

#include <algorithm>
#include <cmath>

namespace trazo {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ∫ from −∞ to s of the tent max(0, 1 − |x|): the bilinear weight of a texel, in texel units about its centre.
double tentIntegralTo(double s) {
    if (s <= -1.0) return 0.0;
    if (s <= 0.0) return 0.5 * (s + 1.0) * (s + 1.0);
    if (s < 1.0) return 1.0 - 0.5 * (1.0 - s) * (1.0 - s);
    return 1.0;
}

struct TexelShare {
    uint32_t texel;
    double share;  // ∫ of the texel's bilinear weight over the cell, in units of the axis' [0, 1]
};

// For each of `cells` equal cells of an axis of `texels` texels: the texels whose bilinear weight reaches into the
// cell, and its integral there. Texel m's weight is the tent about its centre m + ½; tents beyond the ends are
// those of texels wrapped around (u) or clamped to the first and last (v), as environmentTexel reads them, so the
// shares of a cell add up to its width.
std::vector<std::vector<TexelShare>> cellShares(uint32_t texels, uint32_t cells, bool wrap) {
    std::vector<std::vector<TexelShare>> out(cells);
    for (uint32_t c = 0; c < cells; ++c) {
        const double x0 = double(c) / cells * texels, x1 = double(c + 1) / cells * texels;
        for (int64_t m = int64_t(std::floor(x0 - 0.5)) - 1; m <= int64_t(std::floor(x1 - 0.5)) + 1; ++m) {
            const double centre = double(m) + 0.5;
            const double share = (tentIntegralTo(x1 - centre) - tentIntegralTo(x0 - centre)) / texels;
            if (!(share > 0.0)) continue;
            const int64_t n = int64_t(texels);
            const uint32_t t = uint32_t(wrap ? ((m % n) + n) % n : std::clamp<int64_t>(m, 0, n - 1));
            auto same = std::find_if(out[c].begin(), out[c].end(), [&](const TexelShare& s) { return s.texel == t; });
            if (same != out[c].end())
                same->share += share;
            else
                out[c].push_back({t, share});
        }
    }
    return out;
}

// Appends the CDF of n weights (n + 1 floats from 0). A cell of positive weight gets a positive width even where
// rounding to float would give it none (the next float up), so the last entry may exceed 1 by a few ulps: the
// kernels divide by it.
void appendCdf(const double* weights, uint32_t n, std::vector<float>& cdf) {
    double total = 0.0;
    for (uint32_t i = 0; i < n; ++i) total += weights[i];
    float previous = 0.0f;
    double prefix = 0.0;
    cdf.push_back(0.0f);
    for (uint32_t i = 0; i < n; ++i) {
        prefix += weights[i];
        float c = previous;
        if (weights[i] > 0.0) c = std::max(float(prefix / total), std::nextafter(previous, INFINITY));
        cdf.push_back(c);
        previous = c;
    }
}

// Rec. 709 luminance of |background ⊙ texel|, the brightness the grid follows; NaN as 0, bounded so sums stay finite.
double luminance(Vec3 weight, Vec3 texel) {
    const double l = double(weight.x) * std::fabs(texel.x) + double(weight.y) * std::fabs(texel.y) +
                     double(weight.z) * std::fabs(texel.z);
    return l > 0.0 ? std::min(l, 1e30) : 0.0;
}

}  // namespace

EnvironmentData environmentTables(Vec3 background, float rotationDegrees, int32_t textureIndex,
                                  const TextureImage* image, std::vector<float>& cdf) {
    EnvironmentData env{};
    env.background = background;
    env.texture = image ? textureIndex : -1;
    const double rotation = double(rotationDegrees) * kPi / 180.0;
    env.cosRotation = float(std::cos(rotation));
    env.sinRotation = float(std::sin(rotation));
    env.cdfOffset = uint32_t(cdf.size());
    const Vec3 weight = abs(background) * Vec3(0.2126f, 0.7152f, 0.0722f);
    if (!image) {
        env.power = float(4.0 * kPi * luminance(weight, Vec3(1.0f)));
        return env;
    }
    const uint32_t width = uint32_t(image->width), height = uint32_t(image->height);
    env.cols = std::clamp(kEnvironmentCellsPerTexel * width, kMinEnvironmentCols, kMaxEnvironmentCols);
    env.rows = std::clamp(kEnvironmentCellsPerTexel * height, kMinEnvironmentRows, kMaxEnvironmentRows);
    const auto colShares = cellShares(width, env.cols, true), rowShares = cellShares(height, env.rows, false);

    // weights[J][I] = ∫∫ over cell (I, J) of the bilinear luminance du dv, times the row's mean sin θ.
    std::vector<double> weights(size_t(env.rows) * env.cols, 0.0), texelRow(width);
    double total = 0.0;
    for (uint32_t row = 0; row < env.rows; ++row) {
        double* cells = &weights[size_t(row) * env.cols];
        for (const TexelShare& r : rowShares[row]) {
            const Vec3* texels = &image->texels[size_t(height - 1 - r.texel) * width];  // stored bottom row first
            for (uint32_t i = 0; i < width; ++i) texelRow[i] = luminance(weight, texels[i]);
            for (uint32_t col = 0; col < env.cols; ++col) {
                double sum = 0.0;
                for (const TexelShare& c : colShares[col]) sum += c.share * texelRow[c.texel];
                cells[col] += r.share * sum;
            }
        }
        const double theta0 = kPi * row / env.rows, theta1 = kPi * (row + 1) / env.rows;
        const double meanSin = (std::cos(theta0) - std::cos(theta1)) / (theta1 - theta0);
        for (uint32_t col = 0; col < env.cols; ++col) total += (cells[col] *= meanSin);
    }
    env.power = float(2.0 * kPi * kPi * total);  // dω = 2π² sin θ du dv

    std::vector<double> rowTotals(env.rows, 0.0);
    for (uint32_t row = 0; row < env.rows; ++row)
        for (uint32_t col = 0; col < env.cols; ++col) rowTotals[row] += weights[size_t(row) * env.cols + col];
    appendCdf(rowTotals.data(), env.rows, cdf);
    for (uint32_t row = 0; row < env.rows; ++row) appendCdf(&weights[size_t(row) * env.cols], env.cols, cdf);
    return env;
}

void appendEnvironment(Vec3 background, float rotationDegrees, const TextureImage* image, SceneArrays& out) {
    const size_t cdfBefore = out.environmentCdf.size();
    const int32_t texture = image ? int32_t(out.textures.size()) : -1;
    const EnvironmentData env = environmentTables(background, rotationDegrees, texture, image, out.environmentCdf);
    if (!(env.power > 0.0f)) {
        out.environmentCdf.resize(cdfBefore);
        return;
    }
    if (image) {
        out.textures.push_back({uint32_t(out.texels.size()), uint32_t(image->width), uint32_t(image->height)});
        out.texels.insert(out.texels.end(), image->texels.begin(), image->texels.end());
    }
    out.environment.push_back(env);
}

}  // namespace trazo
