// The error probe's lattice, frame and estimate (formulas in the header).
#include "render/error_probe.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace trazo {

namespace {

constexpr uint32_t kProbeSeedSalt = 0x70726f62u;  // "prob": the probe's seed is hashCombine(seed, this)

uint32_t latticeSide(uint32_t size, uint32_t offset, uint32_t stride) {
    return size > offset ? (size - offset + stride - 1) / stride : 0u;
}

}  // namespace

PixelLattice probeLattice(uint32_t width, uint32_t height, uint32_t seed) {
    const double pixels = double(width) * double(height);
    const uint32_t stride =
        std::max(kProbeMinStride, (uint32_t)std::floor(std::sqrt(pixels / double(kProbeTargetPixels))));
    PixelLattice l;
    l.stride = stride;
    const uint32_t h = hashCombine(seed, kProbeSeedSalt + 1u);
    // An offset inside the image even when it is narrower than the stride.
    l.offsetX = (h & 0xffffu) % std::min(stride, std::max(width, 1u));
    l.offsetY = (h >> 16) % std::min(stride, std::max(height, 1u));
    l.width = latticeSide(width, l.offsetX, stride);
    l.height = latticeSide(height, l.offsetY, stride);
    return l;
}

FrameParams probeFrame(const FrameParams& image, const PixelLattice& lattice) {
    FrameParams f = image;
    f.seed = hashCombine(image.seed, kProbeSeedSalt);
    f.lattice = lattice;
    return f;
}

namespace {

// Per pixel, the halves' statistic of error_estimate.h, Σ_c (nA·nB/n²)(A − B)²; −1 without two halves.
double halvesStatistic(const AccumPixel& p) {
    const double n = p.count, nB = p.countB, nA = n - nB;
    if (!(nA > 0.0 && nB > 0.0)) return -1.0;
    double s = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double d = (p.sum[c] - p.sumB[c]) / nA - p.sumB[c] / nB;
        s += nA * nB / (n * n) * d * d;
    }
    return s;
}

}  // namespace

ErrorEstimate estimateErrorWithProbe(const std::vector<AccumPixel>& image, uint32_t width,
                                     const PixelLattice& lattice, const std::vector<AccumPixel>& probe) {
    ErrorEstimate e;
    if (image.empty() || probe.empty() || probe.size() != (size_t)lattice.width * lattice.height) return e;
    e.passes = (uint32_t)image[0].count;
    e.secondHalfPasses = (uint32_t)image[0].countB;
    e.probePixels = (uint32_t)probe.size();
    double mean = 0.0, halvesAll = 0.0, halvesLattice = 0.0;
    bool halves = true;
    for (const AccumPixel& p : image) {
        if (p.count > 0.0) mean += (p.sum[0] + p.sum[1] + p.sum[2]) / p.count;
        const double h = halvesStatistic(p);
        halves = halves && h >= 0.0;
        halvesAll += h;
    }
    e.meanValue = mean / (3.0 * image.size());

    double squares = 0.0;
    for (uint32_t j = 0; j < lattice.height; ++j) {
        for (uint32_t i = 0; i < lattice.width; ++i) {
            const AccumPixel& g = probe[(size_t)j * lattice.width + i];
            const size_t at = (size_t)(lattice.offsetY + lattice.stride * j) * width + lattice.offsetX + lattice.stride * i;
            if (at >= image.size()) return e;
            const AccumPixel& f = image[at];
            if (!(f.count > 0.0) || f.count != g.count) return e;  // the probe must hold the image's passes
            halvesLattice += halvesStatistic(f);
            for (int c = 0; c < 3; ++c) {
                const double d = f.sum[c] / f.count - g.sum[c] / g.count;
                squares += 0.5 * d * d;
            }
        }
    }
    e.available = true;
    double mse = squares / (3.0 * probe.size());
    // The ratio estimator of two-phase sampling: where the image has halves, their statistic, known at every
    // pixel, scales the lattice's estimate by how much noisier the whole image is than the lattice. A rare
    // bright sample off the lattice (a glossy reflection of a light) then counts, and one on it is not
    // counted stride² times over. The halves' own bias (unequal stratification) cancels in the ratio.
    if (halves && halvesLattice > 0.0)
        mse *= (halvesAll / double(image.size())) / (halvesLattice / double(probe.size()));
    e.rmse = std::sqrt(mse);
    e.relError = e.meanValue > 0.0 ? e.rmse / e.meanValue : (e.rmse > 0.0 ? INFINITY : 0.0);
    return e;
}

}  // namespace trazo
