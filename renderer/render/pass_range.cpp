// Pass ranges: parsing, printing and the merge's set algebra.
#include "render/pass_range.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

namespace trazo {

std::string formatRange(PassRange r) { return std::to_string(r.first) + ":" + std::to_string(r.end); }

std::string formatRanges(const std::vector<PassRange>& ranges) {
    std::string text;
    for (const PassRange& r : ranges) {
        if (!text.empty()) text += ',';
        text += formatRange(r);
    }
    return text;
}

namespace {

bool parseCount(const std::string& text, uint64_t& out) {
    if (text.empty() || text.size() > 12 || text.find_first_not_of("0123456789") != std::string::npos) return false;
    out = std::strtoull(text.c_str(), nullptr, 10);
    return true;
}

}  // namespace

bool parsePassRange(const std::string& text, PassRange& out, std::string& why, uint32_t maxEnd) {
    const size_t colon = text.find(':');
    uint64_t first = 0, end = 0;
    if (colon == std::string::npos || !parseCount(text.substr(0, colon), first) ||
        !parseCount(text.substr(colon + 1), end)) {
        why = "expected FIRST:END, two pass numbers (passes FIRST to END-1), e.g. 0:64";
        return false;
    }
    if (end <= first) {
        why = "END must be greater than FIRST (the range holds passes FIRST to END-1)";
        return false;
    }
    if (end > maxEnd) {
        why = "END must be at most " + std::to_string(maxEnd);
        return false;
    }
    out = PassRange{(uint32_t)first, (uint32_t)end};
    return true;
}

std::vector<PassRange> joinRanges(std::vector<PassRange> ranges) {
    std::erase_if(ranges, [](PassRange r) { return r.count() == 0; });
    std::sort(ranges.begin(), ranges.end(), [](PassRange a, PassRange b) { return a.first < b.first; });
    std::vector<PassRange> joined;
    for (const PassRange& r : ranges) {
        if (!joined.empty() && r.first <= joined.back().end) joined.back().end = std::max(joined.back().end, r.end);
        else joined.push_back(r);
    }
    return joined;
}

uint32_t passCount(const std::vector<PassRange>& disjoint) {
    uint32_t n = 0;
    for (const PassRange& r : disjoint) n += r.count();
    return n;
}

std::vector<PassRange> missingRanges(PassRange target, const std::vector<PassRange>& covered) {
    std::vector<PassRange> missing;
    uint32_t at = target.first;
    for (const PassRange& r : joinRanges(covered)) {
        if (r.end <= at) continue;
        if (r.first >= target.end) break;
        if (r.first > at) missing.push_back(PassRange{at, r.first});
        at = std::max(at, r.end);
    }
    if (at < target.end) missing.push_back(PassRange{at, target.end});
    return missing;
}

PassRange intersect(PassRange a, PassRange b) {
    const uint32_t first = std::max(a.first, b.first), end = std::min(a.end, b.end);
    return end > first ? PassRange{first, end} : PassRange{};
}

}  // namespace trazo
