// resolveImage(): the image an accumulation buffer holds, AccumPixel::estimate() per pixel (linear RGB, row 0 = top).
#pragma once

#include <vector>

#include "core/accumulation.h"

namespace trazo {

inline std::vector<Vec3> resolveImage(const std::vector<AccumPixel>& accum) {
    std::vector<Vec3> image(accum.size());
    for (size_t i = 0; i < accum.size(); ++i)
        image[i] = accum[i].estimate();
    return image;
}

}  // namespace trazo
