// The outline: a mask pixel whose 4-neighbourhood leaves the mask.
#include "model/selection_outline.h"

#include <cstddef>

namespace trazo {

std::vector<uint8_t> outlineOf(const std::vector<uint8_t>& mask, uint32_t width, uint32_t height) {
    std::vector<uint8_t> edge(mask.size(), 0);
    if (mask.size() != size_t(width) * height) return edge;
    const auto on = [&](int64_t x, int64_t y) {
        return x >= 0 && y >= 0 && x < int64_t(width) && y < int64_t(height) && mask[size_t(y) * width + size_t(x)];
    };
    for (int64_t y = 0; y < int64_t(height); ++y)
        for (int64_t x = 0; x < int64_t(width); ++x)
            if (on(x, y) && !(on(x - 1, y) && on(x + 1, y) && on(x, y - 1) && on(x, y + 1)))
                edge[size_t(y) * width + size_t(x)] = 1;
    return edge;
}

}  // namespace trazo
