// Test helper (host): a backend with a known answer for the error estimate's, the progressive render's and the
// error tracker's tests, so their statistics are exact and quick.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "core/rng.h"

namespace trazo {
namespace test {

// A backend without a scene: pass v of pixel i adds f(i, stratum) + noise, with the strata of a grid of
// `strata` cells cycled from a per-pixel offset exactly as the kernels do. Exact value per pixel known. With
// `probe`, it has an error probe: a probe frame's passes draw the listed pixels from the frame's seed (the
// image's draw from a fixed one), so the two are independent.
class FakeBackend final : public Backend {
public:
    FakeBackend(uint32_t pixels, uint32_t strata, float noise, bool probe = false)
        : strata_(strata), noise_(noise), hasProbe_(probe), accum_(pixels) {}
    std::string name() const override { return "fake"; }
    std::string deviceName() const override { return "test"; }
    void upload(const SceneArrays&) override {}
    void resize(uint32_t, uint32_t) override {}
    void reset() override {
        std::fill(accum_.begin(), accum_.end(), AccumPixel{});
        std::fill(probeAccum_.begin(), probeAccum_.end(), AccumPixel{});
    }
    void renderPasses(const FrameParams& frame, uint32_t firstPass, uint32_t passCount) override {
        const bool probe = frame.target.probe;
        if (probe && !hasProbe_) throw std::logic_error("the fake backend has no error probe");
        const uint32_t seed = probe ? frame.seed : 3u;
        for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
            const size_t n = probe ? probePixels_.size() : accum_.size();
            for (size_t k = 0; k < n; ++k) {
                const uint32_t i = probe ? probePixels_[k] : (uint32_t)k;
                const uint32_t s = stratumForPass(seed, i, 0, pass, strata_);
                SampleStream rng(seed, i, pass);
                const float u = (s + rng.next()) / strata_;
                const float noise = noise_ * (rng.next() + rng.next() + rng.next() - 1.5f) * 2.0f;
                (probe ? probeAccum_[k] : accum_[k]).add(Vec3(value(i, u) + noise), frame.inSecondHalf(pass), 1.0f);
            }
        }
        ++(probe ? probeCalls : calls);
    }
    void readAccumulation(std::vector<AccumPixel>& out) override {
        out = accum_;
        ++reads;
    }
    bool hasProbe() const override { return hasProbe_; }
    void resizeProbe(const std::vector<uint32_t>& pixels) override {
        probePixels_ = pixels;
        probeAccum_.assign(pixels.size(), AccumPixel{});
    }
    void readProbe(std::vector<AccumPixel>& out) override { out = probeAccum_; }
    void writeProbe(const std::vector<AccumPixel>& accum) override {
        probeAccum_ = accum;
        ++probeWrites;
    }
    uint64_t raysTraced() const override { return 0; }
    double traceRays(const std::vector<RayQuery>& queries, RayQueryKind, std::vector<RayAnswer>& out) override {
        out.assign(queries.size(), RayAnswer{INFINITY, kMissAnswer});  // no scene: nothing is hit
        return 0.0;
    }

    // A ramp plus a step whose position depends on the pixel (like a penumbra), integrated exactly below.
    static float value(uint32_t i, float u) {
        return u + (u < 0.2f + 0.6f * ((i * 37u) % 100u) / 100.0f ? 0.8f : 0.2f);
    }
    static double exact(uint32_t i) {
        const double edge = 0.2 + 0.6 * ((i * 37u) % 100u) / 100.0;
        return 0.5 + edge * 0.8 + (1.0 - edge) * 0.2;
    }
    double trueRelError() const {
        double se = 0, mean = 0;
        for (uint32_t i = 0; i < accum_.size(); ++i) {
            const double d = accum_[i].sum[0] / accum_[i].count - exact(i);
            se += d * d;
            mean += exact(i);
        }
        return std::sqrt(se / accum_.size()) / (mean / accum_.size());
    }
    int calls = 0;        // renderPasses of the image
    int probeCalls = 0;   // ... of the probe
    int reads = 0;        // readAccumulation
    int probeWrites = 0;  // writeProbe: a grown probe's accumulation put back

private:
    uint32_t strata_;
    float noise_;
    bool hasProbe_;
    std::vector<AccumPixel> accum_;
    std::vector<uint32_t> probePixels_;
    std::vector<AccumPixel> probeAccum_;
};

}  // namespace test
}  // namespace trazo
