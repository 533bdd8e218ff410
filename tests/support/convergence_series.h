// Time-versus-error series (host): render a scene progressively (or with the fixed-grid estimator), read it
// at 1, 2, 4, … passes, and measure the error against a reference; fit the log–log slope and interpolate
// the time to reach an error. Header-only so the benchmark and tests/convergence_test.cpp share it.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

#include "backends/backend.h"
#include "flatten/scene_arrays.h"
#include "render/error_estimate.h"
#include "render/frame_setup.h"
#include "render/progressive_render.h"
#include "scene/scene.h"

namespace trazo::convergence {

struct ConvergencePoint {
    uint32_t passes = 0;
    double seconds = 0;         // render time of these passes (reads and error measurement excluded)
    double rmse = NAN;          // against the reference (error_estimate.h: ReferenceError)
    double relError = NAN;      // rmse / reference mean
    double relMse = NAN;
    double trueRelError = NAN;  // relError with the reference's own estimated error removed in quadrature
    double estRelError = NAN;   // the render's own estimate (estimateError)
    bool balanced = false;      // passes a multiple of 2·cycle: both halves equally stratified
    bool wholeCycles = false;   // passes a multiple of the cycle: every stratum taken equally often
};

struct SeriesRequest {
    uint32_t width = 0, height = 0;
    uint32_t seed = 0;
    uint32_t maxPasses = 256;
    StrataBlocks blocks{};       // the strata a pass takes (StrataBlocks::whole(): the thesis's fixed grid)
    bool cycleMultiples = true;  // also read at cycle·2^k passes (a cycle of several): where the image is balanced
    double maxSeconds = 0;  // > 0: stop doubling once the render time passes this
};

struct Reference {
    std::vector<Vec3> image;
    uint32_t passes = 0;
    double seconds = 0;
    double estRelError = NAN;  // its own estimated relative error
};

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The reference: `passes` progressive passes with its own seed (rounded up to a multiple of 2·cycle, so its
// own estimate is unbiased).
inline Reference renderReference(Backend& backend, const Scene& scene, const SceneArrays& arrays, uint32_t width,
                                 uint32_t height, uint32_t passes, uint32_t seed) {
    const StrataBlocks blocks = StrataBlocks::ones();
    const uint32_t cycle = fullCyclePasses(arrays, blocks), step = splitsHalves(cycle) ? 2 * cycle : 1;
    Reference ref;
    ref.passes = std::max(step, (passes + step - 1) / step * step);
    backend.upload(arrays);
    backend.resize(width, height);
    RenderLimits limits;
    limits.passes = ref.passes;
    limits.cyclePasses = cycle;
    ref.seconds = renderProgressive(backend, makeFrameParams(scene, width, height, seed, blocks), limits).seconds;
    std::vector<AccumPixel> accum;
    backend.readAccumulation(accum);
    ref.estRelError = estimateError(accum).relError;
    ref.image = resolveImage(accum);
    return ref;
}

// The pass counts a series reads: 1, 2, 4, … and maxPasses, plus (optionally) cycle·1, cycle·2, cycle·4, …
inline std::vector<uint32_t> seriesSchedule(uint32_t maxPasses, uint32_t cycle, bool cycleMultiples) {
    std::vector<uint32_t> at;
    for (uint64_t n = 1; n < maxPasses; n *= 2) at.push_back((uint32_t)n);
    if (cycleMultiples && cycle > 1)
        for (uint64_t n = cycle; n < maxPasses; n *= 2) at.push_back((uint32_t)n);
    at.push_back(maxPasses);
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    return at;
}

// One render read at the schedule's pass counts: progressive passes continue the same accumulation, so each
// point costs only the passes added since the previous one.
inline std::vector<ConvergencePoint> runSeries(Backend& backend, const Scene& scene, const SceneArrays& arrays,
                                               const Reference& ref, const SeriesRequest& req) {
    const uint32_t cycle = fullCyclePasses(arrays, req.blocks);
    const FrameParams frame = makeFrameParams(scene, req.width, req.height, req.seed, req.blocks);
    backend.upload(arrays);
    backend.resize(req.width, req.height);
    std::vector<ConvergencePoint> points;
    std::vector<AccumPixel> accum;
    double seconds = 0;
    uint32_t done = 0;
    for (uint32_t target : seriesSchedule(std::max(req.maxPasses, 1u), cycle, req.cycleMultiples)) {
        const auto t0 = std::chrono::steady_clock::now();
        renderPassRange(backend, frame, done, target - done, cycle);
        seconds += secondsSince(t0);
        done = target;
        backend.readAccumulation(accum);
        ConvergencePoint p;
        p.passes = done;
        p.seconds = seconds;
        const ReferenceError r = compareToReference(resolveImage(accum), ref.image);
        p.rmse = r.rmse, p.relError = r.relError, p.relMse = r.relMse;
        const double refErr = std::isfinite(ref.estRelError) ? ref.estRelError : 0.0;
        p.trueRelError = std::sqrt(std::max(0.0, r.relError * r.relError - refErr * refErr));
        p.estRelError = estimateError(accum).relError;
        p.balanced = splitsHalves(cycle) && done % (2 * cycle) == 0;
        p.wholeCycles = done % cycle == 0;
        points.push_back(p);
        if (req.maxSeconds > 0 && seconds > req.maxSeconds) break;
    }
    return points;
}

// Least-squares slope of log(error) against log(seconds) over points with at least minPasses passes
// (error = trueRelError). Expect about −1/2 for a Monte Carlo estimate once past one cycle.
inline double logLogSlope(const std::vector<ConvergencePoint>& points, uint32_t minPasses = 1) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (const ConvergencePoint& p : points) {
        if (p.passes < minPasses || !(p.seconds > 0) || !(p.trueRelError > 0)) continue;
        const double x = std::log(p.seconds), y = std::log(p.trueRelError);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    }
    if (n < 2) return NAN;
    const double d = n * sxx - sx * sx;
    return d != 0 ? (n * sxy - sx * sy) / d : NAN;
}

// Seconds at which the measured error first falls to `error`, interpolated linearly in log(time)–log(error)
// between the two points around the crossing (the first point's time if it is already below); NaN if never.
inline double timeToReach(const std::vector<ConvergencePoint>& points, double error) {
    for (size_t i = 0; i < points.size(); ++i) {
        const ConvergencePoint& p = points[i];
        if (!(p.trueRelError <= error)) continue;
        if (i == 0) return p.seconds;
        const ConvergencePoint& q = points[i - 1];
        if (!(q.seconds > 0) || !(p.seconds > 0) || !(q.trueRelError > 0) || !(p.trueRelError > 0))
            return p.seconds;
        const double e0 = std::log(q.trueRelError), e1 = std::log(p.trueRelError);
        const double t = e0 != e1 ? (std::log(error) - e0) / (e1 - e0) : 1.0;
        return std::exp(std::log(q.seconds) + std::clamp(t, 0.0, 1.0) * (std::log(p.seconds) - std::log(q.seconds)));
    }
    return NAN;
}

}  // namespace trazo::convergence
