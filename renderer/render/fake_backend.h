// Test helper (host): a backend with a known answer for the error estimate's and the progressive render's
// tests (error_estimate_test.cpp, progressive_render_test.cpp), so their statistics are exact and quick.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "core/rng.h"

namespace trazo {
namespace test {

// A backend without a scene: pass v of pixel i adds f(i, stratum) + noise, with the strata of a grid of
// `strata` cells cycled from a per-pixel offset exactly as the kernels do. Exact value per pixel known.
class FakeBackend final : public Backend {
public:
    FakeBackend(uint32_t pixels, uint32_t strata, float noise) : strata_(strata), noise_(noise), accum_(pixels) {}
    std::string name() const override { return "fake"; }
    std::string deviceName() const override { return "test"; }
    void upload(const SceneArrays&) override {}
    void resize(uint32_t, uint32_t) override {}
    void reset() override { std::fill(accum_.begin(), accum_.end(), AccumPixel{}); }
    void renderPasses(const FrameParams& frame, uint32_t firstPass, uint32_t passCount) override {
        for (uint32_t pass = firstPass; pass < firstPass + passCount; ++pass) {
            for (uint32_t i = 0; i < accum_.size(); ++i) {
                const uint32_t s = stratumForPass(3, i, 0, pass, strata_);
                SampleStream rng(3, i, pass);
                const float u = (s + rng.next()) / strata_;
                const float noise = noise_ * (rng.next() + rng.next() + rng.next() - 1.5f) * 2.0f;
                accum_[i].add(Vec3(value(i, u) + noise), frame.inSecondHalf(pass), 1.0f);
            }
        }
        ++calls;
    }
    void readAccumulation(std::vector<AccumPixel>& out) override { out = accum_; }
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
    int calls = 0;

private:
    uint32_t strata_;
    float noise_;
    std::vector<AccumPixel> accum_;
};

}  // namespace test
}  // namespace trazo
