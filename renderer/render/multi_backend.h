// MultiBackend: one Backend over several (one per CUDA device, `--devices`), each driven from its own thread.
// renderPasses splits the pass range into contiguous sub-ranges, one per backend; readAccumulation adds their
// accumulations in backend order with the sum `trazo merge` uses (addAccumulation); the error probe likewise.
// Host code.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "backends/backend.h"
#include "render/pass_range.h"

namespace trazo {

class MultiBackend final : public Backend {
public:
    explicit MultiBackend(std::vector<std::unique_ptr<Backend>> backends);

    std::string name() const override;        // the backends' name ("cuda")
    bool runsOnCuda() const override { return backends_[0]->runsOnCuda(); }
    std::string deviceName() const override;  // "N devices: NAME, NAME, ..."
    bool accepts(const SceneArrays& arrays, std::string& why) const override;
    void upload(const SceneArrays& arrays) override;
    void resize(uint32_t width, uint32_t height) override;
    void reset() override;
    void renderPasses(const FrameParams& frame, uint32_t firstPass, uint32_t passCount) override;
    void readAccumulation(std::vector<AccumPixel>& out) override;
    // The probe as the image: every backend holds one, passes split the same way, read as their sum.
    bool hasProbe() const override;
    void resizeProbe(const std::vector<uint32_t>& pixels) override;
    void readProbe(std::vector<AccumPixel>& out) override;
    void writeProbe(const std::vector<AccumPixel>& accum) override;  // to the first backend, the others cleared
    uint64_t raysTraced() const override;
    using Backend::traceRays;
    double traceRays(const std::vector<RayQuery>& queries, RayQueryKind kind, std::vector<RayAnswer>& out) override;

    size_t size() const { return backends_.size(); }

private:
    // Runs f(i) for every backend, each on its own thread; rethrows the first exception once all are done.
    void forEach(const std::function<void(size_t)>& f);
    // Reads every backend's accumulation (or probe) and adds them in backend order.
    void readSum(void (Backend::*read)(std::vector<AccumPixel>&), std::vector<AccumPixel>& out);

    std::vector<std::unique_ptr<Backend>> backends_;
};

// Backend i's share of passes [first, first + count) split over n backends: contiguous, in order, sizes
// differing by at most one (the first count % n get one more).
PassRange splitPasses(uint32_t first, uint32_t count, size_t n, size_t i);

}  // namespace trazo
