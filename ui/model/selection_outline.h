// The selection's outline: the edge of an object's pixel mask (host, no GL). The display draws it over the
// image, never into the accumulation or a saved image.
#pragma once

#include <cstdint>
#include <vector>

namespace trazo {

// 1 where `mask` (width × height, 1 on the object) is 1 and a 4-neighbour is 0 or outside the image, else 0.
std::vector<uint8_t> outlineOf(const std::vector<uint8_t>& mask, uint32_t width, uint32_t height);

}  // namespace trazo
