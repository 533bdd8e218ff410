// Raw accumulations of the repository's seed scenes for the partial-render tests, and the check that two of
// them agree within the merge bound (render/merge.h).
#pragma once

#include <string>
#include <vector>

#include "backends/backend.h"
#include "render/pass_range.h"

namespace trazo::test {

// Passes `batches` (in that order) of scenes/`sceneName` at width × height with seed 0, rendered as
// `trazo --render` does (auto blocks, halves and strata windows from the full cycle) on `backend`, which is
// uploaded to and resized here.
std::vector<AccumPixel> renderSeedAccumulation(Backend& backend, const std::string& sceneName, uint32_t width,
                                               uint32_t height, const std::vector<PassRange>& batches);

struct MergeComparison {
    size_t pixels = 0;
    size_t identicalPixels = 0;   // every double of the pixel equal
    size_t identicalFloats = 0;   // the image's three floats equal
    double largestRelative = 0;   // of the sums, over the bound's scale max(|a|, |b|)
};
// Expects (EXPECT_*) both counts of every pixel equal exactly, every sum within mergeRelativeBound(passes)
// relative, and every float of the image within one ulp.
MergeComparison expectWithinMergeBound(const std::vector<AccumPixel>& a, const std::vector<AccumPixel>& b,
                                       uint32_t passes);

}  // namespace trazo::test
