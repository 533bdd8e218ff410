// The per-channel refractive index of SPEC §6 (Dispersion), host and device: glTF KHR_materials_dispersion's
// Abbe-number model evaluated at the dominant wavelengths of the sRGB primaries.
#pragma once

#include "core/vec3.h"

namespace trazo {

// n(λ) = max(1, n + (n − 1)·(D/20)·(523655/λ² − 1.5168)), λ in nm, D = 20/V (V the Abbe number). The
// constants make n(587.56 nm) = n (the d line) and n(486.13) − n(656.27) = (n − 1)/V to 0.04%, so V keeps
// its meaning. D = 0 returns n itself, bit for bit and for any n: §6 says the three channels are then n,
// which the clamp would contradict for n < 1 (RefractionIndex only has to be positive).
TRAZO_HD float dispersedIndexAt(float n, float dispersion, float wavelengthNm) {
    if (dispersion == 0.0f) return n;
    const float spread = 523655.0f / (wavelengthNm * wavelengthNm) - 1.5168f;
    return maxOf(1.0f, n + (n - 1.0f) * (dispersion / 20.0f) * spread);
}

// Channel 0, 1, 2 = R, G, B at λR = 611, λG = 549, λB = 464 nm: blue bends most when D > 0 and n > 1.
TRAZO_HD float dispersedIndex(float n, float dispersion, int channel) {
    const float wavelengthNm = channel == 0 ? 611.0f : (channel == 1 ? 549.0f : 464.0f);
    return dispersedIndexAt(n, dispersion, wavelengthNm);
}

// The one channel a ray's weight is non-zero in, or −1 when it has several (or none).
TRAZO_HD int soleChannel(Vec3 w) {
    if (w.y == 0.0f && w.z == 0.0f) return w.x != 0.0f ? 0 : -1;
    if (w.x == 0.0f && w.z == 0.0f) return 1;
    if (w.x == 0.0f && w.y == 0.0f) return 2;
    return -1;
}

// The weight of a ray that carries channel c alone (the "hero" channel, one of three chosen with equal
// frequency): 3·w_c in channel c, 0 in the others, so each channel's expectation stays w.
TRAZO_HD Vec3 heroChannelWeight(Vec3 w, uint32_t channel) {
    return Vec3(channel == 0u ? 3.0f * w.x : 0.0f, channel == 1u ? 3.0f * w.y : 0.0f,
                channel == 2u ? 3.0f * w.z : 0.0f);
}

}  // namespace trazo
