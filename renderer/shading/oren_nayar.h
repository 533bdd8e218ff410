// Oren–Nayar diffuse term of SPEC §5 (qualitative model), cosine included; host and device.
#pragma once

#include "core/vec3.h"

namespace trazo {

// ON(N, L, V, σ) = (N·L)·(A + B·max(0, cos(φL−φV))·sin α·tan β). N, L, V unit; N·L > 0 and N·V > 0 assumed.
// With σ = 0, B = 0 and A = 1, so the result is exactly N·L.
TRAZO_HD float evalOrenNayar(Vec3 n, Vec3 l, Vec3 v, float sigma) {
    const float cosL = fminf(dot(n, l), 1.0f);
    const float cosV = fminf(dot(n, v), 1.0f);
    const float s2 = sigma * sigma;
    const float a = 1.0f - 0.5f * s2 / (s2 + 0.33f);
    const float b = 0.45f * s2 / (s2 + 0.09f);
    if (b == 0.0f) return cosL * a;
    // cos(φL − φV) from the projections of L and V on the tangent plane.
    const Vec3 lt = l - n * cosL;
    const Vec3 vt = v - n * cosV;
    const float tangentLengths = sqrtf(lengthSquared(lt) * lengthSquared(vt));
    const float cosPhi = tangentLengths > 0.0f ? fmaxf(0.0f, dot(lt, vt) / tangentLengths) : 0.0f;
    // α = max(θL, θV) has the smaller cosine; β = min(θL, θV) the larger.
    const float cosAlpha = fminf(cosL, cosV);
    const float cosBeta = fmaxf(cosL, cosV);
    const float sinAlpha = sqrtf(fmaxf(0.0f, 1.0f - cosAlpha * cosAlpha));
    const float tanBeta = sqrtf(fmaxf(0.0f, 1.0f - cosBeta * cosBeta)) / cosBeta;
    return cosL * (a + b * cosPhi * sinAlpha * tanBeta);
}

}  // namespace trazo
