// The thesis's reflectance at a shading point (SPEC §5's Shade without the light's colour): Oren–Nayar diffuse plus
// Cook–Torrance specular, as the thesis writes them (no 1/π).
#pragma once

#include "shading/shading_point.h"
#include "shading/cook_torrance.h"
#include "shading/material.h"
#include "shading/oren_nayar.h"

namespace trazo {

// The material's Shade of SPEC §5 at one shading point. On the host a black lobe is never evaluated (a matte
// surface pays no Cook–Torrance; σ = 0 no Oren–Nayar azimuth) and what depends only on the viewer is computed
// once per point. The device evaluates both lobes per sample without branches: fewer live values, and the
// registers are what limit a GPU thread (ptxas, sm_90: 12 of the 16 variants at or below 9b68041's count).
struct PointBrdf {
    const ShadingPoint& sp;
    const MaterialData& m;
    bool hasDiffuse, hasSpecular;
#if !TRAZO_DEVICE_PATHS
    OrenNayarView diffuseView;
#endif

    TRAZO_HD PointBrdf(const ShadingPoint& spIn, const MaterialData& mIn)
        : sp(spIn), m(mIn), hasDiffuse(!isBlack(mIn.diffuse)), hasSpecular(!isBlack(mIn.specular)) {
#if !TRAZO_DEVICE_PATHS
        diffuseView = orenNayarView(sp.n, sp.v, m.roughness);
#endif
    }

    TRAZO_HD bool reflects() const { return (hasDiffuse || hasSpecular) && dot(sp.n, sp.v) > 0.0f; }
    // Kd·ON(N, L, V, σ) + Ks·CT(N, L, V, σ); N·L > 0 and N·V > 0 assumed.
    TRAZO_HD Vec3 eval(Vec3 l) const {
        Vec3 f(0.0f);
#if !TRAZO_DEVICE_PATHS
        if (hasDiffuse) f = m.diffuse * evalOrenNayar(diffuseView, sp.n, l);
        if (hasSpecular) f += m.specular * evalCookTorrance(sp.n, l, sp.v, m.roughness);
#else  // both lobes, branch-free: a black one adds 0
        f = m.diffuse * evalOrenNayar(sp.n, l, sp.v, m.roughness) +
            m.specular * evalCookTorrance(sp.n, l, sp.v, m.roughness);
#endif
        return f;
    }
};

// PointBrdf(sp, m).reflects() of a point with normal n, viewer v and those lobes, without the view it computes.
TRAZO_HD bool reflectsLight(Vec3 diffuse, Vec3 specular, Vec3 n, Vec3 v) {
    return (!isBlack(diffuse) || !isBlack(specular)) && dot(n, v) > 0.0f;
}

}  // namespace trazo
