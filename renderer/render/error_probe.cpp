// The error probe's draw, frame and estimate (formulas in the header).
#include "render/error_probe.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace trazo {

namespace {

constexpr uint32_t kProbeSeedSalt = 0x70726f62u;  // "prob": the probe's seed is hashCombine(seed, this)

double squaredValue(const AccumPixel& p) {
    if (!(p.count > 0.0)) return 0.0;
    double s = 0.0;
    if (p.count == 1.0) {  // the first pass's: x / 1 is x, so the same sum without its three divisions
        for (int c = 0; c < 3; ++c) s += p.sum[c] * p.sum[c];
        return s;
    }
    for (int c = 0; c < 3; ++c) s += (p.sum[c] / p.count) * (p.sum[c] / p.count);
    return s;
}

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

// A pixel's chance of being drawn, π_i = min(1, base + s_i/τ) with Σ s_i/τ = the bright share's expected
// draw, and its fixed uniform number u_i (drawn when u_i < π_i).
struct ProbeChances {
    double base = 0.0;
    double share = 0.0;  // the bright share's expected draw: perValue = share / Σ s_i
    uint32_t key = 0;

    ProbeChances(size_t n, uint32_t seed) : key(hashCombine(seed, kProbeSeedSalt + 1u)) {
        // Small images: at least ~64 pixels, all of them below 64.
        base = std::max(std::min(kProbeMaxBaseShare, double(kProbeBasePixels) / double(n)),
                        std::min(1.0, double(kProbeMinPixels) / double(n)));
        share = kProbeBrightShare * base * double(n);
    }
    double uniform(uint32_t i) const { return double(hashCombine(key, i)) * 0x1p-32; }  // in [0, 1)
    double chance(double perValue, double value) const { return std::min(1.0, base + perValue * value); }
};

double totalSquaredValue(const std::vector<AccumPixel>& image) {
    double total = 0.0;
    for (const AccumPixel& p : image) total += squaredValue(p);
    return total;
}

}  // namespace

ErrorProbe designProbe(const std::vector<AccumPixel>& image, uint32_t width, uint32_t height, uint32_t seed) {
    ErrorProbe probe;
    const size_t n = (size_t)width * height;
    if (n == 0 || image.size() != n) return probe;
    const ProbeChances chances(n, seed);
    // One pass over the image (it is large): the total, and the pixels that may be drawn whatever the rest adds.
    // The running total only grows, so share / running ≥ perValue, and the chance it gives is ≥ the pixel's.
    struct Candidate {
        uint32_t index;
        double value;
    };
    std::vector<Candidate> candidates;
    double total = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double value = squaredValue(image[i]);
        total += value;
        const double bound = total > 0.0 ? chances.share / total : 0.0;
        if (chances.uniform((uint32_t)i) < chances.chance(bound, value)) candidates.push_back({(uint32_t)i, value});
    }
    const double perValue = total > 0.0 ? chances.share / total : 0.0;
    for (const Candidate& c : candidates) {
        const double chance = chances.chance(perValue, c.value);
        if (chances.uniform(c.index) < chance) {
            probe.pixels.push_back(c.index);
            probe.weights.push_back(1.0 / chance);
        }
    }
    return probe;
}

ErrorProbe growProbe(const std::vector<AccumPixel>& image, uint32_t width, uint32_t height, uint32_t seed,
                     ErrorProbe& probe) {
    ErrorProbe added;
    const size_t n = (size_t)width * height;
    if (n == 0 || image.size() != n) return added;
    const ProbeChances chances(n, seed);
    const double total = totalSquaredValue(image);
    const double perValue = total > 0.0 ? chances.share / total : 0.0;
    size_t k = 0;  // the next probed pixel
    for (size_t i = 0; i < n; ++i) {
        const double chance = chances.chance(perValue, squaredValue(image[i]));
        if (k < probe.pixels.size() && probe.pixels[k] == i) {
            // Drawn before with chance 1/weight: its π' is the larger of the two.
            probe.weights[k] = std::min(probe.weights[k], 1.0 / chance);
            ++k;
        } else if (chances.uniform((uint32_t)i) < chance) {
            // Not drawn before, so u_i was at least every earlier chance: π' is this one.
            added.pixels.push_back((uint32_t)i);
            added.weights.push_back(1.0 / chance);
        }
    }
    return added;
}

void addToProbe(ErrorProbe& probe, std::vector<AccumPixel>& probeAccum, const ErrorProbe& added,
                const std::vector<AccumPixel>& addedAccum) {
    ErrorProbe merged;
    std::vector<AccumPixel> mergedAccum;
    const size_t total = probe.pixels.size() + added.pixels.size();
    merged.pixels.reserve(total);
    merged.weights.reserve(total);
    mergedAccum.reserve(total);
    size_t a = 0, b = 0;
    while (a < probe.pixels.size() || b < added.pixels.size()) {
        const bool fromProbe =
            b == added.pixels.size() || (a < probe.pixels.size() && probe.pixels[a] < added.pixels[b]);
        const ErrorProbe& from = fromProbe ? probe : added;
        const size_t k = fromProbe ? a++ : b++;
        merged.pixels.push_back(from.pixels[k]);
        merged.weights.push_back(from.weights[k]);
        mergedAccum.push_back(fromProbe ? probeAccum[k] : addedAccum[k]);
    }
    probe = std::move(merged);
    probeAccum = std::move(mergedAccum);
}

FrameParams probeFrame(const FrameParams& image) {
    FrameParams f = image;
    f.seed = hashCombine(image.seed, kProbeSeedSalt);
    f.target = PassPixels{true, nullptr, 0};
    return f;
}

ErrorEstimate estimateErrorWithProbe(const std::vector<AccumPixel>& image, const ErrorProbe& probe,
                                     const std::vector<AccumPixel>& probeAccum) {
    ErrorEstimate e;
    if (image.empty() || probe.empty() || probeAccum.size() != probe.pixels.size()) return e;
    e.passes = (uint32_t)image[0].count;
    e.secondHalfPasses = (uint32_t)image[0].countB;
    e.probePixels = (uint32_t)probe.pixels.size();
    double mean = 0.0, halvesAll = 0.0;
    bool halves = true;
    for (const AccumPixel& p : image) {
        if (p.count > 0.0) mean += (p.sum[0] + p.sum[1] + p.sum[2]) / p.count;
        const double h = halvesStatistic(p);
        halves = halves && h >= 0.0;
        halvesAll += h;
    }
    const double values = 3.0 * image.size();
    e.meanValue = mean / values;

    double squares = 0.0, halvesProbed = 0.0;
    for (size_t k = 0; k < probe.pixels.size(); ++k) {
        if (probe.pixels[k] >= image.size()) return e;
        const AccumPixel& f = image[probe.pixels[k]];
        const AccumPixel& g = probeAccum[k];
        if (!(f.count > 0.0) || f.count != g.count) return e;  // the probe must hold the image's passes
        double s = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = f.sum[c] / f.count - g.sum[c] / g.count;
            s += 0.5 * d * d;
        }
        squares += probe.weights[k] * s;
        if (halves) halvesProbed += probe.weights[k] * halvesStatistic(f);
    }
    e.available = true;
    double mse = squares / values;
    // The ratio estimator of two-phase sampling: the halves' statistic, known at every pixel, scales the
    // probed pixels' sum by how much noisier the whole image is than they say. A rare bright sample the draw
    // missed then counts; the halves' own bias (unequal stratification) cancels in the ratio.
    if (halves && halvesProbed > 0.0) mse *= halvesAll / halvesProbed;
    e.rmse = std::sqrt(mse);
    e.relError = e.meanValue > 0.0 ? e.rmse / e.meanValue : (e.rmse > 0.0 ? INFINITY : 0.0);
    return e;
}

}  // namespace trazo
