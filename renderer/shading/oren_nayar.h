// Oren–Nayar diffuse term of SPEC §5 (qualitative model), cosine included; host and device, and the host's SIMD
// lanes: one formula over the number type T (core/number_ops.h).
#pragma once

#include "core/number_ops.h"
#include "core/vec3.h"

namespace trazo {

// What ON needs of the viewer and σ, computed once per shading point and reused for every light sample.
template <class T>
struct OrenNayarViewOf {
    typename T::F a, b;  // A = 1 − σ²/(2(σ²+0.33)), B = 0.45σ²/(σ²+0.09)
    typename T::F cosV, sinV;
    typename T::V vt;  // V projected on the tangent plane, unit (0 when V ∥ N)
};
using OrenNayarView = OrenNayarViewOf<ScalarOps>;

template <class T>
TRAZO_HD OrenNayarViewOf<T> orenNayarViewOf(const typename T::V& n, const typename T::V& v, typename T::F sigma) {
    const typename T::F s2 = sigma * sigma;
    OrenNayarViewOf<T> w;
    w.a = 1.0f - 0.5f * s2 / (s2 + 0.33f);
    w.b = 0.45f * s2 / (s2 + 0.09f);
    w.cosV = T::min(dot(n, v), 1.0f);
    w.sinV = T::sqrt(T::max(0.0f, 1.0f - w.cosV * w.cosV));
    const typename T::V vt = v - n * w.cosV;
    const typename T::F vt2 = dot(vt, vt);
    w.vt = T::select(vt2 > 0.0f, vt * (1.0f / T::sqrt(vt2)), typename T::V{});
    return w;
}
TRAZO_HD OrenNayarView orenNayarView(Vec3 n, Vec3 v, float sigma) { return orenNayarViewOf<ScalarOps>(n, v, sigma); }

// ON(N, L, V, σ) = (N·L)·(A + B·max(0, cos(φL−φV))·sin α·tan β), α = max(θL, θV), β = min(θL, θV).
// N, L, V unit; N·L > 0 and N·V > 0 assumed. With |Lt| = sin θL the azimuth term is
// cos(φL−φV)·sin θL = L·V̂t, so no square root is left per light:
//     θL ≥ θV:  B·max(0, L·V̂t)·tan θV·cos θL,     θL < θV:  B·max(0, L·V̂t)·sin θV.
// With σ = 0, B = 0 and A = 1, so the result is exactly N·L. Lanes may share the view and n (an
// OrenNayarView, a Vec3) with one l each.
template <class T, class W, class N, class L>
TRAZO_HD typename T::F evalOrenNayarOf(const W& w, const N& n, const L& l) {
    const auto cosL = T::min(dot(n, l), 1.0f);
    const auto smooth = w.b == 0.0f;
    if (T::all(smooth)) return cosL * w.a;
    const auto azimuth = T::max(0.0f, dot(l, w.vt));
    // cos θL ≤ cos θV keeps cosL / cosV ≤ 1, so a grazing viewer cannot overflow tan θV.
    const auto slope = cosL <= w.cosV ? (cosL / w.cosV) * w.sinV : w.sinV;
    return smooth ? cosL * w.a : cosL * w.a + w.b * azimuth * slope;
}
TRAZO_HD float evalOrenNayar(const OrenNayarView& w, Vec3 n, Vec3 l) { return evalOrenNayarOf<ScalarOps>(w, n, l); }

TRAZO_HD float evalOrenNayar(Vec3 n, Vec3 l, Vec3 v, float sigma) {
    return evalOrenNayar(orenNayarView(n, v, sigma), n, l);
}

}  // namespace trazo
