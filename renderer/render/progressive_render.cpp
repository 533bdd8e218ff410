// Batching of passes: the first batch is one pass; later ones aim at kBatchSeconds each.
#include "render/progressive_render.h"

#include <algorithm>
#include <chrono>

namespace trazo {

namespace {
constexpr double kBatchSeconds = 0.2;
}

RenderOutcome renderProgressive(Backend& backend, const FrameParams& frame, const RenderLimits& limits,
                                const std::function<void(const RenderProgress&)>& onProgress) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    RenderOutcome out;
    uint32_t batch = 1;
    while (out.passes < limits.passes) {
        const uint32_t count = std::min(batch, limits.passes - out.passes);
        backend.renderPasses(frame, out.passes, count);
        out.passes += count;
        const double t = elapsed();
        if (onProgress) onProgress(RenderProgress{out.passes, limits.passes, t});

        const double perPass = t / out.passes;
        double target = kBatchSeconds;
        if (limits.seconds > 0.0) {
            const double left = limits.seconds - t;
            if (left < 0.5 * perPass) break;  // one more pass would overshoot the budget more than it helps
            target = std::min(target, left);
        }
        batch = (uint32_t)std::clamp(target / std::max(perPass, 1e-9), 1.0, 65536.0);
    }
    out.seconds = elapsed();
    out.rays = backend.raysTraced();
    return out;
}

}  // namespace trazo
