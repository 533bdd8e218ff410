// Texture reader (host): decodes an image file with FreeImage into linear float RGB, bottom row first.
#pragma once

#include <memory>
#include <string>

#include "scene/diagnostic.h"
#include "scene/scene.h"

namespace trazo {

// Texel values are kept as stored (8-bit divided by 255, no sRGB decoding, SPEC §3; `eightBit` says which, for
// the path integrator's decoding at flatten time, SPEC §7); alpha is dropped.
// On failure returns null after reporting at `where` (the Texture block's Source line) with the path and why.
std::shared_ptr<const TextureImage> readTextureImage(const std::string& path, const SourceLocation& where,
                                                     Diagnostics& diags);

}  // namespace trazo
