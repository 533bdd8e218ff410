// Name suggestion (host): case-insensitive edit distance to each candidate; only a close one is offered.
#include "scene/did_you_mean.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

namespace trazo {
namespace {

std::string lower(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = char(std::tolower(static_cast<unsigned char>(c)));
    return r;
}

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string didYouMean(std::string_view wrong, const std::vector<std::string_view>& candidates) {
    // Case-insensitive distance, so that "radius" finds "Radius"; only close names are worth a hint.
    const std::string w = lower(wrong);
    std::string_view best;
    size_t bestDistance = SIZE_MAX;
    for (std::string_view c : candidates) {
        const size_t d = editDistance(w, lower(c));
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    const size_t limit = std::max<size_t>(2, w.size() / 3);
    if (best.empty() || bestDistance > limit) return {};
    return "did you mean '" + std::string(best) + "'?";
}

}  // namespace trazo
