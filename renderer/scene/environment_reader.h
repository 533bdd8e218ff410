// Environment map reader (host): SPEC §7's EnvironmentMap, an equirectangular image of radiance, read as a texture
// is (texture_reader.h: the same formats, size bounds and errors, values kept linear and unclamped), then made a
// radiance every kernel can use: finite and not negative.
#pragma once

#include <memory>
#include <string>

#include "scene/diagnostic.h"
#include "scene/param_check.h"
#include "scene/scene.h"

namespace trazo {

// The largest texel kept, as the largest colour the scene reader takes: BackgroundColor (≤ kMaxColour) times a
// texel stays at 1e24, the bound param_check.h's colours are sized for. Infinite texels (and larger ones) read as it.
constexpr float kMaxEnvironmentTexel = kMaxColour;

// The map at `path`, row 0 the bottom row (TextureImage; a PFM's first row, as the format defines it, where
// FreeImage would make it the top). A file that is missing, unreadable, malformed, in a
// refused format or too large (over kMaxTextureTexels, 8192 × 4096) is an error at `at` (the EnvironmentMap line)
// with the path and the reason, and null comes back; the scene then fails with status 2, as for a texture.
// Components that are NaN or negative read as 0, infinite ones as kMaxEnvironmentTexel, with one warning at `at`
// that says how many texels were changed.
std::shared_ptr<const TextureImage> readEnvironmentMap(const std::string& path, SourceLocation at, Diagnostics& diags);

}  // namespace trazo
