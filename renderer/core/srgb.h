// sRGB's transfer function inverted (IEC 61966-2-1): an encoded value in [0, 1] to linear. Host code: the path
// integrator's 8-bit colour textures are decoded once, at flatten time (SPEC §7 Surfaces). Its inverse, the
// encoding, is DisplayTransform::encode (core/view_transform.h).
#pragma once

#include <cmath>

#include "core/vec3.h"

namespace trazo {

inline float linearFromSrgb(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

inline Vec3 linearFromSrgb(Vec3 encoded) {
    return {linearFromSrgb(encoded.x), linearFromSrgb(encoded.y), linearFromSrgb(encoded.z)};
}

}  // namespace trazo
