// Error of an image from its accumulation's two halves, or against a reference (formulas in the header).
#include "render/error_estimate.h"

namespace trazo {

ErrorEstimate estimateError(const std::vector<AccumPixel>& accum) {
    ErrorEstimate e;
    if (accum.empty()) return e;
    e.passes = (uint32_t)accum[0].count;
    e.secondHalfPasses = (uint32_t)accum[0].countB;
    double variance = 0.0, mean = 0.0;
    bool both = true;
    for (const AccumPixel& p : accum) {
        const double n = p.count, nB = p.countB, nA = n - nB;
        if (!(nA > 0.0 && nB > 0.0)) {
            both = false;
            if (n > 0.0) mean += (p.sum[0] + p.sum[1] + p.sum[2]) / n;
            continue;
        }
        const double w = nA * nB / (n * n);
        for (int c = 0; c < 3; ++c) {
            const double sum = p.sum[c], sumB = p.sumB[c];
            const double d = (sum - sumB) / nA - sumB / nB;
            variance += w * d * d;
            mean += sum / n;
        }
    }
    const double values = 3.0 * accum.size();
    e.meanValue = mean / values;
    if (!both) return e;
    e.available = true;
    e.rmse = std::sqrt(variance / values);
    e.relError = e.meanValue > 0.0 ? e.rmse / e.meanValue : (e.rmse > 0.0 ? INFINITY : 0.0);
    return e;
}

ReferenceError compareToReference(const std::vector<Vec3>& image, const std::vector<Vec3>& reference) {
    ReferenceError r;
    if (image.empty() || image.size() != reference.size()) return r;
    double se = 0.0, rel = 0.0, mean = 0.0;
    for (size_t i = 0; i < image.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double ref = reference[i][c], d = double(image[i][c]) - ref;
            se += d * d;
            rel += d * d / (ref * ref + 0.01);
            mean += ref;
        }
    }
    const double values = 3.0 * image.size();
    r.rmse = std::sqrt(se / values);
    mean /= values;
    r.relError = mean > 0.0 ? r.rmse / mean : (r.rmse > 0.0 ? INFINITY : 0.0);
    r.relMse = rel / values;
    return r;
}

}  // namespace trazo
