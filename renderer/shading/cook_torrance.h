// Cook–Torrance specular term of SPEC §5 (Beckmann D, geometric attenuation G, no Fresnel); host and device.
#pragma once

#include "core/vec3.h"

namespace trazo {

// CT = π·D·G / (4·(N·V)), D = exp(−tan²θH/m²)/(π m² cos⁴θH), m = max(roughness, 0.01).
// N, L, V unit; N·L > 0 and N·V > 0 assumed.
TRAZO_HD float evalCookTorrance(Vec3 n, Vec3 l, Vec3 v, float roughness) {
    const float m = maxOf(roughness, 0.01f);
    const Vec3 h = normalize(l + v);
    const float nh = minOf(dot(n, h), 1.0f);
    const float nv = dot(n, v);
    const float nl = dot(n, l);
    const float vh = dot(v, h);
    if (nh <= 0.0f || vh <= 0.0f) return 0.0f;
    const float nh2 = nh * nh;
    const float tan2 = (1.0f - nh2) / nh2;
    const float m2 = m * m;
    // π·D with the π of D cancelled.
    const float piD = expf(-tan2 / m2) / (m2 * nh2 * nh2);
    const float g = minOf(1.0f, 2.0f * nh * minOf(nv, nl) / vh);
    return piD * g / (4.0f * nv);
}

}  // namespace trazo
