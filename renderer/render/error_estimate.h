// The error of an image: estimated by the accumulation itself (from its two halves), or measured against a
// reference. Both use the same relative error, so an estimate and a measurement can be compared. Host code.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/accumulation.h"

namespace trazo {

// Relative error of an image F against the exact image I, over P pixels and the 3 channels c:
//     relError = sqrt( (1/3P) Σ_{i,c} (F_ic - I_ic)² ) / ( (1/3P) Σ_{i,c} I_ic ),
// the RMSE over all channels divided by the image's mean channel value (one number per image, so dark
// pixels do not blow it up; 0.01 means the typical pixel is off by 1% of the image's mean brightness).
//
// Estimate (estimateError): per pixel and channel the two halves of the accumulation give means A (first
// half, nA samples) and B (second half, nB samples). If they are independent estimates of the same value with
// variances σ²/nA and σ²/nB, the mean of all n = nA + nB samples has variance σ²/n and
//     E[(A - B)²] = σ² (1/nA + 1/nB)   ⇒   Var(F) ≈ (nA·nB / n²) (A - B)²,
// one χ²₁ estimate per pixel-channel, averaged over the image: estimated RMSE = sqrt(mean Var(F)), and
// relError = estimated RMSE / mean channel value of F. Unbiased when the halves are equally stratified,
// which the half split gives at multiples of 2·cycle passes (error_tracker.h).
struct ErrorEstimate {
    bool available = false;   // both halves hold samples in every pixel
    double rmse = NAN;        // estimated RMSE of the image (linear units)
    double relError = NAN;    // rmse / meanValue
    double meanValue = 0.0;   // mean channel value of the image
    uint32_t passes = 0;      // samples per pixel (of the first pixel; all pixels get the same passes)
    uint32_t secondHalfPasses = 0;
    uint32_t probePixels = 0;  // > 0: estimated from an error probe of this many pixels (error_probe.h)
    bool exact = false;        // 0 by construction: every pass is the same image (render_plan.h, noSamplingNoise)
};

ErrorEstimate estimateError(const std::vector<AccumPixel>& accum);

// Measured against a reference (row-major RGB, same size): RMSE and relError as above (the reference's
// mean as denominator), and the relative MSE of the denoising literature (Rousselle et al. 2011),
//     relMse = (1/3P) Σ_{i,c} (F_ic - I_ic)² / (I_ic² + 0.01),
// which weights dark pixels more (reported, not the stopping criterion).
struct ReferenceError {
    double rmse = NAN;
    double relError = NAN;
    double relMse = NAN;
};

ReferenceError compareToReference(const std::vector<Vec3>& image, const std::vector<Vec3>& reference);

}  // namespace trazo
