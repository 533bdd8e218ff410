// The error probe: an estimate of any render's error, a one-pass render's included. After the image's first
// pass, a sample of its pixels is drawn and rendered a second time over the same passes with an independent
// seed. At a probed pixel, per channel, the image's value F and the probe's G are then independent estimates
// of the same pixel with the same distribution, so E[(F − G)²/2] = Var(F), and the Horvitz–Thompson sum
//     estimated MSE = (1/3N) Σ_probed (1/π_i) Σ_c (F_ic − G_ic)²/2
// is unbiased for the image's mean squared error (N pixels, π_i the chance pixel i was drawn), whatever the
// passes, blocks or stratification (the halves of error_estimate.h need two equally stratified halves, which
// one pass, or a cycle of one glossy stratum per pass, does not have). The draw may depend on the first pass
// (it is independent of G): each pixel is drawn with a base chance, ~4096 pixels on large images, plus a share
// proportional to its squared value there, so the few bright pixels that carry most of an image's squared
// error (a specular highlight, a bright indirect path) are probed with certainty instead of by luck. Where
// the image has halves, their statistic, known at every pixel, rescales the sum (a ratio estimator).
// A render of many passes grows its probe before each estimate (growProbe): pixel i is then in the probe when
// u_i < π_i' = the largest chance any image so far gave it (u_i: its fixed uniform number), and weighs 1/π_i'.
// π_i' is a function of the images alone, which are independent of u and of G, so the sum stays unbiased;
// and a rare bright sample that lands after the first pass (a glossy reflection of a small light) is then
// probed with certainty too, where the first pass's draw would have missed it but by luck.
// relError = sqrt(MSE) / the image's mean channel value, as error_estimate.h defines it. The probe costs about
// 1.25 × its base share of the image's work: under 2 % from 512 × 512 up, at most 31 %. Host code.
#pragma once

#include <cstdint>
#include <vector>

#include "core/accumulation.h"
#include "integrator/frame_params.h"
#include "render/error_estimate.h"

namespace trazo {

constexpr uint32_t kProbeBasePixels = 4096;  // the base chance's expected draw on large images
constexpr double kProbeMaxBaseShare = 0.25;  // the base chance on small images
constexpr uint32_t kProbeMinPixels = 64;     // ... unless that would draw fewer pixels than this
constexpr double kProbeBrightShare = 0.25;   // the bright share's expected draw, over the base's

struct ErrorProbe {
    std::vector<uint32_t> pixels;  // image pixel indices (y·width + x), ascending
    std::vector<double> weights;   // 1/π of each
    bool empty() const { return pixels.empty(); }
};

// Draws the probe from the image's accumulation after its first pass (width × height, seed: the render's).
ErrorProbe designProbe(const std::vector<AccumPixel>& image, uint32_t width, uint32_t height, uint32_t seed);

// Updates `probe` to the draw of growProbe (see above) for `image`, the render's accumulation now: the
// probed pixels' weights become 1/π_i', and the pixels it adds are returned (ascending, with their weights),
// for the caller to render over the image's passes and merge (addToProbe). `probe` must be designProbe's
// (or grown from it) for the same image size and seed.
ErrorProbe growProbe(const std::vector<AccumPixel>& image, uint32_t width, uint32_t height, uint32_t seed,
                     ErrorProbe& probe);

// Merges the grown pixels `added` and their accumulation into the probe and its accumulation, keeping the
// pixels ascending.
void addToProbe(ErrorProbe& probe, std::vector<AccumPixel>& probeAccum, const ErrorProbe& added,
                const std::vector<AccumPixel>& addedAccum);

// The image's frame rendering the probe: its own seed (so its strata and jitter are independent of the
// image's) into the backend's probe accumulation (Backend::resizeProbe took the pixels).
FrameParams probeFrame(const FrameParams& image);

// The estimate above from the image's accumulation and the probe's (one AccumPixel per probed pixel).
// Available when every probed pixel holds the image's sample weight in both; probePixels reports the count.
ErrorEstimate estimateErrorWithProbe(const std::vector<AccumPixel>& image, const ErrorProbe& probe,
                                     const std::vector<AccumPixel>& probeAccum);

}  // namespace trazo
