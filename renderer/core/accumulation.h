// AccumPixel: one pixel of the accumulation buffer every backend adds its samples to, and its estimate, the
// pixel the image shows. Kernel and host code (TRAZO_HD): the CUDA passes add to it, resolveImage and the
// viewer's two displays (host upload, CUDA-GL interop) read estimate().
#pragma once

#include "core/hd.h"
#include "core/vec3.h"

namespace trazo {

// RGB sums of weighted samples and the sum of their weights (FrameParams::sampleWeight; 1 for every sample of
// a headless render, so `count` is then the sample count). `sum`/`count` hold every sample; `sumB`/`countB`
// hold the samples of second-half passes only, so the first half is (sum - sumB, count - countB). Two half
// estimates of the same pixel give its error (error_estimate.h). Doubles: a float count stops counting at 2^24
// samples and a float sum stops growing long before, while passes go to 2^30 and the viewer's weights
// multiply them.
struct AccumPixel {
    double sum[3];
    double count;
    double sumB[3];
    double countB;
    // A sample component that is not finite adds 0: one overflowed path must not turn a pixel, and every estimate
    // of the image's error, into NaN or Inf for good (the bounds of docs/LIMITS.md keep valid scenes clear of it).
    TRAZO_HD void add(Vec3 sample, bool secondHalf, float weight) {
        for (int c = 0; c < 3; ++c)
            if (!isFinite(sample[c])) sample[c] = 0.0f;
        const double w = weight;
        for (int c = 0; c < 3; ++c) sum[c] += w * sample[c];
        count += w;
        if (secondHalf) {
            for (int c = 0; c < 3; ++c) sumB[c] += w * sample[c];
            countB += w;
        }
    }
    // The pixel's estimate, sum / count (black before any sample): the one definition of the image.
    TRAZO_HD Vec3 estimate() const {
        if (!(count > 0.0)) return Vec3(0.0f);
        return Vec3(float(sum[0] / count), float(sum[1] / count), float(sum[2] / count));
    }
};

}  // namespace trazo
