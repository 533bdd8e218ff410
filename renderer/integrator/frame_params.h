// FrameParams: the per-render values a pass needs besides the scene (camera, image size, seed).
#pragma once

#include <cstdint>

#include "core/rng.h"
#include "integrator/camera_frame.h"
#include "integrator/strata.h"

namespace trazo {

struct FrameParams {
    CameraFrame camera;
    uint32_t seed = 0;
    // The strata of each grid a pass evaluates (strata.h); StrataBlocks::whole() is the thesis's estimator.
    StrataBlocks blocks{};
    // What a sample of this render counts for in the accumulation (AccumPixel::add). Passes of one render all
    // weigh the same; the viewer, whose blocks grow between segments, weighs a segment's samples by the
    // one-stratum passes each stands for, so later, larger blocks are not outvoted by early small ones.
    float sampleWeight = 1.0f;
    // Passes alternate between the accumulation's two halves in blocks of this many (0: no second half);
    // progressive_render.h chooses it so both halves are equally stratified.
    uint32_t halfBlock = 0;
    TRAZO_HD bool inSecondHalf(uint32_t pass) const { return halfBlock != 0 && ((pass / halfBlock) & 1u); }
    // Every this many passes (a multiple of every grid's size; 0: never) each grid draws a new visiting order.
    // Within a window the grids keep their orders, so which cell of one grid meets which cell of another
    // (a light cell at Q with an indirect direction, say) is fixed; new windows re-pair them, so the estimate
    // converges to the exact integral over all pairings instead of the mean over one pairing.
    uint32_t strataWindow = 0;
    TRAZO_HD uint32_t strataSeed(uint32_t pass) const {
        const uint32_t window = strataWindow != 0 ? pass / strataWindow : 0u;
        return window == 0 ? seed : hashCombine(seed, window);
    }
};

// Accumulation per pixel: RGB sums of weighted samples and the sum of their weights
// (FrameParams::sampleWeight; 1 for every sample of a headless render, so `count` is then the sample count).
// `sum`/`count` hold every sample (the image is estimate() = sum / count); `sumB`/`countB` hold the samples of
// second-half passes only, so the first half is (sum - sumB, count - countB). Two half estimates of the same
// pixel give its error (error_estimate.h). Doubles: a float count stops counting at 2^24 samples and a float
// sum stops growing long before, while passes go to 2^30 and the viewer's weights multiply them.
struct AccumPixel {
    double sum[3];
    double count;
    double sumB[3];
    double countB;
    TRAZO_HD void add(Vec3 sample, bool secondHalf, float weight) {
        const double w = weight;
        for (int c = 0; c < 3; ++c) sum[c] += w * sample[c];
        count += w;
        if (secondHalf) {
            for (int c = 0; c < 3; ++c) sumB[c] += w * sample[c];
            countB += w;
        }
    }
    // The pixel's estimate: what the image shows (resolveImage, the viewer's displays).
    TRAZO_HD Vec3 estimate() const {
        if (!(count > 0.0)) return Vec3(0.0f);
        return Vec3(float(sum[0] / count), float(sum[1] / count), float(sum[2] / count));
    }
};

}  // namespace trazo
