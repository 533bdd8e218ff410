// Cook–Torrance specular term of SPEC §5 (Beckmann D, geometric attenuation G, no Fresnel); host and device, and
// the host's SIMD lanes: one formula over the number type T (core/number_ops.h).
#pragma once

#include "core/number_ops.h"
#include "core/vec3.h"

namespace trazo {

// CT = π·D·G / (4·(N·V)), D = exp(−tan²θH/m²)/(π m² cos⁴θH), m = max(roughness, 0.01).
// N, L, V unit; N·L > 0 and N·V > 0 assumed. 0 outside `live` (lanes: those in use, where libm's expf is called).
// Lanes may share n, v and the roughness (Vec3, float) with one l each.
template <class T, class N, class L, class R>
TRAZO_HD typename T::F cookTorranceOf(const N& n, const L& l, const N& v, R roughness, typename T::B live) {
    const auto m = T::max(roughness, 0.01f);
    const auto h = normalize(l + v);
    const auto nh = T::min(dot(n, h), 1.0f);
    const auto nv = dot(n, v);
    const auto nl = dot(n, l);
    const auto vh = dot(v, h);
    const typename T::B lit = live & !(nh <= 0.0f || vh <= 0.0f);
    if (!T::any(lit)) return T::splat(0.0f);
    const auto nh2 = nh * nh;
    const auto tan2 = (1.0f - nh2) / nh2;
    const auto m2 = m * m;
    // π·D with the π of D cancelled.
    const auto piD = T::exp(-tan2 / m2, lit) / (m2 * nh2 * nh2);
    const auto g = T::min(1.0f, 2.0f * nh * T::min(nv, nl) / vh);
    return lit ? piD * g / (4.0f * nv) : T::splat(0.0f);
}

TRAZO_HD float evalCookTorrance(Vec3 n, Vec3 l, Vec3 v, float roughness) {
    return cookTorranceOf<ScalarOps>(n, l, v, roughness, true);
}

}  // namespace trazo
