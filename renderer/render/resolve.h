// resolveImage(): the accumulation buffer's estimate, sum / count per pixel (linear RGB, row 0 = top).
#pragma once

#include <vector>

#include "integrator/frame_params.h"

namespace trazo {

inline std::vector<Vec3> resolveImage(const std::vector<AccumPixel>& accum) {
    std::vector<Vec3> image(accum.size());
    for (size_t i = 0; i < accum.size(); ++i)
        image[i] = accum[i].count > 0.0f ? accum[i].sum / accum[i].count : Vec3(0.0f);
    return image;
}

}  // namespace trazo
