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
};

// A pass index with this bit set accumulates into the second half as well (see AccumPixel). The host
// chooses which passes those are (progressive_render.h: kernelPassIndex), so the split can follow the
// scene's strata; kernels treat the index like any other (strata and jitter are keyed by it).
constexpr uint32_t kSecondHalfPassBit = 1u << 31;

// Accumulation per pixel: float RGB sums and the number of samples added. `sum`/`count` hold every sample
// (the image is sum / count); `sumB`/`countB` hold the samples of second-half passes only, so the first half
// is (sum - sumB, count - countB). Two half estimates of the same pixel give its error (error_estimate.h).
struct AccumPixel {
    Vec3 sum;
    float count;
    Vec3 sumB;
    float countB;
    TRAZO_HD void add(Vec3 sample, uint32_t pass) {
        sum += sample;
        count += 1.0f;
        if (pass & kSecondHalfPassBit) {
            sumB += sample;
            countB += 1.0f;
        }
    }
};

}  // namespace trazo
