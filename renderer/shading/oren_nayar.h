// Oren–Nayar diffuse term of SPEC §5 (qualitative model), cosine included; host and device.
#pragma once

#include "core/vec3.h"

namespace trazo {

// What ON needs of the viewer and σ, computed once per shading point and reused for every light sample.
struct OrenNayarView {
    float a, b;       // A = 1 − σ²/(2(σ²+0.33)), B = 0.45σ²/(σ²+0.09)
    float cosV, sinV;
    Vec3 vt;          // V projected on the tangent plane, unit (0 when V ∥ N)
};

TRAZO_HD OrenNayarView orenNayarView(Vec3 n, Vec3 v, float sigma) {
    const float s2 = sigma * sigma;
    OrenNayarView w;
    w.a = 1.0f - 0.5f * s2 / (s2 + 0.33f);
    w.b = 0.45f * s2 / (s2 + 0.09f);
    w.cosV = minOf(dot(n, v), 1.0f);
    w.sinV = sqrtf(maxOf(0.0f, 1.0f - w.cosV * w.cosV));
    const Vec3 vt = v - n * w.cosV;
    const float vt2 = lengthSquared(vt);
    w.vt = vt2 > 0.0f ? vt * (1.0f / sqrtf(vt2)) : Vec3(0.0f);
    return w;
}

// ON(N, L, V, σ) = (N·L)·(A + B·max(0, cos(φL−φV))·sin α·tan β), α = max(θL, θV), β = min(θL, θV).
// N, L, V unit; N·L > 0 and N·V > 0 assumed. With |Lt| = sin θL the azimuth term is
// cos(φL−φV)·sin θL = L·V̂t, so no square root is left per light:
//     θL ≥ θV:  B·max(0, L·V̂t)·tan θV·cos θL,     θL < θV:  B·max(0, L·V̂t)·sin θV.
// With σ = 0, B = 0 and A = 1, so the result is exactly N·L.
TRAZO_HD float evalOrenNayar(const OrenNayarView& w, Vec3 n, Vec3 l) {
    const float cosL = minOf(dot(n, l), 1.0f);
    if (w.b == 0.0f) return cosL * w.a;
    const float azimuth = maxOf(0.0f, dot(l, w.vt));
    // cos θL ≤ cos θV keeps cosL / cosV ≤ 1, so a grazing viewer cannot overflow tan θV.
    const float slope = cosL <= w.cosV ? (cosL / w.cosV) * w.sinV : w.sinV;
    return cosL * w.a + w.b * azimuth * slope;
}

TRAZO_HD float evalOrenNayar(Vec3 n, Vec3 l, Vec3 v, float sigma) {
    return evalOrenNayar(orenNayarView(n, v, sigma), n, l);
}

}  // namespace trazo
