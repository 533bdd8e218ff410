// FrameParams: the per-render values a pass needs besides the scene (camera, image size, seed).
#pragma once

#include <cstdint>

#include "integrator/camera_frame.h"

namespace trazo {

struct FrameParams {
    CameraFrame camera;
    uint32_t seed = 0;
    // The thesis's estimator (--fixed-grid): every pass evaluates every stratum of every grid instead of one.
    bool fixedGrid = false;
    // Passes alternate between the accumulation's two halves in blocks of this many (0: no second half);
    // progressive_render.h chooses it so both halves are equally stratified.
    uint32_t halfBlock = 0;
    TRAZO_HD bool inSecondHalf(uint32_t pass) const { return halfBlock != 0 && ((pass / halfBlock) & 1u); }
};

// Accumulation per pixel: float RGB sums and the number of samples added. `sum`/`count` hold every sample
// (the image is sum / count); `sumB`/`countB` hold the samples of second-half passes only, so the first half
// is (sum - sumB, count - countB). Two half estimates of the same pixel give its error (error_estimate.h).
struct AccumPixel {
    Vec3 sum;
    float count;
    Vec3 sumB;
    float countB;
    TRAZO_HD void add(Vec3 sample, bool secondHalf) {
        sum += sample;
        count += 1.0f;
        if (secondHalf) {
            sumB += sample;
            countB += 1.0f;
        }
    }
};

}  // namespace trazo
