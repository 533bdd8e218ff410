// renderProgressive(): runs passes on a backend until a pass count or a time budget is reached,
// in batches sized so progress reports (and the time limit) stay responsive.
#pragma once

#include <cstdint>
#include <functional>

#include "backends/backend.h"

namespace trazo {

struct RenderLimits {
    uint32_t passes = 1;     // stop after this many passes
    double seconds = 0.0;    // and after this wall time, when > 0 (whichever comes first)
};

struct RenderProgress {
    uint32_t passesDone;
    uint32_t passesTarget;
    double elapsedSeconds;
};

struct RenderOutcome {
    uint32_t passes = 0;
    double seconds = 0.0;
    uint64_t rays = 0;
};

RenderOutcome renderProgressive(Backend& backend, const FrameParams& frame, const RenderLimits& limits,
                                const std::function<void(const RenderProgress&)>& onProgress = {});

}  // namespace trazo
