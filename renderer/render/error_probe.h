// The error probe: an estimate of any render's error, a one-pass render's included. A lattice of the image's
// pixels (every stride-th pixel across and down, from an offset the seed draws) is rendered a second time over
// the same passes with an independent seed. At a lattice pixel, per channel, the image's value F and the
// probe's G are then independent estimates of the same pixel with the same distribution, so
//     E[(F − G)²] = 2 Var(F)   ⇒   estimated MSE of the image = mean over the lattice of (F − G)² / 2,
// unbiased whatever the pass count, the blocks or the stratification (the halves of error_estimate.h need two
// equally stratified halves, which one pass, or a cycle of one glossy stratum per pass, does not have).
// relError = sqrt(MSE) / the whole image's mean channel value, as error_estimate.h defines it. The probe costs
// its share of the image's work, 1/stride²: a quarter at most, under 2 % from 512 × 512 up. Host code.
#pragma once

#include <cstdint>
#include <vector>

#include "integrator/frame_params.h"
#include "render/error_estimate.h"

namespace trazo {

// About this many lattice pixels (3 channels each): enough that the estimate's own sampling error stays a few
// percent of it even when the error sits in a small part of the image (a penumbra, a glossy highlight).
constexpr uint32_t kProbeTargetPixels = 4096;
constexpr uint32_t kProbeMinStride = 2;

// The lattice of a width × height image: stride max(2, ⌊√(pixels / kProbeTargetPixels)⌋), offset drawn from
// the seed (so no image structure lines up with it on purpose).
PixelLattice probeLattice(uint32_t width, uint32_t height, uint32_t seed);

// The image's frame with the probe's lattice and its own seed (so its strata and jitter are independent).
FrameParams probeFrame(const FrameParams& image, const PixelLattice& lattice);

// The estimate above from the image's accumulation (width pixels a row) and the probe's. Available when both
// hold the same sample weight in every lattice pixel (they render the same passes); probePixels reports the
// lattice's size.
ErrorEstimate estimateErrorWithProbe(const std::vector<AccumPixel>& image, uint32_t width,
                                     const PixelLattice& lattice, const std::vector<AccumPixel>& probe);

}  // namespace trazo
