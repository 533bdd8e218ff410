// Merging partial renders: the one sum of accumulations (trazo merge, and several devices in one process), and
// the checks that make a merge the image of one render: equal fingerprints, no pass twice, no pass missing.
// Host code.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/accumulation.h"
#include "render/partial_file.h"

namespace trazo {

// total += part, pixel by pixel, every field (sums and counts of both halves). Doubles: the sum of a render's
// parts equals the sum of one render of all its passes to within the bound in docs/PARTIAL_FORMAT.md (counts
// exactly), and adding the parts in one fixed order makes the result independent of how they were listed.
void addAccumulation(std::vector<AccumPixel>& total, const std::vector<AccumPixel>& part);

// How far apart two sums of the same n non-negative samples can be when added in different orders (one render
// in pass order, or its parts' sums added): each is within γ = (n-1)u / (1-(n-1)u) of the exact sum, u = 2^-53
// (Higham, Accuracy and Stability of Numerical Algorithms, §4.2, for any order), so they differ by at most
// 2γ / (1-γ) relative to either. The image's float pixels (sum / count, counts equal: two quotients within
// this + 2^-52 relative) then differ by at most one ulp while that stays below 2^-25, half the smallest relative
// float spacing, so that no two rounding midpoints lie between them: up to 2^26 passes.
double mergeRelativeBound(uint32_t passes);

struct MergeOptions {
    bool allowGaps = false;            // merge what exists; the missing ranges are reported, not refused
    std::optional<PassRange> expected;  // the passes the parts must cover; default [0, the largest end asked)
};

struct MergeResult {
    PartialHeader header;           // passes: what the parts hold; requested: the target; parts, rays, seconds summed
    std::vector<AccumPixel> accum;
    std::vector<PassRange> missing;  // with allowGaps: the target's passes no part holds
};

// Reads every header first (sizes, versions, fingerprints, ranges), then adds the parts in the order of their
// first pass. False with the message (several lines for several problems, each "PATH: ..." or "passes A:B ..."):
// a part that cannot be read or is corrupt, fingerprints that differ (naming both files and the field), passes
// held by two parts, and (without allowGaps) passes missing.
bool mergePartialFiles(const std::vector<std::string>& paths, const MergeOptions& options, MergeResult& result,
                       std::string& error);

}  // namespace trazo
