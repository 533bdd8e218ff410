// PassRange: passes [first, end) of a render, as `--passes A:B` names them, and the set algebra a merge needs
// (union, overlaps, what is missing from a target). Host code.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace trazo {

struct PassRange {
    uint32_t first = 0, end = 0;
    uint32_t count() const { return end > first ? end - first : 0; }
    bool operator==(const PassRange&) const = default;
};

std::string formatRange(PassRange r);                          // "A:B"
std::string formatRanges(const std::vector<PassRange>& ranges);  // "A:B,C:D" ("" for none)
// "A:B" with A < B (B ≤ `maxEnd`); false with the reason.
bool parsePassRange(const std::string& text, PassRange& out, std::string& why, uint32_t maxEnd);

// Sorted by first pass, empty ranges dropped, touching or overlapping ranges joined.
std::vector<PassRange> joinRanges(std::vector<PassRange> ranges);
uint32_t passCount(const std::vector<PassRange>& disjoint);
// The parts of `target` none of `covered` holds, in order.
std::vector<PassRange> missingRanges(PassRange target, const std::vector<PassRange>& covered);
// The intersection of a and b (empty: count() == 0).
PassRange intersect(PassRange a, PassRange b);

}  // namespace trazo
