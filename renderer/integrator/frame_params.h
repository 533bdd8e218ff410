// FrameParams: the per-render values a pass needs besides the scene (camera, image size, seed).
#pragma once

#include <cstdint>

#include "core/rng.h"
#include "integrator/camera_frame.h"
#include "integrator/strata.h"

namespace trazo {

// The pixels a pass renders, and where it adds them. The image (probe false): every pixel, accumulation pixel
// = image pixel. The error probe (render/error_probe.h): a list of image pixel indices, rendered with the
// probe's own seed into an accumulation kProbeRow wide, accumulation pixel (i, j) holding pixels[j·kProbeRow
// + i] (the last row padded). The caller sets `probe`; the backend points `pixels` at its own copy of the list.
constexpr uint32_t kProbeRow = 256;

struct PassPixels {
    bool probe = false;
    const uint32_t* pixels = nullptr;
    uint32_t count = 0;
};

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
    // error_tracker.h chooses it so both halves are equally stratified.
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
    PassPixels target{};
    // The accumulation a pass adds to, and the image pixel each of its pixels is (false: the probe's padding).
    TRAZO_HD uint32_t accumWidth() const { return target.probe ? kProbeRow : camera.width; }
    TRAZO_HD uint32_t accumHeight() const {
        return target.probe ? (target.count + kProbeRow - 1) / kProbeRow : camera.height;
    }
    TRAZO_HD bool imagePixel(uint32_t i, uint32_t j, uint32_t& px, uint32_t& py) const {
        if (!target.probe) {
            px = i, py = j;
            return true;
        }
        const uint32_t k = j * kProbeRow + i;
        if (k >= target.count) return false;
        px = target.pixels[k] % camera.width;
        py = target.pixels[k] / camera.width;
        return true;
    }
};

}  // namespace trazo
